#include "fem/axisymmetric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "core/constants.hpp"
#include "fem/triangle6.hpp"

namespace rollnoise::fem {
namespace {


// Isotropic elasticity in the strain order (e_r, e_z, e_t, g_rz, g_rt, g_tz).
Eigen::Matrix<double, 6, 6> elasticity(const IsotropicMaterial& m) {
  const double e = m.youngs_modulus, nu = m.poisson_ratio;
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) d(i, i) = lambda + 2 * mu;
  for (int i = 3; i < 6; ++i) d(i, i) = mu;
  return d;
}

// The strain-displacement matrix at one point (shape values N, derivatives dN by r and z, radius
// r).
Eigen::Matrix<double, 6, 18> strain_matrix(const Eigen::Matrix<double, 6, 1>& N,
                                           const Eigen::Matrix<double, 2, 6>& dN, double r, int n) {
  Eigen::Matrix<double, 6, 18> b = Eigen::Matrix<double, 6, 18>::Zero();
  for (int i = 0; i < 6; ++i) {
    const int c = 3 * i;  // columns U_r, U_t, U_z of node i
    const double nr = dN(0, i), nz = dN(1, i), nor = N(i) / r;
    b(0, c) = nr;                                // e_r
    b(1, c + 2) = nz;                            // e_z
    b(2, c) = nor, b(2, c + 1) = n * nor;        // e_t
    b(3, c) = nz, b(3, c + 2) = nr;              // g_rz
    b(4, c) = -n * nor, b(4, c + 1) = nr - nor;  // g_rt
    b(5, c + 1) = nz, b(5, c + 2) = -n * nor;    // g_tz
  }
  return b;
}

// Area coordinates of p in the straight-sided triangle t (corners 0..2).
Eigen::Vector3d area_coordinates(const QuadraticTriangleMesh& mesh, const std::array<int, 6>& t,
                                 const Eigen::Vector2d& p) {
  const Eigen::Vector2d a = mesh.nodes[t[0]], b = mesh.nodes[t[1]], c = mesh.nodes[t[2]];
  Eigen::Matrix2d j;
  j.col(0) = b - a;
  j.col(1) = c - a;
  const Eigen::Vector2d x = j.inverse() * (p - a);  // (xi, eta) = (L2, L3)
  return {1.0 - x(0) - x(1), x(0), x(1)};
}

// One quadrature point of a section triangle (coordinates xy): the shape values N, their (r, z)
// derivatives dN, the radius r and the weight w |J| r (without the circumferential integral).
struct SectionPoint {
  Eigen::Matrix<double, 6, 1> N;
  Eigen::Matrix<double, 2, 6> dN;
  double r = 0.0, weight = 0.0;
};

SectionPoint section_point(const Eigen::Matrix<double, 2, 6>& xy, const TrianglePoint& q) {
  SectionPoint p;
  p.N = triangle6_shape(q.xi, q.eta);
  const auto dref = triangle6_shape_derivatives(q.xi, q.eta);
  const Eigen::Matrix2d jac = triangle6_jacobian(dref, xy);
  p.dN = jac.inverse() * dref;
  p.r = xy.row(0).dot(p.N.transpose());
  if (!(p.r > 0.0)) throw std::invalid_argument("axisymmetric section reaches r <= 0");
  p.weight = q.weight * jac.determinant() * p.r;
  return p;
}

}  // namespace

AxisymmetricMatrices assemble_axisymmetric(const QuadraticTriangleMesh& mesh,
                                           const IsotropicMaterial& material, int n) {
  const Eigen::Matrix<double, 6, 6> d = elasticity(material);
  const double circumferential = n == 0 ? 2 * kPi : kPi;
  std::vector<Eigen::Triplet<double>> k_entries, m_entries;
  k_entries.reserve(mesh.triangles.size() * 324);
  m_entries.reserve(mesh.triangles.size() * 108);
  for (const auto& t : mesh.triangles) {
    const auto xy = triangle6_coordinates(mesh.nodes, t);
    Eigen::Matrix<double, 18, 18> ke = Eigen::Matrix<double, 18, 18>::Zero();
    Eigen::Matrix<double, 6, 6> me = Eigen::Matrix<double, 6, 6>::Zero();
    for (const auto& q : triangle_gauss_degree5()) {
      const SectionPoint p = section_point(xy, q);
      const double w = p.weight * circumferential;
      const auto b = strain_matrix(p.N, p.dN, p.r, n);
      ke.noalias() += w * b.transpose() * d * b;
      me.noalias() += w * material.density * p.N * p.N.transpose();
    }
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        for (int a = 0; a < 3; ++a) {
          m_entries.emplace_back(3 * t[i] + a, 3 * t[j] + a, me(i, j));
          for (int c = 0; c < 3; ++c)
            k_entries.emplace_back(3 * t[i] + a, 3 * t[j] + c, ke(3 * i + a, 3 * j + c));
        }
      }
  }
  const int ndof = 3 * static_cast<int>(mesh.nodes.size());
  AxisymmetricMatrices out;
  out.stiffness.resize(ndof, ndof);
  out.mass.resize(ndof, ndof);
  out.stiffness.setFromTriplets(k_entries.begin(), k_entries.end());
  out.mass.setFromTriplets(m_entries.begin(), m_entries.end());
  return out;
}

