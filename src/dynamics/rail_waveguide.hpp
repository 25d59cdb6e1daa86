// The rail as a waveguide: a 2.5D (waveguide, semi-analytical) finite-element model of the
// cross-section, exact along the rail (Gavric, JSV 185, 1995; Gry, JSV 195, 1996; Nilsson, Jones,
// Thompson & Ryue, JSV 321, 2009; Thompson, Railway Noise and Vibration, 2009, Sec. 4.6).
//
// Displacement u(x, y, z, t) = U(y, z) e^{i(omega t - k x)} (rollnoise's e^{i omega t}; d/dx -> -ik
// as in track_beam.hpp), U interpolated by 6-node triangles over the section, three components
// (u_x, u_y, u_z) per node. With the strains e = (e_xx, e_yy, e_zz, g_yz, g_xz, g_xy) and the
// longitudinal component rotated by i, u_x = i u'_x (Gavric 1995, Eq. 10), every strain is a real
// combination of real nodal values times a diagonal phase S = diag(1, 1, 1, 1, i, i):
//
//   e = S (B1 + k B2) U',   B1: (0, du_y/dy, du_z/dz, du_y/dz + du_z/dy, du'_x/dz, du'_x/dy),
//                           B2: (u'_x, 0, 0, 0, -u_z, -u_y) (N-weighted),
//
// and since S^H D S = D for the isotropic D, the strain energy gives the real symmetric
//
//   K(k) = K0 + k K1 + k^2 K2,  K0 = Int B1^T D B1, K1 = Int (B1^T D B2 + B2^T D B1),
//   K2 = Int B2^T D B2,  M = Int rho N^T N,                                                 (W1)
//
// with the material loss factor as D(1 + i eta). A distributed support across the foot's bottom
// (the pad / sleeper / ballast layers of track.hpp, smeared along the rail and over the foot width
// b) adds Ks(omega) = Int_foot N^T N ds diag(K_x, K_y, K_z)(omega) / (L b) to K0 (Eq. 1 of
// track.hpp per rail seat, L the sleeper spacing).
//
// Dispersion: at real k the undamped free rail's det(K(k) - omega^2 M) = 0 is a symmetric
// eigenproblem in omega^2 (W2). Per frequency: the quadratic eigenproblem in k,
//
//   (A2 k^2 + A1 k + A0) phi = 0,  A0 = (1 + i eta) K0 + Ks(omega) - omega^2 M, A1 = (1 + i eta)
//   K1, A2 = (1 + i eta) K2,                                                                (W3)
//
// n = 3 x nodes. K0, K2, M and the support couple no u'_x with (u_y, u_z) and K1 couples only
// those, so Q(-k) = P Q(k) P with P = -1 on the u'_x and +1 elsewhere: the 2n roots come in pairs
// +-k, and with phi = (k v, u_s) (u_s = the (u_y, u_z)) the quadratic problem is linear in k^2,
//
//   [Ax C; 0 As] z + k^2 [Bx 0; C^T Bs] z = 0,  z = (v, u_s),                               (W5)
//
// (Ax, As, Bx, Bs the u'_x and u_s blocks of A0 and A2, C the u'_x-u_s block of A1; substitute
// phi in Q(k) phi = 0 and divide the u'_x rows by k): n x n instead of the 2n x 2n companion form
// [0 I; -A2^{-1}A0 -A2^{-1}A1] (Tisseur & Meerbergen, SIAM Rev. 43, 2001, Sec. 3.4), solved as
// the standard problem B^{-1} A z = -k^2 z. Of each pair the wave travelling or decaying towards
// +x is the root with Im k < 0, for an undamped propagating root the one with positive group
// velocity c_g = Re(phi^H (2k A2 + A1) phi) / (2 omega phi^H M phi) (Nilsson et al. 2009).
//
// Forced response: the Green's function between nodal loads is the inverse Fourier transform of
// Q(k)^{-1} by residues (Q symmetric, simple roots: Res Q^{-1} = phi phi^T / d,
// d = phi^T (2k A2 + A1) phi; contour closed in the lower half plane for x >= 0):
//
//   G'(x) = -i sum_{Im k_j < 0} phi_j phi_j^T e^{-i k_j x} / d_j  (x >= 0),  G'(-x) = P G'(x) P,
//   (W4)
//
// (Gry 1996, Eqs. 23-25; Nilsson et al. 2009, Eq. 20), and in physical variables
// G(x) = T G'(x) T^*, T = diag(i on u_x, 1 elsewhere). Reciprocal by construction:
// G(-x) = G(x)^T.
//
// Reduced model (the cost of Eq. W5 grows as n^3): the section's displacement is restricted to
// a Ritz basis, u'_x = V_x q_x, u_s = V_s q_s, spanned by the free cross-section modes of the
// undamped rail at a few real wavenumbers (Eq. W2, the modes below a cut-off frequency) and the
// static responses to the contact loads, each split into its u'_x and u_s parts and
// orthonormalised per block (Droz, Laine & Inquiete, Compos. Struct. 113, 2014: the waveguide FE
// reduced on cross-section modes; Duhamel, Mace & Brennan, JSV 294, 2006, for the wave
// expansion). The block-diagonal basis keeps the u'_x / u_s structure, so Eqs. (W3)-(W5) hold
// unchanged for the projected matrices V^T K_i V, V^T M V, V^T Ks V; loads and responses are
// projected as V^T f. The basis adds the static responses so that the near field at the load
// (the evanescent waves of high order, dropped with the high modes) keeps its flexibility.
//
// The point receptance (x = 0) without the waves (rail_waveguide_point.cpp): with D = diag(k on
// the u'_x, 1 on the u_s), Eq. (W5)'s substitution phi = D z is Q(k) D = D (A + k^2 B), so
// Q(k)^{-1} = D (Y + k^2)^{-1} B^{-1} D^{-1} with Y = B^{-1} A: its u'_x-u_s blocks carry k or
// 1/k times a function of k^2, are odd in k and integrate to zero over the real k axis, and its
// diagonal blocks are those of (Y + k^2)^{-1} B^{-1}; G'(0) = (1/2 pi) Int Q(k)^{-1} dk with
// Int dk / (k^2 + mu) = pi / sqrt(mu) (Re sqrt(mu) > 0) gives
//
//   G'(0) = blockdiag( 1/2 Y^{-1/2} B^{-1} ),  Y^{-1/2} the principal inverse square root, (W6)
//
// the same roots as Eq. (W4) (k_j = -i sqrt(mu_j), Im k_j < 0, mu_j the eigenvalues of Y), with
// Y^{1/2} from the Schur form Y = U T U^H (no eigenvectors; Higham, Functions of Matrices, SIAM
// 2008, Sec. 6.2). It holds while no mu_j lies on the negative real axis (a real k_j: an
// undamped propagating wave, for which Eq. (W4) takes the group velocity's direction instead).
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "dynamics/receptance.hpp"
#include "dynamics/track.hpp"
#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

