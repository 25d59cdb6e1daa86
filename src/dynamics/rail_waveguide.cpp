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
#include "linalg/lapack_section.hpp"

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
  const linalg::LapackSection lapack;  // lapack_section.hpp: not every LAPACK is reentrant
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

void check_rail_inputs(const RailMaterial& material, const std::optional<FootSupport>& support) {
  if (!(material.youngs_modulus > 0.0) || !(material.density > 0.0) ||
      !(material.poisson_ratio > -1.0 && material.poisson_ratio < 0.5) ||
      !(material.loss_factor >= 0.0))
    throw InputError("rail_material", "rail material: E > 0, rho > 0, -1 < nu < 1/2, eta >= 0");
  if (support) {
    support->vertical.validate("track.support.vertical");
    support->lateral.validate("track.support.lateral");
    support->longitudinal.validate("track.support.longitudinal");
    if (!(support->sleeper_spacing > 0.0))
      throw InputError("rail_support", "sleeper spacing must be > 0");
  }
}

RailWaveguide::RailWaveguide(fem::QuadraticTriangleMesh mesh, const RailMaterial& material,
                             std::optional<FootSupport> support)
    : mesh_(std::move(mesh)), material_(material), support_(std::move(support)) {
  check_rail_inputs(material_, support_);
  const int nn = static_cast<int>(mesh_.nodes.size());
  apply_basis(Eigen::MatrixXd::Identity(nn, nn), Eigen::MatrixXd::Identity(2 * nn, 2 * nn), true);
}

namespace {

// Eq. (W1) in physical nodal components (u'_x, u_y, u_z per node) and the foot integral.
struct FullMatrices {
  Eigen::MatrixXd k0, k1, k2, m;
  Eigen::MatrixXd foot;  // Int_foot N^T N ds / (L b), nodes x nodes (zero without support)
};

FullMatrices assemble_full(const fem::QuadraticTriangleMesh& mesh, const RailMaterial& material,
                           const std::optional<FootSupport>& support) {
  const int nn = static_cast<int>(mesh.nodes.size()), n = 3 * nn;
  FullMatrices f;
  f.k0 = f.k1 = f.k2 = f.m = Eigen::MatrixXd::Zero(n, n);
  const Matrix6 D = elasticity(material);
  Strain18 B1, B2;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    Eigen::Matrix<double, 18, 18> e0 = Eigen::Matrix<double, 18, 18>::Zero(), e1 = e0, e2 = e0,
                                  em = e0;
    for (const SectionPoint& p : section_points(mesh, t)) {
      strain_operators(p, B1, B2);
      const Strain18 DB1 = D * B1, DB2 = D * B2;
      e0 += p.weight * B1.transpose() * DB1;
      e1 += p.weight * (B1.transpose() * DB2 + B2.transpose() * DB1);
      e2 += p.weight * B2.transpose() * DB2;
      const Matrix6 NN = p.weight * material.density * p.shape * p.shape.transpose();
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
          for (int d = 0; d < 3; ++d) em(3 * a + d, 3 * b + d) += NN(a, b);
    }
    const auto& tri = mesh.triangles[t];
    for (int a = 0; a < 18; ++a)
      for (int b = 0; b < 18; ++b) {
        const int i = 3 * tri[a / 3] + a % 3, j = 3 * tri[b / 3] + b % 3;
        f.k0(i, j) += e0(a, b);
        f.k1(i, j) += e1(a, b);
        f.k2(i, j) += e2(a, b);
        f.m(i, j) += em(a, b);
      }
  }
  // Foot: the boundary edges along the lowest z; Int N^T N ds / (L b) (3-point Gauss, exact).
  f.foot = Eigen::MatrixXd::Zero(nn, nn);
  if (!support) return f;
  double zmin = mesh.nodes[0].y(), zmax = zmin;
  for (const auto& p : mesh.nodes) zmin = std::min(zmin, p.y()), zmax = std::max(zmax, p.y());
  const double tol = 1e-6 * (zmax - zmin);
  double width = 0.0;
  const double g = std::sqrt(0.6), gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}, gx[3] = {-g, 0.0, g};
  for (const auto& e : mesh.boundary_edges) {
    bool on_foot = true;
    for (int v : e) on_foot = on_foot && std::abs(mesh.nodes[v].y() - zmin) < tol;
    if (!on_foot) continue;
    const double len = (mesh.nodes[e[2]] - mesh.nodes[e[0]]).norm();
    width += len;
    for (int q = 0; q < 3; ++q) {
      const Eigen::Vector3d N = line3_shape(gx[q]);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) f.foot(e[a], e[b]) += gw[q] * 0.5 * len * N(a) * N(b);
    }
  }
  if (!(width > 0.0)) throw InputError("rail_section", "the rail section has no flat foot");
  f.foot /= support->sleeper_spacing * width;
  return f;
}

