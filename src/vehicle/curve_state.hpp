// The contact state of the leading outer wheel in a curve, from the wheel and rail profiles: ONE
// state (contact point, normal load, creepages, flange contact) that the noise loop runs on
// (docs/noise_loop.md Sec. 7.1).
//
//  1. Wheelset position. Either the quasi-static bogie estimate (curving.hpp) on the profile
//     table, with Kalker's f11, f22 from the Hertz estimate at the leading outer wheel's contact
//     for the static wheel load Q (iterated: contact -> f -> estimate -> contact, until the
//     position settles), the load transfer (K4) and the flange share (K6); or the wheelset's
//     lateral displacement u and yaw psi given (multibody input).
//  2. Contact: geometry::find_contact(pair, {u, psi}) for the outer (= geometry's right) wheel;
//     u and psi of curving.hpp and of the geometry layer have the same sign (u towards the outer
//     flange, psi turning the forward direction towards the outer rail).
//  3. Creepages (unless given): (K2') of wheel_contact.hpp with the actual contact,
//       xi_x = y_c/R - (r_o - r_i)/(2 r0),  xi_y = -psi / cos(gamma),
//       phi  = -sin(gamma)/r_c - cos(gamma)/R
//     r_o, r_i the rolling radii of the outer and inner wheel at (u, psi), gamma and r_c those of
//     the outer contact, r0 the nominal radius, y_c the contact point's lateral distance from the
//     track centre line (the bogie estimate itself uses l0, the centred wheelset's).
//  4. Loads. Vertical load of the outer wheel Q_o = Q + dQ (K4: dQ/Q = 2 h_d h_cg / s^2, s = 2 l0;
//     multibody: the given load, dQ = 0); with the leading axle at its outer flange the flange
//     contact carries Q_f (K6) and the tread contact Q_t = Q_o - Q_f. The normal force of the
//     tread contact follows from its vertical equilibrium with the lateral creep force F_y (on the
//     wheel, contact frame of loop.hpp, whose y axis rises by sin(gamma)):
//       Q_t = N cos(gamma) + F_y sin(gamma)   =>   N = (Q_t - F_y sin(gamma)) / cos(gamma) (K8)
//     F_y from Kalker's f22 scaled to Q_t (K5) with the cubic saturation at mu Q_t (spin
//     neglected, as in the estimate) gave F_y in the estimate; the state itself lowers the wheel
//     vertically under its whole load Q_o (geometry/loaded_contact.hpp, curved_contact.hpp, as
//     CONTACT module 1 with a prescribed vertical force and its curved-surface option): N and F_y
//     from the steady rolling solution of the patch, (K8) = (V1). A patch that wraps onto the
//     flank carries the flank's share: the estimate's flange share is reported, not added.
// The flange contact is reported here; with noise.second_patch = "coupled" it becomes a second
// contact of the wheel in the bogie loop (noise/flange_patch.hpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/material.hpp"
#include "contact/patch.hpp"
#include "geometry/loaded_contact.hpp"
#include "geometry/wheel_rail.hpp"
#include "noise/loop.hpp"
#include "noise/wheel_contact.hpp"
#include "vehicle/curving.hpp"
#include "vehicle/vehicle_parameters.hpp"

namespace rollnoise::noise {

struct CurveStateInput {
  std::shared_ptr<const geometry::WheelRailPair> pair;  ///< required
  contact::Material material;
  geometry::GridOptions grid;  ///< for the Hertz estimate and the patch
  double radius = std::numeric_limits<double>::infinity();  ///< R (m); inf: tangent track
  double speed = 0.0;                                       ///< V (m/s)
  double cant_deficiency = 0.0;  ///< h_d (m), positive when the unbalanced force points outwards
  double wheelbase = 2.5;        ///< 2a (m)
  double cg_height = 1.5;        ///< h_cg (m) above the rails, (K4); 0: no load transfer
  double wheel_load = 0.0;       ///< Q (N): static vertical load per wheel
  double friction = 0.3;         ///< mu, also at the flange
  double spin_offset = 0.0;      ///< of the steady rolling solution (grid.spin_offset)
  /// Elements in x (at most) of the grid on which the wheel is lowered under its load (the
  /// resultant changes by < 0.5 % from 16 to 24 elements in flange-root contact).
  int lowering_nx = 24;
  /// The bogie in equilibrium on the exact contacts (bogie_equilibrium.hpp) instead of the
  /// estimate, with the vehicle's data.
  bool equilibrium = false;
  VehicleParameters vehicle;
  // Multibody input: the wheelset's position (and optionally the creepages) given.
  bool multibody = false;
  double lateral = 0.0;                     ///< u (m)
  double yaw = 0.0;                         ///< psi (rad)
  std::optional<Eigen::Vector3d> creepage;  ///< (xi_x, xi_y, phi); empty: (K2)
  /// Multibody input of the other wheels: the trailing wheelset's u (m) and psi (rad), and per
  /// wheel (indexed by WheelId) its vertical load (N; empty: `static_wheel_load`) and creepages (its own contact frame; empty: (K2')). The leading outer wheel's
  /// load and creepages are `wheel_load` and `creepage` above.
  double trailing_lateral = 0.0, trailing_yaw = 0.0;
  double static_wheel_load = 0.0;  ///< (N) contact.normal_force; 0: wheel_load
  std::array<std::optional<double>, 4> wheel_loads;
  std::array<std::optional<Eigen::Vector3d>, 4> wheel_creepages;
  double table_step = 0.1e-3;               ///< lateral step of the profile table (m)
  /// The profile table of `pair` (profile_curving_table), to share between states; empty: made
  /// here.
  std::shared_ptr<const ProfileCurvingTable> table;