/// Isotropic, linear-elastic rail steel.
struct RailMaterial {
  double youngs_modulus = 210e9;  ///< E (Pa)
  double poisson_ratio = 0.3;     ///< nu (-)
  double density = 7850.0;        ///< rho (kg/m^3)
  double loss_factor = 0.02;      ///< eta (-)
};

/// The pad / sleeper / ballast layers under the foot, smeared along the rail (continuous support).
struct FootSupport {
  Support vertical, lateral, longitudinal;
  double sleeper_spacing = 0.6;  ///< L (m)
  /// Discrete supports only (waveguide_discrete_support.hpp): the length along the rail over which
  /// a seat's force is spread evenly (m, 0 <= seat_length < L; 0: at one x, the former model).
  double seat_length = 0.0;
};

/// The waves of one frequency that travel or decay towards +x (Eq. W3), one per generalised
/// coordinate (n of them for the full model, m for a reduced one).
struct RailWaves {
  cdouble omega;
  Eigen::VectorXcd wavenumbers;  ///< k_j (rad/m)
  /// phi_j in the rotated generalised coordinates (q_x, q_s), columns (for the full model the
  /// nodal u'_x = -i u_x, then the (u_y, u_z) of each node).
  Eigen::MatrixXcd shapes;
  Eigen::VectorXcd norms;  ///< d_j of Eq. (W4)
};

