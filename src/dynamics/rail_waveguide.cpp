#include "dynamics/rail_waveguide.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "dynamics/rail_section.hpp"
#include "fem/triangle6.hpp"

namespace rollnoise::dynamics {

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Strain18 = Eigen::Matrix<double, 6, 18>;

// Isotropic elasticity in the strain order (xx, yy, zz, yz, xz, xy), engineering shear strains.
Matrix6 elasticity(const RailMaterial& m) {
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = E / (2.0 * (1.0 + nu));
  Matrix6 D = Matrix6::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) D(i, i) += 2.0 * mu;
  for (int i = 3; i < 6; ++i) D(i, i) = mu;
  return D;
}

// B1 and B2 of Eq. (W1) at one quadrature point; element dofs (u'_x, u_y, u_z) per node.
void strain_operators(const SectionPoint& p, Strain18& B1, Strain18& B2) {
  B1.setZero();
  B2.setZero();
  for (int a = 0; a < 6; ++a) {
    const double Ny = p.gradient(0, a), Nz = p.gradient(1, a), N = p.shape(a);
    B1(1, 3 * a + 1) = Ny;
    B1(2, 3 * a + 2) = Nz;
    B1(3, 3 * a + 1) = Nz;
    B1(3, 3 * a + 2) = Ny;
    B1(4, 3 * a) = Nz;
    B1(5, 3 * a) = Ny;
    B2(0, 3 * a) = N;
    B2(4, 3 * a + 2) = -N;
    B2(5, 3 * a + 1) = -N;
  }
}

// LAPACK's zgeev (Anderson et al., LAPACK Users' Guide, 3rd ed. 1999): eigenvalues and right
// eigenvectors of a general complex matrix, balanced first. Eigen's ComplexEigenSolver is ~10-50x
// slower on the n ~ 600 problems here.
extern "C" void zgeev_(const char* jobvl, const char* jobvr, const int* n, cdouble* a,
                       const int* lda, cdouble* w, cdouble* vl, const int* ldvl, cdouble* vr,
                       const int* ldvr, cdouble* work, const int* lwork, double* rwork, int* info);

void eigen_decomposition(Eigen::MatrixXcd a, Eigen::VectorXcd& values, Eigen::MatrixXcd& vectors) {
  const int n = static_cast<int>(a.rows()), one = 1;
  values.resize(n);
  vectors.resize(n, n);
  cdouble dummy, query;
  std::vector<double> rwork(2 * n);
  int info = 0, lwork = -1;
  zgeev_("N", "V", &n, a.data(), &n, values.data(), &dummy, &one, vectors.data(), &n, &query,
         &lwork, rwork.data(), &info);
  lwork = static_cast<int>(query.real());
  std::vector<cdouble> work(lwork);
  zgeev_("N", "V", &n, a.data(), &n, values.data(), &dummy, &one, vectors.data(), &n, work.data(),
         &lwork, rwork.data(), &info);
  if (info != 0)
    throw NumericalError("rail waveguide: LAPACK zgeev failed (info = " + std::to_string(info) +
                         ") on the " + std::to_string(n) + " x " + std::to_string(n) +
                         " wavenumber eigenproblem");
}

// The three-node (quadratic) line on xi in [-1, 1], nodes (end -1, mid 0, end +1).
Eigen::Vector3d line3_shape(double xi) {
  return Eigen::Vector3d(0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0));
}

}  // namespace

RailWaveguide::RailWaveguide(fem::QuadraticTriangleMesh mesh, const RailMaterial& material,
                             std::optional<FootSupport> support)
    : mesh_(std::move(mesh)), material_(material), support_(std::move(support)) {
  if (!(material_.youngs_modulus > 0.0) || !(material_.density > 0.0) ||
      !(material_.poisson_ratio > -1.0 && material_.poisson_ratio < 0.5) ||
      !(material_.loss_factor >= 0.0))
    throw InputError("rail_material", "rail material: E > 0, rho > 0, -1 < nu < 1/2, eta >= 0");
  if (support_) {
    support_->vertical.validate("track.support.vertical");
    support_->lateral.validate("track.support.lateral");
    support_->longitudinal.validate("track.support.longitudinal");
    if (!(support_->sleeper_spacing > 0.0))
      throw InputError("rail_support", "sleeper spacing must be > 0");
  }
  assemble();
}

