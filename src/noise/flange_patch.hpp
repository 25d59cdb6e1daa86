// The flange patch of a two-point contact as a second contact of the flanging wheel
// (docs/noise_loop.md Sec. 7.3). Where the bogie estimate puts the leading axle against its outer
// flange (CurveContactState::two_point: flange force Y != 0, vertical share Q_f of (K6) at the
// flange angle delta_f), the leading outer wheel has, besides its tread patch (the wheel lowered
// under its load, wheel_contact.hpp), a patch on the flange flank. It is returned as a second
// WheelContact of the same wheel:
//
//  * place: the contact point the wheel makes on its flank, geometry::find_contact at the axle's
//    yaw psi and the smallest lateral displacement u_f >= u (steps of 0.01 mm, at most 4 mm) whose
//    contact angle reaches delta_f - 0.1 rad (the profile table's flange contact, seen at psi);
//    its wheel and rail profile coordinates, angle, rolling radius and curvatures are the flank's.
//  * load: the planar patch at that point lowered under the vertical load Q_f (loaded_contact.hpp,
//    (V1): Q_f = N_f cos delta + F_y sin delta), so N_f follows from the creep forces of the
//    flank's own steady state; the tread patch keeps its own lowering (the estimate's flange share
//    is not taken off it: Sec. 7.1 step 5).
//  * creepages: (K2') at the flank point (its rolling radius r_f, lateral position y_f, angle):
//    xi_x = y_f/R - (r_f - r_i)/(2 r0), xi_y = -psi/cos(delta), phi = -sin(delta)/r_f -
//    cos(delta)/R. The flank's larger radius makes xi_x large: the flange patch is in full slip.
#pragma once

#include <optional>

#include "vehicle/curve_state.hpp"
#include "noise/wheel_contact.hpp"

namespace rollnoise::noise {

/// The flange patch of the state's leading outer wheel, or empty when the state is not a
/// two-point contact (no flange force, or no vertical share). NumericalError when the flank point
/// is not found within 4 mm of u or its lowering does not converge.
std::optional<WheelContact> flange_patch_contact(const CurveStateInput& in,
                                                 const CurveContactState& s);

/// The flank point of the wheel on the right (outer) rail at yaw psi: the first contact with an
/// angle >= min_angle for lateral displacements u0 + k 0.01 mm, k = 0..400; empty if none.
std::optional<geometry::ContactGeometry> flank_contact(const geometry::WheelRailPair& pair,
                                                       double u0, double psi, double min_angle);

}  // namespace rollnoise::noise
