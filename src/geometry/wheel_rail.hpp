// Wheel-rail contact geometry: a wheelset on a track, the contact point of a wheel on its rail, and
// the undeformed distance h(x, y) on a contact grid around it (non-Hertzian contact, paper
// Sec. 3.5).
//
// Frames (docs/geometry.md has the figures in words):
//   Track frame: x along the track in the direction of travel, y lateral to the right, z vertical
//   downwards (right-handed; the frame of Kalker's CONTACT and of SIMPACK). Origin on the track
//   centre line at the height of the rail-profile origin (the top of the rails for UIC60).
//   The profiles (geometry::Profile) are those of the RIGHT wheel and the RIGHT rail: profile y is
//   parallel to track y (towards the field side), profile z to track z. The left wheel and rail are
//   the mirror image in the plane y = 0; the contact of the left wheel is computed in that mirrored
//   frame (y to the left), so that its results read exactly like the right wheel's.
//   Wheelset frame: the axle along y; a point of the wheel profile at lateral coordinate s lies on
//   the circle of radius r(s) = r0 + z_wheel(s) around the axle, at axle coordinate
//   ξ(s) = back_to_back/2 + taping_line_offset + s from the wheelset centre.
//   Contact frame (the grid of contact::solve_patch): x rolling direction (= track x), y_c in the
//   tangent plane at the contact point, pointing to the field side, z_c along the normal into the
//   rail. With the contact angle δ (the inclination of the rail surface at the contact point;
//   positive when the surface falls towards the gauge side, as on the gauge corner and for flange
//   contact): y_c = (0, cos δ, -sin δ), z_c = (0, sin δ, cos δ) in the track frame.
//
// Wheelset position: lateral displacement u (m, along track y: u > 0 moves the right wheel's flange
// towards its rail), yaw ψ (rad, about track z: ψ > 0 turns the wheelset's forward direction
// from x towards +y). The vertical position w and the roll angle φ (about x) follow from the
// condition that both wheels touch their rails (rigid contact, no penetration).
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "contact/grid.hpp"
#include "contact/hertz.hpp"
#include "contact/material.hpp"
#include "contact/patch.hpp"
#include "geometry/profile.hpp"

namespace rollnoise::geometry {

struct TrackParameters {
  double gauge = 1.435;              ///< between the gauge points of the two rails (m)
  double gauge_point_depth = 0.014;  ///< gauge point below the top of the rail (m), EN 13848-1
  /// Rail inclination, tan of the cant angle (-): 1/40. Applied only to a rail profile that is not
  /// already canted (Profile::canted()).
  double rail_inclination = 1.0 / 40.0;
};

struct WheelsetParameters {
  double nominal_radius = 0.46;  ///< rolling radius r0 at the taping line (m)
  double back_to_back = 1.360;   ///< between the flange backs (m), EN 13715 / S1002 wheelsets
  double taping_line_offset =
      0.070;  ///< from the flange back to the taping line = profile origin (m)
};

struct WheelsetPosition {
  double lateral = 0.0;  ///< u (m), along track y
  double yaw = 0.0;      ///< ψ (rad), about track z
};

/// The full rigid-body position of the wheelset (track frame).
struct WheelsetPose {
  double lateral = 0.0;   ///< u (m)
  double vertical = 0.0;  ///< w: z of the wheelset centre (m, downwards)
  double roll = 0.0;      ///< φ (rad), about x: φ > 0 lowers the right wheel
  double yaw = 0.0;       ///< ψ (rad)
  /// The same pose seen in the mirror image y -> -y (the left wheel as a right wheel).
  WheelsetPose mirrored() const { return {-lateral, vertical, -roll, -yaw}; }
};

enum class Side { Right, Left };

/// A point of the wheel surface: the lowest point of the wheel's circle at profile coordinate s
/// as seen along the track (the wheel's silhouette in the y-z plane), in the track frame.
struct WheelPoint {
  double x = 0.0;       ///< longitudinal position (m): the lead of a yawed wheelset
  double y = 0.0;       ///< m
  double z = 0.0;       ///< m, downwards
  double radius = 0.0;  ///< wheel radius r(s) there (m)
  /// y and z components of the unit radial direction e_r (from the axle to the point): moving
  /// along the wheel's circle by x, the point rises by x^2 / (2 r) along -e_r.
  double radial_y = 0.0, radial_z = 1.0;
};

/// A wheel profile and a rail profile placed on the track: the right wheel of the wheelset on the
/// right rail.
class WheelRailPair {
 public:
  /// Throws InputError when the profiles are of the wrong kind or the gauge point is not found.
  WheelRailPair(Profile wheel, Profile rail, const TrackParameters& track = {},
                const WheelsetParameters& wheelset = {});

  const Profile& wheel() const { return wheel_; }
  /// The rail profile as laid in the track (canted), in the profile frame.
  const Profile& rail() const { return rail_; }
  const TrackParameters& track() const { return track_; }
  const WheelsetParameters& wheelset() const { return wheelset_; }