/// The Ritz basis of the reduced model (see the header comment).
struct RailReduction {
  /// Real wavenumbers (rad/m) at which the free cross-section modes are taken.
  std::vector<double> wavenumbers{0.0, 10.0, 25.0, 50.0, 100.0, 200.0, 400.0};
  double max_frequency = 20000.0;  ///< modes with natural frequency up to this (Hz)
  /// Real wavenumbers (rad/m) of the static responses to the loads; empty: `wavenumbers`.
  std::vector<double> static_wavenumbers;
};

/// The contact points' basis of the continuous waveguide in the loop (docs/models.md Sec. 2.6):
/// the modes below 12 kHz at RailReduction's seven wavenumbers and the static responses to the
/// loads at 0, 100, 400 and 1200 rad/m (the last for the near field of a 10 mm patch).
RailReduction near_field_reduction();

/// The load-independent part of the Ritz basis: per wavenumber of a RailReduction the free
/// cross-section modes up to its max_frequency (RailWaveguide::reduction_modes), computed once
/// per model and passed to reduced() for each set of loads.
struct RailReductionModes {
  std::vector<std::vector<Eigen::VectorXd>> modes;  ///< per wavenumber, full nodal vectors
  /// Cholesky factors of K(k) + shift M at each wavenumber of the static responses (the
  /// static_wavenumbers, or the wavenumbers if those are empty), for reduced()'s static solves.
  std::vector<Eigen::LLT<Eigen::MatrixXd>> static_factors;
};

/// The head as a body (RailWaveguide::head_body): its six load distributions, the work-conjugates
/// of its least-squares rigid motion (mean u_y, mean u_z, roll theta J, mean u_x, and u_x's plane
/// Int s_y u_x dA, Int s_z u_x dA; s = r - r_h), and its area, centroid r_h and second moments
/// I_h about r_h. Every contact's head_loads is loads * at(point, normal): the contacts of one
/// section share one Ritz basis and one 6 x 6 transfer between these distributions.
struct HeadBody {
  Eigen::MatrixXd loads;  ///< dofs() x 6
  double area = 0.0;
  Eigen::Vector2d centroid{0.0, 0.0};
  Eigen::Matrix2d inertia = Eigen::Matrix2d::Zero();
  /// The coefficients of a contact's four columns (Receptance4 order, its frame) on `loads`.
  Eigen::Matrix<double, 6, 4> at(const Eigen::Vector2d& point, const Eigen::Vector2d& normal) const;
};

/// The head body of a section's mesh (RailWaveguide::head_body, which is this on its mesh): the
/// head the triangles with centroid at z >= head_bottom (m); loads in RailWaveguide's dofs.
HeadBody head_body(const fem::QuadraticTriangleMesh& mesh, double head_bottom);

/// The checks RailWaveguide's constructor makes of its material and support (InputError naming
/// the key), for models that build it on first use and check up front.
void check_rail_inputs(const RailMaterial& material, const std::optional<FootSupport>& support);

class RailWaveguide {
 public:
  /// `support`: none for the free rail. The foot is the set of boundary edges along the lowest z.
  RailWaveguide(fem::QuadraticTriangleMesh mesh, const RailMaterial& material,
                std::optional<FootSupport> support);

  /// The model restricted to the Ritz basis of `reduction` enriched by the static responses to
  /// `loads` (physical nodal components, dofs() rows; e.g. contact_loads()).
  RailWaveguide reduced(const RailReduction& reduction, const Eigen::MatrixXd& loads) const;
  /// The same with the modes of reduction_modes(reduction) given (the same bits).
  RailWaveguide reduced(const RailReduction& reduction, const Eigen::MatrixXd& loads,
                        const RailReductionModes& modes) const;
  /// The section modes of the reduction (unreduced model only).
  RailReductionModes reduction_modes(const RailReduction& reduction) const;

