// Stress tests of the steady tangential problem (paper Eq. 3): creepage from 0 and 1e-9 to
// full sliding, spin up to +-2 rad/m, friction 0.05 to 0.6, ellipses a/b = 0.1 to 10 and grids from
// 4 x 4 to 100 x 100. Every solution is checked against Coulomb's law element by element with the
// slip recomputed independently (stress_support.hpp), and against exact properties of the discrete
// problem: linearity in full adhesion, the mirror symmetry in y, the homogeneity in mu.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "../contact/reference_data.hpp"
#include "stress_support.hpp"

using namespace rollnoise;
using namespace rollnoise::stress;

namespace {

const std::vector<double> kCreepages = {0.0, 1e-9, 1e-6, 1e-4, 1e-3, 3e-3, 1e-2, 0.1};
const std::vector<double> kSpins = {0.0, 0.5, -0.5, 2.0, -2.0};

// The paper's ellipse on a 24 x 18 grid: 272 contact elements, cheap enough for ~100 mean states.
const ContactPatch& sweep_patch() {
  static const ContactPatch p = hertz_patch(kPaperRatio, 24, 18);
  return p;
}

TangentialSolution solve(const ContactPatch& p, double mu, const Creepage& c, double offset = 0.0) {
  return solve_steady_rolling(p.influence, p.normal.pn, {mu, kSpeed, c, offset});
}

}  // namespace

TEST(SteadyStress, TractionsStayWithinCoulombBoundForAllMeanStates) {
  // Creepage magnitudes 0 ... 0.1 along three directions, times five spins, mu = 0.3.
  const ContactPatch& p = sweep_patch();
  const double mu = 0.3;
  const std::array<std::array<double, 2>, 3> dirs = {{{1, 0}, {0, 1}, {0.8, -0.6}}};
  const auto t0 = std::chrono::steady_clock::now();
  int solves = 0;
  double worst_adhesion = 0, worst_align = 0, worst_bound = -1;
  std::printf("%10s %6s %5s %6s %6s %9s %6s %9s\n", "|xi|", "dir", "phi", "adh", "slip", "|F|/muN",
              "iter", "residual");
  for (double phi : kSpins)
    for (const auto& d : dirs)
      for (double xi : kCreepages) {
        const Creepage c{xi * d[0], xi * d[1], phi};
        TangentialSolution s;
        ASSERT_NO_THROW(s = solve(p, mu, c)) << describe(c);
        ++solves;
        EXPECT_LE(s.residual, TangentialSolverSettings{}.tolerance) << describe(c);
        const SteadyCheck r = check_steady(p, s, mu, kSpeed, c, 0.0);
        expect_physical(r, describe(c));
        worst_adhesion = std::max(worst_adhesion, r.adhesion_slip);
        worst_align = std::max(worst_align, r.misalignment);
        worst_bound = std::max(worst_bound, r.bound_excess);
        if (xi == 0.0 && phi == 0.0) {
          for (double v : s.px) EXPECT_EQ(v, 0.0) << "zero creepage, zero traction";
          for (double v : s.py) EXPECT_EQ(v, 0.0) << "zero creepage, zero traction";
        }
        if (d[0] == 1 || xi == 0.1)
          std::printf("%10g %6s %5g %6d %6d %9.6f %6d %9.1e\n", xi,
                      d[0] == 1   ? "x"
                      : d[1] == 1 ? "y"
                                  : "xy",
                      phi, r.adhesion, r.slip, std::hypot(r.F.Fx, r.F.Fy) / r.friction_force,
                      s.iterations, s.residual);
      }
  std::printf("%d steady solves on %d elements in %.2f s\n", solves, p.normal.contact_elements(),
              seconds_since(t0));
  std::printf(
      "worst: adhesion slip %.1e sigma, slip misalignment %.1e sigma, |p|/(mu pn) - 1 = %.1e\n",
      worst_adhesion, worst_align, worst_bound);
}