void RailWaveguide::assemble() {
  const int nn = static_cast<int>(mesh_.nodes.size()), n = 3 * nn;
  k0_ = k1_ = k2_ = m_ = Eigen::MatrixXd::Zero(n, n);
  const Matrix6 D = elasticity(material_);
  Strain18 B1, B2;
  for (int t = 0; t < static_cast<int>(mesh_.triangles.size()); ++t) {
    Eigen::Matrix<double, 18, 18> e0 = Eigen::Matrix<double, 18, 18>::Zero(), e1 = e0, e2 = e0,
                                  em = e0;
    for (const SectionPoint& p : section_points(mesh_, t)) {
      strain_operators(p, B1, B2);
      const Strain18 DB1 = D * B1, DB2 = D * B2;
      e0 += p.weight * B1.transpose() * DB1;
      e1 += p.weight * (B1.transpose() * DB2 + B2.transpose() * DB1);
      e2 += p.weight * B2.transpose() * DB2;
      const Matrix6 NN = p.weight * material_.density * p.shape * p.shape.transpose();
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
          for (int d = 0; d < 3; ++d) em(3 * a + d, 3 * b + d) += NN(a, b);
    }
    const auto& tri = mesh_.triangles[t];
    for (int a = 0; a < 18; ++a)
      for (int b = 0; b < 18; ++b) {
        const int i = 3 * tri[a / 3] + a % 3, j = 3 * tri[b / 3] + b % 3;
        k0_(i, j) += e0(a, b);
        k1_(i, j) += e1(a, b);
        k2_(i, j) += e2(a, b);
        m_(i, j) += em(a, b);
      }
  }
  is_axial_ = Eigen::VectorXi::Zero(n);
  for (int i = 0; i < nn; ++i) is_axial_(dof(i, 0)) = 1;

  // Foot: the boundary edges along the lowest z; Int N^T N ds / (L b) (3-point Gauss, exact).
  foot_ = Eigen::MatrixXd::Zero(nn, nn);
  if (!support_) return;
  double zmin = mesh_.nodes[0].y(), zmax = zmin;
  for (const auto& p : mesh_.nodes) zmin = std::min(zmin, p.y()), zmax = std::max(zmax, p.y());
  const double tol = 1e-6 * (zmax - zmin);
  double width = 0.0;
  const double g = std::sqrt(0.6), gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}, gx[3] = {-g, 0.0, g};
  for (const auto& e : mesh_.boundary_edges) {
    bool on_foot = true;
    for (int v : e) on_foot = on_foot && std::abs(mesh_.nodes[v].y() - zmin) < tol;
    if (!on_foot) continue;
    const double len = (mesh_.nodes[e[2]] - mesh_.nodes[e[0]]).norm();
    width += len;
    for (int q = 0; q < 3; ++q) {
      const Eigen::Vector3d N = line3_shape(gx[q]);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) foot_(e[a], e[b]) += gw[q] * 0.5 * len * N(a) * N(b);
    }
  }
  if (!(width > 0.0)) throw InputError("rail_section", "the rail section has no flat foot");
  foot_ /= support_->sleeper_spacing * width;
}

Eigen::MatrixXcd RailWaveguide::support_stiffness(cdouble omega) const {
  const int nn = static_cast<int>(mesh_.nodes.size());
  Eigen::MatrixXcd ks = Eigen::MatrixXcd::Zero(3 * nn, 3 * nn);
  if (!support_) return ks;
  const cdouble K[3] = {support_->longitudinal.dynamic_stiffness(omega),
                        support_->lateral.dynamic_stiffness(omega),
                        support_->vertical.dynamic_stiffness(omega)};
  for (int a = 0; a < nn; ++a)
    for (int b = 0; b < nn; ++b)
      if (foot_(a, b) != 0.0)
        for (int d = 0; d < 3; ++d) ks(dof(a, d), dof(b, d)) = K[d] * foot_(a, b);
  return ks;
}

Eigen::VectorXd RailWaveguide::dispersion(double k, int count) const {
  Eigen::MatrixXd K = k0_ + k * k1_ + k * k * k2_ + support_stiffness(cdouble(0.0)).real();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, m_, Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success)
    throw NumericalError("rail waveguide: dispersion eigensolver failed");
  const int m = std::min<int>(count, static_cast<int>(es.eigenvalues().size()));
  Eigen::VectorXd f(m);
  for (int i = 0; i < m; ++i) f(i) = std::sqrt(std::max(0.0, es.eigenvalues()(i))) / (2.0 * M_PI);
  return f;
}

