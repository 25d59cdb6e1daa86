// study.csv and study.h5 hold each wheel's axle position and two-point flag
// (`leading_outer.wheelset_lateral [m]`, `.wheelset_yaw [rad]`, `.two_point [-]`;
// /study/wheels/<wheel>/{wheelset_lateral, wheelset_yaw, two_point}) as the case files hold them
// (/noise/wheels/<wheel>/contact/*), and the leading outer wheel's flag is the case's own
// /noise/contact/two_point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/cli_support.hpp"
#include "io/hdf5_reader.hpp"

namespace fs = std::filesystem;
using rollnoise::cli_test::run;

namespace {

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  return cells;
}

double scalar(const std::string& file, const std::string& path) {
  const auto v = rollnoise::io::Hdf5Reader(file).numbers(path);
  return v && v->size() == 1 ? v->front() : -999.0;
}

}  // namespace

TEST(StudyWheelPosition, CsvAndH5HoldEachWheelsAxlePositionAndTwoPointFlagOfTheCaseFiles) {
  const fs::path d = rollnoise::cli_test::fresh_dir("study_wheel_position");
  const fs::path study = d / "study.toml";
  std::ofstream(study) << "base = \"" << ROLLNOISE_SOURCE_DIR
                       << "/tests/data/study/curve_small_wheels.toml\"\noutput = \"out\"\n[axes]\n"
                       << "\"curve.radius\" = [300.0, 1000.0]\n";
  const auto r = run("study " + study.string() + " -j 1 -q");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto c = run("collect " + study.string() + " -q");
  ASSERT_EQ(c.status, 0) << c.output;

  std::ifstream csv(d / "out/study.csv");
  std::string header_line;
  std::getline(csv, header_line);
  const std::vector<std::string> header = csv_cells(header_line);
  std::map<std::string, std::size_t> column;
  for (std::size_t k = 0; k < header.size(); ++k) column[header[k]] = k;
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(csv, line);) rows.push_back(csv_cells(line));
  ASSERT_EQ(rows.size(), 2u);

  const std::string h5 = (d / "out/study.h5").string();
  const rollnoise::io::Hdf5Reader study_h5(h5);
  for (const std::string wheel : {"leading_outer", "leading_inner"}) {
    const std::vector<std::pair<std::string, std::string>> quantities = {
        {"wheelset_lateral", "wheelset_lateral [m]"},
        {"wheelset_yaw", "wheelset_yaw [rad]"},
        {"two_point", "two_point [-]"}};
    for (const auto& [dataset, title] : quantities) {
      ASSERT_TRUE(column.count(wheel + "." + title))
          << wheel << "." << title << " in " << header_line;
      const auto collected = study_h5.numbers("/study/wheels/" + wheel + "/" + dataset);
      ASSERT_TRUE(collected && collected->size() == 2) << wheel << " " << dataset;
      for (int k = 0; k < 2; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "out/case_%04d.h5", k);
        const std::string file = (d / name).string();
        const double value = scalar(file, "/noise/wheels/" + wheel + "/contact/" + dataset);
        EXPECT_EQ((*collected)[k], value) << wheel << " " << dataset << ", case " << k;
        EXPECT_NEAR(std::stod(rows[k].at(column[wheel + "." + title])), value,
                    1e-9 * (1.0 + std::abs(value)))
            << wheel << "." << title << ", case " << k;
        if (dataset == "two_point") {
          EXPECT_TRUE(value == 0.0 || value == 1.0) << value;
          if (wheel == "leading_outer") {
            EXPECT_EQ(value, scalar(file, "/noise/contact/two_point")) << "case " << k;
          }
        }
      }
    }
  }
  // the two radii put the leading axle at different places
  const auto lateral = study_h5.numbers("/study/wheels/leading_outer/wheelset_lateral");
  ASSERT_TRUE(lateral && lateral->size() == 2);
  EXPECT_NE((*lateral)[0], (*lateral)[1]);
}
