// The linear NSS model (paper Eqs. 6-30): its limits (steady tangent at w -> 0, contact stiffness
// at high w), the agreement of its three evaluations, symmetry, and its time responses against our
// unsteady solver and CONTACT's unsteady runs (paper Secs. 3.1, 3.2).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "../contact/paper_case.hpp"
#include "../contact/reference_data.hpp"
#include "contact/creepage_history.hpp"
#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "core/errors.hpp"
#include "linalg/harmonic_fit.hpp"
#include "nss/linear_model.hpp"

using namespace rollnoise;
using namespace rollnoise::contact;
using rollnoise::testing::data_path;
using rollnoise::testing::num;
using rollnoise::testing::read_csv;
using namespace rollnoise::testing;

namespace {

// These tests compare with CONTACT, the paper and our unsteady solver stepped at t_k = k dt: CONTACT's
// creepage sampling (tests/nss/creepage_sampling_test.cpp has the midstep ones).
constexpr auto kContactSampling = CreepageSampling::contact;

TangentialForces steady_forces(const Creepage& c, double spin_offset = 0.0) {
  const ContactPatch& p = coarse_patch();
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, c, spin_offset});
  return total_forces(p.grid, s.px, s.py);
}

nss::LinearContactModel model_at(const Creepage& c, double spin_offset = 0.0) {
  const ContactPatch& p = coarse_patch();
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, c, spin_offset});
  return nss::LinearContactModel(p, s, {kMu, kSpeed, spin_offset, kContactSampling});
}

}  // namespace

TEST(LinearModel, ZeroFrequencyEqualsTheTangentOfTheSteadyForceCreepageLaw) {
  // Central finite differences of the steady solver around the paper's Sec. 3.2 mean state.
  const Creepage mean{0.001, 0.001, -0.053};
  const auto f0 = model_at(mean).creep_coefficients_direct(0.0);
  const std::array<double, 3> h = {1e-6, 1e-6, 5e-5};
  for (int k = 0; k < 3; ++k) {
    Creepage plus = mean, minus = mean;
    (&plus.xi_x)[k] += h[k];
    (&minus.xi_x)[k] -= h[k];
    const auto fp = steady_forces(plus), fm = steady_forces(minus);
    const Eigen::Vector3d jac = -Eigen::Vector3d(fp.Fx - fm.Fx, fp.Fy - fm.Fy, fp.Mz - fm.Mz) / (2 * h[k]);
    for (int j = 0; j < 3; ++j) {
      std::printf("f%d%d(0) = %.5g, finite difference %.5g\n", j + 1, k + 1, f0(j, k).real(), jac(j));
      EXPECT_NEAR(f0(j, k).imag(), 0.0, 1e-9 * std::abs(f0(j, k)));
      // within 1 % of the entry, or of its row's largest entry for entries that nearly vanish
      const double row = f0.row(j).cwiseAbs().maxCoeff() * (j == 2 ? 1.0 : 1.0);
      EXPECT_NEAR(f0(j, k).real(), jac(j), 0.01 * std::max(std::abs(jac(j)), 0.05 * row));
    }
  }
}

