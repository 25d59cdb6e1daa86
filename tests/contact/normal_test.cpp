// The normal problem: Hertz's solution, exact load, and CONTACT's contact area.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "core/errors.hpp"
#include "paper_case.hpp"
#include "reference_data.hpp"

using namespace rollnoise::contact;

using rollnoise::testing::kSteel;  // E = 210 GPa, nu = 0.28

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

TEST(NormalProblem, LoadSensitivityIsTheDiscreteDerivativeAndApproachesHertz) {
  // (N1) against central differences of the discrete normal solver (no element enters or leaves
  // the area for a 1e-6 load step), and against Hertz: k_N = 3N/(2 delta) and, at the centre,
  // dpn/dN = p0/(3N) (the N-derivative of p0 sqrt(1 - rho^2), p0, a, b ~ N^(1/3)).
  const Material steel{210e9, 0.28};
  const double N = 98100;
  const HertzContact hz = hertz_from_semi_axes(7.18e-3, 5.29e-3, N, steel);
  for (int n : {30, 60}) {
    const Grid g = Grid::around_ellipse(n + 1, n + 1, hz.a, hz.b, 1.1);  // odd: an element at the centre
    const GridField h = quadratic_distance(g, hz.A, hz.B);
    const ContactPatch p = solve_patch(g, steel, h, N);
    const HalfSpaceOperator op(p.influence, Problem::Normal);
    const NormalLoadSensitivity s = normal_load_sensitivity(g, op, p.normal);
    const double dN = 1e-6 * N;
    const ContactPatch pp = solve_patch(g, steel, h, N + dN), pm = solve_patch(g, steel, h, N - dN);
    ASSERT_EQ(pp.normal.contact_elements(), p.normal.contact_elements());
    ASSERT_EQ(pm.normal.contact_elements(), p.normal.contact_elements());
    double worst = 0.0, peak = 0.0;
    for (int k = 0; k < g.size(); ++k) {
      const double fd = (pp.normal.pn[k] - pm.normal.pn[k]) / (2 * dN);
      worst = std::max(worst, std::abs(fd - s.dpn_dN[k]));
      peak = std::max(peak, std::abs(s.dpn_dN[k]));
    }
    const double k_fd = 2 * dN / (pp.normal.approach - pm.normal.approach);
    const double centre = s.dpn_dN[g.index(n / 2, n / 2)];
    const double err = std::abs(s.stiffness() / hz.normal_stiffness() - 1.0);
    std::printf("%d x %d: k_N = %.5g N/m (finite difference %.5g, Hertz %.5g), dpn/dN at the centre %.5g "
                "(Hertz %.5g), max |dpn/dN - fd| = %.1e of %.3g\n",
                n + 1, n + 1, s.stiffness(), k_fd, hz.normal_stiffness(), centre, hz.p0 / (3 * N), worst, peak);
    EXPECT_LT(worst, 1e-5 * peak);
    EXPECT_NEAR(s.stiffness(), k_fd, 1e-5 * k_fd);
    // within 0.2 % of Hertz on both grids (measured 1.4e-4 and 6.4e-4: the set of elements in
    // contact changes with the grid, so the error does not fall monotonically)
    EXPECT_LT(err, 2e-3);
    EXPECT_NEAR(centre, hz.p0 / (3 * N), 0.03 * hz.p0 / (3 * N));
  }
}