// The physical dofs in the generalised order: all u'_x (node order), then (u_y, u_z) per node.
Eigen::VectorXi axial_first(int nn) {
  Eigen::VectorXi p(3 * nn);
  for (int i = 0; i < nn; ++i)
    p(i) = RailWaveguide::dof(i, 0), p(nn + 2 * i) = RailWaveguide::dof(i, 1),
    p(nn + 2 * i + 1) = RailWaveguide::dof(i, 2);
  return p;
}

// An orthonormal basis of the span of `columns` (each normalised first; rank-revealing QR).
Eigen::MatrixXd orthonormal_span(Eigen::MatrixXd columns) {
  for (int j = 0; j < columns.cols(); ++j) {
    const double norm = columns.col(j).norm();
    if (norm > 0.0) columns.col(j) /= norm;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(columns);
  qr.setThreshold(1e-9);
  const int rank = static_cast<int>(qr.rank());
  return Eigen::MatrixXd(qr.householderQ()) * Eigen::MatrixXd::Identity(columns.rows(), rank);
}

}  // namespace

void RailWaveguide::apply_basis(const Eigen::MatrixXd& vx, const Eigen::MatrixXd& vs,
                                bool identity) {
  const FullMatrices f = assemble_full(mesh_, material_, support_);
  const int nn = static_cast<int>(mesh_.nodes.size()), mx = static_cast<int>(vx.cols()),
            m = mx + static_cast<int>(vs.cols());
  const Eigen::VectorXi p = axial_first(nn);
  Eigen::MatrixXd V;  // in the axial-first order (the unreduced model: none, V^T K V = K)
  if (!identity) {
    V = Eigen::MatrixXd::Zero(3 * nn, m);
    V.topLeftCorner(nn, mx) = vx;
    V.bottomRightCorner(2 * nn, m - mx) = vs;
  }
  auto project = [&](const Eigen::MatrixXd& k) -> Eigen::MatrixXd {
    if (identity) return k(p, p);
    return V.transpose() * k(p, p) * V;
  };
  k0_ = project(f.k0);
  k1_ = project(f.k1);
  k2_ = project(f.k2);
  m_ = project(f.m);
  for (int d = 0; d < 3; ++d) {
    Eigen::MatrixXd foot = Eigen::MatrixXd::Zero(3 * nn, 3 * nn);
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b) foot(dof(a, d), dof(b, d)) = f.foot(a, b);
    foot_[d] = project(foot);
  }
  basis_x_ = vx;
  basis_s_ = vs;
  axial_ = mx;
}

