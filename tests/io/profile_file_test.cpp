// The profile-file readers (src/io/profile_file.hpp): SIMPACK point files with their processing
// flags, CSV, and the errors of malformed files.
#include "io/profile_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "core/errors.hpp"

namespace fs = std::filesystem;
using namespace rollnoise;
using namespace rollnoise::geometry;
using rollnoise::io::read_profile;

namespace {

const std::string kProfiles = std::string(ROLLNOISE_SOURCE_DIR) + "/models/profiles/";
const std::string kWheelFile = kProfiles + "MBench_S1002_v3.prw";
const std::string kRailFile = kProfiles + "MBench_UIC60_v3.prr";

// A fresh temporary folder for bad files (per process and test: ctest runs tests in parallel).
fs::path temp_dir() {
  const fs::path d =
      fs::temp_directory_path() / ("rollnoise_io_" + std::to_string(::getpid()) + "_" +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::create_directories(d);
  return d;
}

std::string write(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

// The SIMPACK header of a wheel file, with the given point lines.
std::string simpack_wheel(const std::string& points) {
  return "! test wheel\n  header.begin\n    version = 1\n    type = 1 ! wheel\n  header.end\n"
         "  spline.begin\n    units.len.f = +1.0e+03\n    point.begin\n" +
         points + "    point.end\n  spline.end\n";
}

// Expect an InputError whose message names the file, the line and contains `what`.
void expect_input_error(const std::string& path, int line, const std::string& what,
                        std::optional<ProfileKind> kind = std::nullopt) {
  try {
    read_profile(path, kind);
    FAIL() << "no InputError for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path + ":" + std::to_string(line) + ":"), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
    EXPECT_EQ(e.key(), path);
  }
}

}  // namespace

// The Manchester S1002 point file, read with its flags (mirror.y = 1, inversion = 1, lengths in
// mm), has the taping line at its origin, the flange at negative y and a 28 mm high flange.
TEST(ProfileReader, S1002FileIsAWheelWithFlangeOnTheGaugeSide) {
  const Profile w = read_profile(kWheelFile);
  EXPECT_EQ(w.kind(), ProfileKind::Wheel);
  EXPECT_EQ(w.y_points().size(), 399u);  // the commented first line '!7.0E+01 ...' is skipped
  EXPECT_NEAR(w.y_min(), -69.612628e-3, 1e-12);
  EXPECT_NEAR(w.y_max(), 60e-3, 1e-12);
  EXPECT_NEAR(w.z(0.0), 0.0, 1e-9);       // taping line: nominal radius
  EXPECT_NEAR(w.z(-55e-3), 28e-3, 1e-6);  // flange tip (arc G centre): 28 mm high
  EXPECT_LT(w.slope(0.03), 0.0);          // the radius falls towards the field side
}

// The UIC60 file is a rail, already canted (its comment says so), with the crown on top (z = 0),
// the R300 crown and the R13 gauge corner on the -y side.
TEST(ProfileReader, UIC60FileIsACantedRailWithItsStandardRadii) {
  const Profile r = read_profile(kRailFile);
  EXPECT_EQ(r.kind(), ProfileKind::Rail);
  EXPECT_TRUE(r.canted());
  double top = 1.0;
  for (double z : r.z_points()) top = std::min(top, z);
  EXPECT_NEAR(top, 0.0, 1e-6);
  // UIC60 head: crown radius 300 mm around the rail axis (y ≈ -7.3 mm here), 80 mm further out,
  // 13 mm at the corners. The gauge corner is on the -y side: it is where the head is steep.
  EXPECT_NEAR(1.0 / r.curvature(-7.3e-3), 0.300, 0.003);
  EXPECT_NEAR(1.0 / r.curvature(-20e-3), 0.080, 0.002);
  EXPECT_NEAR(1.0 / r.curvature(-36.5e-3), 0.013, 0.0005);
  EXPECT_GT(-r.slope(-40e-3), 1.0);  // gauge face steeper than 45 degrees
}

// CSV: y, z in mm with a header line; the same points as the SIMPACK file give the same profile.
TEST(ProfileReader, CsvWithHeaderReadsMillimetres) {
  const fs::path d = temp_dir();
  const Profile w = read_profile(kWheelFile);
  std::ofstream f(d / "s1002.csv");
  f << "y_mm,z_mm\n";
  f.precision(12);
  for (std::size_t i = 0; i < w.y_points().size(); ++i)
    f << w.y_points()[i] * 1e3 << "," << w.z_points()[i] * 1e3 << "\n";
  f.close();
  const Profile c = read_profile((d / "s1002.csv").string(), ProfileKind::Wheel);
  EXPECT_EQ(c.kind(), ProfileKind::Wheel);
  EXPECT_EQ(c.y_points().size(), w.y_points().size());
  for (double s = -60e-3; s < 59e-3; s += 1.3e-3) EXPECT_NEAR(c.z(s), w.z(s), 1e-12);
  // A CSV file says nothing about its kind: the caller must.
  EXPECT_THROW(read_profile((d / "s1002.csv").string()), InputError);
  fs::remove_all(d);
}

// Malformed files are InputErrors naming the file, the line and the problem.
TEST(ProfileReader, BadFilesGiveInputErrorsWithFileAndLine) {
  const fs::path d = temp_dir();
  const std::string ok = "    -2.0 0.1\n    -1.0 0.0\n    0.0 0.0\n    1.0 0.0\n    2.0 0.1\n";
  // empty
  expect_input_error(write(d, "empty.prw", ""), 1, "empty");
  expect_input_error(write(d, "empty.csv", "\n\n"), 1, "empty", ProfileKind::Rail);
  // NaN in the point block: line 10 (the header takes 7 lines, point.begin is line 8)
  expect_input_error(
      write(d, "nan.prw", simpack_wheel("    -2.0 0.1\n    -1.0 nan\n    0.0 0.0\n    1.0 0.0\n")),
      10, "not a finite number");
  expect_input_error(write(d, "nan.csv", "y,z\n1,2\n2,nan\n3,4\n4,5\n"), 3, "not a finite number",
                     ProfileKind::Rail);
  expect_input_error(write(d, "word.csv", "1,2\n2,abc\n3,4\n4,5\n"), 2, "not a number",
                     ProfileKind::Rail);
  // too few points
  expect_input_error(write(d, "few.prw", simpack_wheel("    0.0 0.0\n    1.0 0.0\n")), 8,
                     "at least 4");
  expect_input_error(write(d, "few.csv", "y,z\n0,0\n1,1\n"), 3, "at least 4", ProfileKind::Rail);
  // unsorted y (line 11: the fourth point goes back)
  expect_input_error(write(d, "unsorted.prw",
                           simpack_wheel("    -2.0 0.1\n    -1.0 0.0\n    1.0 0.0\n    0.5 0.0\n"
                                         "    2.0 0.1\n")),
                     12, "strictly monotone");
  expect_input_error(write(d, "duplicate.csv", "0,0\n1,0\n1,0.5\n2,1\n3,2\n"), 3,
                     "strictly monotone", ProfileKind::Rail);
  // no point block, or an unclosed one
  expect_input_error(write(d, "noblock.prw", "  header.begin\n    type = 1\n  header.end\n"), 3,
                     "no point block");
  expect_input_error(write(d, "open.prr",
                           "  header.begin\n    type = 0\n  header.end\n"
                           "  point.begin\n" +
                               ok),
                     9, "no closing 'point.end'");
  // a bad header type, and a wheel where a rail is expected
  expect_input_error(write(d, "type.prw",
                           "  header.begin\n    type = 7\n  header.end\n"
                           "  point.begin\n" +
                               ok + "  point.end\n"),
                     2, "expected 0 rail or 1 wheel");
  expect_input_error(write(d, "kind.prw", simpack_wheel(ok)), 4, "a rail profile was expected",
                     ProfileKind::Rail);
  // a missing file
  EXPECT_THROW(read_profile((d / "missing.prw").string()), InputError);
  // a good file in the same format reads (the tests above fail for the stated reason only)
  const Profile good = read_profile(write(d, "good.prw", simpack_wheel(ok)));
  EXPECT_EQ(good.y_points().size(), 5u);
  EXPECT_NEAR(good.y_min(), -2e-3, 1e-15);
  fs::remove_all(d);
}
