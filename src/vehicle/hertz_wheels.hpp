// Every wheel's Hertzian tread contact of a two-axle bogie from the quasi-static curving estimate
// (curving.hpp), for the Hertzian curve cases, which have no profiles (docs/squeal.md Sec. 8.2):
// what squeal per wheelset needs of each wheel, its load, creepages and contact position.
//
// Assumptions (the conical tread of the estimate, the same wheel and rail radii for every wheel):
//  * Load: the tread load Q_w of the estimate (K4, K5: Q +- dQ by the cant deficiency, less a
//    flange share Q_f, none on the conical tread). The case's normal force N_case belongs to the
//    static load Q, so the wheel's normal force is N_w = N_case Q_w / Q (the leading outer wheel of
//    an estimate without load transfer has the case's own contact).
//  * Curvatures: the case's (its a, b), the same at every wheel (one cone, one rail head); so the
//    semi-axes scale as a_w = a (N_w / N_case)^(1/3), b_w likewise (Hertz at fixed curvatures,
//    Johnson 1985 Eqs. 4.39-4.41), and the grid with them (the same elements per semi-axis).
//  * Contact angle: the cone's, gamma (the estimate's), at every wheel, tilted towards the track
//    centre (each wheel in its own frame, the mirrored one for the inner wheel, as
//    noise/wheel_contact.hpp).
//  * Kinematic creepages (K2') of noise/wheel_contact.hpp on the cone, axle i at (y_i, psi_i):
//      outer: xi_x =  l0/R - Delta_r(y_i)/(2 r0), xi_y = -psi_i/cos(gamma),
//             phi = -sin(gamma)/r_o - cos(gamma)/R,   r_o = r0 + Delta_r/2
//      inner: xi_x = -l0/R + Delta_r(y_i)/(2 r0), xi_y = +psi_i/cos(gamma),
//             phi = -sin(gamma)/r_i + cos(gamma)/R,   r_i = r0 - Delta_r/2
//    (the inner wheel's own frame: kappa = -1/R, yaw -psi).
//  * Contact position on the wheel: the running circle shifted by the axle's displacement, -y_i on
//    the outer wheel and +y_i on the inner one (towards its field side, its own frame); on the rail
//    head its centre line.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "noise/wheel_contact.hpp"
#include "vehicle/curving.hpp"

namespace rollnoise::noise {

struct HertzWheel {
  WheelId wheel = WheelId::leading_outer;
  double lateral = 0.0, yaw = 0.0;  ///< y_i (m), psi_i (rad) of its axle
  double vertical_load = 0.0;       ///< Q_w (N) of its tread contact
  double load_ratio = 1.0;          ///< Q_w / Q: N_w = N_case Q_w / Q
  double rolling_radius = 0.0;      ///< r_c (m)
  ContactPosition position;         ///< (shift on the wheel, rail offset, gamma), its own frame
  Eigen::Vector3d creepage = Eigen::Vector3d::Zero();  ///< (xi_x, xi_y, phi), its own frame
  /// a_w / a = b_w / b = (Q_w / Q)^(1/3)
  double semi_axis_ratio() const;
};

/// The wheels `wheels` of the estimate `e` found from `in` (the conical tread: no profile table).
std::vector<HertzWheel> hertz_wheels(const BogieCurvingInput& in, const CurvingEstimate& e,
                                     const std::vector<WheelId>& wheels);

}  // namespace rollnoise::noise