TEST(LinearModel, HighFrequencyContactActsAsATangentialSpring) {
  // Continuum: f11 ~ V K/(i w), |f11| w/V -> K, arg f11 -> -90 deg. The discrete-time model
  // differentiates with (1 - z)/dt = i w e^{-i w dt/2} sinc(w dt/2) instead of i w (the rolling
  // step is a backward difference), so on a grid f11 (1 - z)/(dt V) -> K, real; the half-step
  // delay w dt/2 vanishes under refinement.
  const auto m = model_at({0.001, 0, 0});
  const double fn = m.nyquist_frequency(), dt = m.time_step();
  const std::vector<double> freqs = {0.2 * fn, 0.3 * fn, 0.5 * fn, 0.7 * fn};
  const auto f = m.creep_coefficients(freqs);
  std::vector<double> K;
  for (size_t i = 0; i < freqs.size(); ++i) {
    const std::complex<double> D = (1.0 - std::polar(1.0, -2 * M_PI * freqs[i] * dt)) / dt;
    const std::complex<double> k = f[i](0, 0) * D / kSpeed;
    K.push_back(std::abs(k));
    std::printf("f = %.0f Hz: arg f11 = %.2f deg, arg f11 (1-z)/dt = %.2f deg, K = %.4g N/m\n", freqs[i],
                std::arg(f[i](0, 0)) * 180 / M_PI, std::arg(k) * 180 / M_PI, K.back());
    if (i >= 1) {
      EXPECT_NEAR(std::arg(k) * 180 / M_PI, 0.0, 2.0) << "arg f11 -> -90 deg (+ half step)";
    }
  }
  for (size_t i = 1; i < K.size(); ++i) EXPECT_NEAR(K[i] / K[1], 1.0, 0.02) << "constant stiffness";
  // Under refinement the plain phase at a fixed frequency approaches -90 degrees.
  const Grid fine = Grid::around_ellipse(48, 35, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, kN, kSteel);
  const ContactPatch pf = solve_patch(fine, kSteel, quadratic_distance(fine, h.A, h.B), kN);
  const auto sf = solve_steady_rolling(pf.influence, pf.normal.pn, {kMu, kSpeed, {0.001, 0, 0}, 0.0});
  const double f3k = 3000.0;
  const double arg_coarse = std::arg(m.creep_coefficients({f3k})[0](0, 0)) * 180 / M_PI;
  const double arg_fine =
      std::arg(nss::LinearContactModel(pf, sf, {kMu, kSpeed, 0.0, kContactSampling}).creep_coefficients({f3k})[0](0, 0)) * 180 / M_PI;
  std::printf("arg f11 at 3 kHz: coarse %.2f deg, fine %.2f deg\n", arg_coarse, arg_fine);
  EXPECT_LT(std::abs(arg_fine + 90), std::abs(arg_coarse + 90));
}

TEST(LinearModel, FastSweepHessenbergAndDirectSolveAgree) {
  for (Creepage c : {Creepage{0, 0, 0}, Creepage{0.001, 0.001, -0.053}, Creepage{0.004, 0, 0}}) {
    const auto m = model_at(c);
    const std::vector<double> freqs = {0.0, 100.0, 1000.0, 5000.0, m.nyquist_frequency()};
    const auto fast = m.creep_coefficients(freqs), hess = m.creep_coefficients_hessenberg(freqs);
    for (size_t i = 0; i < freqs.size(); ++i) {
      const auto direct = m.creep_coefficients_direct(freqs[i]);
      EXPECT_LT((fast[i] - direct).norm(), 1e-9 * direct.norm()) << freqs[i] << " Hz";
      EXPECT_LT((hess[i] - direct).norm(), 1e-9 * direct.norm()) << freqs[i] << " Hz";
    }
  }
}

TEST(LinearModel, SymmetricPatchWithoutSpinOrLateralCreepageDecouplesLongitudinalFromLateral) {
  const auto m = model_at({0.001, 0, 0});
  for (const auto& f : m.creep_coefficients({0.0, 500.0, 2000.0})) {
    const double scale = std::abs(f(0, 0));
    EXPECT_LT(std::abs(f(0, 1)), 1e-9 * scale);
    EXPECT_LT(std::abs(f(0, 2)), 1e-9 * scale * 1e-2);
    EXPECT_LT(std::abs(f(1, 0)), 1e-9 * scale);
    EXPECT_LT(std::abs(f(2, 0)), 1e-9 * scale * 1e-2);
  }
}

