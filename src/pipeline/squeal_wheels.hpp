// Squeal per wheelset with all its contacts (docs/squeal.md Sec. 8.2): every wheel of curve.wheels
// with its own contact state (patch, steady rolling, linear model as a ContactTransfer, k_N), the
// two wheels of each wheelset in one characteristic equation (S1) through the rigid wheelset and
// the rails (noise::laplace_loop with the case's rail model, any of them), the roots by
// continuation from every wheel's modes (noise::mode_roots); each root belongs to the wheel with
// the largest modal share (dominant_wheel).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "noise/contact_transfer.hpp"
#include "noise/stability.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/squeal.hpp"

namespace rollnoise::pipeline {

/// One root of a wheelset's loop, with the wheel it belongs to.
struct WheelRoot {
  noise::WheelId wheel = noise::WheelId::leading_outer;  ///< dominant wheel (largest share)
  noise::ModeRoot root;
  double share = 0.0;  ///< that wheel's modal share of the root (0..1)
};

struct WheelsetSqueal {
  std::vector<noise::WheelId> wheels;  ///< of curve.wheels on this wheelset
  /// Second patches among its contacts (noise.second_patch = "coupled": the leading outer wheel's
  /// flange patch of a two-point contact), after the wheels' tread contacts.
  int second_patches = 0;
  std::vector<WheelRoot> roots;
  /// Non-empty: the wheelset was left out, why (a wheel's linearised contact alone is unstable
  /// under falling friction, docs/falling_friction.md Sec. 3).
  std::string skipped;
  long evaluations = 0;
  double seconds = 0.0;
};

/// Per wheelset of curve.wheels (leading, then trailing, those with a wheel in the list): the
/// profile cases' per-wheel curve states, or for a Hertzian case with curve.creepage = "estimate"
/// each wheel's Hertz state from the bogie estimate (pipeline/squeal_hertz_wheels.hpp); empty
/// without a curve state or with noise.squeal_wheelsets = "off". `r` the case's squeal run (its
/// curve, contact); any rail model (beam or waveguide); an unstable contact alone is not an error
/// here: its wheelset is skipped
/// (WheelsetSqueal::skipped).
std::vector<WheelsetSqueal> squeal_wheelsets(const SquealResult& r, const NoiseCase& nc,
                                             const noise::StabilityOptions& options = {});

/// The roots of one wheel over all wheelsets (in frequency order), and every unstable root.
std::vector<WheelRoot> wheel_roots(const std::vector<WheelsetSqueal>& s, noise::WheelId w);
std::vector<WheelRoot> unstable_roots(const std::vector<WheelsetSqueal>& s);

}  // namespace rollnoise::pipeline