namespace {

// The static responses' shift (rad/s)^2 (the free rail's rigid modes at k = 0: K + shift M is
// positive definite).
const double kStaticShift = std::pow(2.0 * M_PI * 10.0, 2);

// The support's static stiffness on the full model's nodal degrees of freedom.
Eigen::MatrixXd static_support(const FullMatrices& f, const std::optional<FootSupport>& support,
                               int nn) {
  Eigen::MatrixXd ks = Eigen::MatrixXd::Zero(3 * nn, 3 * nn);
  if (support) {
    const double K[3] = {support->longitudinal.dynamic_stiffness(0.0).real(),
                         support->lateral.dynamic_stiffness(0.0).real(),
                         support->vertical.dynamic_stiffness(0.0).real()};
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b)
        for (int d = 0; d < 3; ++d)
          ks(RailWaveguide::dof(a, d), RailWaveguide::dof(b, d)) = K[d] * f.foot(a, b);
  }
  return ks;
}

}  // namespace

RailReduction near_field_reduction() {
  RailReduction r;
  r.max_frequency = 12000.0;
  r.static_wavenumbers = {0.0, 100.0, 400.0, 1200.0};
  return r;
}

namespace {

// LAPACK's dstevx: selected eigenpairs of a symmetric tridiagonal matrix by bisection and inverse
// iteration (Anderson et al., LAPACK Users' Guide, 3rd ed. 1999, Sec. 2.4.4).
extern "C" void dstevx_(const char* jobz, const char* range, const int* n, double* d, double* e,
                        const double* vl, const double* vu, const int* il, const int* iu,
                        const double* abstol, int* m, double* w, double* z, const int* ldz,
                        double* work, int* iwork, int* ifail, int* info);

// The modes K phi = lambda M phi with lambda <= lambda_max, M-orthonormal, ascending; `mass` the
// Cholesky factor M = L L^T. As the dense generalized solver (C = L^{-1} K L^{-T} = Q T Q^T,
// Householder tridiagonalization; Golub & Van Loan, Matrix Computations, 4th ed. 2013, Sec. 8.3
// and 8.7.2) but only the wanted eigenvectors of T, by bisection and inverse iteration, instead of
// all of them by the QL iteration: the section has ~45 modes below 12 kHz of n = 675.
std::vector<Eigen::VectorXd> section_modes_below(const Eigen::LLT<Eigen::MatrixXd>& mass,
                                                 const Eigen::MatrixXd& K, double lambda_max) {
  const int n = static_cast<int>(K.rows());
  Eigen::MatrixXd C = mass.matrixL().solve(K);
  C = mass.matrixL().solve(C.transpose()).transpose();
  const Eigen::Tridiagonalization<Eigen::MatrixXd> tri(C);
  Eigen::VectorXd d = tri.diagonal(), e(std::max(1, n - 1));
  if (n > 1) e.head(n - 1) = tri.subDiagonal();
  // vl below the lowest eigenvalue (Gershgorin bound of T), vu = lambda_max
  double lowest = 0.0;
  for (int i = 0; i < n; ++i)
    lowest = std::min(
        lowest, d(i) - (i > 0 ? std::abs(e(i - 1)) : 0.0) - (i + 1 < n ? std::abs(e(i)) : 0.0));
  const double vl = lowest - 1.0 - 1e-6 * std::abs(lowest), vu = lambda_max, abstol = 0.0;
  const int one = 1;
  int found = 0, info = 0;
  Eigen::VectorXd w(n);
  Eigen::MatrixXd Z(n, n);
  std::vector<double> work(5 * n);
  std::vector<int> iwork(5 * n), ifail(n);
  {
    const linalg::LapackSection lapack;  // lapack_section.hpp
    dstevx_("V", "V", &n, d.data(), e.data(), &vl, &vu, &one, &one, &abstol, &found, w.data(),
            Z.data(), &n, work.data(), iwork.data(), ifail.data(), &info);
  }
  if (info != 0)
    throw NumericalError("rail waveguide: cross-section eigensolver failed (LAPACK dstevx, info " +
                         std::to_string(info) + ")");
  if (found == 0) return {};  // none below lambda_max (high k); Eigen's solve of 0 columns is UB
  Eigen::MatrixXd modes = tri.matrixQ() * Z.leftCols(found);  // eigenvectors of C
  modes = mass.matrixU().solve(modes);                        // phi = L^{-T} z
  std::vector<Eigen::VectorXd> out;
  for (int j = 0; j < found; ++j) out.push_back(modes.col(j));
  return out;
}

}  // namespace

