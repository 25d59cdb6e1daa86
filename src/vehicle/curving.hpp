// A quasi-static estimate of the mean creepages and the contact position of the leading outer
// wheel of a two-axle bogie in a curve (docs/noise_loop.md Sec. 6).
//
// Model: the classical quasi-static curving analysis of a rigid two-axle bogie (Boocock, J. Mech.
// Eng. Sci. 11, 1969; Elkins & Gostling, 5th IAVSD Symposium 1977; Wickens, Fundamentals of Rail
// Vehicle Dynamics, 2003, chapter on curving; Iwnicki (ed.), Handbook of Railway Vehicle Dynamics,
// 2006, chapter on curving), reduced to what the noise loop needs:
//
//  * Frame: x forward, z up, y lateral towards the OUTER rail (the curve turns towards -y; for the
//    right-handed frame y is to the left, so the curve is a right-hand one and the yaw rate is
//    -V/R). Axles at x = +a (leading) and -a (trailing), 2a the wheelbase; y_i the lateral
//    displacement of axle i from the local track centre line; contact points at y = +-l0.
//  * The bogie frame is rigid (no yaw flexibility between axles and frame) and free in yaw (no
//    yaw moment from the car body). Its yaw relative to the tangent at its centre is
//    theta = (y1 - y2)/(2a); the angles of attack relative to the local radial are
//      psi_1 = theta + a/R,   psi_2 = theta - a/R                                              (K1)
//    (psi > 0: the axle points outwards; a bogie with both axles at the same y has psi_1 = a/R,
//    the "yaw angle ~ wheelbase/(2R)").
//  * Kinematic creepages of axle i (steady state, small angles; Wickens 2003), outer wheel:
//      xi_x = l0/R - Delta_r(y_i)/(2 r0),  xi_y = -psi_i / cos(gamma),
//      phi  = -sin(gamma)/r_c - cos(gamma)/R                                                   (K2)
//    with the rolling-radius difference Delta_r = r_outer - r_inner (2 lambda y for a conical tread
//    of conicity lambda), r_c the rolling radius at the contact, gamma the contact angle (normal
//    tilted towards the track centre, the sign convention of loop.hpp). The inner wheel has
//    -xi_x and the same xi_y. phi is the component along the contact normal of the wheel's rolling
//    (V/r_c about the axle) and curving (-V/R about z) angular velocities, divided by V.
//  * Creep forces on the wheels: Kalker's linear law F = -f xi (f11, f22; spin neglected in the
//    equilibrium) with the cubic saturation of Johnson & Vermeulen (1964) / Shen, Hedrick & Elkins
//    (1983) on the combined force: |F| = mu Q (u - u^2/3 + u^3/27) for u = |f xi|/(mu Q) < 3, else
//    mu Q (equal wheel loads Q).
//  * Equilibrium of the bogie (lateral force, yaw moment about its centre) with the unbalanced
//    lateral force F_u = 4 Q h_d / (2 l0) of the cant deficiency h_d (positive outwards):
//      sum_i C_i psi_i + Y_1 + Y_2 + F_u = 0
//      sum_i l0 f11 S_i xi_x,i + a (C_1 psi_1 - C_2 psi_2) + a (Y_1 - Y_2) = 0                 (K3)
//    (S_i, C_i = f22 S_i the secant creep stiffnesses of the two wheels of axle i, Y_i the flange
//    forces on axle i, which vanish unless |y_i| = y_f, the flangeway clearance; a flange force
//    can only push the axle away from the rail it touches). Solved by enumerating the flange
//    contacts (fewest first; for each, the lateral equation fixes the flange force or the bogie
//    yaw and the yaw equation is one scalar equation in the free displacement, solved by
//    bisection) and a relaxed fixed-point iteration on the saturation. Where a tabulated
//    Delta_r(y) jumps (the contact jumping across the profile), the axle may settle on the jump:
//    a two-point contact whose effective rolling-radius difference lies within the jump.
//
//  * Load transfer by the cant deficiency (quasi-static, rigid vehicle; the lateral unbalanced
//    force m g h_d / s at the centre of gravity, height h_cg above the rails, balanced by the
//    moment of the wheel-load differences over the contact-point distance s = 2 l0):
//      dQ / Q = 2 h_d h_cg / s^2                                                             (K4)
//    (the caller computes dQ, BogieCurvingInput::load_transfer); outer wheels Q + dQ, inner Q - dQ.
//  * Per-wheel creep law: f11, f22 of wheel w scale as (Q_w/Q)^(2/3) (Hertz: a, b ~ N^(1/3) at
//    fixed curvatures, Johnson 1985 Eqs. 4.39-4.41, so c^2 = ab ~ N^(2/3)), and its force saturates
//    at mu Q_w, Q_w the vertical load of its tread contact                                  (K5)
//  * Two-point contact: a flanging wheel's flange force Y (the lateral force of the flange on the
//    axle) is carried by a flange contact at the flange angle delta_f with normal force N_f and
//    friction mu_f N_f acting on the wheel up the flange slope (Nadal's assumption: the flange
//    contact leads the axle of a wheelset with a positive angle of attack and slides downwards on
//    the rail, Nadal 1908; Iwnicki 2006, chapter on derailment):
//      |Y| = N_f (sin delta_f - mu_f cos delta_f),   Q_f = N_f (cos delta_f + mu_f sin delta_f)
//      (K6)
//    and the wheel's tread contact carries Q_w - Q_f (used in (K5), iterated with the saturation).
//  * Gravitational stiffness: the normal load of each tread contact leans with its contact angle,
//    so axle i at y_i adds the lateral force (towards the track centre for a restoring profile)
//      G_i = -(Q_o tan gamma_o(y_i) - Q_in tan gamma_in(y_i))                                 (K7)
//    (Q tan gamma: the normal force's lateral part when the vertical load is Q; Wickens 2003,
//    chapter on the wheelset on track) to the lateral equation of (K3) and a (G_1 - G_2) to the
//    yaw equation; gamma_in(y) = gamma_o(-y) for symmetric profiles. Without it the balance is
//    homogeneous in the creep forces: with saturated creep forces (all scale with mu) and no
//    cant deficiency, the position and the creepages could not depend on friction. With profiles
//    near the flange root (gamma_o ~ 0.5 rad) it carries much of the guidance; with a conical
//    tread it is 2 dQ lambda.
//
// Limits of validity: steady curving of a rigid two-axle bogie; radii from about 150 m (small
// angles, linear kinematics) to tangent track; tread contact (a flange contact enters as the
// lateral stop y_f and, with delta_f, with its vertical share (K6); the creepages are those of
// the tread contact; the flange contact's own creepages, with its large rolling radius, are not
// estimated); conical tread unless Delta_r(y) is given (or profiles, ProfileCurvingTable); no
// spin in the force balance, no suspension yaw stiffness, no
// traction or braking; one pair f11, f22 (scaled per wheel by its load) for all wheels. It gives
// magnitudes and signs, not a multibody simulation.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "noise/loop.hpp"

