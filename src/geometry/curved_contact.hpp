// A contact patch on a curved reference surface: for a patch that spans a strongly curved part of
// the profiles (flange root to flank, where the contact angle runs from about 0.4 to 1 rad), the
// grid follows the rail profile, as CONTACT's conformal (curved-surface) option does (Vollebregt,
// "Conformal contact: corrections and new results", VSD 56 (2018) 1622-1632; CONTACT user guide,
// module 1, D = 4: grid lines along the arc length of a curved contact reference surface, the
// half-space influence coefficients of the flattened surface).
//
// Grid: x along the track (from the contact point's lead, as undeformed_distance), and s the arc
// length along the rail profile from the contact point (towards the field side). Each grid row
// s has its own rail point R(s), contact angle δ(s) = atan(-dz_rail/dy) and normal n(s) = (0,
// sin δ, cos δ) (track frame, into the rail); its undeformed distance is measured along n(s):
//
//   h(x, s) = g(s) + k(s) (x - x_w(s))^2 / (2 r(s))                                       (C1)
//
// (g(s) the distance from R(s) to the wheel's cross-section along n(s), the rest as in
// undeformed_distance, wheel_rail.hpp, evaluated in the frame of row s). The elastic part is that
// of a half-space on the flattened (x, s) grid.
//
// Vertical load: the wheel is lowered by dz along track z; row s sees the normal approach
// dz cos δ(s):
//
//   e(x, s) = h(x, s) - dz cos δ(s) + (A p)(x, s) >= 0,   p e = 0,                          (C2)
//   Q = sum [pn cos δ(s) + py sin δ(s)] dx ds                                               (C3)
//
// (C2) is solved with the force-prescribed normal solver on h~ = h - dz (cos δ - c0): its
// approach α then equals dz c0 at the fixed point dz = α / c0; c0 is the pressure-weighted mean
// of cos δ, which makes the fixed point's rate small (the approach of a field h~ moves by the
// weighted mean of its change). N = sum pn dx ds is adjusted until (C3) holds.
//
// Creepages: each element gets the rigid slip of the wheel's material at its own place (wheel
// body 1, as the contact solvers; ω the wheel's angular velocity, V the speed, ψ the yaw, 1/R the
// curvature, x_a = x + x_c the lead from the axle):
//
//   ξx(s)    = ξx0 - (ω/V)(r(s) - r_c) + (y(s) - y_c)/R
//   ξs(x, s) = ξy0 + [v_y cos δ(s) - v_z sin δ(s)] - [same at (0, 0)],
//   v_y = -(ω/V) r(s) sin ψ - x_a / R,   v_z = (ω/V) x_a                                     (C4)
//
// with ω/V = 1/r_c; at a flat patch (δ constant) (C4) is the linear form ξx0 - φ s, ξy0 + φ x
// with φ = -sin δ/r_c - cos δ/R (K2 of docs/noise_loop.md Sec. 7), so the curved patch reduces
// to the planar one (test).
#pragma once

#include "geometry/loaded_contact.hpp"

namespace rollnoise::geometry {

/// The wheel lowered under its vertical load on the curved reference surface of the rail
/// profile, (C1)-(C4). `in.rolling.creepage` holds (ξx0, ξy0, ·) at the contact point; in.yaw and
/// in.inverse_radius give (C4). Forces in the result are summed with each row's orientation.
LoadedContact lower_on_curved_surface(const WheelRailPair& pair, const ContactGeometry& c,
                                      const VerticalLoadInput& in);

}  // namespace rollnoise::geometry
