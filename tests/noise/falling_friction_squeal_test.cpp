// The single-mode criterion: one wheel mode on a rigid rail, the NSS contact in full slip with
// falling friction. The instability threshold found by the squeal numerics (route 2 of
// noise/stability.hpp, bisection on the modal damping ratio until Re s crosses 0) equals the
// classical single-mode criterion (nss/falling_friction.hpp, S2)
//   2 zeta w_n m + N mu'(v) psi^2 = 0   (rigid full-slip contact, f_par = N V mu'(v))
// within 1 %. The contact is the full linear NSS model (its elastic correction included, not
// removed): at w -> 0 in full slip it tends to the rigid limit to second order in the scatter of
// the local slip speeds (tests/nss/falling_friction_test.cpp: 0.46 % here), so the mode is put at a
// low frequency against the contact's V/a. The same threshold from the model's own Re f_par at the
// crossing frequency (2 zeta w_n m + Re f_par(w) psi^2 / V = 0, exact for this loop) is checked to
// 1e-6: that one tests the numerics alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../contact/paper_case.hpp"
#include "contact/steady_rolling.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/stability.hpp"
#include "nss/falling_friction.hpp"
#include "nss/linear_model.hpp"

using namespace rollnoise;
using noise::cdouble;

TEST(FallingFrictionSqueal, SingleModeThresholdEqualsTheClassicalCriterion) {
  // the paper's case (block scope: noise_fixture.hpp's kSpeed and kN are another case's)
  using rollnoise::testing::kMu, rollnoise::testing::kN, rollnoise::testing::kSpeed;
  using rollnoise::testing::paper_patch;
  const auto& patch = paper_patch("coarse");
  const contact::Creepage mean{0.0, 0.05, 0.0};  // full slip along y, no spin
  const contact::FallingFriction law{0.5, 2.0};  // A, B (s/m)
  const auto steady = contact::solve_steady_rolling(patch.influence, patch.normal.pn,
                                                    {kMu, kSpeed, mean, 0.0, law});
  const nss::LinearContactModel model(patch, steady, {kMu, kSpeed, 0.0, law});  // midstep sampling
  ASSERT_EQ(model.adhesion_elements(), 0);
  ASSERT_TRUE(model.falling_friction());
  const double radius = model.spectral_radius();
  std::printf("contact spectral radius %.6f\n", radius);
  ASSERT_LT(radius, 1.0);  // the contact alone is stable: the threshold is the mode's

  // One mode along the slip direction (y): modal mass m, shape psi at the contact, 40 Hz.
  const double fn = 40.0, wn = 2.0 * M_PI * fn, m = 1.0, psi = 0.02;
  const Eigen::Matrix2d rigid =
      nss::full_slip_creep_coefficients(kN, kSpeed, mean.xi_x, mean.xi_y, {kMu, law});
  const double zeta_classical = nss::critical_damping_ratio(rigid(1, 1), kSpeed, psi, m, wn);
  ASSERT_GT(zeta_classical, 0.0);

  // The loop: rigid rail (zero receptance), no rigid wheelset, the contact (Hertz spring, (V/s)
  // f^-1).
  noise::LoopMode mode;
  mode.frequency = fn;
  mode.modal_mass = m;
  mode.shape = Eigen::Vector4d(0.0, 0.0, psi, 0.0);
  const double kH = 1e9;  // the normal direction does not couple (g = 0, shape along y)
  noise::LaplaceLoop loop = noise::LaplaceLoop::one_contact({mode}, [&](cdouble s) {
    return Eigen::MatrixXcd(noise::contact_receptance_laplace(
        s, kH, kSpeed, model.creep_coefficients_laplace(s), noise::LoadCoefficients::Zero()));
  });
  auto root = [&](double zeta) {
    loop.modes[0].damping_ratio = zeta;
    const noise::ModeRoot r = noise::mode_root(loop, 0);
    EXPECT_TRUE(r.converged);
    return r;
  };
  double lo = 0.9 * zeta_classical, hi = 1.1 * zeta_classical;  // unstable at lo, stable at hi
  ASSERT_GT(root(lo).s.real(), 0.0);
  ASSERT_LT(root(hi).s.real(), 0.0);
  noise::ModeRoot r;
  for (int it = 0; it < 20; ++it) {  // bracket 0.2 zeta_c / 2^20: 2e-7 relative
    const double mid = 0.5 * (lo + hi);
    r = root(mid);
    (r.s.real() > 0.0 ? lo : hi) = mid;
  }
  const double zeta_threshold = 0.5 * (lo + hi);
  // The exact threshold of this loop with the model's f_par at the crossing frequency w = Im s.
  const double w = r.s.imag();
  const cdouble f22 = model.creep_coefficients_laplace(cdouble(0.0, w))(1, 1);
  const double zeta_model = nss::critical_damping_ratio(f22.real(), kSpeed, psi, m, wn);
  std::printf(
      "threshold zeta: route 2 %.8e, classical (rigid) %.8e (%.3f %%), model Re f_par(%.3f Hz) "
      "%.8e\n",
      zeta_threshold, zeta_classical, 100.0 * (zeta_threshold / zeta_classical - 1.0),
      w / (2 * M_PI), zeta_model);
  EXPECT_NEAR(zeta_threshold, zeta_classical, 0.01 * zeta_classical);
  EXPECT_NEAR(zeta_threshold, zeta_model, 1e-6 * zeta_model);
}