namespace rollnoise::geometry {
class WheelRailPair;
}

namespace rollnoise::noise {

/// The contact geometry of a wheelset on its track against its lateral displacement, from the
/// profiles (geometry::find_contact for both wheels): the outer wheel is the geometry layer's
/// right wheel, and y = u (towards its flange) is the lateral displacement of curving.hpp.
struct ProfileCurvingTable {
  std::vector<double> lateral;                    ///< y = u (m), increasing
  std::vector<double> rolling_radius_difference;  ///< r_outer - r_inner (m)
  std::vector<double> contact_angle;              ///< of the outer wheel (rad)
  std::vector<double> rolling_radius;             ///< of the outer wheel (m)
  std::vector<double>
      wheel_position;  ///< wheel profile coordinate s of the contact (m), field side > 0
  std::vector<double>
      rail_position;  ///< rail profile coordinate of the contact (m), field side > 0
  /// The largest tabulated y before the outer wheel's contact jumps to the flange (contact angle
  /// above the threshold of profile_curving_table): the flangeway clearance of the profiles (m).
  double flange_clearance = 0.0;
  /// Contact angle (rad) of the outer wheel's contact at the first tabulated y beyond the flange
  /// clearance: the flange angle delta_f of a flange contact at the clearance.
  double flange_angle = 0.0;

