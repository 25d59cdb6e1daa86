// A Hertzian case from the radii of wheel and rail (contact.wheel_radius, contact.rail_radius,
// contact.wheel_profile_radius): the semi-axes follow the load by Hertz theory.
//
// The check is independent of contact::hertz_from_curvatures (which inverts Johnson's Eqs.
// 4.39-4.41 with complete elliptic integrals): the semi-ellipsoidal pressure p0 (1 - x^2/a^2 -
// y^2/b^2)^(1/2) on a, b displaces the surfaces by delta - A x^2 - B y^2 with (Johnson 1985,
// Contact Mechanics, Sec. 3.6, in integral form)
//   A = p0 a b / (2 E*) Int_0^inf dw / sqrt((a^2 + w)^3 (b^2 + w) w),
//   B = p0 a b / (2 E*) Int_0^inf dw / sqrt((a^2 + w) (b^2 + w)^3 w),   p0 = 3N / (2 pi a b),
// integrated here by Simpson's rule after w = a^2 tan^2(theta); A and B must be the curvatures of
// the radii, h = x^2 / (2 R_w) + y^2 (1/R_r + 1/R_p) / 2. Tolerance 1e-8 relative (the inversion
// converges to 1e-15 in the eccentricity; Simpson on 4000 intervals of a smooth periodic-like
// integrand is exact to ~1e-12).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/contact_case.hpp"

namespace {

using namespace rollnoise;

constexpr double kE = 210e9, kNu = 0.28;

pipeline::ContactCase hertz_from_radii(double normal_force, const std::string& radii) {
  const std::string toml = "[material]\nE = 210e9\nnu = 0.28\n[contact]\nnormal_force = " +
                           std::to_string(normal_force) + "\n" + radii;
  return io::read_contact_case(io::CaseReader::from_string(toml, "radii.toml"));
}

// Int_0^(pi/2) f(theta) by Simpson's rule on n intervals.
template <class F>
double simpson(F f, int n = 4000) {
  const double h = 0.5 * M_PI / n;
  double s = f(0.0) + f(0.5 * M_PI);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return s * h / 3.0;
}

// The curvature coefficients A, B of the pressure on the ellipse a, b under N (header).
std::pair<double, double> curvatures_of_patch(double a, double b, double N) {
  const double Es = kE / (2.0 * (1.0 - kNu * kNu));
  const double p0 = 3.0 * N / (2.0 * M_PI * a * b);
  auto q = [&](double t) {
    return b * b * std::cos(t) * std::cos(t) + a * a * std::sin(t) * std::sin(t);
  };
  const double ia = simpson(
      [&](double t) { return 2.0 * std::cos(t) * std::cos(t) / (a * a * std::sqrt(q(t))); });
  const double ib =
      simpson([&](double t) { return 2.0 * std::cos(t) * std::cos(t) / std::pow(q(t), 1.5); });
  return {p0 * a * b / (2.0 * Es) * ia, p0 * a * b / (2.0 * Es) * ib};
}

}  // namespace

TEST(HertzFromRadii, ConicalTreadOnRailHeadGivesThePatchOfTheRadiiCurvatures) {
  const double N = 98100.0, Rw = 0.46, Rr = 0.3;
  const pipeline::ContactCase c = hertz_from_radii(N, "wheel_radius = 0.46\nrail_radius = 0.3\n");
  ASSERT_GT(c.a, c.b);  // the smaller curvature along x: the longer axis
  const auto [A, B] = curvatures_of_patch(c.a, c.b, N);
  EXPECT_NEAR(A / (0.5 / Rw), 1.0, 1e-8) << "a = " << c.a << ", b = " << c.b;
  EXPECT_NEAR(B / (0.5 / Rr), 1.0, 1e-8);
}

TEST(HertzFromRadii, ConcaveWheelProfileWidensThePatch) {
  const double N = 60000.0, Rw = 0.46, Rr = 0.3, Rp = -0.5;
  const pipeline::ContactCase c =
      hertz_from_radii(N, "wheel_radius = 0.46\nrail_radius = 0.3\nwheel_profile_radius = -0.5\n");
  ASSERT_GT(c.b, c.a);
  const auto [A, B] = curvatures_of_patch(c.a, c.b, N);
  EXPECT_NEAR(A / (0.5 / Rw), 1.0, 1e-8);
  EXPECT_NEAR(B / (0.5 * (1.0 / Rr + 1.0 / Rp)), 1.0, 1e-8);
}

TEST(HertzFromRadii, EqualRadiiGiveHertzsCircle) {
  // a = (3 N R / (4 E*))^(1/3) (Johnson 1985, Sec. 4.2), E* = E / (2 (1 - nu^2))
  const double N = 50000.0, R = 0.4;
  const pipeline::ContactCase c = hertz_from_radii(N, "wheel_radius = 0.4\nrail_radius = 0.4\n");
  const double a = std::cbrt(3.0 * N * R / (4.0 * kE / (2.0 * (1.0 - kNu * kNu))));
  EXPECT_NEAR(c.a / a, 1.0, 1e-12);
  EXPECT_NEAR(c.b / a, 1.0, 1e-12);
}

TEST(HertzFromRadii, DoubledLoadScalesBothSemiAxesByCubeRootOfTwo) {
  const std::string radii = "wheel_radius = 0.46\nrail_radius = 0.3\nwheel_profile_radius = 1.2\n";
  const pipeline::ContactCase one = hertz_from_radii(60000.0, radii),
                              two = hertz_from_radii(120000.0, radii);
  EXPECT_NEAR(two.a / one.a, std::cbrt(2.0), 1e-9);
  EXPECT_NEAR(two.b / one.b, std::cbrt(2.0), 1e-9);
}

TEST(HertzFromRadii, RadiiTogetherWithSemiAxesAreRefusedNamingTheKey) {
  try {
    hertz_from_radii(98100.0, "wheel_radius = 0.46\nrail_radius = 0.3\na = 7.18e-3\n");
    FAIL() << "accepted radii and contact.a";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.a"), std::string::npos) << e.what();
  }
}

TEST(HertzFromRadii, WheelRadiusWithoutRailRadiusIsRefusedNamingIt) {
  try {
    hertz_from_radii(98100.0, "wheel_radius = 0.46\n");
    FAIL() << "accepted contact.wheel_radius alone";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.rail_radius"), std::string::npos) << e.what();
  }
}

TEST(HertzFromRadii, ConformalConcaveProfileIsRefusedNamingIt) {
  try {
    hertz_from_radii(98100.0,
                     "wheel_radius = 0.46\nrail_radius = 0.3\nwheel_profile_radius = -0.25\n");
    FAIL() << "accepted a conformal contact";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.wheel_profile_radius"), std::string::npos)
        << e.what();
  }
}
