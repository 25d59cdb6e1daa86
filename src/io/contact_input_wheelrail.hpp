// CONTACT module-1 input (wheel-rail contact) for a profile case (`rollnoise contact-input`,
// docs/contact_interop.md Sec. 1): the right wheel of the wheelset on its rail, the case's
// profiles (named by bare file name: CONTACT reads them next to the .inp, where the command copies
// them), the wheelset position (lateral u, yaw psi; roll from rollnoise's equilibrium), the
// vertical load prescribed (N = 1, FZ = contact.normal_force) and the wheelset speeds that give the
// case's longitudinal and lateral mean creepage to first order:
//   VPITCH = -V (1 - xi_x) / r_c         (r_c the rolling radius at rollnoise's contact point),
//   VY     = V (psi + xi_y / cos delta)  (CONTACT: CETA = (psi - VY/V) cos delta = -xi_y).
// CONTACT derives the spin from the contact angle and radius itself; creepage.mean[2] is not
// mapped (the comment lines of the file say so). Steady rolling only.
#pragma once

#include <string>
#include <vector>

#include "noise/wheel_contact.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::io {

/// The module-1 input of a placed profile case `c`; `rail_file`, `wheel_file` the bare names the
/// input gives the profiles. InputError naming the key that cannot be mapped.
std::string module1_input(const pipeline::ContactCase& c, const std::vector<std::string>& comments,
                          const std::string& rail_file, const std::string& wheel_file);

/// The module-1 input of one wheel `w` of a curve's bogie (noise::bogie_wheel_contacts) on the
/// case `c` placed at that wheel's contact (pipeline::placed_contact_at): CONTACT's right wheel
/// (C = 1) in the wheel's own frame (the inner wheels mirrored y -> -y, as rollnoise computes
/// them): Y = the axle's lateral position, YAW, ROLL of that frame, FZ = the wheel's vertical load
/// Q, CURV = -kappa (kappa = +1/R outer, -1/R inner; `inverse_radius` = 1/R; CONTACT's sign, as its
/// C1 run), VPITCH = -2 V/(r_c + r_other) ((K2') creepages) or -V (1 + kappa y_c - xi_x)/r_c
/// (given), VY = V (psi + xi_y / cos delta). InputError naming the key of a state that cannot be
/// mapped.
std::string module1_wheel_input(const pipeline::ContactCase& c, const noise::WheelContact& w,
                                double inverse_radius, const std::vector<std::string>& comments,
                                const std::string& rail_file, const std::string& wheel_file);

}  // namespace rollnoise::io
