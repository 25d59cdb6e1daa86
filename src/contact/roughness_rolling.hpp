// Unsteady rolling over a rail roughness with the wheel as a mass (docs/corrugation.md Sec. 7): the
// time-domain counterpart of the corrugation loop's roughness -> normal load -> wear chain
// (docs/corrugation.md Sec. 4), with the exact normal problem at every step.
//
// Structure. The wheel is a rigid mass m on a rigid rail, held by a dashpot c to the fixed frame
// (the car body's static load N0 through a soft suspension), moving vertically; z is its
// displacement towards the rail from the mean state, so the approach of the contact is
// delta = delta_bar + z (delta_bar that of the mean state, N0 without roughness), and
//   m z'' + c z' = N0 - N(t)                                                              (R2)
// (N the contact force, compressive positive). Its receptance for the loop (noise/loop.hpp L1:
// the displacement up per force up on the wheel) is alpha_w = 1 / (-m w^2 + i w c).
//
// Time integration: Newmark with beta = 1/12, gamma = 1/2 (Fox & Goodwin 1949; e.g. Hughes 2000,
// The Finite Element Method, Sec. 9.1), on the contact solver's own step dt = dx/V:
//   z_{k+1} = z_k + dt v_k + dt^2 ((1/2 - beta) a_k + beta a_{k+1}),
//   v_{k+1} = v_k + dt ((1 - gamma) a_k + gamma a_{k+1}),   m a_{k+1} + c v_{k+1} = N0 - N_{k+1}.
// Without damping it is Numerov's fourth-order scheme: the discrete mass receptance at w dt = theta
// is the continuous one times theta^2 (10 + 2 cos theta) / (48 sin^2(theta/2)) = 1 + theta^4/240
// + ... (1.3e-4 at theta = 0.42, 15 steps per period); the damper's term is integrated to second
// order (the trapezoidal velocity), an error ~ (c w / |m w^2|) theta^2 / 12. Conditionally stable
// for the undamped contact resonance, w_c dt < sqrt(6) (w_c = sqrt(k_N/m): w_c dt ~ 0.06 on the
// paper's case with m = 600 kg).
//
// Each step is implicit in N_{k+1}: with the predictor z*, v* (a_{k+1} = 0 above) the displacement
// is z_{k+1} = z* + s (N0 - c v* - N_{k+1}), s = beta dt^2 / (m + gamma dt c), and the contact
// requires
//   delta(N_{k+1}, r_{k+1}) = delta_bar + z* + s (N0 - c v*) - s N_{k+1}                     (R3)
// with delta(N, r) the approach of the normal problem at the load N on h + r (transient_rolling.hpp
// R1). (R3) is solved by the secant method on N (each iterate a normal solve; the slope
// d delta/dN + s kept from step to step), to |dN| below `load_tolerance` N0; then the tangential
// step with the creepage held.
#pragma once

#include <functional>

#include "contact/transient_rolling.hpp"

namespace rollnoise::contact {

/// The wheel of (R2).
struct WheelMass {
  double mass = 600.0;       ///< m (kg)
  double damping = 0.0;      ///< c (N s/m), the dashpot to the fixed frame
  double static_load = 0.0;  ///< N0 (N)
};

/// The wheel's state at a step: displacement towards the rail from the mean state (m), its
/// velocity and acceleration.
struct WheelState {
  double z = 0.0, v = 0.0, a = 0.0;
};

/// One Newmark step of (R2) for the contact force N at the new time: returns the new state.
WheelState newmark_step(const WheelMass& w, const WheelState& s, double dt, double normal_force);

/// The roughness r(X) (m, positive a depression) along the rail coordinate X (m), uniform across
/// the rail.
using RailRoughness = std::function<double(double)>;

struct RoughnessRollingInput {
  Creepage creepage;              ///< held constant (the tangential structures rigid)
  RailRoughness roughness;        ///< r(X)
  WheelMass wheel;                ///< (R2)
  double approach = 0.0;          ///< delta_bar (m): the approach of the mean state
  long steps = 0;                 ///< steps k = 0 .. steps - 1, step k at t_k = k dt
  double load_tolerance = 1e-11;  ///< on |dN| / N0 in the secant iteration of (R3)
};

/// What a step gives besides the tangential solution.
struct RoughnessStep {
  double normal_force = 0.0;  ///< N_k (N)
  WheelState wheel;           ///< the wheel after the step
  int normal_solves = 0;      ///< normal solves of (R3) at this step
};

using RoughnessStepCallback =
    std::function<void(long, const RoughnessStep&, const TangentialSolution&)>;

/// Steps k = 0 .. steps - 1 of `rolling` (after TransientRolling::set_normal_problem, with the
/// state it holds: e.g. the steady tractions of the mean creepage) over the rail roughness: at
/// step k the element at x of the grid is over X = x + k dx (t_k = k dt), r_k = r(X); the wheel
/// starts at rest in the mean state. `on_step` receives each step. NumericalError when (R3) does
/// not converge in 30 iterations.
void roll_over_roughness(TransientRolling& rolling, const Grid& g, const RoughnessRollingInput& in,
                         const RoughnessStepCallback& on_step);

}  // namespace rollnoise::contact
