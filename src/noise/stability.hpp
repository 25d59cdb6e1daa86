// Linear stability of the closed wheel-rail-contact loop (curve squeal; docs/squeal.md): one path
// for one wheel and for a wheelset or bogie with several contacts (one wheel alone is the loop of
// one contact).
//
// The loop of N contacts (contact_set_loop.hpp, M3) without excitation, A(s) F = 0, has a
// non-trivial F at the zeros of
//
//   det A(s) = 0,   A(s) = W(s) + R(s) + blockdiag(alpha_c,a(s)),   s = sigma + i omega      (S1)
//
// (4N x 4N, each block in its contact's frame; harmonic e^{i omega t} -> e^{s t}, i omega -> s).
// A zero with Re s > 0 is a self-excited (growing) vibration. The parts at complex s:
//  * wheels: the rigid wheelset C_ab / s^2 between any two contacts of one wheelset
//    (contact_set.hpp: rigid_flexibility6 in the contact frames; -C/omega^2 -> C/s^2) plus each
//    wheel's modes, exactly (the analytic continuation of the modal sum):
//      sum_k Psi_k Psi_k^T / (m_k D_k(s)),  D_k(s) = omega_k^2 + 2 zeta_k omega_k s + s^2,
//    Psi_k (4N) the mode's shape at every contact of ITS wheel (the table's amplitudes moved by
//    each contact's lever arm and turned into its frame) and zero at the other wheels' contacts.
//    The wheels have their own (equal) mode tables;
//  * rails: RailModel::laplace_transfers between contacts on one rail (the beams continued as
//    RailModel::receptance_laplace with the hysteretic loss factors k(1 + i eta) as constants, the
//    waveguide's waves at complex omega), zero between the rails;
//  * contacts: contact_receptance_laplace with each contact's f(s), g(s) of its ContactTransfer
//    (contact_transfer.hpp; g only with the normal coupling on).
//
// Route 2 (mode_roots). With R(s) everything but the flexible wheel modes, Psi = [Psi_1 .. Psi_M]
// (4N x M) and Sylvester's determinant identity,
//   det A(s) = det R(s) det(diag(m_j D_j(s)))^{-1} det( diag(m_j D_j(s)) + Psi^T R(s)^{-1} Psi ),
// so the zeros of (S1) are those of the modal form (a dynamic stiffness per mode)
//   H(s) = det R(s) det( diag(m_j D_j(s)) + Psi^T R(s)^{-1} Psi )                            (S2)
// (rows scaled by 1/(m_j omega_j^2); det R removes the poles of R^{-1}). It has no poles at the
// uncoupled modes, unlike det A, which is what makes Newton reliable next to lightly damped
// modes. Which root continues mode k: the homotopy
//   H(s; lambda) = det R(s) det( diag(m_j D_j(s)) + lambda Psi^T R(s)^{-1} Psi ),  lambda: 0 -> 1,
//   (S3)
// has at lambda = 0 exactly the uncoupled roots s0_k = -zeta omega_k + i omega_k sqrt(1 - zeta^2)
// of every wheel; all modes are coupled by the same lambda, so the root paths of different modes
// are paths of one analytic family and do not merge (one root per mode). Each path is followed by
// Euler-Newton continuation: tangent predictor ds/dlambda = -H_lambda/H_s, Newton corrector,
// accepted when the corrector stays within a trust radius (half the distance to the nearest other
// uncoupled root, within [0.1, 5] % of |s0|) and within half the predictor's step, else the step is
// halved. At lambda = 1 the root is a zero of (S1). Newton: the derivative by a central difference
// in the complex plane (h = 1e-6 |s|; H is analytic), then secant updates.
// Modes with the same uncoupled root (the sin/cos partners of a mode table, the same mode of the
// two wheels) form a cluster K of c modes: H has a c-fold root there at lambda = 0, whose c
// branches leave along the eigenvalues of -lambda diag(m_j D_j'(s0))^{-1} (Psi^T R(s0)^{-1} Psi)_KK
// (first order); they start there at lambda = 1e-3, each assigned to the mode with the largest
// component of its eigenvector, and are continued together (the trust radius also keeps each
// branch within half the distance to the others' predictions; Newton and the tangent work on H
// deflated by the other branches, H / prod_j (s - s_j)).
// Contacts that the structures do not couple (e.g. two wheelsets with the rails' transfer off)
// have independent factors of (S1), whose root paths may cross: each such group is continued
// alone.
// Reported: s, Im s/2 pi, the damping ratio -Re s/|s|, unstable = Re s > 0, the residual
// |det M| / prod_i |M_i,:| of the modal matrix M = diag(D_j/omega_j^2) + diag(1/(m_j omega_j^2))
// Psi^T R^{-1} Psi at the root (Hadamard's bound: 0 <= residual <= 1), sigma_min/sigma_max of the
// equilibrated A(s) (both ~0 at a true zero), and which wheel the root belongs to: the null vector
// q of M (the modal amplitudes of the free vibration) gives each wheel's share
// sum_{j in wheel} |q_j|^2 / |q|^2; the root is the wheel's with the largest share (a root of two
// wheels alike, e.g. on tangent track, has shares near 1/2 each).
//
// Route 1 (coupled_eigenvalues), for one contact: the rational (state-space) models of the rail
// and of the contact coupled with the wheel's modal state space; the eigenvalues of the whole (a
// descriptor system, real QZ). See the function.
//
// Files: laplace_loop.cpp (the loop at complex s), mode_roots.cpp (route 2),
// coupled_eigenvalues.cpp (route 1).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/contact_set.hpp"
#include "noise/contact_transfer.hpp"
#include "noise/loop.hpp"