  /// Nodal degrees of freedom of the section mesh (3 per node).
  int dofs() const { return 3 * static_cast<int>(mesh_.nodes.size()); }
  /// Generalised coordinates of the eigenproblem (dofs() for the full model).
  int coordinates() const { return static_cast<int>(m_.rows()); }
  /// Degree of freedom of `node` in direction 0 (x), 1 (y), 2 (z).
  static int dof(int node, int direction) { return 3 * node + direction; }
  const fem::QuadraticTriangleMesh& mesh() const { return mesh_; }

  /// The lowest `count` natural frequencies (Hz) of the undamped rail at real wavenumber k (rad/m),
  /// Eq. (W2); a support enters with its static stiffness.
  Eigen::VectorXd dispersion(double k, int count) const;

  /// Eq. (W3) at angular frequency omega (rad/s; real, or complex for the continuation
  /// omega = -i s). Real omega and Im omega < 0 (Re s > 0): the waves with Im k < 0. Im omega > 0
  /// (Re s < 0, a decaying root): the continuation along the vertical path from the real frequency
  /// Re omega (continued_branch below), where a wave may have crossed the real k axis.
  RailWaves waves(cdouble omega) const;

  /// The continuation to Im omega > 0 (Re s < 0; docs/models.md Sec. 2.6, receptance_laplace):
  /// of each root pair +-k_j of Eq. (W5) at omega (k_j = sqrt(-mu_j) given with Im k_j <= 0), the
  /// member nearer to the waves with Im k < 0 at the real frequency Re omega (their wavenumbers,
  /// eigenvalues only) is the continued one, as the beams' RailModel::receptance_laplace takes
  /// the root nearest to the physical one at the real frequency; true where that is -k_j, the
  /// root with Im > 0 (a wave that crossed the real axis between Re omega and omega).
  std::vector<bool> continued_branch(cdouble omega, const Eigen::VectorXcd& roots) const;

  /// Eq. (W4): responses r_i = response.col(i) . u(x_r) per loads f_j = load.col(j) applied at
  /// x_l, x = x_r - x_l (m); `response` and `load` in physical nodal components (dofs() rows).
  Eigen::MatrixXcd transfer(const RailWaves& w, const Eigen::MatrixXd& response,
                            const Eigen::MatrixXd& load, double x) const;

  /// transfer(waves(omega), response, load, 0) by Eq. (W6): the Schur form of Eq. (W5)'s matrix
  /// instead of its eigenvectors (~the same result to round-off; falls back to the waves at a
  /// real omega with an undamped propagating wave).
  Eigen::MatrixXcd point_transfer(cdouble omega, const Eigen::MatrixXd& response,
                                  const Eigen::MatrixXd& load) const;

  /// The nodal load distributions of a contact on the section's boundary at `node` with the
  /// rail's outward normal `normal` (unit, in (y, z)) as the loop's contact frame
  /// (docs/noise_loop.md Sec. 1), columns in Receptance4 order: force along the normal n, force
  /// along x, force along the lateral tangent t = (n_z, -n_y), and a moment about n applied as the
  /// linearly varying axial traction over the head (the triangles with centroid z >= `head_bottom`,
  /// m) that does work on psi_n = -t . grad u_x of the plane fitted to u_x over the head by least
  /// squares: the rotation about n of the head as a whole (Timoshenko's section rotation), not the
  /// local one under the load. The response is projected on the same distributions, so the
  /// receptance is reciprocal.
  Eigen::MatrixXd contact_loads(int node, const Eigen::Vector2d& normal, double head_bottom) const;

  /// As contact_loads with the forces spread as a uniform traction over the part of the boundary
  /// within `half_width` (m) of `point` (y, z) instead of a nodal point force (whose receptance
  /// grows without bound as the mesh is refined: the point load on a solid).
  Eigen::MatrixXd patch_loads(const Eigen::Vector2d& point, double half_width,
                              const Eigen::Vector2d& normal, double head_bottom) const;