  /// The fields lie within the model (the contract of curve_contact_state; user input is checked
  /// with its case keys by pipeline::check_curve_state_input).
  bool valid() const;
};

/// The solution of the bogie's equilibrium (bogie_equilibrium.hpp).
struct BogieEquilibrium;

struct CurveContactState {
  bool estimated = false;             ///< true: from the bogie estimate; false: multibody input
  CurvingEstimate estimate;           ///< when estimated
  /// The bogie in equilibrium (CurveStateInput::equilibrium): positions, residual, every wheel's
  /// contact state at the solution.
  std::shared_ptr<const BogieEquilibrium> equilibrium;
  int position_iterations = 0;        ///< contact -> f -> estimate iterations
  double lateral = 0.0, yaw = 0.0;    ///< u (m), psi (rad) of the wheelset
  geometry::ContactGeometry contact;  ///< tread contact of the outer wheel
  double inner_rolling_radius = 0.0;  ///< r_i (m)
  /// Kalker's coefficients at the contact for the load Q (N); 0 for the equilibrium (not used)
  double f11 = 0.0, f22 = 0.0;
  double wheel_load = 0.0;            ///< Q (N)
  double load_transfer = 0.0;         ///< dQ (N)
  double tread_load = 0.0;            ///< Q_o (N): the vertical load the patch carries
  double lateral_creep_force = 0.0;   ///< F_y (N) on the wheel, contact frame
  double normal_force = 0.0;          ///< N (N) of the tread contact, (K8) = (V1)
  /// The tread contact lowered vertically under Q_t: patch, steady state, forces (N, F_y above).
  std::shared_ptr<const geometry::LoadedContact> loaded;
  bool two_point = false;             ///< the leading axle at its outer flange
  double flange_angle = 0.0;          ///< delta_f (rad)
  double flange_lateral_force = 0.0;  ///< |Y| (N)
  double flange_normal_force = 0.0;   ///< N_f (N)
  double flange_vertical_load = 0.0;  ///< Q_f (N)
  Eigen::Vector3d creepage = Eigen::Vector3d::Zero();  ///< (xi_x, xi_y, phi) (-, -, 1/m)
  /// The leading outer wheel as a wheel value (contact, creepage and loaded above are its).
  WheelContact wheel;

  /// The loop's contact position: wheel profile coordinate s, rail profile coordinate, angle.
  ContactPosition position() const {
    return {contact.wheel_s, contact.rail_y, contact.contact_angle};
  }
};

/// The multibody key of a wheel's `what` ("wheel_load", "creepage"): wheelset.wheel_load,
/// wheelset.inner_wheel_load, trailing_wheelset.wheel_load, trailing_wheelset.inner_wheel_load.
std::string multibody_key(WheelId id, const std::string& what);

/// Load transfer to the outer wheel (K4): dQ = 2 Q h_d h_cg / s^2 (N).
double cant_deficiency_load_transfer(double wheel_load, double cant_deficiency, double cg_height,
                                     double contact_distance);

/// Vertical load of a flange contact carrying the lateral force |Y| at the flange angle delta
/// with friction mu up the flange (K6): |Y| (cos d + mu sin d) / (sin d - mu cos d) (N).
double flange_vertical_load(double lateral_force, double flange_angle, double mu);

/// The input of wheel `id`'s contact (wheel_contact) at the axle position (u, psi): the profiles,
/// material, grid, curve and friction of `in`; no load or creepage set.
WheelContactInput wheel_input(const CurveStateInput& in, WheelId id, double u, double psi);

/// Steps 1-4 above. `in` valid() (a contract); NumericalError from the estimate.
CurveContactState curve_contact_state(const CurveStateInput& in);

/// Steps 1-2 alone: the estimate's axle positions (CurveContactState::estimate) and the leading
/// outer wheel's rigid contact, with Kalker's coefficients there; no wheel lowered. The errors
/// of curve_contact_state.
CurveContactState estimated_curve_position(const CurveStateInput& in);

/// Every wheel's contact state, in the order of `wheels` (docs/noise_loop.md Sec. 7.2): each wheel
/// on its own rail at its axle's (u, psi) (leading: the state's; trailing: the estimate's trailing
/// axle, or the multibody input), lowered under its vertical load (estimate: Q +- dQ on the
/// outer/inner wheels (K4); multibody: the given loads), creepages (K2') or given. The leading
/// outer wheel is the state's own `wheel` (not recomputed).
std::vector<WheelContact> bogie_wheel_contacts(const CurveStateInput& in,
                                               const CurveContactState& s,
                                               const std::vector<WheelId>& wheels);

/// The patch of the state: geometry::solve_wheel_rail_patch at the contact with the normal force N.
contact::ContactPatch solve_curve_patch(const CurveStateInput& in, const CurveContactState& s);

}  // namespace rollnoise::noise
