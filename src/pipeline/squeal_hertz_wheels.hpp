// Every wheel's contact for squeal per wheelset in a Hertzian curve case (contact.geometry =
// "hertz", curve.creepage = "estimate"; docs/squeal.md Sec. 9.3): the bogie curving estimate on the
// conical tread WITH the load transfer of the cant deficiency (K4; the top-level single contact
// keeps the case's normal force), each wheel's Hertz state from it (vehicle/hertz_wheels.hpp: load
// Q_w, N_w = N_case Q_w/Q, a and b scaled by (Q_w/Q)^(1/3) at the case's curvatures, the grid with
// them, creepages (K2') in the wheel's own frame) and the mean-contact stage on it.
#pragma once

#include <vector>

#include "noise/loop.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/contact_case.hpp"
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

/// The Hertz states of the wheels of curve.wheels (listed_wheel_ids) for the placed Hertzian case
/// `placed` (the case's own normal force, a, b, grid). InputError naming the curve key as
/// check_bogie_curving_input does.
std::vector<noise::HertzWheel> hertz_curve_wheels(const ContactCase& placed, const NoiseCase& nc);

/// `placed` with the wheel's normal force, semi-axes, grid and creepages (nothing solved).
ContactCase hertz_wheel_case(const ContactCase& placed, const noise::HertzWheel& w);

/// Each wheel's mean contact (options `o`), as hertz_curve_wheels gives the wheels.
std::vector<SquealWheelContact> hertz_squeal_wheels(const ContactCase& placed, const NoiseCase& nc,
                                                    const MeanContactOptions& o);

}  // namespace rollnoise::pipeline