RailWaves RailWaveguide::waves(double omega) const {
  // Eq. (W5): K0, K2, M and the support couple no u'_x with (u_y, u_z), K1 only those; with
  // phi = (k v, u_s) the quadratic problem becomes the linear pencil in lambda = k^2
  //   [Ax C; 0 As] z + lambda [Bx 0; C^T Bs] z = 0,  z = (v, u_s),
  // solved as the standard problem B^{-1} A z = -lambda z (B block-triangular, K2's blocks SPD).
  const int n = dofs(), nn = n / 3;
  const cdouble damp(1.0, material_.loss_factor);
  const Eigen::MatrixXcd A0 =
      (damp * k0_ - omega * omega * m_).cast<cdouble>() + support_stiffness(cdouble(omega));
  Eigen::VectorXi ax(nn), tr(2 * nn);
  for (int i = 0; i < nn; ++i) ax(i) = dof(i, 0), tr(2 * i) = dof(i, 1), tr(2 * i + 1) = dof(i, 2);
  const Eigen::MatrixXd K1c = k1_(ax, tr);
  const Eigen::LLT<Eigen::MatrixXd> K2x(k2_(ax, ax)), K2s(k2_(tr, tr));
  auto solve = [](const Eigen::LLT<Eigen::MatrixXd>& llt, const Eigen::MatrixXcd& r) {
    Eigen::MatrixXcd x(r.rows(), r.cols());
    x.real() = llt.solve(r.real());
    x.imag() = llt.solve(r.imag());
    return x;
  };
  Eigen::MatrixXcd A(n, n);  // rows, columns ordered (v, u_s)
  A << A0(ax, ax), damp * K1c.cast<cdouble>(), Eigen::MatrixXcd::Zero(2 * nn, nn), A0(tr, tr);
  Eigen::MatrixXcd Y(n, n);
  Y.topRows(nn) = solve(K2x, A.topRows(nn)) / damp;
  Y.bottomRows(2 * nn) = solve(K2s, A.bottomRows(2 * nn) / damp - K1c.transpose() * Y.topRows(nn));
  Eigen::VectorXcd mu;
  Eigen::MatrixXcd Z;
  eigen_decomposition(std::move(Y), mu, Z);

  RailWaves w;
  w.omega = omega;
  w.wavenumbers.resize(n);
  w.shapes.resize(n, n);
  for (int j = 0; j < n; ++j) {
    const cdouble root = std::sqrt(-mu(j));
    w.wavenumbers(j) = root.imag() > 0.0 ? -root : root;
    w.shapes.col(j)(ax) = w.wavenumbers(j) * Z.col(j).head(nn);
    w.shapes.col(j)(tr) = Z.col(j).tail(2 * nn);
  }
  // Q'(k_j) phi_j for all j by real matrix products; d_j = phi_j^T Q'(k_j) phi_j.
  auto times = [](const Eigen::MatrixXd& a, const Eigen::MatrixXcd& b) {
    Eigen::MatrixXcd c(a.rows(), b.cols());
    c.real() = a * b.real();
    c.imag() = a * b.imag();
    return c;
  };
  const Eigen::MatrixXcd K2Phi = times(k2_, w.shapes), K1Phi = times(k1_, w.shapes);
  const Eigen::MatrixXcd MPhi = times(m_, w.shapes);
  w.norms.resize(n);
  for (int j = 0; j < n; ++j) {
    const cdouble k = w.wavenumbers(j);
    const Eigen::VectorXcd dq = damp * (2.0 * k * K2Phi.col(j) + K1Phi.col(j));
    w.norms(j) = w.shapes.col(j).transpose() * dq;
    // An undamped propagating root travels towards +x if its group velocity is positive; else
    // its partner -k, P phi does (Q'(-k) P phi = -P Q'(k) phi, so d changes sign).
    if (std::abs(k.imag()) <= 1e-7 * std::abs(k) &&
        w.shapes.col(j).dot(dq).real() / w.shapes.col(j).dot(MPhi.col(j)).real() < 0.0) {
      w.wavenumbers(j) = -k;
      w.shapes.col(j)(ax) *= -1.0;
      w.norms(j) = -w.norms(j);
    }
  }
  return w;
}

