// The matrix-free path of the linear NSS model (K0 applied by FFT, solved by preconditioned CG;
// nss/reduced_form.cpp, "Matrix-free path") against the dense path (Cholesky factor of K0), the
// reference: creep and normal-load coefficients over [0, Nyquist], the time response, and the
// grid independence of the PCG iteration counts that the preconditioner is for.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "../contact/paper_case.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "core/errors.hpp"
#include "nss/linear_model.hpp"

using namespace rollnoise;
using namespace rollnoise::contact;

namespace {

using rollnoise::testing::kMu;                     // 0.3
constexpr double kV = rollnoise::testing::kSpeed;  // 50 km/h (m/s)

// The paper's ellipse (a = 7.18 mm, b = 5.29 mm, N = 98.1 kN) on an nx x ny grid.
ContactPatch patch(int nx, int ny) {
  const Material m{210e9, 0.28};
  const Grid g = Grid::around_ellipse(nx, ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, m);
  return solve_patch(g, m, quadratic_distance(g, h.A, h.B), 98100);
}

struct Models {
  nss::LinearContactModel dense, mf;
};

Models models(const ContactPatch& p, const Creepage& c, double offset = 0.0) {
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kV, c, offset});
  return {nss::LinearContactModel(p, s, {kMu, kV, offset, {}, nss::LinearSolver::dense}),
          nss::LinearContactModel(p, s, {kMu, kV, offset, {}, nss::LinearSolver::matrix_free})};
}

template <class T>
double max_relative_difference(const std::vector<T>& a, const std::vector<T>& ref) {
  double worst = 0.0, scale = 0.0;
  for (const auto& r : ref) scale = std::max(scale, r.norm());
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - ref[i]).norm() / std::max(ref[i].norm(), 1e-3 * scale));
  return worst;
}

// Mean PCG iterations per K0 solve over a short time response (12 steps of a random creepage).
double iterations_per_solve(const ContactPatch& p, const Creepage& c) {
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kV, c, 0.0});
  const nss::LinearContactModel m(p, s, {kMu, kV, 0.0, {}, nss::LinearSolver::matrix_free});
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, 1e-4);
  std::vector<Eigen::Vector3d> xi;
  for (int k = 0; k < 12; ++k) xi.emplace_back(n(rng), n(rng), 10 * n(rng));
  m.time_response(xi);
  return double(m.inner_iterations()) / double(m.inner_solves());
}

}  // namespace

TEST(MatrixFree, CreepAndLoadCoefficientsEqualTheDensePathFromZeroToNyquist) {
  // Full adhesion, the paper's partial slip, full sliding, and spin with CONTACT's spin offset.
  // The PCG tolerance 1e-12 (relative residual) keeps f within ~1e-12 of the dense path (measured
  // 2e-13 to 8e-12); the acceptance is 1e-9.
  const ContactPatch p = patch(24, 18);
  struct State {
    Creepage c;
    double offset;
  };
  for (const State& st : {State{{0, 0, 0}, 0.0}, State{{1e-3, 1e-3, -0.053}, 0.0}, State{{0.1, 0, 0}, 0.0},
                          State{{2e-4, -1e-4, 1.0}, 1.0 / 6.0}}) {
    const Models m = models(p, st.c, st.offset);
    ASSERT_FALSE(m.dense.matrix_free());
    ASSERT_TRUE(m.mf.matrix_free());
    std::vector<double> freqs;
    for (int i = 0; i <= 40; ++i) freqs.push_back(m.dense.nyquist_frequency() * i / 40);
    const auto fd = m.dense.creep_coefficients(freqs), fm = m.mf.creep_coefficients(freqs);
    const auto gd = m.dense.normal_load_coefficients(freqs), gm = m.mf.normal_load_coefficients(freqs);
    EXPECT_EQ(m.mf.sweep_info().method, nss::SweepInfo::Method::krylov);
    EXPECT_TRUE(m.mf.sweep_info().matrix_free);
    EXPECT_LE(max_relative_difference(fm, fd), 1e-9) << st.c.xi_x << " " << st.c.phi;
    if (m.dense.has_normal_load_input()) {
      EXPECT_LE(max_relative_difference(gm, gd), 1e-9) << st.c.xi_x;
    }
    if (st.c.xi_x != 1e-3) continue;
    // partial slip: the exact recursion on the matrix-free path (PCG started from the rolled traction)
    const std::vector<double> three = {0.0, 0.3 * m.dense.nyquist_frequency(), m.dense.nyquist_frequency()};
    EXPECT_LE(max_relative_difference(m.mf.creep_coefficients_markov(three), m.dense.creep_coefficients_markov(three)),
              1e-9);
  }
}

TEST(MatrixFree, TimeResponseEqualsTheDensePath) {
  // Partial slip with a normal-load input; random creepages and loads (seeded).
  const ContactPatch p = patch(24, 18);
  const Models m = models(p, {1e-3, 1e-3, -0.053});
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Eigen::Vector3d> xi;
  std::vector<double> dN;
  for (int k = 0; k < 80; ++k) {
    xi.emplace_back(1e-4 * n(rng), 1e-4 * n(rng), 1e-3 * n(rng));
    dN.push_back(1e3 * n(rng));
  }
  const auto Fd = m.dense.time_response(xi, dN), Fm = m.mf.time_response(xi, dN);
  double scale = 0.0, worst = 0.0;
  for (const auto& F : Fd) scale = std::max(scale, F.head<2>().norm());
  for (size_t k = 0; k < Fd.size(); ++k) worst = std::max(worst, (Fm[k] - Fd[k]).head<2>().norm() / scale);
  EXPECT_LE(worst, 1e-9);
  EXPECT_GT(m.mf.inner_solves(), 0);
}

