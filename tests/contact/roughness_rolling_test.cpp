// Unsteady rolling over a rail roughness (contact/transient_rolling.hpp R1,
// contact/roughness_rolling.hpp R2-R3): what holds exactly without the linear model.
//  - a depression uniform over the patch under a prescribed load moves the approach by its depth
//    and leaves the pressure as it was (the gap h + r + A pn - delta only shifts);
//  - the wheel mass rolling into such a depression comes to rest in it at its static load (the
//    dashpot damps the contact resonance): it follows the depression by its depth;
//  - the Newmark scheme (beta = 1/12, gamma = 1/2) follows a free mass under a force quadratic in
//    time exactly at the steps (Numerov's recurrence: fourth order).
// The same-model check against the linear wear transfer over a harmonic roughness is in
// tests/nss/wear_transfer_test.cpp (UnsteadySolverOverARailRoughness...).
#include "contact/roughness_rolling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "contact/steady_rolling.hpp"
#include "paper_case.hpp"

using namespace rollnoise;
using namespace rollnoise::contact;
using namespace rollnoise::testing;

TEST(RoughnessRolling, UniformDepressionUnderAPrescribedLoadMovesTheApproachNotThePressure) {
  const ContactPatch& p = paper_patch("coarse");
  TransientRolling tr(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  tr.set_normal_problem(p.undeformed_distance, p.normal.force);
  const double depth = 3e-6;
  const double delta = tr.normal_approach(p.normal.force, GridField(p.grid.size(), depth));
  EXPECT_NEAR(delta - p.normal.approach, depth, 1e-9 * depth);
  double largest = 0.0, difference = 0.0;
  for (int k = 0; k < p.grid.size(); ++k) {
    largest = std::max(largest, p.normal.pn[k]);
    difference = std::max(difference, std::abs(tr.pressure()[k] - p.normal.pn[k]));
  }
  EXPECT_LT(difference, 1e-9 * largest);
  EXPECT_EQ(tr.approach(), delta);
}

TEST(RoughnessRolling, WheelMassComesToRestInAUniformDepressionAtItsStaticLoad) {
  const ContactPatch& p = paper_patch("coarse");
  const Creepage c{0.001, 0.0, 0.0};
  const TangentialSolution s0 =
      solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, c, 0.0});
  TransientRolling tr(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  tr.set_tractions(s0.px, s0.py);
  tr.set_normal_problem(p.undeformed_distance, p.normal.force);
  const double kN = 1.5e9;  // about the paper case's contact stiffness
  RoughnessRollingInput in;
  in.creepage = c;
  const double depth = 1e-6;
  in.roughness = [&](double) { return depth; };
  in.wheel = {600.0, 2.0 * 0.7 * std::sqrt(kN * 600.0), p.normal.force};  // damping ratio ~0.7
  in.approach = p.normal.approach;
  in.steps = 400;  // ~14 ms: ~3.5 periods of the contact resonance (~250 Hz)
  RoughnessStep last;
  double lowest = p.normal.force;
  roll_over_roughness(tr, p.grid, in, [&](long, const RoughnessStep& r, const TangentialSolution&) {
    last = r;
    lowest = std::min(lowest, r.normal_force);
  });
  // the depression first unloads the contact (by up to k_N times its depth), then the wheel follows
  EXPECT_LT(lowest, p.normal.force - 0.3 * kN * depth);
  EXPECT_NEAR(last.normal_force, p.normal.force, 1e-3 * kN * depth);
  EXPECT_NEAR(last.wheel.z, depth, 1e-3 * depth);
  EXPECT_NEAR(tr.approach() - p.normal.approach, last.wheel.z, 1e-6 * depth);
}

TEST(RoughnessRolling, NewmarkOneTwelfthFollowsAFreeMassUnderAQuadraticForceExactly) {
  // F(t) = F0 + F2 t^2 on m from rest: z(t) = (F0 t^2/2 + F2 t^4/12) / m. With gamma = 1/2 the
  // steps obey Numerov's z_{k+1} - 2 z_k + z_{k-1} = dt^2 (a_{k+1} + 10 a_k + a_{k-1})/12
  // (velocities eliminated), whose local error dt^6 z^(6)/240 vanishes here, and the first step is
  // exact for this z (its error is in the odd powers of t): z exact at every step. The trapezoidal
  // rule (beta = 1/4) would miss by dt^4 z''''/12 per step: 8.7e-4 of z after 50 steps.
  const WheelMass w{600.0, 0.0, 0.0};
  const double dt = 1e-4, F0 = 1e3, F2 = -3e9;
  auto force = [&](double t) { return F0 + F2 * t * t; };
  WheelState s{0.0, 0.0, F0 / w.mass};
  for (int k = 1; k <= 50; ++k) {
    const double t = k * dt;
    s = newmark_step(w, s, dt, -force(t));  // m z'' = N0 - N with N0 = 0, N = -F
    const double z = (F0 * t * t / 2 + F2 * t * t * t * t / 12) / w.mass;
    EXPECT_NEAR(s.z, z, 1e-10 * std::abs(z)) << k;
  }
}