TEST(LinearModel, FrequencyAboveNyquistIsAnInputError) {
  const auto m = model_at({0.001, 0, 0});
  EXPECT_NO_THROW(m.creep_coefficients({m.nyquist_frequency()}));
  EXPECT_THROW(m.creep_coefficients({1.01 * m.nyquist_frequency()}), InputError);
  EXPECT_THROW(m.creep_coefficients_direct(-1.0), InputError);
}

TEST(LinearModel, RecursionAgreesWithHarmonicSynthesisAfterTheStart) {
  // M0 Q_k = M1 Q_{k-1} + W_k from rest, against -Re(f xi^ e^{i w t}) (paper Eqs. 33-34).
  const auto m = model_at({0.001, 0.001, -0.053});
  const auto h = CreepageHistory::multiharmonic({0.001, 0.001, -0.053}, {1e-6, 1e-6, 5e-6}, 100, 5000, 50, 3);
  const auto f = m.creep_coefficients(h.frequencies());
  const double dt = m.time_step();
  std::vector<Eigen::Vector3d> xi;
  for (int k = 0; k < 800; ++k) {
    const auto v = h.variation(k * dt);
    xi.emplace_back(v[0], v[1], v[2]);
  }
  const auto F = m.time_response(xi);
  double err = 0, ref = 0;
  for (int k = 500; k < 800; ++k) {  // after 16 contact lengths
    Eigen::Vector3d syn = Eigen::Vector3d::Zero();
    for (size_t n = 0; n < h.frequencies().size(); ++n) {
      Eigen::Vector3cd x;
      for (int j = 0; j < 3; ++j) x(j) = h.amplitude()[j] * std::polar(1.0, h.phases()[j][n]);
      syn -= (f[n] * x * std::polar(1.0, 2 * M_PI * h.frequencies()[n] * k * dt)).real();
    }
    err = std::max(err, (F[k] - syn).norm());
    ref = std::max(ref, syn.norm());
  }
  EXPECT_LT(err, 1e-8 * ref);
}

// ---- against the unsteady solver and CONTACT (paper Sec. 3.1) ----

TEST(LinearModel, Section31AmplitudeAndPhaseAgreeWithTheUnsteadySolverAndCONTACT) {
  // xi_x = 0.001 + 5e-5 cos(2 pi 1000 t); linear model F~ = -f11 xi~.
  const ContactPatch& p = coarse_patch();
  const Creepage mean{0.001, 0, 0};
  const auto steady = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, mean, 0.0});
  const nss::LinearContactModel m(p, steady, {kMu, kSpeed, 0.0, kContactSampling});
  const std::complex<double> F = -m.creep_coefficients({1000.0})[0](0, 0) * 5e-5;
  const double amp = std::abs(F), phase = std::arg(F) * 180 / M_PI;

  // our unsteady solver, fitted over the last 5 periods of 10 ms (as CONTACT's harmonic_fit.csv)
  const auto history = CreepageHistory::harmonic(mean, {5e-5, 0, 0}, 1000.0);
  TransientRolling rolling(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  rolling.set_tractions(steady.px, steady.py);
  std::vector<double> t, fx;
  for (int k = 1; k <= 291; ++k) {
    const auto& s = rolling.step(history.at(k * rolling.time_step()));
    if (k * rolling.time_step() < 0.005029) continue;
    t.push_back(k * rolling.time_step());
    fx.push_back(total_forces(p.grid, s.px, s.py).Fx);
  }
  const auto fit = linalg::fit_harmonic(t, fx, 1000.0);
  double ref_amp = 0, ref_phase = 0;
  for (const auto& row : read_csv(data_path("contact/U1/harmonic_fit.csv")))
    if (row.at("grid") == "coarse" && row.at("quantity") == "Fx_N")
      ref_amp = num(row, "amp"), ref_phase = num(row, "phase_deg");
  std::printf("Fx at 1 kHz: linear %.3f N at %.3f deg; unsteady %.3f N at %.3f deg; CONTACT %.3f N at %.3f deg\n",
              amp, phase, fit.amplitude, fit.phase * 180 / M_PI, ref_amp, ref_phase);
  EXPECT_NEAR(amp, fit.amplitude, 0.01 * fit.amplitude);
  EXPECT_NEAR(phase, fit.phase * 180 / M_PI, 1.0);
  EXPECT_NEAR(amp, ref_amp, 0.02 * ref_amp);
  EXPECT_NEAR(phase, ref_phase, 2.0);
}

