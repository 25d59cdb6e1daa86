// Every wheel's contact for squeal per wheelset in a Hertzian curve case (contact.geometry =
// "hertz", curve.creepage = "estimate"; docs/squeal.md Sec. 8.2): the bogie curving estimate on the
// conical tread WITH the load transfer of the cant deficiency (K4), each wheel's Hertz state from
// it (vehicle/hertz_wheels.hpp: load Q_w, N_w = N_case Q_w/Q, a and b scaled by (Q_w/Q)^(1/3) at
// the case's curvatures, the grid with them, creepages (K2') in the wheel's own frame) and the
// mean-contact stage on it. When these states are computed (noise.squeal_wheelsets = "on"), the
// top-level single contact of `squeal` is the leading outer wheel's state from the same estimate
// (leading_outer_placement), so that /squeal/* and /squeal/wheels/leading_outer share one contact.
#pragma once

#include <vector>

#include "noise/loop.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/mean_contact.hpp"
#include "pipeline/noise_case.hpp"
#include "vehicle/hertz_wheels.hpp"

namespace rollnoise::pipeline {

/// One wheel's contact for the characteristic equation: where it couples, and its mean contact.
struct SquealWheelContact {
  noise::WheelId wheel = noise::WheelId::leading_outer;
  noise::ContactPosition position;
  MeanContact mean;
  bool second_patch = false;  ///< the flange patch of a two-point contact (noise.second_patch)
};

/// The Hertz states of the wheels `wheels` (default: those of curve.wheels, listed_wheel_ids) for
/// the placed Hertzian case `placed` (the case's own normal force, a, b, grid), from the bogie
/// estimate with the load transfer. InputError naming the curve key as check_bogie_curving_input
/// does.
std::vector<noise::HertzWheel> hertz_curve_wheels(const ContactCase& placed, const NoiseCase& nc);
std::vector<noise::HertzWheel> hertz_curve_wheels(const ContactCase& placed, const NoiseCase& nc,
                                                  const std::vector<noise::WheelId>& wheels);

/// `placed` with the wheel's normal force, semi-axes, grid and creepages (nothing solved).
ContactCase hertz_wheel_case(const ContactCase& placed, const noise::HertzWheel& w);

/// Whether squeal computes per-wheel Hertz states for the case resolve_curve placed as `p`:
/// noise.squeal_wheelsets = "on", a Hertzian case (no profiles) with a curve estimate.
bool has_hertz_wheel_states(const CurvePlacement& p, const NoiseCase& nc);

/// The leading outer wheel's placement from `p` (resolve_curve's, the static wheel load Q): its
/// Hertz state (hertz_wheel_case) and, in the curve setup, the estimate with the load transfer
/// (whose contact position is that wheel's). With curve.cg_height = 0 it is `p` itself (to
/// rounding of the creepages).
CurvePlacement leading_outer_placement(const CurvePlacement& p, const NoiseCase& nc);

/// Each wheel's mean contact (options `o`), as hertz_curve_wheels gives the wheels, `placed` the
/// case resolve_curve placed. `leading_outer`: the leading outer wheel's mean contact when already
/// solved (squeal's top level, leading_outer_placement with the same options): reused, not solved
/// again.
std::vector<SquealWheelContact> hertz_squeal_wheels(const ContactCase& placed, const NoiseCase& nc,
                                                    const MeanContactOptions& o,
                                                    const MeanContact* leading_outer = nullptr);

}  // namespace rollnoise::pipeline