  /// Lateral coordinate of the gauge point on the (canted) rail profile (m).
  double gauge_point() const { return gauge_point_; }
  /// Track y of the rail profile origin (m): gauge/2 - gauge_point().
  double rail_offset() const { return rail_offset_; }
  /// Axle coordinate of the wheel profile origin (the taping line) from the wheelset centre (m).
  double wheel_offset() const { return wheelset_.back_to_back / 2 + wheelset_.taping_line_offset; }

  /// Depth of the rail surface (m) at track y, and its slope dz/dy (-).
  double rail_z(double y) const { return rail_.z(y - rail_offset_); }
  double rail_z(double y, Profile::Cursor& cursor) const { return rail_.z(y - rail_offset_, cursor); }
  double rail_slope(double y) const { return rail_.slope(y - rail_offset_); }
  bool rail_contains(double y) const { return rail_.contains(y - rail_offset_); }

  /// The wheel point at profile coordinate s for the wheelset pose (exact for a body of
  /// revolution: the point of the circle s where the surface normal is perpendicular to x).
  WheelPoint wheel_point(double s, const WheelsetPose& pose) const;

  /// The wheel profile tabulated once at the search step (kSampleStep = 0.1 mm over
  /// [y_min, y_max]): s_k, the radius r(s_k) and its slope r'(s_k). minimum_gap scans it for every
  /// pose, so no spline is evaluated in its inner loop; copies of the pair share the table.
  struct WheelTable {
    std::vector<double> s, radius, slope;
  };
  const WheelTable& wheel_table() const { return *wheel_table_; }

  /// Minimum vertical distance rail - wheel (m, negative = penetration) of the right wheel for the
  /// pose, and the wheel profile coordinate s where it occurs.
  double minimum_gap(const WheelsetPose& pose, double* s_at_minimum = nullptr) const;

  /// The pose in which both wheels touch their rails (vertical position and roll found).
  /// Throws NumericalError if the roll iteration fails.
  WheelsetPose equilibrium(const WheelsetPosition& position) const;