TEST(SteadyStress, ForceCreepageCurveIsLinearInAdhesionMonotoneAndSaturatesAtMuN) {
  const ContactPatch& p = sweep_patch();
  const double mu = 0.3;
  const int n_contact = p.normal.contact_elements();
  for (const auto& d : std::array<std::array<double, 2>, 3>{{{1, 0}, {0, 1}, {0.8, -0.6}}}) {
    std::vector<TangentialForces> F;
    std::vector<int> adhesion;
    for (double xi : kCreepages) {
      const Creepage c{xi * d[0], xi * d[1], 0.0};
      const auto s = solve(p, mu, c);
      F.push_back(total_forces(p.grid, s.px, s.py));
      adhesion.push_back(s.count(ElementState::adhesion));
      const double Fn = std::hypot(F.back().Fx, F.back().Fy);
      if (xi > 0) {
        // the force opposes the creepage: F.xi = -(f11 xi_x^2 + f22 xi_y^2) < 0 in the linear
        // range, and -mu N |xi| in full sliding
        EXPECT_LT(F.back().Fx * d[0] + F.back().Fy * d[1], -0.5 * Fn) << describe(c);
      }
    }
    // xi = 1e-9 and 1e-6 (indices 1, 2): full adhesion, where the discrete problem is linear, so
    // F(1e-9) = 1e-3 F(1e-6). Each solution has a relative residual <= 1e-11, which moves it by at
    // most cond(J) 1e-11 ~ 5e-10 (cond_2(J) = 47 on this grid, conditioning_test.cpp): 1e-8 of |F|.
    EXPECT_EQ(adhesion[1], n_contact);
    if (adhesion[2] == n_contact) {
      const double Fn = std::hypot(F[2].Fx, F[2].Fy);
      EXPECT_NEAR(F[1].Fx / 1e-3, F[2].Fx, 1e-8 * Fn);
      EXPECT_NEAR(F[1].Fy / 1e-3, F[2].Fy, 1e-8 * Fn);
    }
    // |F| grows with |xi| along the ray (Coulomb friction with a fixed direction of creepage): each
    // value at least the previous one within the same 1e-8
    for (size_t i = 1; i < F.size(); ++i)
      EXPECT_GE(std::hypot(F[i].Fx, F[i].Fy), std::hypot(F[i - 1].Fx, F[i - 1].Fy) * (1 - 1e-8))
          << "|xi| = " << kCreepages[i];
    // xi = 0.1 is full sliding: no adhesion, |F| = mu N up to the elastic turning of the slip
    // directions (measured 1e-6 relative on this grid; 0.2 % as in tests/contact), F antiparallel
    // to xi.
    const TangentialForces& Fs = F.back();
    const double Fn = std::hypot(Fs.Fx, Fs.Fy);
    EXPECT_EQ(adhesion.back(), 0);
    EXPECT_NEAR(Fn, mu * p.normal.force, 2e-3 * mu * p.normal.force);
    EXPECT_NEAR((Fs.Fx * d[0] + Fs.Fy * d[1]) / Fn, -1.0, 1e-3);
    const double muN = mu * p.normal.force;
    std::printf("direction (%.1f, %.1f): |F|/(mu N) = %.3e at 1e-9, %.3e at 1e-6, %.4f at 1e-3,",
                d[0], d[1], std::hypot(F[1].Fx, F[1].Fy) / muN, std::hypot(F[2].Fx, F[2].Fy) / muN,
                std::hypot(F[4].Fx, F[4].Fy) / muN);
    std::printf(" %.6f at 0.1; adhesion %d/%d at 1e-6, %d at 1e-3; linearity %.1e\n", Fn / muN,
                adhesion[2], n_contact, adhesion[4],
                std::hypot(F[1].Fx / 1e-3 - F[2].Fx, F[1].Fy / 1e-3 - F[2].Fy) /
                    std::hypot(F[2].Fx, F[2].Fy));
  }
}

TEST(SteadyStress, ReversingSpinAndLateralCreepageMirrorsTheForcesOfASymmetricPatch) {
  // y -> -y maps the patch onto itself and (xi_x, xi_y, phi) onto (xi_x, -xi_y, -phi), so
  // Fx is even and Fy, Mz are odd. Exact for the discrete problem (grid and pn symmetric); the two
  // solutions agree to the solver tolerance 1e-11 amplified by the condition of the Newton
  // Jacobian (<= 1e3 measured in conditioning_test.cpp): 1e-6 of mu N (for Mz: of mu N c).
  const ContactPatch& p = sweep_patch();
  const double mu = 0.3, scale = mu * p.normal.force;
  double worst = 0;
  for (double phi : {0.5, 2.0})
    for (double xi : {0.0, 1e-4, 1e-3, 3e-3, 1e-2, 0.1})
      for (const Creepage c : {Creepage{xi, 0.0, phi}, Creepage{0.6 * xi, 0.8 * xi, phi}}) {
        const Creepage m{c.xi_x, -c.xi_y, -c.phi};
        const auto sa = solve(p, mu, c);
        const auto a = total_forces(p.grid, sa.px, sa.py);
        const auto sb = solve(p, mu, m);
        const auto b = total_forces(p.grid, sb.px, sb.py);
        EXPECT_NEAR(a.Fx, b.Fx, 1e-6 * scale) << describe(c);
        EXPECT_NEAR(a.Fy, -b.Fy, 1e-6 * scale) << describe(c);
        EXPECT_NEAR(a.Mz, -b.Mz, 1e-6 * scale * kC) << describe(c);
        worst = std::max({worst, std::abs(a.Fx - b.Fx) / scale, std::abs(a.Fy + b.Fy) / scale,
                          std::abs(a.Mz + b.Mz) / (scale * kC)});
        if (xi == 0.0) {
          // pure spin: Fy = -f23 phi with f23 > 0 (Kalker), the sign kept up to saturation
          EXPECT_LT(a.Fy * phi, 0.0) << describe(c);
        }
      }
  std::printf("mirror symmetry y -> -y: worst force difference %.1e of mu N\n", worst);
}

