// The normal problem: Hertz's solution, exact load, and CONTACT's contact area.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "core/errors.hpp"
#include "reference_data.hpp"

using namespace rollnoise::contact;

namespace {
const Material kSteel{210e9, 0.28};
}

TEST(Hertz, CurvaturesAndApproachOfThePaperCaseMatchCONTACT) {
  // tests/data/contact/README.md: A1 = 1.08718e-3 /mm, B1 = 1.71987e-3 /mm, approach 0.104176 mm.
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  EXPECT_NEAR(h.A, 1.08718, 1e-5);
  EXPECT_NEAR(h.B, 1.71987, 1e-5);
  EXPECT_NEAR(h.approach, 0.104176e-3, 1e-9);
  EXPECT_NEAR(h.p0, 1233.19e6, 0.01e6);
}

TEST(Hertz, CurvaturesInvertToTheSemiAxes) {
  for (double ratio : {0.1, 0.3, 0.7, 1.0, 1.5, 3.0, 10.0}) {
    const double a = 6e-3 * std::sqrt(ratio), b = 6e-3 / std::sqrt(ratio);
    const HertzContact h = hertz_from_semi_axes(a, b, 50e3, kSteel);
    const HertzContact back = hertz_from_curvatures(h.A, h.B, 50e3, kSteel);
    EXPECT_NEAR(back.a, a, 1e-9 * a) << "a/b = " << ratio;
    EXPECT_NEAR(back.b, b, 1e-9 * b) << "a/b = " << ratio;
  }
}

class HertzNumerical : public ::testing::TestWithParam<double> {};

TEST_P(HertzNumerical, CarriesTheLoadAndMatchesSemiAxesAndPeakPressure) {
  // Quadratic gap from Hertz theory, solved numerically: exactly N, semi-axes within one element,
  // peak pressure within 2 %.
  const double ratio = GetParam(), N = 98100;
  const double a = 6e-3 * std::sqrt(ratio), b = 6e-3 / std::sqrt(ratio);
  const HertzContact h = hertz_from_semi_axes(a, b, N, kSteel);
  const Grid g = Grid::around_ellipse(40, 40, a, b, 1.15);
  const ContactPatch patch = solve_patch(g, kSteel, quadratic_distance(g, h.A, h.B), N);
  EXPECT_NEAR(patch.normal.force, N, 1e-9 * N);
  double xmax = 0, ymax = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (patch.normal.pn[g.index(i, j)] > 0)
        xmax = std::max(xmax, std::abs(g.x(i)) + g.dx / 2), ymax = std::max(ymax, std::abs(g.y(j)) + g.dy / 2);
  EXPECT_NEAR(xmax, a, g.dx);
  EXPECT_NEAR(ymax, b, g.dy);
  EXPECT_NEAR(patch.normal.max_pressure(), h.p0, 0.02 * h.p0);
  EXPECT_NEAR(patch.normal.approach, h.approach, 0.02 * h.approach);
}

INSTANTIATE_TEST_SUITE_P(AspectRatios, HertzNumerical, ::testing::Values(0.5, 1.0, 1.357, 2.0));

TEST(NormalProblem, ContactAreaAndApproachMatchCONTACTOnBothGrids) {
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  struct G { int nx, ny, contact; double approach_mm; };
  for (const G& ref : {G{34, 25, 538, 0.104158}, G{68, 50, 2096, 0.104168}}) {
    const Grid g = Grid::around_ellipse(ref.nx, ref.ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
    const ContactPatch patch = solve_patch(g, kSteel, quadratic_distance(g, h.A, h.B), 98100);
    EXPECT_EQ(patch.normal.contact_elements(), ref.contact);
    EXPECT_NEAR(patch.normal.approach * 1e3, ref.approach_mm, 1e-6);
    EXPECT_NEAR(patch.normal.max_pressure() * 1e-6, 1233, 0.5);
  }
}

TEST(NormalProblem, FftAndDenseBackendsGiveTheSamePressure) {
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  const Grid g = Grid::around_ellipse(20, 16, 7.18e-3, 5.29e-3, 1.2);
  const auto hq = quadratic_distance(g, h.A, h.B);
  const ContactPatch d = solve_patch(g, kSteel, hq, 98100, Backend::Dense);
  const ContactPatch f = solve_patch(g, kSteel, hq, 98100, Backend::Fft);
  for (int k = 0; k < g.size(); ++k) EXPECT_NEAR(d.normal.pn[k], f.normal.pn[k], 1e-6 * h.p0);
}

TEST(NormalProblem, PatchTouchingTheGridBorderIsRejected) {
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  const Grid g = Grid::around_ellipse(20, 16, 7.18e-3, 5.29e-3, 0.9);  // smaller than the patch
  EXPECT_THROW(solve_patch(g, kSteel, quadratic_distance(g, h.A, h.B), 98100), rollnoise::InputError);
}
