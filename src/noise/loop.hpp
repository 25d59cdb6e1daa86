// The closed rolling-noise loop per frequency (docs/noise_loop.md; docs/noise_loop.md).
//
// Unknowns: the contact force variation on the wheel in the contact frame, F = (Fz, Fx, Fy, Mz)
// (normal, longitudinal, lateral, spin moment; with a contact angle gamma the frame is the tilted
// contact frame, see below). The wheel's contact point moves by u_w = alpha_w F, the rail's by
// u_r = alpha_r (-F) (the rail carries -F), the contact deforms by Eq. (C1) of
// contact_receptance.hpp, e = u_w - u_r = -alpha_c F - r e_z. Hence
//
//   (alpha_w + alpha_r + alpha_c) F = -r e_z                                                 (L1)
//
// with r the combined (effective) roughness, taken positive for a *depression* of the running
// surfaces (a dip opens the undeformed gap by r; a bump of height h is r = -h). Only |F/r| enters
// band levels, so this sign is a phase convention (the one of docs/noise_loop.md).
// Outputs: F per unit roughness (N/m, N m/m), and the velocities of the wheel's and the rail's
// contact points, v_w = i omega alpha_w F and v_r = i omega alpha_r (-F), in the global frame
// (z, x, y, rot z) (m/s and rad/s per m of roughness).
//
// Geometry (docs/noise_loop.md Sec. 4). The structures are handled as 6x6 receptances at a point,
// order (x, y, z, rot x, rot y, rot z) in the global frame (x forward, y lateral, z up), so that
//  * a lateral shift of the contact point is a rigid lever arm (exact for the rigid wheelset,
//    whose receptance is rebuilt at the contact point from its centre; for the wheel's modal part
//    and the rail, which are only known at their reference point in the 4 contact directions, the
//    missing rotations about x and y are taken as zero - see docs/noise_loop.md), and
//  * a contact angle gamma (rotation of the contact frame about x; gamma > 0 turns the normal
//    towards -y, e.g. towards the track centre for a wheel at +y) projects both onto the contact
//    frame n = (0, -sin g, cos g), t_x = (1, 0, 0), t_y = (0, cos g, sin g), spin about n.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/rail_contact.hpp"
#include "dynamics/rail_model.hpp"
#include "dynamics/receptance.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel.hpp"

