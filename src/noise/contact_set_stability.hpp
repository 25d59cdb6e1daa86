// Squeal of a wheelset (or bogie) with all its contacts (docs/squeal.md Sec. 8): the
// characteristic equation of the loop with several contacts (contact_set_loop.hpp, M3) without
// excitation,
//
//   det A(s) = 0,   A(s) = W(s) + R(s) + blockdiag(alpha_c,a(s)),   s = sigma + i omega      (S6)
//
// (4N x 4N, each block in its contact's frame; (S1) of stability.hpp for N = 1). The parts at
// complex s are those of stability.hpp, per contact and between contacts:
//  * wheels: the rigid wheelset C_ab / s^2 between any two contacts of one wheelset
//    (contact_set.hpp: rigid_flexibility6 in the contact frames) plus each wheel's modes,
//      sum_k Psi_k Psi_k^T / (m_k D_k(s)),  D_k(s) = omega_k^2 + 2 zeta_k omega_k s + s^2,
//    Psi_k (4N) the mode's shape at every contact of ITS wheel (the table's amplitudes moved by
//    each contact's shift and turned into its frame; contact_set.hpp's limitation: one set of
//    amplitudes for all points of a wheel) and zero at the other wheels' contacts. The two wheels
//    of a wheelset have their own (equal) mode tables;
//  * rails: RailModel::laplace_transfers between contacts on one rail (the beams continued as
//    RailModel::receptance_laplace, the waveguide's waves at complex omega), zero between the
//    rails;
//  * contacts: contact_receptance_laplace with each contact's f(s), g(s) (g only with the normal
//    coupling on).
//
// Roots (route 2 of stability.hpp, generalised to 4N): with R(s) everything but the flexible wheel
// modes and Psi = [Psi_1 .. Psi_M] (4N x M), Sylvester's determinant identity gives the modal form
//
//   H(s; lambda) = det R(s) det( diag(m_j D_j(s)) + lambda Psi^T R(s)^{-1} Psi )              (S7)
//
// (rows scaled by 1/(m_j omega_j^2)), whose roots at lambda = 1 are those of (S6); at lambda = 0
// they are the uncoupled modes of BOTH wheels, continued together by the same Euler-Newton homotopy
// as stability.hpp (one analytic family: paths do not merge; modes with one uncoupled root, the
// sin/ cos partners and the same mode of the two wheels, form a cluster started from the
// first-order splitting). Which wheel a root belongs to: the null vector q of the modal matrix of
// (S7) at the root (the modal amplitudes of the free vibration) gives each wheel's share sum_{j in
// wheel} |q_j|^2 / |q|^2; the root is the wheel's with the largest share (a root of two wheels
// alike, e.g. on tangent track, has shares near 1/2 each).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "dynamics/wheel.hpp"
#include "noise/contact_set.hpp"
#include "noise/contact_transfer.hpp"
#include "noise/stability.hpp"

namespace rollnoise::noise {

/// One flexible mode of one wheel with its shape at every contact of the set.
struct ContactSetMode {
  double frequency = 0.0;      ///< undamped natural frequency (Hz)
  double damping_ratio = 0.0;  ///< zeta (-)
  double modal_mass = 0.0;     ///< m_k (kg)
  Eigen::VectorXd shape;       ///< Psi_k (4N): (n, x, y, rot n) at each contact, zero off its wheel
  std::string label;
  std::size_t index = 0;  ///< position in the wheel's mode table
  int wheel = 0;          ///< index into ContactSetLaplaceLoop::wheels
};

/// (S6) split for (S7): A(s) = rest(s) + sum_k Psi_k Psi_k^T / (m_k D_k(s)).
struct ContactSetLaplaceLoop {
  std::vector<ContactSetMode> modes;
  std::vector<std::pair<int, int>> wheels;  ///< (wheelset, side) of each wheel with a contact
  std::vector<int> contact_wheel;           ///< the wheel (index into wheels) of each contact
  /// Rigid wheelsets, rails and contacts (4N x 4N, contact frames).
  std::function<Eigen::MatrixXcd(cdouble s)> rest;
  Eigen::MatrixXcd matrix(cdouble s) const;  ///< A(s) of (S6)
};

/// One contact's model for squeal: its transfer f(s), g(s) and normal stiffness.
struct SquealContact {
  ContactPoint point;
  const ContactTransfer* transfer = nullptr;  ///< not owned; must outlive the loop
  double normal_stiffness = 0.0;              ///< k_N (N/m)
};

/// The loop (S6) of a set of contacts: every wheel that has a contact gets the modes of `wheel`;
/// `normal_coupling` switches g (C3) on; `cross` selects the cross terms as in the noise loop.
ContactSetLaplaceLoop contact_set_laplace_loop(const dynamics::WheelModel& wheel,
                                               const dynamics::RailModel& rail,
                                               const std::vector<SquealContact>& contacts,
                                               double speed, bool normal_coupling,
                                               const CrossCoupling& cross = {});

/// A root of (S6) continued from one wheel's mode.
struct ContactSetRoot {
  ModeRoot root;  ///< as stability.hpp (root.mode indexes ContactSetLaplaceLoop::modes)
  int wheel = 0;  ///< the wheel of the mode it continues
  std::vector<double> wheel_share;  ///< per wheel, sum of |q_j|^2 over its modes / |q|^2
  int dominant_wheel = 0;           ///< the wheel with the largest share
};

/// (S7) for every mode in the band (StabilityOptions as stability.hpp).
std::vector<ContactSetRoot> contact_set_mode_roots(const ContactSetLaplaceLoop& loop,
                                                   const StabilityOptions& options = {});

}  // namespace rollnoise::noise