  /// The contact's loads through the head as a body: the forces along n, x and t at `point`
  /// (y, z) applied as the body-force distributions over the head (the triangles with centroid
  /// z >= `head_bottom`) whose work is done on the head's least-squares rigid motion evaluated at
  /// the point (the mean u, the roll about x fitted to u_y, u_z, the plane fitted to u_x), and the
  /// spin moment as in contact_loads. Same columns and frame as contact_loads; the response is the
  /// same projection (reciprocal). It leaves out the local deformation of the head under the
  /// patch (the contact model's elastic half-space holds it), which a patch load carries as a
  /// real compliance that grows with the mesh's and the basis's highest wavenumber along x (the
  /// line load along y is a point along x); docs/models.md Sec. 2.11.
  Eigen::MatrixXd head_loads(const Eigen::Vector2d& point, const Eigen::Vector2d& normal,
                             double head_bottom) const;
  /// The head as a body (HeadBody): head_loads(point, normal, b) = head_body(b).loads *
  /// head_body(b).at(point, normal).
  HeadBody head_body(double head_bottom) const;

  /// A uniform traction of unit resultant (N per N) in direction `direction` (0 x, 1 y, 2 z) over
  /// the boundary edges `edges` (indices into mesh().boundary_edges), as consistent nodal loads
  /// Int N ds / length. Used as a load and as the matching average of the response.
  Eigen::VectorXd edge_traction(const std::vector<int>& edges, int direction) const;

  /// The 4x4 receptance between contacts a (response) and b (load) at x = x_a - x_b.
  Receptance4 contact_receptance(const RailWaves& w, const Eigen::MatrixXd& loads_a,
                                 const Eigen::MatrixXd& loads_b, double x) const;

  /// Eq. (W4) factored for many distances between the same distributions: the waves'
  /// participation A_s(d) = phi^T P^s T V^T d (s = +1 or -1, T = i on the u_x rows), so that
  /// transfer(w, r, f, x) = A_s(r)^T diag(-i e^{-i k_j |x|} / d_j) A_{-s}(f), s the sign of x
  /// (x = 0: s = +1). Used by the discrete supports (waveguide_discrete_support.hpp).
  Eigen::MatrixXcd wave_amplitudes(const RailWaves& w, const Eigen::MatrixXd& d, double sign) const;

 private:
  fem::QuadraticTriangleMesh mesh_;
  RailMaterial material_;
  std::optional<FootSupport> support_;
  // Eq. (W1) in the generalised coordinates (q_x, q_s): the first `axial_` are u'_x.
  Eigen::MatrixXd k0_, k1_, k2_, m_;
  Eigen::MatrixXd foot_[3];            // V^T (Int_foot N^T N ds / (L b)) V per direction x, y, z
  Eigen::MatrixXd basis_x_, basis_s_;  // V_x (nodes x axial_), V_s (2 nodes x rest)
  int axial_ = 0;

  Eigen::MatrixXcd support_stiffness(cdouble omega) const;
  /// Eq. (W5)'s Y = B^{-1} A at omega, rows and columns ordered (v, q_s).
  Eigen::MatrixXcd pencil(cdouble omega) const;
  /// B^{-1} g for Eq. (W5)'s B = (1 + i eta) [K2x 0; K1c^T K2s] (block forward substitution).
  Eigen::MatrixXcd pencil_solve(const Eigen::MatrixXcd& g) const;
  /// V^T f: physical nodal loads (dofs() rows) to generalised ones.
  Eigen::MatrixXd project(const Eigen::MatrixXd& f) const;
  Eigen::MatrixXd nodal_loads(const Eigen::VectorXd& weights, const Eigen::Vector2d& normal,
                              double head_bottom) const;
  /// `identity`: vx, vs are identities (the unreduced model; the projection is skipped).
  void apply_basis(const Eigen::MatrixXd& vx, const Eigen::MatrixXd& vs, bool identity = false);
};

/// The bottom of the UIC60 head (z of the head's underside at its side, m) for contact_loads.
constexpr double kUic60HeadBottom = 0.133;

/// Node of the boundary nearest to `point` (y, z) (m).
int nearest_boundary_node(const fem::QuadraticTriangleMesh& mesh, const Eigen::Vector2d& point);

}  // namespace rollnoise::dynamics