namespace {

// The compressed-column pattern of K (every pair of nodes of a triangle couples all three
// components) and of M (like components only), from each node's sorted neighbours, with the
// position of node i in node j's neighbour list found per triangle entry.
class NodalPattern {
 public:
  explicit NodalPattern(const QuadraticTriangleMesh& mesh) {
    const int nodes = static_cast<int>(mesh.nodes.size());
    neighbours_.resize(nodes);
    for (const auto& t : mesh.triangles)
      for (int j : t) neighbours_[j].insert(neighbours_[j].end(), t.begin(), t.end());
    k_start_.assign(3 * nodes + 1, 0);
    m_start_.assign(3 * nodes + 1, 0);
    for (int j = 0; j < nodes; ++j) {
      auto& nb = neighbours_[j];
      std::sort(nb.begin(), nb.end());
      nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
      for (int c = 0; c < 3; ++c) {
        k_start_[3 * j + c + 1] = k_start_[3 * j + c] + 3 * static_cast<int>(nb.size());
        m_start_[3 * j + c + 1] = m_start_[3 * j + c] + static_cast<int>(nb.size());
      }
    }
  }
  // Position of node i among node j's neighbours.
  int position(int i, int j) const {
    const auto& nb = neighbours_[j];
    return static_cast<int>(std::lower_bound(nb.begin(), nb.end(), i) - nb.begin());
  }
  // Index into the values of K / M of (row 3 i + a, column 3 j + c), p = position(i, j).
  int k_index(int p, int j, int a, int c) const { return k_start_[3 * j + c] + 3 * p + a; }
  int m_index(int p, int j, int c) const { return m_start_[3 * j + c] + p; }
  // An all-zero matrix with the pattern of K (mass = false) or M (mass = true).
  Eigen::SparseMatrix<double> zeros(bool mass) const {
    const int ndof = 3 * static_cast<int>(neighbours_.size());
    const auto& start = mass ? m_start_ : k_start_;
    Eigen::SparseMatrix<double> a(ndof, ndof);
    a.resizeNonZeros(start.back());
    std::copy(start.begin(), start.end(), a.outerIndexPtr());
    int* rows = a.innerIndexPtr();
    for (std::size_t j = 0; j < neighbours_.size(); ++j)
      for (int c = 0; c < 3; ++c)
        for (int i : neighbours_[j])
          if (mass)
            *rows++ = 3 * i + c;
          else
            for (int r = 0; r < 3; ++r) *rows++ = 3 * i + r;
    std::fill(a.valuePtr(), a.valuePtr() + a.nonZeros(), 0.0);
    return a;
  }

 private:
  std::vector<std::vector<int>> neighbours_;
  std::vector<int> k_start_, m_start_;
};

}  // namespace

// The element matrices are added into the values of a pattern built once from the nodes'
// neighbours, in the order of the triangles: the same pattern and the same sums as a triplet
// assembly (which adds duplicates in the order of the triplets), without its sort of ~450 000
// triplets per part.
AxisymmetricOrders::AxisymmetricOrders(const QuadraticTriangleMesh& mesh,
                                       const IsotropicMaterial& material) {
  const Eigen::Matrix<double, 6, 6> d = elasticity(material);
  const NodalPattern pattern(mesh);
  k0_ = pattern.zeros(false), k1_ = k0_, k2_ = k0_, m_ = pattern.zeros(true);
  double *k0 = k0_.valuePtr(), *k1 = k1_.valuePtr(), *k2 = k2_.valuePtr(), *m = m_.valuePtr();
  for (const auto& t : mesh.triangles) {
    const auto xy = triangle6_coordinates(mesh.nodes, t);
    Eigen::Matrix<double, 18, 18> ke0 = Eigen::Matrix<double, 18, 18>::Zero(), ke1 = ke0, ke2 = ke0;
    Eigen::Matrix<double, 6, 6> me = Eigen::Matrix<double, 6, 6>::Zero();
    for (const auto& q : triangle_gauss_degree5()) {
      const SectionPoint p = section_point(xy, q);
      const double w = p.weight;
      const Eigen::Matrix<double, 6, 18> b0 = strain_matrix(p.N, p.dN, p.r, 0);
      const Eigen::Matrix<double, 6, 18> b1 = strain_matrix(p.N, p.dN, p.r, 1) - b0;
      const Eigen::Matrix<double, 18, 6> b0d = w * b0.transpose() * d;
      const Eigen::Matrix<double, 18, 6> b1d = w * b1.transpose() * d;
      ke0.noalias() += b0d * b0;
      ke1.noalias() += b0d * b1 + b1d * b0;
      ke2.noalias() += b1d * b1;
      me.noalias() += w * material.density * p.N * p.N.transpose();
    }
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        const int p = pattern.position(t[i], t[j]);
        for (int c = 0; c < 3; ++c) {
          m[pattern.m_index(p, t[j], c)] += me(i, j);
          for (int a = 0; a < 3; ++a) {
            const int v = pattern.k_index(p, t[j], a, c), ei = 3 * i + a, ej = 3 * j + c;
            k0[v] += ke0(ei, ej), k1[v] += ke1(ei, ej), k2[v] += ke2(ei, ej);
          }
        }
      }
  }
}

