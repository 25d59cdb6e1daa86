// One wheel's contact state in a curve, as CONTACT module 1 finds it: the wheel on its own rail at
// its axle's lateral displacement u and yaw psi, lowered VERTICALLY under its vertical load on the
// curved reference surface of the rail profile (geometry/loaded_contact.hpp, curved_contact.hpp),
// with the creepages of its own contact (docs/noise_loop.md Sec. 7.2). Returned as one immutable
// value; a bogie is a list of them (bogie_wheel_contacts in curve_state.hpp).
//
// Wheels: leading/trailing axle x outer/inner rail. The outer wheel is the geometry layer's right
// wheel (track y towards the outer rail); the inner wheel is its LEFT wheel, whose contact is
// computed in the mirror image y -> -y (geometry/wheel_rail.hpp): its contact point, angle,
// profile coordinates, creepages and contact-frame forces read exactly like an outer wheel's (y_c
// towards ITS field side, i.e. away from the outer rail). In that frame the inner wheel sees the
// yaw -psi and the curvature -1/R (the curve turns towards its field side).
//
// Kinematic creepages of one wheel (K2 of docs/noise_loop.md with the actual contact), in the
// wheel's own (mirrored for the inner wheel) contact frame, body 1 = the wheel:
//
//   xi_x = kappa y_c - (r_c - r_other) / (2 r0),  xi_y = -psi_s / cos(gamma),
//   phi  = -sin(gamma) / r_c - kappa cos(gamma)                                             (K2')
//
// kappa = +1/R for an outer, -1/R for an inner wheel; psi_s = +psi (outer), -psi (inner); y_c the
// contact point's lateral distance from the track centre line (this side's frame, so > 0), r_c its
// rolling radius, r_other the rolling radius of the other wheel of the same axle at (u, psi), r0
// the nominal radius, gamma the contact angle. With y_c = l0 and r_other from the same axle this
// is the (K2) of curving.hpp; the inner wheel has -xi_x of the outer at a symmetric position.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/material.hpp"
#include "geometry/loaded_contact.hpp"
#include "geometry/wheel_rail.hpp"
#include "noise/loop.hpp"

namespace rollnoise::noise {

enum class WheelId { leading_outer, leading_inner, trailing_outer, trailing_inner };

/// "leading_outer", "leading_inner", "trailing_outer", "trailing_inner".
const char* wheel_name(WheelId w);
/// The wheel of a name; empty for an unknown name.
std::optional<WheelId> wheel_from_name(const std::string& name);
inline bool is_outer(WheelId w) {
  return w == WheelId::leading_outer || w == WheelId::trailing_outer;
}
inline bool is_leading(WheelId w) {
  return w == WheelId::leading_outer || w == WheelId::leading_inner;
}
constexpr std::array<WheelId, 4> kAllWheels = {WheelId::leading_outer, WheelId::leading_inner,
                                               WheelId::trailing_outer, WheelId::trailing_inner};

struct WheelContactInput {
  std::shared_ptr<const geometry::WheelRailPair> pair;  ///< required
  contact::Material material;
  geometry::GridOptions grid;   ///< of the patch
  int lowering_nx = 24;         ///< elements in x (at most) of the lowering (curve_state.hpp)
  /// The lowering's fixed-point tolerance (VerticalLoadInput::settle).
  double lowering_settle = 1e-5;
  /// Every small-gap region in the patch (VerticalLoadInput::gap_regions).
  bool gap_regions = false;
  double inverse_radius = 0.0;  ///< 1/R (1/m), 0 on tangent track
  double speed = 0.0;           ///< V (m/s)
  double friction = 0.3;        ///< mu
  double spin_offset = 0.0;     ///< of the steady rolling solution
  WheelId wheel = WheelId::leading_outer;
  double lateral = 0.0;        ///< u (m) of the wheel's axle, towards the outer rail
  double yaw = 0.0;            ///< psi (rad) of the wheel's axle, turning towards the outer rail
  double vertical_load = 0.0;  ///< the wheel's vertical load (N), > 0
  /// epsilon: the axle turns at (1 + epsilon) V / r0 (a free-rolling axle's rolling speed, an
  /// unknown of the bogie's equilibrium, vehicle/bogie_equilibrium.hpp). Then the wheel's
  /// creepages refer to that speed, not to the mean rolling radius of (K2'):
  ///   xi_x = kappa y_c + 1 - (1 + epsilon) r_c / r0,
  ///   phi = -(1 + epsilon) sin(gamma) / r0 - kappa cos(gamma)
  /// and the rows of the curved patch roll at omega / V = (1 + epsilon) / r0 (C4), so that the
  /// creepage field does not jump with the contact point across a contact jump. Empty: (K2').
  std::optional<double> axle_spin;
  /// (xi_x, xi_y, phi) in the wheel's own contact frame (multibody input); empty: (K2').
  std::optional<Eigen::Vector3d> creepage;
  /// This wheel's lowered contact at a nearby state to start from, its grid kept
  /// (VerticalLoadInput::start); empty: from the Hertz estimate.
  std::shared_ptr<const geometry::LoadedContact> start;
  /// Keep the tangential solver's factors for states started from this one
  /// (VerticalLoadInput::keep_factors).
  bool keep_factors = false;
};

struct WheelContact {
  WheelId wheel = WheelId::leading_outer;
  double lateral = 0.0, yaw = 0.0;    ///< u (m), psi (rad) of the axle
  geometry::ContactGeometry contact;  ///< this side's frame (mirrored for the inner wheel)
  double other_rolling_radius = 0.0;  ///< r_other (m): the other wheel of the axle
  Eigen::Vector3d creepage = Eigen::Vector3d::Zero();  ///< (xi_x, xi_y, phi), this side's frame
  bool creepage_given = false;                         ///< multibody creepages, not (K2')
  double vertical_load = 0.0;                          ///< Q_w (N)
  /// The patch lowered under Q_w on the curved surface: N, creep forces, force_track (this side).
  std::shared_ptr<const geometry::LoadedContact> loaded;

  double normal_force() const { return loaded->normal_force; }
  /// The resultant on the wheel in the track frame: (longitudinal, lateral towards the OUTER
  /// rail, up) (N); for the inner wheel the mirrored lateral component changes sign.
  std::array<double, 3> force_track() const;
  /// The loop's contact position (wheel profile coordinate, rail profile coordinate, angle).
  ContactPosition position() const {
    return {contact.wheel_s, contact.rail_y, contact.contact_angle};
  }
};

/// (K2') at the contact `c` of one side: kappa = +-1/R of that side, r0 the nominal radius.
Eigen::Vector3d kinematic_creepage(const geometry::ContactGeometry& c, double other_rolling_radius,
                                   double nominal_radius, double kappa);

/// The lowering's input for the wheel `in` (material, grid with at most in.lowering_nx elements in
/// x, friction, speed, spin offset) at the creepages (xi_x, xi_y, phi) and vertical load (N);
/// planar.
geometry::VerticalLoadInput vertical_load_input(const WheelContactInput& in,
                                                const Eigen::Vector3d& creepage,
                                                double vertical_load);

/// The wheel's contact: contact point of its side at (u, psi), creepages, the patch lowered
/// under its vertical load. InputError naming curve.wheels for an input outside the model.
WheelContact wheel_contact(const WheelContactInput& in);

}  // namespace rollnoise::noise
