// Profiles: the Steffen spline and the analytic S1002 (the readers: tests/io/profile_file_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "geometry/profile.hpp"
#include "geometry/s1002.hpp"
#include "io/profile_file.hpp"

using namespace rollnoise;
using namespace rollnoise::geometry;

// Test of item 3 of the brief: the analytic S1002 (EN 13715) and the point file agree within
// 0.01 mm over the tread, s from -26 mm (end of the flange root, start of section B) to +60 mm
// (field side), with the file's origin at the taping line (s = y, no offset). Sampled every 0.01
// mm, i.e. mostly between the file's points (0.35 mm apart): this tests the spline too.
TEST(S1002, AnalyticDefinitionMatchesPointFileOnTreadWithin10Micrometres) {
  const Profile w =
      io::read_profile(std::string(ROLLNOISE_SOURCE_DIR) + "/models/profiles/MBench_S1002_v3.prw");
  double worst = 0.0;
  for (double s = -26e-3; s <= 60e-3 + 1e-12; s += 0.01e-3)
    worst = std::max(worst, std::abs(w.z(s) - s1002_height(std::min(s, 60e-3))));
  EXPECT_LT(worst, 0.01e-3);
  EXPECT_LT(worst, 1e-7);  // measured 4e-8 m: the file samples the definition exactly
  // The flange too, up to the steep flange back (at s = -69 mm the spline is 3 µm off).
  worst = 0.0;
  for (double s = -69e-3; s <= -26e-3; s += 0.01e-3)
    worst = std::max(worst, std::abs(w.z(s) - s1002_height(s)));
  EXPECT_LT(worst, 0.01e-3);
}

// The eight sections join: the analytic profile is continuous at every section boundary
// (a wrong coefficient or sign shows up as a jump).
TEST(S1002, SectionsJoinContinuously) {
  for (double b :
       {-62.764705882, -49.662510381, -39.764473993, -38.426669071, -35.0, -26.0, 32.15796}) {
    const double s = b * 1e-3, e = 1e-9;
    EXPECT_NEAR(s1002_height(s - e), s1002_height(s + e), 2e-7) << "boundary s = " << b << " mm";
  }
  EXPECT_NEAR(s1002_height(0.0), 0.0, 1e-15);  // the taping line
  EXPECT_THROW(s1002_height(61e-3), std::domain_error);
  const Profile p = s1002_profile();
  EXPECT_NEAR(p.z(-55e-3), 28e-3, 1e-7);
}

// Steffen's spline does not ring: step-like data (a flank) gives a monotone interpolant that
// never leaves the range of the data.
TEST(ProfileSpline, MonotoneDataGiveMonotoneCurveWithoutOvershoot) {
  std::vector<double> y, z;
  for (int i = 0; i <= 20; ++i) {
    y.push_back(i * 1e-3);
    z.push_back(i < 10 ? 0.0 : (i == 10 ? 5e-3 : 10e-3));
  }
  const Profile p(y, z, ProfileKind::Rail, "step");
  double prev = -1.0;
  for (double t = 0.0; t <= 20e-3; t += 0.01e-3) {
    const double v = p.z(t);
    EXPECT_GE(v, -1e-15);
    EXPECT_LE(v, 10e-3 + 1e-15);
    EXPECT_GE(v, prev - 1e-15) << "not monotone at y = " << t;
    prev = v;
  }
}

// The smoothed curvature is exact for a parabola and close to 1/ρ for a circle, while the raw
// second derivative of the piecewise cubic scatters from knot to knot.
TEST(ProfileSpline, SmoothedCurvatureOfCircularArcIsInverseRadius) {
  const double rho = 0.08;
  std::vector<double> y, z;
  for (double t = -30e-3; t <= 30e-3 + 1e-12; t += 0.4e-3) {
    y.push_back(t);
    z.push_back(rho - std::sqrt(rho * rho - t * t));
  }
  const Profile p(y, z, ProfileKind::Rail, "arc");
  for (double t : {-20e-3, -5.1e-3, 0.0, 3.3e-3, 17.7e-3})
    EXPECT_NEAR(p.curvature(t), 1.0 / rho, 0.002 / rho) << "y = " << t;
}