  /// Linear interpolation of a column at y (clamped to the table).
  double at(const std::vector<double>& column, double y) const;
};

/// Tabulates the geometry for y in [-max_lateral, max_lateral] in steps of `step`; the flange
/// clearance is the last y > 0 whose contact angle stays below `flange_angle` (rad).
/// std::domain_error when the centred wheelset's contact is on the flange already (no flangeway
/// clearance: the profile pair is outside the estimate; the pipeline names the profile keys).
ProfileCurvingTable profile_curving_table(const geometry::WheelRailPair& pair,
                                          double max_lateral = 0.010, double step = 0.1e-3,
                                          double flange_angle = 0.6);

struct BogieCurvingInput {
  double radius = 0.0;           ///< R (m); +infinity for tangent track
  double speed = 0.0;            ///< V (m/s); only for the yaw rate (informational)
  double cant_deficiency = 0.0;  ///< h_d (m), positive when the unbalanced force points outwards
  double wheelbase = 2.5;        ///< 2a (m)
  double wheel_radius = 0.46;    ///< r0 (m), nominal rolling radius
  double track_gauge = 1.435;    ///< (m)
  /// l0 (m), half the distance between the nominal contact points; 0: (gauge + 0.065)/2 = 0.75 m
  /// (running circles 32.5 mm outside the gauge points).
  double contact_half_distance = 0.0;
  double conicity = 0.15;  ///< lambda of the conical tread (used when no Delta_r(y) given)
  /// Optional rolling-radius difference Delta_r(y) = r_outer - r_inner (m) of the wheelset at
  /// lateral displacement y (m), e.g. from the profiles; odd in y.
  std::function<double(double)> rolling_radius_difference;
  /// Contact angle at the tread contact of the outer wheel (rad); NaN: atan(conicity).
  double contact_angle = std::numeric_limits<double>::quiet_NaN();
  double flange_clearance = 0.005;  ///< y_f (m): lateral play from the centred position
  double wheel_load = 50e3;         ///< Q (N) per wheel
  double friction = 0.3;            ///< mu
  double f11 = 0.0;                 ///< Kalker's f11 = G c^2 C11 of one wheel (N), > 0
  double f22 = 0.0;                 ///< f22 = G c^2 C22 (N), > 0
  bool saturation = true;           ///< cubic creep-force saturation (false: linear creep law)
  /// Optional profile geometry. When set it replaces the conical tread: Delta_r(y), the contact
  /// angle, the rolling radius and the contact positions on wheel and rail come from the table,
  /// and the flange clearance is the table's (rolling_radius_difference, contact_angle and
  /// flange_clearance above are ignored).
  std::shared_ptr<const ProfileCurvingTable> profiles;
  /// Load transfer dQ (N) by the cant deficiency (K4): the outer wheels carry Q + dQ, the inner
  /// ones Q - dQ. Each wheel's creep coefficients scale as (Q_w / Q)^(2/3) and its creep force
  /// saturates at mu Q_w (K5); f11, f22 above are those of a wheel carrying Q.
  double load_transfer = 0.0;
  /// Flange angle delta_f (rad) of the flange contact of a flanging wheel: the flange force Y then
  /// also takes the vertical share Q_f of (K6) from that wheel's tread contact (two-point contact).
  /// NaN: the profile table's flange_angle with profiles, else no vertical share (the flange is a
  /// lateral stop only).
  double flange_angle = std::numeric_limits<double>::quiet_NaN();
  double flange_friction = std::numeric_limits<double>::quiet_NaN();  ///< mu_f; NaN: friction
  /// Include the lateral components of the wheels' normal loads (K7) in the balance.
  bool gravitational_stiffness = true;

