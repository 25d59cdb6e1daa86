// A study of a case with several wheels (curve.wheels): each case file holds every wheel's bands as
// `rollnoise noise` writes them (/noise/wheels/<wheel>/bands/*), and `collect` gives each wheel its
// columns (`leading_inner.Fy_1000Hz [dB re 1 N]`, /study/wheels/<wheel>/*) with the case files'
// values.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "../cli/cli_support.hpp"

namespace fs = std::filesystem;
using rollnoise::cli_test::run;

namespace {

// A dataset of numbers (as doubles) and its size; empty when missing.
std::vector<double> read_doubles(const std::string& file, const std::string& path) {
  std::vector<double> out;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return out;
  if (H5Lexists(f, path.c_str(), H5P_DEFAULT) > 0) {
    const hid_t set = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    out.resize(std::size_t(H5Sget_simple_extent_npoints(space)));
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(f);
  return out;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  return cells;
}

std::string wheels_base_case() {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/tests/data/study/curve_small_wheels.toml";
}

}  // namespace

// Two cases (two wheel roughness spectra, sharing the loop) of the leading wheelset's two wheels.
TEST(StudyWheels, CollectedPerWheelColumnsEqualTheCaseFilesBandLevels) {
  const fs::path d = rollnoise::cli_test::fresh_dir("study_wheels");
  const fs::path study = d / "study.toml";
  std::ofstream(study) << "base = \"" << wheels_base_case() << "\"\noutput = \"out\"\n[axes]\n"
                       << "\"roughness.wheel\" = [\"cast-iron\", \"disc-braked\"]\n";
  const auto r = run("study " + study.string() + " -j 1 -q");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto c = run("collect " + study.string());
  ASSERT_EQ(c.status, 0) << c.output;

  // the CSV: header cells by name, two rows
  std::ifstream csv(d / "out/study.csv");
  std::string header_line;
  std::getline(csv, header_line);
  const std::vector<std::string> header = split(header_line);
  std::map<std::string, std::size_t> column;
  for (std::size_t k = 0; k < header.size(); ++k) column[header[k]] = k;
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(csv, line);) rows.push_back(split(line));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(column.count("leading_inner.Fy_1000Hz [dB re 1 N]")) << header_line;
  EXPECT_TRUE(column.count("leading_outer.Fz_1000Hz [dB re 1 N]")) << header_line;
  EXPECT_TRUE(column.count("leading_inner.rail_vz_1000Hz [dB re 1e-9 m/s]")) << header_line;
  EXPECT_TRUE(column.count("leading_inner.normal_force [N]")) << header_line;
  EXPECT_FALSE(column.count("trailing_inner.Fy_1000Hz [dB re 1 N]")) << "a wheel no case has";

  const std::string h5 = (d / "out/study.h5").string();
  const std::vector<double> centres = read_doubles(h5, "/study/band_centre");
  ASSERT_FALSE(centres.empty());
  const std::size_t nb = centres.size();
  const char* force_names[4] = {"Fz", "Fx", "Fy", "Mz"};
  for (const std::string wheel : {"leading_outer", "leading_inner"}) {
    const std::vector<double> study_force =
                                  read_doubles(h5, "/study/wheels/" + wheel + "/force_level"),
                              study_velocity =
                                  read_doubles(h5, "/study/wheels/" + wheel + "/velocity_level");
    ASSERT_EQ(study_force.size(), 2 * nb * 4) << wheel;
    ASSERT_EQ(study_velocity.size(), 2 * nb * 8) << wheel;
    for (int k = 0; k < 2; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "out/case_%04d.h5", k);
      const std::string file = (d / name).string();
      const std::vector<double> force = read_doubles(
                                    file, "/noise/wheels/" + wheel + "/bands/force_level"),
                                velocity = read_doubles(
                                    file, "/noise/wheels/" + wheel + "/bands/velocity_level");
      ASSERT_EQ(force.size(), nb * 4)
          << "the case file has the wheel's bands: " << file << " " << wheel;
      ASSERT_EQ(velocity.size(), nb * 8) << file << " " << wheel;
      // study.h5: the case file's values exactly (copied, not recomputed)
      for (std::size_t j = 0; j < nb * 4; ++j)
        EXPECT_EQ(study_force[k * nb * 4 + j], force[j]) << wheel << " " << j;
      for (std::size_t j = 0; j < nb * 8; ++j)
        EXPECT_EQ(study_velocity[k * nb * 8 + j], velocity[j]) << wheel << " " << j;
      // study.csv: the same to its 10 significant digits (|level| < 200 dB: 2e-7 dB). The wheel's
      // band columns follow each other as the case's own do: nb x (Fz, Fx, Fy, Mz), then [wheel,
      // rail] x nb x 4.
      std::size_t first = header.size();
      for (std::size_t q = 0; q < header.size() && first == header.size(); ++q)
        if (header[q].rfind(wheel + ".Fz_", 0) == 0) first = q;
      ASSERT_LT(first + 12 * nb, header.size()) << header_line;
      for (std::size_t j = 0; j < nb * 4; ++j) {
        EXPECT_EQ(header[first + j].rfind(wheel + "." + force_names[j % 4] + "_", 0), 0u)
            << header[first + j];
        EXPECT_NEAR(std::stod(rows[k].at(first + j)), force[j], 2e-7)
            << header[first + j] << ", case " << k;
      }
      for (int side = 0; side < 2; ++side)
        for (std::size_t j = 0; j < nb * 4; ++j) {
          const std::size_t q = first + nb * 4 + side * nb * 4 + j;
          EXPECT_EQ(header[q].rfind(wheel + (side ? ".rail_" : ".wheel_"), 0), 0u) << header[q];
          EXPECT_NEAR(std::stod(rows[k].at(q)), velocity[(j / 4) * 8 + side * 4 + j % 4], 2e-7)
              << header[q] << ", case " << k;
        }
    }
  }
  // the two roughness spectra give the wheels different levels (the wheels' bands follow each
  // case's roughness)
  const std::vector<double> inner = read_doubles(h5, "/study/wheels/leading_inner/force_level");
  double largest = 0.0;
  for (std::size_t j = 0; j < nb * 4; ++j)
    largest = std::max(largest, std::abs(inner[j] - inner[nb * 4 + j]));
  EXPECT_GT(largest, 0.5) << "dB between the cast-iron and the disc-braked wheel's levels";
}