TEST(LinearModel, Section32ForcesWithinTwoPercentOfTheVariationAmplitude) {
  // Mean (0.001, 0.001, -0.053), all varied by 5 % at 1 kHz, against our unsteady solver.
  const ContactPatch& p = coarse_patch();
  const Creepage mean{0.001, 0.001, -0.053};
  const auto history = CreepageHistory::harmonic(mean, {5e-5, 5e-5, 0.0027}, 1000.0);
  const auto steady = solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, mean, 0.0});
  const TangentialForces fbar = total_forces(p.grid, steady.px, steady.py);
  const nss::LinearContactModel m(p, steady, {kMu, kSpeed, 0.0, kContactSampling});
  const auto f = m.creep_coefficients({1000.0})[0];
  const Eigen::Vector3cd xhat(5e-5, 5e-5, 0.0027);
  TransientRolling rolling(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  rolling.set_tractions(steady.px, steady.py);
  double err_x = 0, err_y = 0, amp_x = 0, amp_y = 0;
  for (int k = 1; k <= 291; ++k) {
    const double t = k * rolling.time_step();
    const auto& s = rolling.step(history.at(t));
    const Eigen::Vector3d lin = -(f * xhat * std::polar(1.0, 2 * M_PI * 1000.0 * t)).real();
    if (t < 2e-3) continue;
    const auto F = total_forces(p.grid, s.px, s.py);
    err_x = std::max(err_x, std::abs(F.Fx - fbar.Fx - lin(0)));
    err_y = std::max(err_y, std::abs(F.Fy - fbar.Fy - lin(1)));
    amp_x = std::max(amp_x, std::abs(lin(0)));
    amp_y = std::max(amp_y, std::abs(lin(1)));
  }
  std::printf("Sec. 3.2: max error Fx %.2f N of %.1f N, Fy %.2f N of %.1f N\n", err_x, amp_x, err_y, amp_y);
  EXPECT_LT(err_x, 0.02 * amp_x);
  EXPECT_LT(err_y, 0.02 * amp_y);
}

TEST(LinearModel, Table1MagnitudesOfF11AndF22WithinTwentyPercentOfThePaper) {
  // Paper Table 1 (1 kHz, mean xi_x = 0.001): f11 = 3.30e5 - 2.31e6 i, f22 = 3.32e5 - 2.53e6 i.
  const auto f = model_at({0.001, 0, 0}).creep_coefficients({1000.0})[0];
  const std::complex<double> p11(3.30e5, -2.31e6), p22(3.32e5, -2.53e6);
  std::printf("Table 1: f11 = %.3g %+.3gi (paper %.3g %+.3gi), f22 = %.3g %+.3gi (paper %.3g %+.3gi)\n",
              f(0, 0).real(), f(0, 0).imag(), p11.real(), p11.imag(), f(1, 1).real(), f(1, 1).imag(),
              p22.real(), p22.imag());
  std::printf("         f23 = %.4g %+.4gi (paper 2462.2 - 1909.1i), f32 = %.4g %+.4gi (paper -9425.7 - 1.88e4i)\n",
              f(1, 2).real(), f(1, 2).imag(), f(2, 1).real(), f(2, 1).imag());
  EXPECT_NEAR(std::abs(f(0, 0)), std::abs(p11), 0.2 * std::abs(p11));
  EXPECT_NEAR(std::abs(f(1, 1)), std::abs(p22), 0.2 * std::abs(p22));
}

