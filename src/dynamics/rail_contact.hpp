// A contact point on a structure and the geometry of its receptance there (docs/noise_loop.md
// Sec. 4; docs/models.md Sec. 2.8): the 6-dof receptance at a point, the lever arm of a rigid
// offset and the contact frame. The loop (noise/loop.hpp) and every rail model
// (RailModel::contact_transfers, track.hpp) use them.
//
// A receptance at a point in 6 degrees of freedom has the order (x, y, z, rot x, rot y, rot z) in
// the structure's frame (x forward, y lateral, z up).
//
// Lever arm (rigid offset; Thompson 2009, Sec. 5.2 for the wheel's contact point): with
// L(d) = [[I, -S(d)], [0, I]], S(d) v = d x v, the receptance between the points P_a + d_a and
// P_b + d_b rigidly attached to P_a and P_b is
//
//   alpha' = L(d_a) alpha L(d_b)^T                                                          (G1)
//
// (a force F at P + d is F plus the moment d x F at P); reciprocity is preserved.
//
// Contact frame of a contact angle gamma (rotation about x; gamma > 0 turns the normal towards
// -y): n = (0, -sin g, cos g), t_x = (1, 0, 0), t_y = (0, cos g, sin g), spin about n; the columns
// of T(gamma) (6 x 4). A 6x6 alpha_ab in the contact frames of a and b is T_a^T alpha_ab T_b.  (G2)
#pragma once

#include <Eigen/Core>
#include <utility>

#include "dynamics/receptance.hpp"

namespace rollnoise::dynamics {

/// A receptance at a point in 6 degrees of freedom, order (x, y, z, rot x, rot y, rot z).
using Receptance6 = Eigen::Matrix<cdouble, 6, 6>;

/// Index in a Receptance6 of each Receptance4 entry (z, x, y, rot z).
constexpr int kSixOfFour[4] = {2, 0, 1, 5};

/// A contact point on the rail: where along it, where on its profile and how inclined.
struct RailContact {
  double x = 0.0;              ///< position along the rail (m), from a sleeper (0 over a sleeper)
  double offset_y = 0.0;       ///< lateral offset on the head from the centre line (m)
  double contact_angle = 0.0;  ///< gamma (rad), the contact frame (G2)
};
/// (response point a, load point b).
using RailContactPair = std::pair<RailContact, RailContact>;

/// S(d) of the lever arm (G1): S(d) v = d x v.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& d);

/// The 4x4 (z, x, y, rot z) receptance as a 6x6 with zero rows and columns for rot x, rot y.
Receptance6 embed(const Receptance4& a);

/// (G1) at one point: L(d) alpha L(d)^T.
Receptance6 move_point(const Receptance6& a, const Eigen::Vector3d& d);

/// (G1) between two points: L(d_a) alpha L(d_b)^T.
Receptance6 move_points(const Receptance6& alpha, const Eigen::Vector3d& d_a,
                        const Eigen::Vector3d& d_b);

/// Columns: the contact directions (n, t_x, t_y, spin about n) in the 6-dof order, T(gamma).
Eigen::Matrix<double, 6, 4> contact_frame(double contact_angle);

/// T_a a T_b^T: a receptance between two contacts' frames as a 6x6 at the two points (rank 4:
/// the rotations about x and t_y are not carried).
Receptance6 from_contact_frames(const Receptance4& a, double angle_a, double angle_b);

}  // namespace rollnoise::dynamics
