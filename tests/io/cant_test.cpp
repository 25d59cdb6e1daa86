// curve.cant: the cant deficiency follows from the speed, I = s V^2 / (g R) - D with s = 1.5 m and
// g = 9.81 m/s^2 (EN 13803), so that a study of the speed on a canted curve varies the deficiency;
// curve.cant with curve.cant_deficiency is refused naming the key.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/input_problems.hpp"
#include "io/noise_case.hpp"

namespace {

using namespace rollnoise;

const std::string kCurveCase = R"(
[contact]
normal_force = 98100.0
a = 7.18e-3
b = 5.29e-3
[curve]
radius = 300.0
)";

pipeline::NoiseCase read_curve_case(const std::vector<std::string>& overrides) {
  const io::CaseReader r = io::CaseReader::from_string(kCurveCase, "cant.toml", overrides);
  io::InputProblems problems;
  pipeline::NoiseCase c = io::read_noise_case(r, problems);
  problems.throw_if_any();
  return c;
}

}  // namespace

TEST(CurveCant, SpeedChangeWithCantFixedChangesDeficiencyAsEn13803Says) {
  const double R = 300.0, D = 0.1, s = 1.5, g = 9.81;
  const double slow = read_curve_case({"curve.cant=0.1", "rolling.speed=20.0"}).cant_deficiency;
  const double fast = read_curve_case({"curve.cant=0.1", "rolling.speed=30.0"}).cant_deficiency;
  EXPECT_NEAR(slow, s * 20.0 * 20.0 / (g * R) - D, 1e-12);
  EXPECT_NEAR(fast, s * 30.0 * 30.0 / (g * R) - D, 1e-12);
  EXPECT_NEAR(fast - slow, s * (30.0 * 30.0 - 20.0 * 20.0) / (g * R), 1e-12);
}

TEST(CurveCant, GivenDeficiencyStaysWhateverTheSpeed) {
  const double slow =
      read_curve_case({"curve.cant_deficiency=0.05", "rolling.speed=20.0"}).cant_deficiency;
  const double fast =
      read_curve_case({"curve.cant_deficiency=0.05", "rolling.speed=30.0"}).cant_deficiency;
  EXPECT_EQ(slow, 0.05);
  EXPECT_EQ(fast, 0.05);
}

TEST(CurveCant, CantWithDeficiencyIsRefusedNamingTheKey) {
  try {
    read_curve_case({"curve.cant=0.1", "curve.cant_deficiency=0.05"});
    FAIL() << "accepted both";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curve.cant_deficiency"), std::string::npos) << e.what();
  }
}

TEST(CurveCant, CantOnTangentTrackIsRefusedNamingIt) {
  try {
    read_curve_case({"curve.cant=0.1", "curve.radius=0.0"});
    FAIL() << "accepted cant on tangent track";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curve.cant"), std::string::npos) << e.what();
  }
}