TEST(LinearModel, EveryMeanStateFromFullAdhesionToNearFullSlidingGivesFinitePassiveCoefficients) {
  // S5's force-creepage curve: 538 adhesion elements at 0, 25 at 0.0045, none at 0.006.
  for (double xi : {0.0, 1e-8, 0.0045, 0.006}) {
    const auto m = model_at({xi, 0, 0});
    const std::vector<double> freqs = {0.0, 300.0, 3000.0, m.nyquist_frequency()};
    const auto fast = m.creep_coefficients(freqs);
    for (size_t i = 0; i < freqs.size(); ++i) {
      ASSERT_TRUE(fast[i].allFinite()) << "xi = " << xi;
      const auto direct = m.creep_coefficients_direct(freqs[i]);
      EXPECT_LT((fast[i] - direct).norm(), 1e-9 * direct.norm()) << "xi = " << xi << ", " << freqs[i] << " Hz";
      // the contact dissipates: the creep force is never in phase with the creepage rate reversal
      EXPECT_GE(fast[i](0, 0).real(), -1e-9 * std::abs(fast[i](0, 0))) << "xi = " << xi;
      EXPECT_GE(fast[i](1, 1).real(), -1e-9 * std::abs(fast[i](1, 1))) << "xi = " << xi;
    }
    std::printf("xi = %g: %d adhesion, %d slip; f11(0) = %.4g N, f11(3 kHz) = %.4g %+.4gi N\n", xi,
                m.adhesion_elements(), m.slip_elements(), fast[0](0, 0).real(), fast[2](0, 0).real(),
                fast[2](0, 0).imag());
  }
}

// ---- the fast sweep (block Krylov reduced model) against the exact evaluations ----

TEST(LinearModel, FastSweepAgreesWithTheExactRecursionAndTheDirectSolveFromZeroToNyquist) {
  // Mean states from full adhesion to full sliding, with lateral creepage and spin, and a spin
  // offset. The reduced model must pass its own check (no fallback) and agree to 1e-9 (relative,
  // Frobenius) with the exact Markov recursion on 241 frequencies over [0, Nyquist] and with the
  // direct complex LU (the paper's form) at four of them.
  struct Case {
    Creepage c;
    double spin_offset;
  };
  const std::vector<Case> cases = {{{0, 0, 0}, 0.0},          {{1e-8, 0, 0}, 0.0},
                                   {{0.001, 0.001, -0.053}, 0.0}, {{0.001, -0.0005, 0.1}, 1.0 / 6.0},
                                   {{0.004, 0, 0}, 0.0},      {{0.0045, 0, 0}, 0.0},
                                   {{0.006, 0, 0}, 0.0}};
  for (const auto& cs : cases) {
    const auto m = model_at(cs.c, cs.spin_offset);
    const double fn = m.nyquist_frequency();
    std::vector<double> freqs;
    for (int i = 0; i <= 240; ++i) freqs.push_back(fn * i / 240.0);
    const auto fast = m.creep_coefficients(freqs);
    const auto info = m.sweep_info();
    EXPECT_EQ(info.method, nss::SweepInfo::Method::krylov) << cs.c.xi_x;
    const auto exact = m.creep_coefficients_markov(freqs);
    double worst = 0.0;
    for (size_t i = 0; i < freqs.size(); ++i) {
      const double e = (fast[i] - exact[i]).norm() / exact[i].norm();
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-9) << "xi = (" << cs.c.xi_x << ", " << cs.c.xi_y << ", " << cs.c.phi << "), " << freqs[i]
                         << " Hz";
    }
    double worst_direct = 0.0;
    for (double f : {0.0, 0.13 * fn, 0.61 * fn, fn}) {
      const auto direct = m.creep_coefficients_direct(f);
      const auto fa = m.creep_coefficients({f})[0];
      worst_direct = std::max(worst_direct, (fa - direct).norm() / direct.norm());
      EXPECT_LT((fa - direct).norm(), 1e-9 * direct.norm()) << "xi_x = " << cs.c.xi_x << ", " << f << " Hz";
    }
    std::printf("xi = (%g, %g, %g): %d adhesion, %d slip: %d block steps (dimension %d), %zu Markov parameters, "
                "estimate %.1e; vs exact recursion %.1e, vs direct %.1e\n",
                cs.c.xi_x, cs.c.xi_y, cs.c.phi, m.adhesion_elements(), m.slip_elements(), info.block_steps,
                info.reduced_dimension, m.markov_parameters().size(), info.error_estimate, worst, worst_direct);
  }
}