TEST(MatrixFree, PcgIterationCountsAreNearlyGridIndependent) {
  // The preconditioner (the inverse of the circulant symbol of A/dt + cbar on the contact
  // elements, cbar the median slip diagonal c_e times the slip unknowns' share of r; slip unknowns
  // scaled by sqrt((kappa + cbar)/(kappa + c))) against 24 x 18, 34 x 25 and 68 x 50 (4x the
  // elements of 34 x 25). Measured 14-17 iterations in adhesion, 17-21 in partial slip (19-27 with
  // cbar = 0) and 8-9 in full sliding (39-61 with cbar = 0: the slip diagonal dominates there);
  // without the slip scaling 85-95 in partial slip, unpreconditioned CG grows with the condition
  // number of A (~ the grid size). The bounds allow 1.6x growth from the coarsest grid to the finest.
  for (const Creepage& c : {Creepage{0, 0, 0}, Creepage{1e-3, 1e-3, -0.053}, Creepage{0.1, 0, 0}}) {
    std::vector<double> its;
    for (auto [nx, ny] : std::vector<std::pair<int, int>>{{24, 18}, {34, 25}, {68, 50}})
      its.push_back(iterations_per_solve(patch(nx, ny), c));
    std::printf("xi_x = %g: PCG iterations per solve %.1f (24x18), %.1f (34x25), %.1f (68x50)\n", c.xi_x, its[0],
                its[1], its[2]);
    EXPECT_LE(its.back(), c.xi_x == 0 ? 25.0 : c.xi_x < 0.01 ? 28.0 : 15.0);
    EXPECT_LE(its.back(), 1.6 * its.front());
  }
}

// Threads share out the columns of a block (nss/step_solver.hpp, "Threads"); each column is
// computed with the same operations as in a serial run, so f, g and the time response are the
// same to the last bit with 1 and with 4 threads, on both paths (4 > the cores of a CI machine:
// the threads then interleave, which must not matter either).
TEST(MatrixFree, ResultsDoNotDependOnTheNumberOfThreads) {
  const ContactPatch p = patch(24, 18);
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kV, Creepage{1e-3, 1e-3, -0.053}, 0.0});
  std::vector<double> freqs;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1e-4, 1e-4);
  std::vector<Eigen::Vector3d> xi;
  std::vector<double> dN;
  for (int k = 0; k < 20; ++k) {
    xi.emplace_back(u(rng), u(rng), 50 * u(rng));
    dN.push_back(1e7 * u(rng));
  }
  for (nss::LinearSolver solver : {nss::LinearSolver::dense, nss::LinearSolver::matrix_free}) {
    std::vector<std::vector<nss::CreepMatrix>> f;
    std::vector<std::vector<nss::LoadVector>> g;
    std::vector<std::vector<Eigen::Vector3d>> F;
    for (int threads : {1, 4}) {
      nss::LinearModelInput in{kMu, kV, 0.0, {}, solver};
      in.threads = threads;
      const nss::LinearContactModel m(p, s, in);
      ASSERT_EQ(m.threads(), threads);
      if (freqs.empty())
        for (int i = 0; i <= 40; ++i) freqs.push_back(m.nyquist_frequency() * i / 40);
      f.push_back(m.creep_coefficients(freqs));
      g.push_back(m.normal_load_coefficients(freqs));
      F.push_back(m.time_response(xi, dN));
    }
    const char* path = solver == nss::LinearSolver::dense ? "dense" : "matrix-free";
    for (size_t i = 0; i < freqs.size(); ++i) {
      EXPECT_TRUE(f[0][i] == f[1][i]) << path << " f at " << freqs[i] << " Hz";
      EXPECT_TRUE(g[0][i] == g[1][i]) << path << " g at " << freqs[i] << " Hz";
    }
    for (size_t k = 0; k < xi.size(); ++k) EXPECT_TRUE(F[0][k] == F[1][k]) << path << " step " << k;
  }
}

TEST(MatrixFree, ThreadCountOutsideZeroToFourIsRefusedNamingTheKey) {
  const ContactPatch p = patch(16, 12);
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kV, Creepage{1e-3, 0, 0}, 0.0});
  for (int threads : {-1, 5}) {
    nss::LinearModelInput in{kMu, kV, 0.0};
    in.threads = threads;
    try {
      nss::LinearContactModel m(p, s, in);
      ADD_FAILURE() << threads << " threads accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "solver.threads") << e.what();
    }
  }
  nss::LinearModelInput in{kMu, kV, 0.0};
  const nss::LinearContactModel automatic(p, s, in);
  EXPECT_GE(automatic.threads(), 1);
  EXPECT_LE(automatic.threads(), nss::kMaxThreads);
}
