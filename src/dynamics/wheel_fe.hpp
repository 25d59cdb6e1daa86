// The wheel as an axisymmetric finite-element structure (fem/axisymmetric.hpp): its modes for
// n = 0..n_max up to f_max with the bore clamped, each classified by family (axial, radial or
// circumferential, from the whole section's motion: wheel_mode_family.hpp) and nodal circles, and
// its shape (U_r, U_theta, U_z) sampled along the tread and flange surface (docs/models.md
// Sec. 3.4).
//
// The bore is clamped: a rigid axle seat transmits only the n = 0 and n = 1 resultants (force and
// moment) of the bore tractions, so for n >= 2 the clamp is what the wheelset does; the n = 0, 1
// modes, where the axle's own flexibility and the rigid-body motion matter, are those of the
// rigid-wheelset model of today (dynamics/wheel.hpp) and are reported here for information only.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "dynamics/wheel.hpp"
#include "fem/axisymmetric.hpp"
#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

/// The wheel's cross-section: a closed outline in (r, z) (m), z lateral from the taping line,
/// positive towards the field side (the profile coordinate s), with the outline segments (i: point
/// i -> i + 1) of the bore and of the running surface (tread and flange).
struct WheelSection {
  std::vector<Eigen::Vector2d> outline;
  std::vector<int> bore_segments;
  std::vector<int> tread_segments;
};

struct WheelFeOptions {
  fem::IsotropicMaterial material;  ///< steel by default
  double mesh_size = 0.008;         ///< target element size (m)
  int n_max = 10;                   ///< highest number of nodal diameters
  double f_max = 6000.0;            ///< highest natural frequency kept (Hz)
  double tread_spacing = 1e-3;      ///< spacing of the tread samples in s (m)
  /// Threads for the orders n (solver.threads: 0 = one per hardware thread, at most 4). The modes
  /// do not depend on it (bit-identical).
  int threads = 0;
};

enum class ModeFamily { kAxial, kRadial, kCircumferential };
const char* family_name(ModeFamily f);
/// The family of a mode known only on the tread (an imported mode; rows (U_r, U_theta, U_z)): the
/// direction with the largest mean square on the tread. The FE modes are classified by the whole
/// section (section_family, wheel_mode_family.hpp): the tread alone names the one-nodal-circle
/// axial modes, whose rim rocks, radial.
ModeFamily tread_family(const Eigen::MatrixX3d& tread_shape);

/// One mode of order n, mass-normalised (phi^T M phi = 1 with M over the whole wheel): modal mass
/// 1 kg for the shapes as given.
struct WheelFeMode {
  double frequency = 0.0;  ///< Hz
  int n = 0;               ///< nodal diameters
  ModeFamily family = ModeFamily::kAxial;
  int nodal_circles = 0;  ///< -1: unknown (an imported mode)
  /// > 0: this mode's own damping ratio (an imported mode); 0: the case's by family.
  double damping_ratio = 0.0;
  /// (U_r, U_theta, U_z) (m per sqrt(kg)) at the tread samples, one row per sample: the motion is
  /// u_r = U_r cos n theta, u_theta = U_theta sin n theta, u_z = U_z cos n theta.
  Eigen::MatrixX3d tread_shape;
  /// The whole section's shape: (U_r, U_theta, U_z) of node i at 3 i + 0, 1, 2 (mesh of
  /// WheelFeModes), mass-normalised.
  Eigen::VectorXd dofs;
};

struct WheelFeModes {
  fem::QuadraticTriangleMesh mesh;
  std::vector<double> tread_s;     ///< lateral coordinate s (m) of the tread samples, ascending
  std::vector<double> tread_r;     ///< radius (m) of the tread samples
  std::vector<WheelFeMode> modes;  ///< ascending in n, then frequency
  double mass = 0.0;               ///< of the wheel (kg)
};

/// Meshes the section and computes the modes. std::invalid_argument for a section without bore
/// or tread segment or options outside their ranges (a contract: io checks them with their keys).
WheelFeModes wheel_fe_modes(const WheelSection& section, const WheelFeOptions& options);

/// The tread samples of wheel_fe_modes alone (tread_s, tread_r, the same values; no mesh, no
/// modes): what the contact's radius needs (tread_radius_at) before the modes are computed.
WheelFeModes wheel_fe_tread(const WheelSection& section, const WheelFeOptions& options);

/// (U_r, U_theta, U_z) of a mode at lateral position s on the tread (linear interpolation between
/// samples); throws InputError when s is outside the sampled tread.
Eigen::Vector3d tread_shape_at(const WheelFeModes& w, const WheelFeMode& mode, double s);

}  // namespace rollnoise::dynamics

#include "dynamics/wheel_fe_contact.hpp"