AxisymmetricMatrices AxisymmetricOrders::matrices(int n) const {
  const double circumferential = n == 0 ? 2 * kPi : kPi;
  AxisymmetricMatrices out;
  // K_0, K_1, K_2 share one pattern (NodalPattern): the combination runs over their values.
  out.stiffness = k0_;
  const double dn = n, dn2 = dn * n;
  const double *v0 = k0_.valuePtr(), *v1 = k1_.valuePtr(), *v2 = k2_.valuePtr();
  double* v = out.stiffness.valuePtr();
  for (Eigen::Index i = 0; i < k0_.nonZeros(); ++i)
    v[i] = circumferential * (v0[i] + dn * v1[i] + dn2 * v2[i]);
  out.mass = circumferential * m_;
  return out;
}

MeshPoint locate(const QuadraticTriangleMesh& mesh, const Eigen::Vector2d& point,
                 double tolerance) {
  double best = std::numeric_limits<double>::infinity();
  MeshPoint at;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const auto& t = mesh.triangles[e];
    const Eigen::Vector2d a = mesh.nodes[t[0]];
    // Cheap rejection: a point within `tolerance` of the triangle is within its size + tolerance of
    // corner 0.
    const double size = std::max((mesh.nodes[t[1]] - a).norm(), (mesh.nodes[t[2]] - a).norm());
    if ((point - a).norm() > size + tolerance) continue;
    const Eigen::Vector3d l = area_coordinates(mesh, t, point);
    // Outside: the clamped coordinates give a point of the triangle (exact on an edge).
    Eigen::Vector3d c = l.cwiseMax(0.0);
    c /= c.sum();
    const Eigen::Vector2d q = c(0) * a + c(1) * mesh.nodes[t[1]] + c(2) * mesh.nodes[t[2]];
    const double dist = l.minCoeff() >= 0.0 ? 0.0 : (q - point).norm();
    if (dist < best) best = dist, at = {static_cast<int>(e), c(1), c(2)};
    if (dist == 0.0) break;
  }
  if (at.triangle < 0 || best > tolerance)
    throw std::invalid_argument("point (" + std::to_string(point.x()) + ", " +
                                std::to_string(point.y()) + ") m is outside the section mesh");
  return at;
}

Eigen::Vector3d displacement_at(const QuadraticTriangleMesh& mesh, const Eigen::VectorXd& dofs,
                                const MeshPoint& at) {
  const auto& t = mesh.triangles[at.triangle];
  const auto N = triangle6_shape(at.xi, at.eta);
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (int i = 0; i < 6; ++i) u += N(i) * dofs.segment<3>(3 * t[i]);
  return u;
}

Eigen::Vector3d displacement_at(const QuadraticTriangleMesh& mesh, const Eigen::VectorXd& dofs,
                                const Eigen::Vector2d& point, double tolerance) {
  return displacement_at(mesh, dofs, locate(mesh, point, tolerance));
}

Eigen::Vector3d kinetic_energy_shares(const Eigen::SparseMatrix<double>& mass,
                                      const Eigen::VectorXd& phi) {
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  for (int c = 0; c < mass.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(mass, c); it; ++it)
      e(it.row() % 3) += phi(it.row()) * it.value() * phi(it.col());  // M couples like components
  return e / e.sum();
}

int sign_changes(const std::vector<double>& values, double relative_threshold) {
  double big = 0.0;
  for (double x : values) big = std::max(big, std::abs(x));
  int changes = 0, sign = 0;
  for (double x : values) {
    if (std::abs(x) < relative_threshold * big) continue;
    const int s = x > 0 ? 1 : -1;
    if (sign != 0 && s != sign) ++changes;
    sign = s;
  }
  return changes;
}

std::vector<int> nodes_on_segments(const QuadraticTriangleMesh& mesh,
                                   const std::vector<int>& segments) {
  std::set<int> nodes;
  for (std::size_t e = 0; e < mesh.boundary_edges.size(); ++e)
    if (std::find(segments.begin(), segments.end(), mesh.boundary_edge_segment[e]) !=
        segments.end())
      nodes.insert(mesh.boundary_edges[e].begin(), mesh.boundary_edges[e].end());
  return {nodes.begin(), nodes.end()};
}

}  // namespace rollnoise::fem
