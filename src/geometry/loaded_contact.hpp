// One wheel's contact under its vertical wheel load, as CONTACT module 1 finds it with a prescribed
// vertical force (control digit N = 1): the wheelset is lowered VERTICALLY (track z) until the
// vertical force that the contact transmits, normal force and tangential (creep) forces together,
// equals the prescribed wheel load. Returned as one immutable value (docs/geometry.md Sec. 7).
//
// For a contact in one plane at the contact angle δ (contact frame of wheel_rail.hpp: y_c =
// (0, cos δ, -sin δ), z_c = (0, sin δ, cos δ) in the track frame, z down), a vertical lowering dz
// is a normal approach dz cos δ (plus a tangential rigid shift that does not change a steady
// rolling state). The forces on the wheel in the contact frame, (F_x, F_y) from the steady rolling
// solution and the normal force N, give the vertical load on the rail
//
//   Q = N cos δ + F_y sin δ                                                              (V1)
//
// (downwards on the rail, = upwards on the wheel), which CONTACT prints as FZ(TR). The normal force
// solves (V1) for the prescribed Q: N_{k+1} = (Q - F_y(N_k) sin δ) / cos δ, a contraction with
// factor |dF_y/dN| tan δ <= mu tan δ (F_y saturates at mu N), so a few iterations reach 1e-10.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "geometry/wheel_rail.hpp"

namespace rollnoise::geometry {

struct LoadedContact;

struct VerticalLoadInput {
  double vertical_load = 0.0;  ///< Q (N): the wheel's vertical load (FZ(TR) on the rail in CONTACT)
  contact::Material material;
  GridOptions grid;
  /// Friction, speed, creepages (of the wheel, body 1, in this side's contact frame) and the spin
  /// offset of the steady rolling problem.
  contact::SteadyRollingInput rolling;
  double tolerance = 1e-10;  ///< on the relative change of N per iteration
  /// On the curved surface: the fixed point is settled when the vertical force is within
  /// max(tolerance, settle) Q, the lowering changes by less than 10 s of itself and the
  /// pressure-weighted mean cos(delta) by less than s, s = max(settle, 1e-7) (curved_contact.hpp).
  /// The default keeps the forces to about 1e-5; the bogie's equilibrium, which differentiates
  /// them, asks for 1e-9.
  double settle = 1e-5;
  /// On the curved surface: the grid covers every region of the rail profile within 30 mm of the
  /// contact point where the gap is small, not only the one around it, so that the wheel lowered
  /// near a contact jump touches in both (a two-point contact whose load shares follow from the
  /// common vertical lowering, (C2)); false: the region around the contact point.
  bool gap_regions = false;
  int max_iterations = 30;
  /// true: the patch on a curved reference surface (the rail profile; curved_contact.hpp), with
  /// the vertical lowering projected on each row's normal and the creepages of each row; false:
  /// one plane at the contact angle of the contact point.
  bool curved = false;
  /// For the curved surface's local creepages (this side's frame): the wheelset's yaw psi (rad)
  /// and the track curvature 1/R (1/m; > 0 when the curve turns away from this side's field
  /// side, i.e. for the outer wheel).
  double yaw = 0.0;
  double inverse_radius = 0.0;
  /// The wheel's angular velocity over the speed, omega / V (1/m), for the rows' creepages (C4);
  /// 0: 1 / r_c (the contact point's circle rolls at V).
  double rolling_rate = 0.0;
  /// On the curved surface: a solved state of the same wheel a small step away (a Newton
  /// iteration's or a finite difference's neighbour) to start from. Its grid is kept where it lies
  /// on the rail (the same element counts and sizes, the rows at the same rail points, the columns
  /// at the same distances along the track: no row comes or goes, so the forces vary smoothly with
  /// the state), its N, lowering and mean cos(delta) start the fixed point, its pressure and
  /// tractions the solvers, and its tangential solver's factors (if kept) precondition the
  /// first Newton steps. Empty: the grid chosen for the load, the fixed point from the Hertz
  /// estimate.
  std::shared_ptr<const LoadedContact> start;
  /// Keep the tangential solver's factors with the result (LoadedContact::tangential_factors), for
  /// states started from it: (2n)^2 floats for n contact elements.
  bool keep_factors = false;
};

/// The contact of one wheel under its vertical load. Forces are those on the WHEEL.
struct LoadedContact {
  ContactGeometry geometry;  ///< contact point and angle (this side's frame, as find_contact)
  std::shared_ptr<const contact::ContactPatch> patch;  ///< the solved normal problem at N
  contact::TangentialSolution tangential;             ///< steady rolling on the patch
  double vertical_load = 0.0;                          ///< Q (N), as prescribed
  double normal_force = 0.0;                           ///< N (N) along the contact normal
  /// (F_x, F_y, M_z) on the wheel in the contact frame (N, N, N m), F_y along y_c.
  std::array<double, 3> creep_force{};
  /// The resultant on the wheel in this side's track frame: (longitudinal, lateral towards this
  /// side's field side, upwards) (N). F_up = Q by construction (V1).
  std::array<double, 3> force_track{};
  double vertical_approach = 0.0;  ///< dz (m): the vertical lowering under the load
  /// On the curved surface: c0 of the fixed point's last iteration (the pressure-weighted mean
  /// cos(delta), curved_contact.hpp), with which a start from this state continues it.
  double mean_cos = 0.0;
  int iterations = 0;              ///< of the fixed point on N
  bool curved = false;             ///< on a curved reference surface (curved_contact.hpp)
  /// Contact angle of each grid row (rad; all δ for a planar patch), and its range over the rows
  /// that carry pressure.
  std::vector<double> row_angle;
  double angle_min = 0.0, angle_max = 0.0;
  /// The steady tangential solver's last factors (VerticalLoadInput::keep_factors; else null).
  std::shared_ptr<const contact::NewtonFactors> tangential_factors;
};

/// (F_x, F_y, M_z) on the wheel (body 1) from the tractions of a tangential solution (N, N, N m).
std::array<double, 3> integrate_creep_force(const contact::Grid& g,
                                            const contact::TangentialSolution& t);

/// The forces on the wheel in this side's track frame (longitudinal, lateral towards the field
/// side, up) from the contact-frame forces on the wheel (F_x, F_y along y_c, N along the normal,
/// which pushes the wheel away from the rail): F_lat = F_y cos δ - N sin δ, F_up = N cos δ +
/// F_y sin δ (V1).
std::array<double, 3> wheel_force_in_track_frame(double contact_angle, double fx, double fy,
                                                 double normal_force);

/// Lower the wheel onto its rail under the vertical load: the patch at the contact `c` and the
/// steady rolling state, N iterated to (V1) (in.curved: lower_on_curved_surface). Throws
/// NumericalError when N does not settle.
LoadedContact lower_under_vertical_load(const WheelRailPair& pair, const ContactGeometry& c,
                                        const VerticalLoadInput& in);

}  // namespace rollnoise::geometry