Eigen::MatrixXcd RailWaveguide::transfer(const RailWaves& w, const Eigen::MatrixXd& response,
                                         const Eigen::MatrixXd& load, double x) const {
  // H = R^T T P^s G'(|x|) P^s T^* F (Eq. W4), s = [x < 0]; T = i, P = -1 on u_x.
  const cdouble I(0.0, 1.0);
  const double sign = x < 0.0 ? -1.0 : 1.0;
  Eigen::MatrixXcd r = response.cast<cdouble>(), f = load.cast<cdouble>();
  for (int i = 0; i < dofs(); ++i)
    if (is_axial_(i)) r.row(i) *= I * sign, f.row(i) *= -I * sign;
  const Eigen::MatrixXcd Y = w.shapes.transpose() * r, Z = w.shapes.transpose() * f;
  Eigen::VectorXcd weight(w.wavenumbers.size());
  for (int j = 0; j < weight.size(); ++j)
    weight(j) = -I * std::exp(-I * w.wavenumbers(j) * std::abs(x)) / w.norms(j);
  return Y.transpose() * weight.asDiagonal() * Z;
}

Eigen::MatrixXd RailWaveguide::contact_loads(int node, const Eigen::Vector2d& normal,
                                             double head_bottom) const {
  const Eigen::Vector2d n = normal.normalized(), t(n.y(), -n.x());
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(dofs(), 4);
  L(dof(node, 1), kZ) = n.x();
  L(dof(node, 2), kZ) = n.y();
  L(dof(node, 0), kX) = 1.0;
  L(dof(node, 1), kY) = t.x();
  L(dof(node, 2), kY) = t.y();
  // psi_n = -t . b, b the gradient of the plane u_x = a + b . (r - r_h) fitted over the head
  // (least squares over the triangles whose centroid lies at z >= head_bottom):
  // b = I_h^{-1} Int_head (r - r_h) u_x dA, I_h = Int_head (r - r_h)(r - r_h)^T dA.
  double area = 0.0;
  Eigen::Vector2d first(0.0, 0.0);
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  std::vector<int> head;
  for (int t = 0; t < static_cast<int>(mesh_.triangles.size()); ++t) {
    Eigen::Vector2d c(0.0, 0.0);
    for (int a = 0; a < 3; ++a) c += mesh_.nodes[mesh_.triangles[t][a]] / 3.0;
    if (c.y() < head_bottom) continue;
    head.push_back(t);
    for (const SectionPoint& p : section_points(mesh_, t)) {
      area += p.weight;
      first += p.weight * p.position;
      second += p.weight * p.position * p.position.transpose();
    }
  }
  if (head.empty())
    throw InputError("rail_section", "no triangle of the rail head above it");
  const Eigen::Vector2d rh = first / area;
  const Eigen::Matrix2d Ih = second - area * rh * rh.transpose();
  const Eigen::Vector2d c = -Ih.inverse() * t;  // psi_n = c . Int (r - r_h) u_x dA
  for (int tri : head)
    for (const SectionPoint& p : section_points(mesh_, tri))
      for (int b = 0; b < 6; ++b)
        L(dof(mesh_.triangles[tri][b], 0), kRotZ) += p.weight * c.dot(p.position - rh) * p.shape(b);
  return L;
}

Eigen::VectorXd RailWaveguide::edge_traction(const std::vector<int>& edges, int direction) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs());
  double length = 0.0;
  for (int i : edges) {
    const auto& e = mesh_.boundary_edges.at(i);
    const double len = (mesh_.nodes[e[2]] - mesh_.nodes[e[0]]).norm();
    // Int N ds of the quadratic line: (1/6, 2/3, 1/6) of its length.
    f(dof(e[0], direction)) += len / 6.0;
    f(dof(e[1], direction)) += 2.0 * len / 3.0;
    f(dof(e[2], direction)) += len / 6.0;
    length += len;
  }
  if (!(length > 0.0)) throw InputError("rail_section", "edge traction on no boundary edge");
  return f / length;
}

Receptance4 RailWaveguide::contact_receptance(const RailWaves& w, const Eigen::MatrixXd& loads_a,
                                              const Eigen::MatrixXd& loads_b, double x) const {
  return transfer(w, loads_a, loads_b, x);
}

int nearest_boundary_node(const fem::QuadraticTriangleMesh& mesh, const Eigen::Vector2d& point) {
  int best = -1;
  double dist = 0.0;
  for (const auto& e : mesh.boundary_edges)
    for (int v : e) {
      const double d = (mesh.nodes[v] - point).norm();
      if (best < 0 || d < dist) best = v, dist = d;
    }
  if (best < 0) throw InputError("rail_section", "the rail mesh has no boundary");
  return best;
}

}  // namespace rollnoise::dynamics