namespace rollnoise::noise {

/// One flexible mode of one wheel with its shape at every contact of the loop.
struct LoopMode {
  double frequency = 0.0;      ///< undamped natural frequency (Hz)
  double damping_ratio = 0.0;  ///< zeta (-)
  double modal_mass = 0.0;     ///< m_k (kg)
  Eigen::VectorXd shape;       ///< Psi_k (4N): (n, x, y, rot n) at each contact, zero off its wheel
  std::string label;
  std::size_t index = 0;  ///< position in the wheel's mode table
  int wheel = 0;          ///< index into LaplaceLoop::wheels
};

/// m_k D_k(s) = m_k (omega_k^2 + 2 zeta_k omega_k s + s^2): the mode's dynamic stiffness at s.
inline cdouble modal_denominator(const LoopMode& m, cdouble s) {
  const double w = dynamics::angular(m.frequency);
  return m.modal_mass * (w * w + 2.0 * m.damping_ratio * w * s + s * s);
}

/// The uncoupled mode's root s0 = -zeta omega + i omega sqrt(1 - zeta^2) (1/s), D_k(s0) = 0.
inline cdouble uncoupled_root(const LoopMode& m) {
  const double w = dynamics::angular(m.frequency), z = m.damping_ratio;
  return {-z * w, w * std::sqrt(1.0 - z * z)};
}

/// (S1) split for (S2): A(s) = rest(s) + sum_k Psi_k Psi_k^T / (m_k D_k(s)).
struct LaplaceLoop {
  std::vector<LoopMode> modes;
  std::vector<std::pair<int, int>> wheels;  ///< (wheelset, side) of each wheel with a contact
  std::vector<int> contact_wheel;           ///< the wheel (index into wheels) of each contact
  /// Rigid wheelsets, rails and contacts (4N x 4N, contact frames).
  std::function<Eigen::MatrixXcd(cdouble s)> rest;
  Eigen::MatrixXcd matrix(cdouble s) const;  ///< A(s) of (S1)
  /// A loop of one contact on one wheel from its parts (e.g. a model system in a test): the
  /// modes' shapes are 4-vectors, `rest` is 4 x 4.
  static LaplaceLoop one_contact(std::vector<LoopMode> modes,
                                 std::function<Eigen::MatrixXcd(cdouble s)> rest);
};

/// One contact's model for squeal: its transfer f(s), g(s) and normal stiffness.
struct SquealContact {
  ContactPoint point;
  const ContactTransfer* transfer = nullptr;  ///< not owned; must outlive the loop
  double normal_stiffness = 0.0;              ///< k_N (N/m)
};

/// The modes of every wheel that has a contact among `points` (all from `wheel`), each with its
/// shape at every contact (the FE wheel's shapes at each contact's position on the tread), and
/// the wheels as LaplaceLoop::wheels, contact_wheel.
struct LoopModes {
  std::vector<LoopMode> modes;
  std::vector<std::pair<int, int>> wheels;
  std::vector<int> contact_wheel;
};
LoopModes loop_modes(const dynamics::WheelModel& wheel, const std::vector<ContactPoint>& points);

/// The rigid wheelsets' flexibility C (4N x 4N, contact frames) of alpha = C / s^2; the cross
/// terms between the contacts of one wheelset with `cross.wheelset`.
Eigen::MatrixXd rigid_flexibility(const dynamics::RigidWheelset& wheelset,
                                  const std::vector<ContactPoint>& points,
                                  const CrossCoupling& cross = {});

/// The loop (S1) of a set of contacts (one or more): every wheel that has a contact gets the modes
/// of `wheel`; `normal_coupling` switches g (C3) on; `cross` selects the cross terms as in the
/// noise loop.
LaplaceLoop laplace_loop(const dynamics::WheelModel& wheel, const dynamics::RailModel& rail,
                         const std::vector<SquealContact>& contacts, double speed,
                         bool normal_coupling, const CrossCoupling& cross = {});

/// The rail at complex s in the contact frame at one `position` as a function of s
/// (RailModel::laplace_transfers at rail_contact(rail, position), to_contact_frame): its setup
/// (the waveguide's basis at the contact) is done once, here; `rail` must outlive it.
std::function<Receptance4(cdouble s)> rail_laplace_at_contact(const dynamics::RailModel& rail,
                                                             const ContactPosition& position);
/// The same at one s (sets up each call).
Receptance4 rail_receptance_laplace(const dynamics::RailModel& rail, cdouble s, const ContactPosition& position);

/// The starts of the c branches of a c-fold root s0 at lambda = lambda1 from the first-order
/// splitting matrix N = diag(m D'(s0))^{-1} Psi^T B_K(s0)^{-1} Psi (route 2, mode_roots.cpp): the
/// eigenvalues nu_i of N give s0 - lambda1 nu_i; branch i goes to the mode with the largest
/// component of its eigenvector (assigned greedily, the most dominant pair first). In the order of
/// N's rows.
std::vector<cdouble> cluster_starts(const Eigen::MatrixXcd& N, cdouble s0, double lambda1);

struct StabilityOptions {
  /// Route 2 searches the roots of the modes with band_min <= frequency <= band_max (Hz); all
  /// modes stay in the wheels' receptance.
  double band_min = 0.0, band_max = 1e300;
  double tolerance = 1e-11;     ///< Newton: |delta s| <= tolerance |s|
  int max_iterations = 8;       ///< Newton iterations per continuation step
  double min_step = 1.0 / 4096; ///< smallest homotopy step in lambda before giving up
  double max_step = 1.0;        ///< largest homotopy step (tests: a fine path as the reference)
};

/// One root of (S1), continued from a wheel mode (route 2).
struct ModeRoot {
  std::size_t mode = 0;  ///< index into LaplaceLoop::modes
  std::string label;
  double natural_frequency = 0.0;  ///< of the uncoupled mode (Hz)
  cdouble s0;                      ///< uncoupled root
  cdouble s;                       ///< coupled root (1/s)
  double frequency = 0.0;          ///< Im s / 2 pi (Hz)
  double damping_ratio = 0.0;      ///< -Re s / |s|
  bool unstable = false;           ///< Re s > 0
  double residual = 0.0;           ///< of (S2) in the modal form at lambda = 1 (see above)
  double singular_ratio = 0.0;     ///< sigma_min / sigma_max of the equilibrated A(s)
  int iterations = 0;              ///< Newton iterations, all continuation steps
  int steps = 0;                   ///< accepted continuation steps
  bool converged = false;
  int wheel = 0;                    ///< the wheel of the mode it continues (LaplaceLoop::wheels)
  std::vector<double> wheel_share;  ///< per wheel, sum of |q_j|^2 over its modes / |q|^2
  int dominant_wheel = 0;           ///< the wheel with the largest share
  double own_share = 0.0;  ///< |q_mode|^2 / |q|^2: the continued mode's share of the root's vector
  /// -1, or the mode whose root this mode's continuation reached as well (distinct_roots): then
  /// converged = false and unstable = false, this mode's own root not found.
  long same_root_as = -1;
  /// true: found by a second, finer continuation after the first reached another mode's root
  /// (mode_roots)
  bool refined = false;
};

/// Each root once: where the continuations of two modes end on the same root (within 1e-7 of |s|),
/// the root belongs to the mode with the larger share of its vector (own_share; the nearer
/// uncoupled root s0 where the shares are equal); the other keeps its label
/// with converged = false, unstable = false and same_root_as = that mode (its own root is not
/// found, its stability not decided). Roots that are not converged are left as they are.
std::vector<ModeRoot> distinct_roots(std::vector<ModeRoot> roots);

/// Route 2 for every mode of the loop in the band, ordered by mode. A mode whose continuation
/// fails is returned with converged = false (and its last root). Each root once (distinct_roots);
/// a mode whose continuation reached another mode's root then has its own searched by Newton from
/// its uncoupled root on (S2) deflated by the roots found near it (refined = true when found;
/// docs/squeal.md Sec. 4.2).
std::vector<ModeRoot> mode_roots(const LaplaceLoop& loop, const StabilityOptions& options = {});
/// Route 2 for mode k alone (with its cluster).
ModeRoot mode_root(const LaplaceLoop& loop, std::size_t k, const StabilityOptions& options = {});

/// A real continuous-time state-space model x' = A x + B u, y = C x + D u.
struct StateSpace {
  Eigen::MatrixXd A, B, C, D;
  int states() const { return static_cast<int>(A.rows()); }
};

/// Route 1: the eigenvalues of the coupled rational model of one contact (docs/squeal.md Sec. 4).
///  * wheel: the rigid wheelset (u'' = C_rig F) and its modes (q_k'' + 2 zeta_k omega_k q_k' +
///    omega_k^2 q_k = psi_k^T F / m_k, u = sum psi_k q_k), contact frame, exact:
///    `rigid_flexibility` (4 x 4) and `modes` (4-vector shapes) of the loop of one contact;
///  * rail: 4 inputs (the force on the rail, -F, contact frame n, x, y, rot n), 4 outputs (its
///    displacement), C_r (sI - A_r)^{-1} B_r + D_r = alpha_r(s);
///  * contact: inputs (xi_x, xi_y, phi, N), outputs (F_x, F_y, M_z),
///    C_c (sI - A_c)^{-1} B_c + D_c = [-f(s) | g(s)] (the `rollnoise statespace` convention), with
///    xi = e_t'/V, N = F_n, and the normal Hertz spring e_n = -F_n / k_H (C1).
/// Unknowns (x_w, x_r, x_c, F): E X' = M X with the algebraic rows of the contact; the finite
/// generalised eigenvalues (real QZ) are returned, infinite ones (|beta| <= 1e-12 |alpha|)
/// dropped. The force unknowns are scaled by k_H and the modal velocities by omega_k so that the
/// pencil is balanced.
std::vector<cdouble> coupled_eigenvalues(const Eigen::MatrixXd& rigid_flexibility,
                                         const std::vector<LoopMode>& modes, const StateSpace& rail,
                                         const StateSpace& contact, double normal_stiffness,
                                         double speed);

}  // namespace rollnoise::noise