TEST(SteadyStress, ForcesScaleWithFrictionFrom005To06) {
  // The discrete problem is homogeneous: (p, s) solves it for (mu, xi) iff (k p, k s) solves it
  // for (k mu, k xi) (w and |p| <= mu pn scale together). So F(mu, mu x)/mu does not depend on mu.
  // Both solutions are exact to the Newton tolerance 1e-11 times the Jacobian's condition (<= 1e3
  // measured in conditioning_test.cpp): 1e-6 of mu N (of mu N c for Mz), a 100x margin.
  const ContactPatch& p = sweep_patch();
  const std::vector<double> mus = {0.05, 0.1, 0.3, 0.6};
  const std::vector<Creepage> per_mu = {
      {1e-9 / 0.3, 0, 0}, {1e-3 / 0.3, 0, 0},       {1e-3 / 0.3, 1e-3 / 0.3, -0.1},
      {0, 0, 2.0 / 0.6},  {5e-3 / 0.3, -2e-3, 1.0}, {0.1 / 0.3, 0, 0}};
  double worst = 0;
  for (const Creepage& x : per_mu) {
    std::vector<TangentialForces> F;
    for (double mu : mus) {
      const Creepage c{mu * x.xi_x, mu * x.xi_y, mu * x.phi};
      const auto s = solve(p, mu, c);
      expect_physical(check_steady(p, s, mu, kSpeed, c, 0.0),
                      "mu = " + std::to_string(mu) + " " + describe(c));
      const auto f = total_forces(p.grid, s.px, s.py);
      F.push_back({f.Fx / mu, f.Fy / mu, f.Mz / mu});
    }
    for (size_t i = 1; i < mus.size(); ++i) {
      const double scale = p.normal.force;  // per unit mu
      EXPECT_NEAR(F[i].Fx, F[0].Fx, 1e-6 * scale)
          << "mu = " << mus[i] << ", xi/mu = " << describe(x);
      EXPECT_NEAR(F[i].Fy, F[0].Fy, 1e-6 * scale)
          << "mu = " << mus[i] << ", xi/mu = " << describe(x);
      EXPECT_NEAR(F[i].Mz, F[0].Mz, 1e-6 * scale * kC)
          << "mu = " << mus[i] << ", xi/mu = " << describe(x);
      worst =
          std::max({worst, std::abs(F[i].Fx - F[0].Fx) / scale, std::abs(F[i].Fy - F[0].Fy) / scale,
                    std::abs(F[i].Mz - F[0].Mz) / (scale * kC)});
    }
  }
  std::printf("friction homogeneity mu = 0.05 ... 0.6: worst difference of F/mu %.1e of N\n",
              worst);
}

namespace {

// Kalker's C11, C22, C23 for nu = 0.25 at a/b (tests/data/kalker, exact table rows).
std::array<double, 3> kalker_row(double a_over_b) {
  using rollnoise::testing::num;
  for (const auto& row : rollnoise::testing::read_csv(
           rollnoise::testing::data_path("kalker/kalker_linear_theory.csv")))
    if (std::abs(num(row, "a_over_b") - a_over_b) < 1e-9 && num(row, "nu") == 0.25)
      return {num(row, "C11"), num(row, "C22"), num(row, "C23")};
  throw std::runtime_error("no Kalker row");
}

}  // namespace

