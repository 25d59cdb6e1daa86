// Slip-velocity-dependent (falling) friction, per contact element (docs/falling_friction.md, Sec. 1):
//
//   mu(v) = mu_s [ (1 - A) e^{-B v} + A ],   v = |s| the local slip speed (m/s),
//
// the exponential law of Polach (Wear 258, 2005, 992-1000, Eq. 10, there with the creep velocity
// w), used with falling friction in curve-squeal models. mu_s = mu(0) is the static coefficient
// (case key friction.mu), A = mu(inf)/mu_s the kinetic ratio in (0, 1] (friction.kinetic_ratio),
// B >= 0 the decay (s/m, friction.decay). A = 1 or B = 0 is Coulomb's constant mu_s, and every
// solver then takes its constant-friction path unchanged (bit for bit).
//
//   dmu/dv = -mu_s (1 - A) B e^{-B v}  <= 0,  steepest at v = 0:  |mu'(0)| = mu_s (1 - A) B.
//
// The solvers keep the traction bound g = mu_s pn (the adhesion limit, static friction) and scale
// it in slip by ratio(v) = mu(v)/mu_s, so only the slip branch of the element law changes.
#pragma once

#include <cmath>

namespace rollnoise::contact {

/// The falling part of the law: A and B (the defaults are constant friction).
struct FallingFriction {
  double kinetic_ratio = 1.0;  ///< A = mu(inf)/mu_s, in (0, 1]
  double decay = 0.0;          ///< B (s/m), >= 0

  /// Whether mu depends on v at all (else every solver uses Coulomb's constant-friction path).
  bool active() const { return kinetic_ratio != 1.0 && decay != 0.0; }
  /// mu(v)/mu_s = (1 - A) e^{-B v} + A.
  double ratio(double v) const { return (1.0 - kinetic_ratio) * std::exp(-decay * v) + kinetic_ratio; }
  /// d(mu/mu_s)/dv = -(1 - A) B e^{-B v} (s/m).
  double ratio_slope(double v) const { return -(1.0 - kinetic_ratio) * decay * std::exp(-decay * v); }
  /// max_v |d(mu/mu_s)/dv| = (1 - A) B (at v = 0).
  double steepest_ratio_slope() const { return (1.0 - kinetic_ratio) * decay; }
};

/// The whole law mu(v) = mu_s ratio(v).
struct FrictionLaw {
  double mu_s = 0.3;        ///< static friction coefficient mu(0)
  FallingFriction falling;  ///< A, B

  double mu(double v) const { return falling.active() ? mu_s * falling.ratio(v) : mu_s; }
  /// dmu/dv (s/m); 0 for constant friction.
  double slope(double v) const { return falling.active() ? mu_s * falling.ratio_slope(v) : 0.0; }
};

/// Throw InputError (keys friction.kinetic_ratio, friction.decay) unless 0 < A <= 1 and B >= 0,
/// finite. Defined in friction_law.cpp.
void check_falling_friction(const FallingFriction& f);

}  // namespace rollnoise::contact