  double half_distance() const;
  /// The fields lie within the model (the contract of estimate_bogie_curving; user input is checked
  /// with its case keys by pipeline::check_bogie_curving_input).
  bool valid() const;
};

struct AxleCurving {
  double lateral = 0.0;       ///< y_i (m), towards the outer rail
  double attack_angle = 0.0;  ///< psi_i (rad), (K1)
  double flange_force = 0.0;  ///< Y_i (N): lateral force of a flange on the axle (< 0 outer flange)
  int flange = 0;             ///< 0 none, +1 outer flange, -1 inner flange
  double flange_normal_force = 0.0;   ///< N_f (N) of the flange contact (K6), 0 without
  double flange_vertical_load = 0.0;  ///< Q_f (N) carried by the flange contact (K6)
  /// Vertical loads (N) of the tread contacts of the outer and inner wheel: Q +- dQ, less Q_f on
  /// the flanging wheel.
  double tread_load_outer = 0.0, tread_load_inner = 0.0;
  double xi_x_outer = 0.0;  ///< xi_x of the outer wheel (K2)
};

struct CurvingEstimate {
  AxleCurving leading, trailing;
  double bogie_yaw = 0.0;         ///< theta (rad)
  double unbalanced_force = 0.0;  ///< F_u (N) per bogie
  double load_transfer = 0.0;     ///< dQ (N) per wheel, (K4)
  double flange_angle = 0.0;      ///< delta_f (rad) used in (K6); 0 without vertical share
  double yaw_rate = 0.0;          ///< -V/R (rad/s)
  // The leading outer wheel's tread contact, contact frame of loop.hpp:
  double xi_x = 0.0, xi_y = 0.0, phi = 0.0;  ///< creepages (-, -, rad/m)
  double rolling_radius = 0.0;               ///< r_c (m)
  double contact_angle = 0.0;                ///< gamma (rad)
  /// Lateral position of the contact on the wheel relative to the wheel model's reference point
  /// (the nominal running circle) (m): -y1 for the conical tread, the profile coordinate s of the
  /// contact with profiles.
  double contact_shift_on_wheel = 0.0;
  /// Lateral position of the contact on the rail head from the rail's centre line (m): 0 for the
  /// conical tread, the rail profile coordinate with profiles.
  double rail_contact_offset = 0.0;
  int iterations = 0;

  /// (xi_x, xi_y, phi) of the leading outer wheel.
  Eigen::Vector3d creepage() const { return {xi_x, xi_y, phi}; }
  /// The loop's contact position (wheel shift, rail offset, contact angle).
  ContactPosition position() const {
    return {contact_shift_on_wheel, rail_contact_offset, contact_angle};
  }
};

/// Secant factor of the cubic saturation: |F| = mu Q u s(u), s = 1 - u/3 + u^2/27 (u < 3), 1/u
/// (u >= 3), u = |f xi| / (mu Q) (Johnson & Vermeulen 1964; Shen, Hedrick & Elkins 1983).
double saturation_secant_factor(double u);

/// The flange contact of (K6) for an input: its angle delta_f (`flange_angle`, else the profile
/// table's, else 0: no vertical share) and its friction mu_f (`flange_friction`, else `friction`).
struct FlangeFriction {
  double angle = 0.0;     ///< delta_f (rad)
  double friction = 0.0;  ///< mu_f (-)
  /// Nadal's limit (K6): the flange carries a lateral force only while sin delta_f - mu_f cos
  /// delta_f > 0, i.e. mu_f < tan delta_f (Nadal 1908); always true without a flange share.
  bool below_nadal_limit() const;
};
FlangeFriction flange_friction(const BogieCurvingInput& in);

/// The estimate (K1)-(K3). `in` valid() (a contract); std::domain_error when the flange friction
/// reaches Nadal's limit (FlangeFriction::below_nadal_limit; the pipeline checks it first, naming
/// the key: pipeline::check_bogie_curving_input, pipeline::curve_state_input); NumericalError if the
/// saturation iteration does not converge.
CurvingEstimate estimate_bogie_curving(const BogieCurvingInput& in);

}  // namespace rollnoise::noise