TEST(SteadyStress, EllipsesFromAspectRatio01To10GiveKalkerStiffnessAndCoulombTractions) {
  // a/b from 0.1 to 10 at constant c = sqrt(ab), 10 elements across the minor axis and about
  // square elements (100 x 10 at a/b = 10). nu = 0.25 for Kalker's table.
  const Material m{210e9, 0.25};
  const double mu = 0.3, G = m.shear_modulus(), xi = 1e-6;
  std::printf("%6s %8s %7s %8s %8s %8s %8s %8s %8s %7s\n", "a/b", "grid", "contact", "C11",
              "Kalker", "C22", "Kalker", "C23", "Kalker", "time s");
  for (double r : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0}) {
    const auto t0 = std::chrono::steady_clock::now();
    const int nx = r >= 1 ? static_cast<int>(std::lround(10 * r)) : 10;
    const int ny = r >= 1 ? 10 : static_cast<int>(std::lround(10 / r));
    const ContactPatch p = hertz_patch(r, nx, ny, m);
    const double a = kC * std::sqrt(r), b = kC / std::sqrt(r), c = std::sqrt(a * b);
    std::array<double, 3> C{};
    const std::array<Creepage, 3> unit = {Creepage{xi, 0, 0}, Creepage{0, xi, 0},
                                          Creepage{0, 0, xi / c}};
    for (int k = 0; k < 3; ++k) {
      const auto s = solve(p, mu, unit[k]);
      expect_physical(check_steady(p, s, mu, kSpeed, unit[k], 0.0), "a/b = " + std::to_string(r));
      const auto f = total_forces(p.grid, s.px, s.py);
      // Fx = -G c^2 C11 xi_x; Fy = -G c^2 C22 xi_y; Fy = -G c^3 C23 phi with phi = xi/c
      C[k] = -(k == 0 ? f.Fx : f.Fy) / (G * c * c * xi);
    }
    // partial slip with spin and full sliding on the same patch
    for (const Creepage cr : {Creepage{3e-3, 1e-3, 1.0}, Creepage{0.1, 0.0, -2.0}}) {
      TangentialSolution s;
      ASSERT_NO_THROW(s = solve(p, mu, cr)) << "a/b = " << r << " " << describe(cr);
      expect_physical(check_steady(p, s, mu, kSpeed, cr, 0.0),
                      "a/b = " + std::to_string(r) + " " + describe(cr));
    }
    const auto K = kalker_row(r);
    std::printf("%6.1f %4dx%-3d %7d %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %7.2f\n", r, nx, ny,
                p.normal.contact_elements(), C[0], K[0], C[1], K[1], C[2], K[2], seconds_since(t0));
    // Discretisation error with 10 elements across the minor axis: the discrete patch is stiffer
    // than Kalker's continuum by 3-9.4 % for C11, C22 and 1-5 % for C23 (measured over a/b = 0.1
    // .. 10; first order in the element size, 3 % at 30 elements across in tests/contact). 12 %
    // bounds these with a margin; a sign error, a wrong axis or a broken patch is off by far more.
    EXPECT_NEAR(C[0], K[0], 0.12 * K[0]) << "C11 at a/b = " << r;
    EXPECT_NEAR(C[1], K[1], 0.12 * K[1]) << "C22 at a/b = " << r;
    EXPECT_NEAR(C[2], K[2], 0.12 * K[2]) << "C23 at a/b = " << r;
  }
}