namespace rollnoise::noise {

using dynamics::cdouble;
using dynamics::Receptance4;

/// The 6-dof receptance at a point, the lever arm and the contact frame (dynamics/rail_contact.hpp):
///   Receptance6, order (x, y, z, rot x, rot y, rot z); kSixOfFour; embed (4x4 as 6x6);
///   move_point, L(d) alpha L(d)^T, L = [[I, -S(d)], [0, I]], S(d) v = d x v (a force F at P + d
///   is the force F plus the moment d x F at P); contact_frame, the columns (n, t_x, t_y, spin).
using dynamics::contact_frame;
using dynamics::embed;
using dynamics::kSixOfFour;
using dynamics::move_point;
using dynamics::Receptance6;
using Vector4c = Eigen::Matrix<cdouble, 4, 1>;

/// The (z, x, y, rot z) rows and columns of a 6x6 receptance.
Receptance4 reduce(const Receptance6& a);

/// T^T alpha T: the 4x4 receptance in the contact frame (n, x, y, rot n).
Receptance4 to_contact_frame(const Receptance6& a, double contact_angle);

/// Position of the contact point used by the loop.
struct ContactPosition {
  /// Lateral shift (m) of the contact on the wheel from the wheel model's reference point (the
  /// point (0, y_c, -R) of dynamics::RigidWheelset, where the mode shapes are given); negative
  /// towards the flange for a wheel at +y.
  double wheel_shift_y = 0.0;
  /// Lateral offset (m) of the contact on the rail head from the rail's centre line (where
  /// dynamics::RailModel gives its receptance).
  double rail_offset_y = 0.0;
  /// Contact angle gamma (rad), see above.
  double contact_angle = 0.0;
};

/// The rigid wheelset's 6x6 receptance at its centre, -(1/omega^2) diag(1/M, 1/M, 1/M, 1/I_xx,
/// 1/I_yy, 1/I_zz).
Receptance6 wheelset_centre_receptance(const dynamics::RigidWheelset& w, double frequency);

/// The wheel at the shifted contact point: the rigid wheelset moved from its centre to
/// (0, y_c + shift, -R) (exact), plus the modal part moved by (0, shift, 0) with zero modal
/// rotations about x and y (approximate, see docs/noise_loop.md).
Receptance6 wheel_receptance6(const dynamics::WheelModel& wheel, double frequency, double shift_y);

/// The rail's contact point of `position` at the case's place along the rail (RailModel::position).
dynamics::RailContact rail_contact(const dynamics::RailModel& rail, const ContactPosition& position);

/// The rail's 6x6 at the contact point (RailModel::contact_transfers: the beams' centre-line
/// receptance moved by the offset, the waveguide loaded there), one frequency, computed directly.
Receptance6 rail_receptance6(const dynamics::RailModel& rail, double frequency,
                             const ContactPosition& position);

/// The rail's 4x4 in the contact frame at `position`: to_contact_frame of rail_receptance6.
Receptance4 rail_contact_receptance(const dynamics::RailModel& rail, double frequency,
                                    const ContactPosition& position);
/// The same at several frequencies, each computed directly, the setup done once.
std::vector<Receptance4> rail_contact_receptances(const dynamics::RailModel& rail,
                                                  const std::vector<double>& frequencies,
                                                  const ContactPosition& position);

/// T a T^T (T = contact_frame): a contact-frame 4x4 as a global 6x6 at the contact point (rank 4:
/// the rotations about x and t_y are not carried), for the rail's velocities in the loop.
Receptance6 from_contact_frame(const Receptance4& a, double contact_angle);

/// Wheel and rail receptances precomputed at a list of frequencies for one contact position:
/// compute once, then run the loop for as many contact models and roughness spectra as needed.
struct StructuralReceptances {
  std::vector<double> frequency;  ///< Hz
  ContactPosition position;
  std::vector<Receptance6> wheel, rail;                  ///< global 6x6 at the contact point
  std::vector<Receptance4> wheel_contact, rail_contact;  ///< the same in the contact frame
};

StructuralReceptances structural_receptances(const dynamics::WheelModel& wheel,
                                             const dynamics::RailModel& rail,
                                             const ContactPosition& position,
                                             const std::vector<double>& frequencies);

/// The costly, position-independent part of structural_receptances: the wheel's modal receptance
/// at its reference point per frequency. Cases with the same wheel and frequencies share it (a
/// study computes it once, docs/study.md). The rail is evaluated at each contact's position
/// (RailModel::contact_transfers on the whole grid at once).
struct StructureSpectra {
  std::vector<double> frequency;  ///< Hz
  std::vector<Receptance4> wheel_modal;
};
StructureSpectra structure_spectra(const dynamics::WheelModel& wheel,
                                   const std::vector<double>& frequencies);

/// The receptances at `position` from the spectra and the rail model (its contact_transfers at
/// `position` on the spectra's frequencies): the same arithmetic as the overload above.
StructuralReceptances structural_receptances(const dynamics::WheelModel& wheel,
                                             const dynamics::RailModel& rail,
                                             const StructureSpectra& spectra,
                                             const ContactPosition& position);

/// From 4x4 (z, x, y, rot z) receptances at the contact point, e.g. read from files (no lever
/// arm: the shifts in `position` must be zero; the contact angle is applied).
StructuralReceptances structural_receptances(const std::vector<double>& frequencies,
                                             const std::vector<Receptance4>& wheel,
                                             const std::vector<Receptance4>& rail,
                                             double contact_angle = 0.0);

enum class Coupling {
  kFull,          ///< the 4x4 system (L1)
  kVerticalOnly,  ///< normal direction alone: Fz = -r / (alpha_w + alpha_r + alpha_c)_zz
};

struct LoopOptions {
  Coupling coupling = Coupling::kFull;
  cdouble roughness = 1.0;  ///< r in (L1) (m); 1 gives transfer functions per unit roughness
  bool velocities = true;   ///< also compute wheel and rail velocities
};

struct LoopResult {
  std::vector<double> frequency;         ///< Hz
  std::vector<Vector4c> force;           ///< Fz, Fx, Fy, Mz on the wheel, contact frame
  std::vector<Vector4c> wheel_velocity;  ///< global z, x, y, rot z (m/s, rad/s)
  std::vector<Vector4c> rail_velocity;   ///< global z, x, y, rot z (m/s, rad/s)
};

/// Solves (L1) at every frequency of `structures` with the contact receptances `contact` (one per
/// frequency, in the contact frame; for Coupling::kVerticalOnly only their (0, 0) entry is read).
LoopResult solve_loop(const StructuralReceptances& structures,
                      const std::vector<Receptance4>& contact, const LoopOptions& options = {});

/// (L1) at one frequency from contact-frame 4x4 receptances; returns F.
Vector4c solve_contact_forces(const Receptance4& wheel, const Receptance4& rail,
                              const Receptance4& contact, const LoopOptions& options = {});

}  // namespace rollnoise::noise