RailReductionModes RailWaveguide::reduction_modes(const RailReduction& reduction) const {
  if (reduction.wavenumbers.empty() || !(reduction.max_frequency > 0.0))
    throw InputError("rail_reduction", "at least one wavenumber and a positive cut-off frequency");
  const FullMatrices f = assemble_full(mesh_, material_, support_);
  const Eigen::MatrixXd ks = static_support(f, support_, static_cast<int>(mesh_.nodes.size()));
  const double lambda_max = std::pow(2.0 * M_PI * reduction.max_frequency, 2);
  const Eigen::LLT<Eigen::MatrixXd> mass(f.m);  // the same at every wavenumber
  if (mass.info() != Eigen::Success)
    throw NumericalError("rail waveguide: the section's mass matrix is not positive definite");
  RailReductionModes out;
  for (double k : reduction.wavenumbers)
    out.modes.push_back(section_modes_below(mass, f.k0 + k * f.k1 + k * k * f.k2 + ks, lambda_max));
  // the static solves' factors, the same for every set of loads
  for (double k : reduction.static_wavenumbers.empty() ? reduction.wavenumbers
                                                       : reduction.static_wavenumbers) {
    out.static_factors.emplace_back(f.k0 + k * f.k1 + k * k * f.k2 + ks + kStaticShift * f.m);
    if (out.static_factors.back().info() != Eigen::Success)
      throw NumericalError("rail waveguide: the static stiffness is not positive definite");
  }
  return out;
}

RailWaveguide RailWaveguide::reduced(const RailReduction& reduction,
                                     const Eigen::MatrixXd& loads) const {
  return reduced(reduction, loads, reduction_modes(reduction));
}

RailWaveguide RailWaveguide::reduced(const RailReduction& reduction, const Eigen::MatrixXd& loads,
                                     const RailReductionModes& modes) const {
  if (loads.rows() != dofs())
    throw InputError("rail_reduction", "loads need one row per nodal degree of freedom");
  if (modes.modes.size() != reduction.wavenumbers.size())
    throw InputError("rail_reduction", "the modes are not of this reduction's wavenumbers");
  const FullMatrices f = assemble_full(mesh_, material_, support_);
  const int nn = static_cast<int>(mesh_.nodes.size()), n = 3 * nn;
  const Eigen::MatrixXd ks = static_support(f, support_, nn);  // the support's static stiffness
  // In the rotated variables the load is T^* f = f_s - i f_x and K(k) is real: the static
  // responses to the u_x part and to the (u_y, u_z) part of each load span the response.
  Eigen::MatrixXd split = Eigen::MatrixXd::Zero(n, 2 * loads.cols());
  for (int i = 0; i < n; ++i)
    split.row(i).segment(i % 3 == 0 ? 0 : loads.cols(), loads.cols()) = loads.row(i);
  std::vector<Eigen::VectorXd> vectors;
  std::size_t statics = 0;  // static wavenumbers done (the factors of `modes` in this order)
  auto add_static_responses = [&](double k) {
    const Eigen::MatrixXd u =
        statics < modes.static_factors.size()
            ? modes.static_factors[statics].solve(split)
            : Eigen::LLT<Eigen::MatrixXd>(f.k0 + k * f.k1 + k * k * f.k2 + ks + kStaticShift * f.m)
                  .solve(split);
    ++statics;
    for (int j = 0; j < u.cols(); ++j) vectors.push_back(u.col(j));
  };
  const bool statics_with_modes = reduction.static_wavenumbers.empty();
  for (std::size_t i = 0; i < reduction.wavenumbers.size(); ++i) {
    for (const Eigen::VectorXd& v : modes.modes[i]) vectors.push_back(v);
    if (statics_with_modes) add_static_responses(reduction.wavenumbers[i]);
  }
  for (double k : reduction.static_wavenumbers) add_static_responses(k);
  const Eigen::VectorXi p = axial_first(nn);
  Eigen::MatrixXd cx(nn, vectors.size()), cs(2 * nn, vectors.size());
  for (std::size_t j = 0; j < vectors.size(); ++j) {
    const Eigen::VectorXd v = vectors[j](p);
    cx.col(j) = v.head(nn);
    cs.col(j) = v.tail(2 * nn);
  }
  RailWaveguide r = *this;
  r.apply_basis(orthonormal_span(cx), orthonormal_span(cs));
  return r;
}