TEST(SteadyStress, GridsFrom4x4To100x100SolveNormalAndSteadyProblems) {
  // Normal problem, full sliding and partial slip (the paper's Sec. 3.2 mean state) on every grid
  // from 4 x 4 (4 contact elements) to 100 x 100 (6140): 2-3 s for the partial slip on 100 x 100
  // (Jacobian-free Newton-GMRES), full sliding converges in a few Newton steps on any grid.
  const double mu = 0.3;
  const Creepage sliding{0.1, 0.0, 0.0}, partial{1e-3, 1e-3, -0.053};
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, kN, kSteel);
  std::printf("%9s %7s %10s %10s %12s %10s %12s\n", "grid", "contact", "p_max/p0", "normal s",
              "sliding s", "partial s", "adh/slip");
  for (auto [nx, ny] : std::vector<std::pair<int, int>>{
           {4, 4}, {5, 5}, {6, 6}, {8, 8}, {12, 9}, {34, 25}, {48, 36}, {68, 50}, {100, 100}}) {
    auto t0 = std::chrono::steady_clock::now();
    const ContactPatch p = hertz_patch(kPaperRatio, nx, ny);
    const double t_normal = seconds_since(t0);
    // the load is carried exactly (the normal solver rescales to N); the pressure is bounded by a
    // few times Hertz's p0 even on 4 x 4 (the discrete peak is an element mean: below p0 on fine
    // grids, above it where few elements carry the load)
    EXPECT_NEAR(p.normal.force, kN, 1e-9 * kN) << nx << " x " << ny;
    EXPECT_LT(p.normal.max_pressure(), 3.0 * h.p0) << nx << " x " << ny;
    t0 = std::chrono::steady_clock::now();
    TangentialSolution s;
    ASSERT_NO_THROW(s = solve(p, mu, sliding)) << nx << " x " << ny;
    const double t_sliding = seconds_since(t0);
    expect_physical(check_steady(p, s, mu, kSpeed, sliding, 0.0), "full sliding");
    EXPECT_EQ(s.count(ElementState::adhesion), 0);
    const auto F = total_forces(p.grid, s.px, s.py);
    EXPECT_NEAR(std::hypot(F.Fx, F.Fy), mu * p.normal.force, 2e-3 * mu * p.normal.force);
    t0 = std::chrono::steady_clock::now();
    ASSERT_NO_THROW(s = solve(p, mu, partial)) << nx << " x " << ny;
    const double t_partial = seconds_since(t0);
    const int adh = s.count(ElementState::adhesion), slp = s.count(ElementState::slip);
    expect_physical(check_steady(p, s, mu, kSpeed, partial, 0.0), "partial slip");
    std::printf("%4dx%-4d %7d %10.4f %10.3f %12.3f %10.3f %6d/%-5d\n", nx, ny,
                p.normal.contact_elements(), p.normal.max_pressure() / h.p0, t_normal, t_sliding,
                t_partial, adh, slp);
  }
}

// The NSS model on 100 x 100 (the paper's ellipse) in partial slip (r = 10371 reduced unknowns: the
// dense Cholesky factor alone would be 0.86 GB) and full sliding (r = 6140), on the matrix-free
// path (K0 by FFT and PCG, the columns of a block on the machine's threads): memory O(r x Krylov
// basis), ~0.1 GB. The Krylov model must pass its own a-posteriori check (1e-10 between models
// Lc/3 steps apart) and f must be finite and passive at 51 frequencies over [0, Nyquist].
// ~30-60 s in Release on 2 cores; not under the sanitizers (the PCG products are FFTW, the
// Krylov steps the same code as on 34 x 25).
TEST(SteadyStress, LargeGrid100x100NssModel) {
  if (kSanitized) GTEST_SKIP() << "100 x 100 matrix-free sweep: Release only";
  const double mu = 0.3;
  const ContactPatch p = hertz_patch(kPaperRatio, 100, 100);
  for (const Creepage c : {Creepage{1e-3, 1e-3, -0.053}, Creepage{0.1, 0, 0}}) {
    auto t0 = std::chrono::steady_clock::now();
    TangentialSolution s;
    ASSERT_NO_THROW(s = solve(p, mu, c));
    const double t_steady = seconds_since(t0);
    expect_physical(check_steady(p, s, mu, kSpeed, c, 0.0), describe(c));
    t0 = std::chrono::steady_clock::now();
    nss::LinearModelInput in{mu, kSpeed, 0.0, {}, nss::LinearSolver::matrix_free,
                             contact::CreepageSampling::contact};  // passivity theorem
    const nss::LinearContactModel m(p, s, in);
    ASSERT_TRUE(m.matrix_free());
    std::vector<double> freqs;
    for (int i = 0; i <= 50; ++i) freqs.push_back(m.nyquist_frequency() * i / 50);
    const auto f = m.creep_coefficients(freqs);
    EXPECT_EQ(m.sweep_info().method, nss::SweepInfo::Method::krylov) << describe(c);
    EXPECT_LE(m.sweep_info().error_estimate, 1e-10) << describe(c);
    for (const auto& fk : f) {
      EXPECT_TRUE(fk.allFinite());
      EXPECT_GE(passivity_margin(fk, kC, false), -1e-9);
    }
    std::printf(
        "100x100 %s: %d adhesion, %d slip; steady %.2f s (%d Newton, %d GMRES iterations, %d LU); "
        "matrix-free NSS model + 51 frequencies %.2f s (r = %d, %d block steps, %.1f PCG iterations per "
        "solve, %d threads)\n",
        describe(c).c_str(), s.count(ElementState::adhesion), s.count(ElementState::slip), t_steady,
        s.iterations, s.linear_iterations, s.factorisations, seconds_since(t0), m.reduced_unknowns(),
        m.sweep_info().block_steps, double(m.inner_iterations()) / double(m.inner_solves()), m.threads());
  }
}