 private:
  Profile wheel_, rail_;
  TrackParameters track_;
  WheelsetParameters wheelset_;
  double gauge_point_ = 0.0;
  double rail_offset_ = 0.0;
  std::shared_ptr<const WheelTable> wheel_table_;
};

struct ContactOptions {
  /// Half-width (m) of the least-squares window for the lateral curvatures at the contact point.
  double curvature_window = 1e-3;
  /// false: the contact point, its angle and rolling radius only (rail_curvature,
  /// wheel_curvature, A and B left at 0), as a profile table needs them.
  bool curvatures = true;
};

/// The contact point of one wheel and the local geometry there. For Side::Left all track
/// quantities are in the mirrored frame (y to the left).
struct ContactGeometry {
  Side side = Side::Right;
  WheelsetPose pose;             ///< of the wheelset (track frame, not mirrored)
  double x = 0.0;                ///< contact point, track frame (m): lead of a yawed wheelset
  double y = 0.0;                ///< m
  double z = 0.0;                ///< m
  double rail_y = 0.0;           ///< lateral coordinate on the rail profile (m)
  double wheel_s = 0.0;          ///< lateral coordinate on the wheel profile (m), S1002's s
  double contact_angle = 0.0;    ///< δ (rad)
  double rolling_radius = 0.0;   ///< r(s) at the contact point (m)
  double rail_curvature = 0.0;   ///< lateral curvature of the rail profile (1/m), > 0 convex crown
  double wheel_curvature = 0.0;  ///< lateral curvature of the wheel profile (1/m), > 0 hollow tread
  /// h ≈ A x^2 + B y^2 at the contact point (1/m): A = cos(δ + φ) / (2 r) (the wheel's circle
  /// is tilted by the roll φ; k(0) of undeformed_distance), B = g''(0)/2 of the lateral
  /// undeformed distance g (least-squares over ContactOptions::curvature_window).
  double A = 0.0;
  double B = 0.0;
  WheelsetPose local_pose;  ///< the pose as seen from this side (mirrored for the left wheel)
};

/// Find the contact point of the wheel on `side` for the wheelset position.
ContactGeometry find_contact(const WheelRailPair& pair, const WheelsetPosition& position,
                             Side side = Side::Right, const ContactOptions& options = {});
/// The same for the wheelset already in its equilibrium pose (`pair.equilibrium(position)`): both
/// sides of one position share it (the roll iteration is most of a contact search).
ContactGeometry find_contact_at_pose(const WheelRailPair& pair, const WheelsetPose& pose, Side side,
                                     const ContactOptions& options = {});

/// Lateral undeformed distance g(y_c) (m) between the wheel and rail cross-sections along the
/// contact normal, at the tangent-plane coordinate y_c (m) from the contact point; a large value
/// (far_distance) where one of the profiles does not reach y_c.
double lateral_gap(const WheelRailPair& pair, const ContactGeometry& c, double y_c);
constexpr double far_distance = 1e-2;

/// Everything about one lateral strip y_c of the contact frame of `c`: the gap g(y_c) along the
/// normal, the wheel radius r and the lead x_w (relative to c.x) of the wheel point of the strip,
/// and the projection factor k of the wheel's longitudinal rise (undeformed_distance below).
struct GapStrip {
  bool found = false;
  double gap = far_distance;
  double radius = 0.0;
  double lead = 0.0;
  double k = 1.0;
};
GapStrip gap_strip(const WheelRailPair& pair, const ContactGeometry& c, double y_c);

/// The undeformed distance on the grid (contact frame, x from the contact point's lead, y_c from
/// the contact point), layout [iy][ix] (contact::GridField):
///   h(x, y) = g(y) + k(y) (x - x_w(y))^2 / (2 r(y)),
/// with g the lateral gap above, r(y) the rolling radius of the wheel point under y, x_w(y) its
/// lead relative to the contact point (0 without yaw) and k(y) the projection on the contact
/// normal of the wheel's rise x^2/(2r) along -e_r: with e_r = (e_y, e_z) in the contact frame and
/// the wheel's lateral slope dz_w/dy_c, k = e_z - e_y dz_w/dy_c; without yaw this is
/// k = cos(δ + φ) + sin(δ + φ) dz_w/dy_c, i.e. cos(δ + φ) at the contact point (Meusnier's
/// theorem for the normal curvature of the rolling circle). The rail is straight along x.
contact::GridField undeformed_distance(const WheelRailPair& pair, const ContactGeometry& c,
                                       const contact::Grid& grid);

struct GridOptions {
  double scale = 1.25;      ///< extent = scale x the Hertz semi-axes (at least)
  double gap_factor = 1.5;  ///< also cover the y-range where g(y) <= gap_factor x Hertz approach
  int nx = 40;              ///< elements in x over the extent
  /// At least this many elements across the lateral Hertz width 2b: dy = min(dx, 2b / n). Square
  /// elements unless the patch is much narrower than long (flange contact).
  int min_elements_across = 16;
  int max_elements = 20000;  ///< cap on nx * ny (dy grows beyond it)
  /// Floor on B / A for the Hertz estimate of a (nearly) conformal contact (B <= 0 is not
  /// Hertzian).
  double min_curvature_ratio = 0.02;
};

/// The Hertz estimate from the curvatures at the contact point (B floored as in GridOptions).
contact::HertzContact hertz_estimate(const ContactGeometry& c, double normal_force,
                                     const contact::Material& material,
                                     const GridOptions& options = {});

/// A grid around the contact point for the load: x in [-scale a, scale a], y covering
/// [-scale b, scale b] and the y-range where g <= gap_factor x approach (Hertz estimates);
/// dx = 2 scale a / nx, dy = min(dx, 2b / min_elements_across).
contact::Grid choose_grid(const WheelRailPair& pair, const ContactGeometry& c, double normal_force,
                          const contact::Material& material, const GridOptions& options = {});

/// The rows of `g` over [y_lo, y_hi] with the element width dy (wider when nx x ny would exceed
/// max_elements), centred on the range.
void cover_rows(contact::Grid& g, double y_lo, double y_hi, double dy, int max_elements);

/// choose_grid + undeformed_distance + contact::solve_patch; when the contact area reaches the
/// border of the grid, the grid is enlarged (scale x 1.5, up to 3 times).
contact::ContactPatch solve_wheel_rail_patch(const WheelRailPair& pair, const ContactGeometry& c,
                                             double normal_force, const contact::Material& material,
                                             GridOptions options = {});

/// Size and shape of a solved patch (elements with pn > 0).
struct PatchShape {
  int elements = 0;
  double area = 0.0;                                          ///< m^2
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;  ///< outer element edges (m)
  double length() const { return x_max - x_min; }             ///< extent in x (m)
  double width() const { return y_max - y_min; }              ///< extent in y (m)
  double peak_pressure = 0.0;                                 ///< Pa
  double force = 0.0;                                         ///< N
  /// Area / (π length width / 4): 1 for an ellipse, 4/π for a rectangle, below 1 for a patch
  /// with re-entrant or tapering sides.
  double ellipse_fill() const { return area / (M_PI * length() * width() / 4.0); }
};
PatchShape patch_shape(const contact::ContactPatch& patch);

/// Extent in x (m) of the contact area in the grid row containing y (0 if none).
double patch_length_at(const contact::ContactPatch& patch, double y);

/// How far the patch is from an ellipse: the largest difference, over the grid rows in contact,
/// between the row's extent in x and that of the ellipse with the patch's extents,
///   L_e(y) = length sqrt(1 - ((y - y_mid) / (width / 2))^2),
/// divided by the length (-). A few hundredths for a Hertzian patch (the discretisation).
double patch_ellipse_deviation(const contact::ContactPatch& patch);

}  // namespace rollnoise::geometry