TEST(LinearModel, FastSweepFallsBackWhenTheImpulseResponseIsCutShort) {
  // With the Markov parameters limited to 3 contact lengths neither the Krylov model nor the exact
  // recursion can decay to round-off: the sweep falls back to the Hessenberg form (exact).
  const auto m = model_at({0.001, 0.001, -0.053});
  const std::vector<double> freqs = {0.0, 1000.0, m.nyquist_frequency()};
  const auto f = m.creep_coefficients(freqs, 3);
  EXPECT_EQ(m.sweep_info().method, nss::SweepInfo::Method::hessenberg);
  EXPECT_TRUE(m.markov_parameters().empty());
  for (size_t i = 0; i < freqs.size(); ++i) {
    const auto direct = m.creep_coefficients_direct(freqs[i]);
    EXPECT_LT((f[i] - direct).norm(), 1e-9 * direct.norm()) << freqs[i] << " Hz";
  }
}

TEST(LinearModel, KrylovMarkovParametersAreTheExactOnesBeforeTheirExtrapolation) {
  // Moment matching: the reduced model after k block steps reproduces h_0 .. h_{k-1} exactly.
  const auto m = model_at({0.001, 0.001, -0.053});
  (void)m.creep_coefficients({0.0});
  const auto h = m.markov_parameters();
  const int k = m.sweep_info().block_steps;
  ASSERT_GT(k, 10);
  // the exact h_j from the time response to a unit impulse in each creepage: F_j = h_j e_c
  for (int c = 0; c < 3; ++c) {
    std::vector<Eigen::Vector3d> xi(k, Eigen::Vector3d::Zero());
    xi[0](c) = 1.0;
    const auto F = m.time_response(xi);
    for (int j = 0; j < k; ++j)
      EXPECT_LT((F[j] - h[j].col(c)).norm(), 1e-10 * h[0].norm()) << "h_" << j << ", column " << c;
  }
}

#include "linalg/cholesky_solve.hpp"

TEST(LinearModel, TallSkinnyKernelsAgreeWithEigen) {
  for (int n : {5, 37, 38, 41, 200}) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
    Eigen::MatrixXd K = A * A.transpose() + n * Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd K_copy = K;
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(K);
    for (int cols : {1, 2, 3, 4, 5, 8}) {
      const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, cols);
      Eigen::MatrixXd X = B;
      linalg::cholesky_solve_in_place(K, X);
      EXPECT_LT((K_copy * X - B).norm(), 1e-12 * B.norm() * K_copy.norm() / n) << n << " x " << cols;
    }
    for (int k : {1, 3, 4}) {  // block sizes: 3 creepage inputs, plus the normal load
      const Eigen::MatrixXd V = Eigen::MatrixXd::Random(n, 11), X = Eigen::MatrixXd::Random(n, k);
      for (int c : {0, 3, 4, 7, 11}) {
        const Eigen::MatrixXd C = linalg::transposed_product(V, c, X);
        EXPECT_LT((C - V.leftCols(c).transpose() * X).norm(), 1e-13 * (1 + C.norm()));
        Eigen::MatrixXd Y = X;
        linalg::subtract_product(V, n, c, C, Y);
        EXPECT_LT((Y - (X - V.leftCols(c) * C)).norm(), 1e-13 * (1 + Y.norm()));
      }
    }
  }
}
