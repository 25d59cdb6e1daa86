// The axisymmetric (Fourier) finite-element model of a solid of revolution: the cross-section in
// (r, z) meshed with 6-node triangles, the displacements of circumferential order n
//   u_r = U_r(r, z) cos n theta,  u_theta = U_theta(r, z) sin n theta,  u_z = U_z(r, z) cos n theta
// (for n = 0 u_theta = U_theta: the torsional motion, uncoupled from (U_r, U_z)). Linear isotropic
// elasticity, consistent mass. Zienkiewicz, Taylor & Zhu (2013) Sec. 9.5 ("axisymmetric solids with
// non-symmetric load"); Wilson, AIAA J. 3 (1965) 2269-2274.
//
// Degrees of freedom: 3 per node, node i -> 3 i + {0: U_r, 1: U_theta, 2: U_z}. The matrices carry
// the circumferential integral, int_0^{2 pi} cos^2 n theta d theta = pi (n >= 1) or 2 pi (n = 0),
// so that a mode normalised to phi^T M phi = 1 is the physical displacement field of a unit modal
// mass.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "fem/mesh.hpp"

namespace rollnoise::fem {

/// Linear isotropic elastic material (SI).
struct IsotropicMaterial {
  double youngs_modulus = 2.1e11;  // Pa
  double poisson_ratio = 0.3;
  double density = 7850.0;  // kg/m^3
};

/// Stiffness and mass of one circumferential order n (3 DOFs per node, all nodes free).
struct AxisymmetricMatrices {
  Eigen::SparseMatrix<double> stiffness;  // N/m
  Eigen::SparseMatrix<double> mass;       // kg
};

/// Assembles K and M of order n >= 0 over the section mesh (r = node x > 0 everywhere). Strains
/// (cylindrical, per cos/sin factor, Zienkiewicz et al. Eq. 9.29):
///   e_r = U_r,r   e_z = U_z,z   e_t = (U_r + n U_t)/r   g_rz = U_r,z + U_z,r
///   g_rt = U_t,r - U_t/r - n U_r/r   g_tz = U_t,z - n U_z/r
/// K = c_n int B^T D B r dr dz, M = c_n rho int N^T N r dr dz, c_n = pi (n >= 1), 2 pi (n = 0),
/// integrated by the 7-point degree-5 rule.
AxisymmetricMatrices assemble_axisymmetric(const QuadraticTriangleMesh& mesh,
                                           const IsotropicMaterial& material, int n);

/// K and M of every order n from three order-independent parts, assembled once: the strain matrix
/// is affine in n, B_n = B_0 + n B_1 (B_1 = B at n = 1 minus B_0), so
///   K_n = c_n (K_0 + n K_1 + n^2 K_2),  M_n = c_n M_1,  with (integrals over r dr dz)
///   K_0 = int B_0^T D B_0,  K_1 = int (B_0^T D B_1 + B_1^T D B_0),  K_2 = int B_1^T D B_1,
/// equal to assemble_axisymmetric(mesh, material, n) to round-off, with one sparsity pattern for
/// all n (the union of the parts', explicit zeros kept). A mesh's orders n = 0..10 cost one
/// assembly with three element products instead of eleven.
class AxisymmetricOrders {
 public:
  AxisymmetricOrders(const QuadraticTriangleMesh& mesh, const IsotropicMaterial& material);
  AxisymmetricMatrices matrices(int n) const;

 private:
  Eigen::SparseMatrix<double> k0_, k1_, k2_, m_;  // without c_n
};

/// Where a point lies in the mesh: its triangle and reference coordinates (xi, eta).
struct MeshPoint {
  int triangle = -1;
  double xi = 0.0, eta = 0.0;
};

/// Locates (r, z) in the triangle that contains it (the nearest triangle, and the nearest point of
/// it, for a point just outside, e.g. on a curved surface sampled between nodes). Throws
/// std::invalid_argument when the point is farther than `tolerance` from the mesh.
MeshPoint locate(const QuadraticTriangleMesh& mesh, const Eigen::Vector2d& point,
                 double tolerance = 1e-6);

/// The displacement (U_r, U_theta, U_z) of a DOF vector at a located point, by the shape functions.
Eigen::Vector3d displacement_at(const QuadraticTriangleMesh& mesh, const Eigen::VectorXd& dofs,
                                const MeshPoint& at);

/// locate() then displacement_at().
Eigen::Vector3d displacement_at(const QuadraticTriangleMesh& mesh, const Eigen::VectorXd& dofs,
                                const Eigen::Vector2d& point, double tolerance = 1e-6);

/// The shares of phi^T M phi carried by U_r, U_theta and U_z (they sum to 1): which direction a
/// mode moves in, weighted by mass.
Eigen::Vector3d kinetic_energy_shares(const Eigen::SparseMatrix<double>& mass,
                                      const Eigen::VectorXd& phi);

/// Sign changes along a sequence of values (e.g. a mode's displacement along a line: its nodal
/// points), ignoring values smaller than `relative_threshold` times the largest magnitude.
int sign_changes(const std::vector<double>& values, double relative_threshold);

/// Nodes on the boundary edges that lie on the given outline segments (sorted, unique).
std::vector<int> nodes_on_segments(const QuadraticTriangleMesh& mesh,
                                   const std::vector<int>& segments);

}  // namespace rollnoise::fem