Eigen::MatrixXcd RailWaveguide::support_stiffness(cdouble omega) const {
  Eigen::MatrixXcd ks = Eigen::MatrixXcd::Zero(coordinates(), coordinates());
  if (!support_) return ks;
  const cdouble K[3] = {support_->longitudinal.dynamic_stiffness(omega),
                        support_->lateral.dynamic_stiffness(omega),
                        support_->vertical.dynamic_stiffness(omega)};
  for (int d = 0; d < 3; ++d) ks += K[d] * foot_[d].cast<cdouble>();
  return ks;
}

Eigen::MatrixXd RailWaveguide::project(const Eigen::MatrixXd& f) const {
  const int nn = static_cast<int>(mesh_.nodes.size());
  const Eigen::MatrixXd g = f(axial_first(nn), Eigen::all);
  Eigen::MatrixXd q(coordinates(), f.cols());
  q.topRows(axial_) = basis_x_.transpose() * g.topRows(nn);
  q.bottomRows(coordinates() - axial_) = basis_s_.transpose() * g.bottomRows(2 * nn);
  return q;
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

Eigen::MatrixXcd RailWaveguide::pencil_solve(const Eigen::MatrixXcd& g) const {
  // B = (1 + i eta) [K2x 0; K1c^T K2s] is block lower-triangular with SPD diagonal blocks:
  // x_x = K2x^{-1} g_x / (1 + i eta), x_s = K2s^{-1} (g_s / (1 + i eta) - K1c^T x_x).
  const int m = coordinates(), mx = axial_, ms = m - mx;
  const cdouble damp(1.0, material_.loss_factor);
  const Eigen::MatrixXd K1c = k1_.topRightCorner(mx, ms);
  const Eigen::LLT<Eigen::MatrixXd> K2x(k2_.topLeftCorner(mx, mx)),
      K2s(k2_.bottomRightCorner(ms, ms));
  auto solve = [](const Eigen::LLT<Eigen::MatrixXd>& llt, const Eigen::MatrixXcd& r) {
    Eigen::MatrixXcd x(r.rows(), r.cols());
    x.real() = llt.solve(r.real());
    x.imag() = llt.solve(r.imag());
    return x;
  };
  Eigen::MatrixXcd x(m, g.cols());
  x.topRows(mx) = solve(K2x, g.topRows(mx)) / damp;
  x.bottomRows(ms) = solve(K2s, g.bottomRows(ms) / damp - K1c.transpose() * x.topRows(mx));
  return x;
}

Eigen::MatrixXcd RailWaveguide::pencil(cdouble omega) const {
  // Eq. (W5): K0, K2, M and the support couple no q_x with q_s, K1 only those; with
  // phi = (k v, q_s) the quadratic problem becomes the linear pencil in lambda = k^2
  //   [Ax C; 0 As] z + lambda [Bx 0; C^T Bs] z = 0,  z = (v, q_s),
  // solved as the standard problem B^{-1} A z = -lambda z (B block-triangular, K2's blocks SPD).
  const int m = coordinates(), mx = axial_, ms = m - mx;
  const cdouble damp(1.0, material_.loss_factor);
  const Eigen::MatrixXcd A0 =
      damp * k0_.cast<cdouble>() - omega * omega * m_.cast<cdouble>() + support_stiffness(omega);
  Eigen::MatrixXcd A(m, m);  // rows, columns ordered (v, q_s)
  A << A0.topLeftCorner(mx, mx), damp * k1_.topRightCorner(mx, ms).cast<cdouble>(),
      Eigen::MatrixXcd::Zero(ms, mx), A0.bottomRightCorner(ms, ms);
  return pencil_solve(A);
}

RailWaves RailWaveguide::waves(cdouble omega) const {
  const int m = coordinates(), mx = axial_, ms = m - mx;
  const cdouble damp(1.0, material_.loss_factor);
  Eigen::MatrixXcd Y = pencil(omega);
  Eigen::VectorXcd mu;
  Eigen::MatrixXcd Z;
  eigen_decomposition(std::move(Y), mu, Z);

  RailWaves w;
  w.omega = omega;
  w.wavenumbers.resize(m);
  w.shapes.resize(m, m);
  for (int j = 0; j < m; ++j) {
    const cdouble root = std::sqrt(-mu(j));
    w.wavenumbers(j) = root.imag() > 0.0 ? -root : root;
  }
  // Im omega > 0 (Re s < 0): the member of each pair that continues the wave from Re omega
  const std::vector<bool> flip = continued_branch(omega, w.wavenumbers);
  for (int j = 0; j < m; ++j) {
    if (flip[static_cast<std::size_t>(j)]) w.wavenumbers(j) = -w.wavenumbers(j);
    w.shapes.col(j).head(mx) = w.wavenumbers(j) * Z.col(j).head(mx);
    w.shapes.col(j).tail(ms) = Z.col(j).tail(ms);
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
  w.norms.resize(m);
  for (int j = 0; j < m; ++j) {
    const cdouble k = w.wavenumbers(j);
    const Eigen::VectorXcd dq = damp * (2.0 * k * K2Phi.col(j) + K1Phi.col(j));
    w.norms(j) = w.shapes.col(j).transpose() * dq;
    // An undamped propagating root (real omega) travels towards +x if its group velocity is
    // positive; else its partner -k, P phi does (Q'(-k) P phi = -P Q'(k) phi, so d changes sign).
    if (omega.imag() == 0.0 && std::abs(k.imag()) <= 1e-7 * std::abs(k) &&
        w.shapes.col(j).dot(dq).real() / w.shapes.col(j).dot(MPhi.col(j)).real() < 0.0) {
      w.wavenumbers(j) = -k;
      w.shapes.col(j).head(mx) *= -1.0;
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
  Eigen::MatrixXcd r = project(response).cast<cdouble>(), f = project(load).cast<cdouble>();
  r.topRows(axial_) *= I * sign;
  f.topRows(axial_) *= -I * sign;
  const Eigen::MatrixXcd Y = w.shapes.transpose() * r, Z = w.shapes.transpose() * f;
  Eigen::VectorXcd weight(w.wavenumbers.size());
  for (int j = 0; j < weight.size(); ++j)
    weight(j) = -I * std::exp(-I * w.wavenumbers(j) * std::abs(x)) / w.norms(j);
  return Y.transpose() * weight.asDiagonal() * Z;
}

Eigen::MatrixXd RailWaveguide::contact_loads(int node, const Eigen::Vector2d& normal,
                                             double head_bottom) const {
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(static_cast<int>(mesh_.nodes.size()));
  weights(node) = 1.0;
  return nodal_loads(weights, normal, head_bottom);
}

Eigen::MatrixXd RailWaveguide::patch_loads(const Eigen::Vector2d& point, double half_width,
                                           const Eigen::Vector2d& normal,
                                           double head_bottom) const {
  // The part of each straight boundary edge r(xi) = c + xi d, xi in [-1, 1], inside the disc
  // |r - point| <= a: |d|^2 xi^2 + 2 d.(c - point) xi + |c - point|^2 - a^2 <= 0; Int N ds over
  // it by 3-point Gauss (exact for the quadratic N).
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(static_cast<int>(mesh_.nodes.size()));
  double length = 0.0;
  const double g = std::sqrt(0.6), gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}, gx[3] = {-g, 0.0, g};
  for (const auto& e : mesh_.boundary_edges) {
    const Eigen::Vector2d c = 0.5 * (mesh_.nodes[e[0]] + mesh_.nodes[e[2]]),
                          d = 0.5 * (mesh_.nodes[e[2]] - mesh_.nodes[e[0]]);
    const double qa = d.squaredNorm(), qb = d.dot(c - point),
                 qc = (c - point).squaredNorm() - half_width * half_width;
    const double disc = qb * qb - qa * qc;
    if (disc <= 0.0) continue;
    const double lo = std::max(-1.0, (-qb - std::sqrt(disc)) / qa),
                 hi = std::min(1.0, (-qb + std::sqrt(disc)) / qa);
    if (!(hi > lo)) continue;
    const double jac = d.norm() * 0.5 * (hi - lo);
    for (int q = 0; q < 3; ++q) {
      const Eigen::Vector3d N = line3_shape(0.5 * (lo + hi) + 0.5 * (hi - lo) * gx[q]);
      for (int a = 0; a < 3; ++a) weights(e[a]) += gw[q] * jac * N(a);
    }
    length += jac * 2.0;
  }
  if (!(length > 0.0))
    throw InputError("rail_contact", "the load patch does not reach the rail's outline");
  return nodal_loads(weights / length, normal, head_bottom);
}

Eigen::MatrixXd RailWaveguide::nodal_loads(const Eigen::VectorXd& weights,
                                           const Eigen::Vector2d& normal,
                                           double head_bottom) const {
  const Eigen::Vector2d n = normal.normalized(), t(n.y(), -n.x());
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(dofs(), 4);
  for (int node = 0; node < weights.size(); ++node) {
    if (weights(node) == 0.0) continue;
    L(dof(node, 1), kZ) = weights(node) * n.x();
    L(dof(node, 2), kZ) = weights(node) * n.y();
    L(dof(node, 0), kX) = weights(node);
    L(dof(node, 1), kY) = weights(node) * t.x();
    L(dof(node, 2), kY) = weights(node) * t.y();
  }
  // psi_n = -t . b, b the gradient of the plane u_x = a + b . (r - r_h) fitted over the head
  // (least squares over the triangles whose centroid lies at z >= head_bottom):
  // b = I_h^{-1} Int_head (r - r_h) u_x dA, I_h = Int_head (r - r_h)(r - r_h)^T dA; its work
  // conjugates are the head body's distributions 4 and 5 (head_body).
  const HeadBody h = head_body(head_bottom);
  const Eigen::Vector2d c = -h.inertia.inverse() * t;  // psi_n = c . Int (r - r_h) u_x dA
  L.col(kRotZ) = c.x() * h.loads.col(4) + c.y() * h.loads.col(5);
  return L;
}

HeadBody RailWaveguide::head_body(double head_bottom) const {
  return dynamics::head_body(mesh_, head_bottom);
}

HeadBody head_body(const fem::QuadraticTriangleMesh& mesh, double head_bottom) {
  // The head's rigid motion by least squares over its area A (centroid r_h, s = r - r_h): the
  // mean u; the roll theta = Int (s_y u_z - s_z u_y) dA / J, J = Int |s|^2 dA; u_x's plane
  // a + b . s, b = I_h^{-1} Int s u_x dA. The six distributions are the work-conjugates of
  // (mean u_y, mean u_z, theta J, mean u_x, Int s_y u_x dA, Int s_z u_x dA).
  std::vector<int> head;
  double area = 0.0;
  Eigen::Vector2d first(0.0, 0.0);
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (int tri = 0; tri < static_cast<int>(mesh.triangles.size()); ++tri) {
    Eigen::Vector2d c(0.0, 0.0);
    for (int a = 0; a < 3; ++a) c += mesh.nodes[mesh.triangles[tri][a]] / 3.0;
    if (c.y() < head_bottom) continue;
    head.push_back(tri);
    for (const SectionPoint& p : section_points(mesh, tri)) {
      area += p.weight;
      first += p.weight * p.position;
      second += p.weight * p.position * p.position.transpose();
    }
  }
  if (head.empty()) throw InputError("rail_section", "no triangle of the rail head above it");
  HeadBody h;
  h.area = area;
  h.centroid = first / area;
  h.inertia = second - area * h.centroid * h.centroid.transpose();
  const double J = h.inertia.trace();
  h.loads = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(mesh.nodes.size()), 6);
  for (int tri : head)
    for (const SectionPoint& p : section_points(mesh, tri)) {
      const Eigen::Vector2d s = p.position - h.centroid;
      for (int b = 0; b < 6; ++b) {
        const int node = mesh.triangles[tri][b];
        const double w = p.weight * p.shape(b);
        h.loads(RailWaveguide::dof(node, 1), 0) += w / area;
        h.loads(RailWaveguide::dof(node, 2), 1) += w / area;
        h.loads(RailWaveguide::dof(node, 1), 2) -= w * s.y() / J;
        h.loads(RailWaveguide::dof(node, 2), 2) += w * s.x() / J;
        h.loads(RailWaveguide::dof(node, 0), 3) += w / area;
        h.loads(RailWaveguide::dof(node, 0), 4) += w * s.x();
        h.loads(RailWaveguide::dof(node, 0), 5) += w * s.y();
      }
    }
  return h;
}

Eigen::Matrix<double, 6, 4> HeadBody::at(const Eigen::Vector2d& point,
                                         const Eigen::Vector2d& normal) const {
  // At the point (d = point - r_h) the in-plane motion is mean + theta (-d_z, d_y) and u_x = a +
  // b . d; the spin psi_n = -t . b (contact_loads).
  const Eigen::Vector2d n = normal.normalized(), t(n.y(), -n.x()), d = point - centroid;
  const Eigen::Matrix2d Ihi = inertia.inverse();
  const Eigen::Vector2d bx = Ihi * d, bs = -Ihi * t;
  Eigen::Matrix<double, 6, 4> C = Eigen::Matrix<double, 6, 4>::Zero();
  C.col(kZ) << n.x(), n.y(), -d.y() * n.x() + d.x() * n.y(), 0.0, 0.0, 0.0;
  C.col(kX) << 0.0, 0.0, 0.0, 1.0, bx.x(), bx.y();
  C.col(kY) << t.x(), t.y(), -d.y() * t.x() + d.x() * t.y(), 0.0, 0.0, 0.0;
  C.col(kRotZ) << 0.0, 0.0, 0.0, 0.0, bs.x(), bs.y();
  return C;
}

Eigen::MatrixXd RailWaveguide::head_loads(const Eigen::Vector2d& point,
                                          const Eigen::Vector2d& normal, double head_bottom) const {
  const HeadBody h = head_body(head_bottom);
  return h.loads * h.at(point, normal);
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

Eigen::MatrixXcd RailWaveguide::wave_amplitudes(const RailWaves& w, const Eigen::MatrixXd& d,
                                                double sign) const {
  // As transfer(): the response side's rotation i s on u_x (the load side's -i s = i (-s)).
  Eigen::MatrixXcd q = project(d).cast<cdouble>();
  q.topRows(axial_) *= cdouble(0.0, sign < 0.0 ? -1.0 : 1.0);
  return w.shapes.transpose() * q;
}

}  // namespace rollnoise::dynamics
