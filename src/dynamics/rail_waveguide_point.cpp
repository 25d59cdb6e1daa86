// The waveguide rail's point receptance (x = 0) by Eq. (W6) of rail_waveguide.hpp: the diagonal
// blocks of 1/2 Y^{-1/2} B^{-1}, Y^{-1/2} from the Schur form of Eq. (W5)'s Y, instead of the
// residue sum of Eq. (W4) over Y's eigenvectors (RailWaveguide::waves). The Schur form is the
// eigenproblem without its last steps (the triangular eigenvectors, LAPACK ztrevc3, and their
// back-transformation), and Eq. (W4)'s products of the m waves go too.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "linalg/lapack_section.hpp"

namespace rollnoise::dynamics {

namespace {

// The Schur form A = U T U^H of a general complex matrix (T upper triangular, U unitary): the
// Hessenberg reduction A = Q H Q^H by Householder reflections (Eigen's HessenbergDecomposition;
// Golub & Van Loan, Matrix Computations, 4th ed. 2013, Alg. 7.4.2), then LAPACK's zhseqr
// (Anderson et al., LAPACK Users' Guide, 3rd ed. 1999: the small-bulge multishift QR of Braman,
// Byers & Mathias, SIAM J. Matrix Anal. Appl. 23, 2002) on H, accumulating into Q. Eigen's
// vectorised reduction for n < 128 is faster here than LAPACK's unblocked zgehd2 + zung2r on
// the reference BLAS (zgees' path). On return `a` holds T and `u` the Schur vectors.
extern "C" void zhseqr_(const char* job, const char* compz, const int* n, const int* ilo,
                        const int* ihi, cdouble* h, const int* ldh, cdouble* w, cdouble* z,
                        const int* ldz, cdouble* work, const int* lwork, int* info);

// Diagonal scaling A := D^{-1} A D, D returned, so that each row and column have comparable
// norms: Eq. (W5)'s v = q_x / k and q_s differ in units by a length, so Y's off-diagonal blocks
// are scaled by ~k and 1/k. The iteration of Parlett & Reinsch (Numer. Math. 13, 1969) as LAPACK's
// zgebal does it (job "S", LAPACK 3.11): per index the power of 2 f that brings the column's 2-norm
// c and the row's r closest, applied when it lowers c + r below 0.95 of its value, sweeps until
// none is applied (the overflow guards dropped: the entries here are far from the range's ends).
// In Eigen: zgebal on the reference BLAS (its norms by dznrm2) took ~3x as long, same factors.
Eigen::VectorXd balance(Eigen::MatrixXcd& a) {
  constexpr double radix = 2.0, factor = 0.95;
  const int n = static_cast<int>(a.rows());
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  for (bool converged = false; !converged;) {
    converged = true;
    for (int i = 0; i < n; ++i) {
      double c = a.col(i).norm(), r = a.row(i).norm();
      if (c == 0.0 || r == 0.0) continue;
      const double s = c + r;
      double f = 1.0;
      while (c < r / radix) f *= radix, c *= radix, r /= radix;
      while (c / radix >= r) f /= radix, c /= radix, r *= radix;
      if (c + r >= factor * s) continue;
      d(i) *= f;
      a.row(i) /= f;
      a.col(i) *= f;
      converged = false;
    }
  }
  return d;
}

void schur_form(Eigen::MatrixXcd& a, Eigen::MatrixXcd& u) {
  const int n = static_cast<int>(a.rows()), one = 1;
  {
    const Eigen::HessenbergDecomposition<Eigen::MatrixXcd> hessenberg(a);
    a = hessenberg.matrixH();
    u = hessenberg.matrixQ();
  }
  Eigen::VectorXcd w(n);
  cdouble query;
  int info = 0, lwork = -1;
  const linalg::LapackSection lapack;  // lapack_section.hpp: not every LAPACK is reentrant
  zhseqr_("S", "V", &n, &one, &n, a.data(), &n, w.data(), u.data(), &n, &query, &lwork, &info);
  lwork = std::max(1, static_cast<int>(query.real()));
  std::vector<cdouble> work(lwork);
  zhseqr_("S", "V", &n, &one, &n, a.data(), &n, w.data(), u.data(), &n, work.data(), &lwork, &info);
  if (info != 0)
    throw NumericalError("rail waveguide: LAPACK zhseqr failed (info = " + std::to_string(info) +
                         ") on the " + std::to_string(n) + " x " + std::to_string(n) +
                         " wavenumber eigenproblem");
}

// The principal square root S of an upper triangular T (S^2 = T, Re S_ii >= 0) by the recurrence
// of Bjorck & Hammarling (Linear Algebra Appl. 52/53, 1983; Higham, Functions of Matrices, 2008,
// Alg. 6.3): S_ii = sqrt(T_ii), S_ij = (T_ij - sum_{i<l<j} S_il S_lj) / (S_ii + S_jj), column by
// column, each column bottom-up.
Eigen::MatrixXcd principal_sqrt_upper(const Eigen::MatrixXcd& t) {
  const int n = static_cast<int>(t.rows());
  Eigen::MatrixXcd s = Eigen::MatrixXcd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    s(j, j) = std::sqrt(t(j, j));
    for (int i = j - 1; i >= 0; --i) {
      const int len = j - i - 1;  // sum_{i<l<j} S_il S_lj, without conjugation
      const cdouble sum = len > 0
                              ? cdouble(s.row(i).segment(i + 1, len) * s.col(j).segment(i + 1, len))
                              : cdouble(0.0);
      s(i, j) = (t(i, j) - sum) / (s(i, i) + s(j, j));
    }
  }
  return s;
}

// The eigenvalues alone of a general complex matrix: balanced, the Hessenberg form (Eigen), then
// zhseqr without the Schur form and vectors (job "E", compz "N").
Eigen::VectorXcd eigenvalues_only(Eigen::MatrixXcd a) {
  const int n = static_cast<int>(a.rows()), one = 1;
  balance(a);
  a = Eigen::HessenbergDecomposition<Eigen::MatrixXcd>(a).matrixH();
  Eigen::VectorXcd w(n);
  cdouble query, none;
  int info = 0, lwork = -1;
  const linalg::LapackSection lapack;  // lapack_section.hpp
  zhseqr_("E", "N", &n, &one, &n, a.data(), &n, w.data(), &none, &one, &query, &lwork, &info);
  lwork = std::max(1, static_cast<int>(query.real()));
  std::vector<cdouble> work(lwork);
  zhseqr_("E", "N", &n, &one, &n, a.data(), &n, w.data(), &none, &one, work.data(), &lwork, &info);
  if (info != 0)
    throw NumericalError("rail waveguide: LAPACK zhseqr failed (info = " + std::to_string(info) +
                         ") on the " + std::to_string(n) + " x " + std::to_string(n) +
                         " wavenumber eigenproblem");
  return w;
}

}  // namespace

std::vector<bool> RailWaveguide::continued_branch(cdouble omega, const Eigen::VectorXcd& roots) const {
  std::vector<bool> flip(static_cast<std::size_t>(roots.size()), false);
  if (!(omega.imag() > 0.0)) return flip;  // real omega or Re s > 0: Im k < 0 is the continuation
  const Eigen::VectorXcd mu = eigenvalues_only(pencil(cdouble(omega.real(), 0.0)));
  std::vector<cdouble> reference(static_cast<std::size_t>(mu.size()));
  for (Eigen::Index j = 0; j < mu.size(); ++j) {
    const cdouble root = std::sqrt(-mu(j));
    reference[static_cast<std::size_t>(j)] = root.imag() > 0.0 ? -root : root;
  }
  auto distance = [&](cdouble k) {
    double d = std::numeric_limits<double>::infinity();
    for (const cdouble& r : reference) d = std::min(d, std::abs(k - r));
    return d;
  };
  for (Eigen::Index j = 0; j < roots.size(); ++j)
    flip[static_cast<std::size_t>(j)] = distance(-roots(j)) < distance(roots(j));
  return flip;
}

Eigen::MatrixXcd RailWaveguide::point_transfer(cdouble omega, const Eigen::MatrixXd& response,
                                               const Eigen::MatrixXd& load) const {
  const int m = coordinates(), mx = axial_, ms = m - mx;
  Eigen::MatrixXcd t = pencil(omega), u;
  const Eigen::VectorXd d = balance(t);  // t = D^{-1} Y D
  schur_form(t, u);
  // Eq. (W6) needs Y's eigenvalues mu_j = -k_j^2 off the negative real axis; an undamped
  // propagating wave (RailWaves' test: |Im k| <= 1e-7 |k| at real omega) goes to Eq. (W4).
  if (omega.imag() == 0.0)
    for (int j = 0; j < m; ++j) {
      const cdouble root = std::sqrt(-t(j, j));
      if (std::abs(root.imag()) <= 1e-7 * std::abs(root))
        return transfer(waves(omega), response, load, 0.0);
    }
  // Eq. (W6)'s principal square root takes every root with Im k <= 0; where the continuation to
  // Im omega > 0 takes the other member of a pair (continued_branch), Eq. (W4) with those waves.
  if (omega.imag() > 0.0) {
    Eigen::VectorXcd roots(m);
    for (int j = 0; j < m; ++j) {
      const cdouble root = std::sqrt(-t(j, j));
      roots(j) = root.imag() > 0.0 ? -root : root;
    }
    const std::vector<bool> flip = continued_branch(omega, roots);
    if (std::find(flip.begin(), flip.end(), true) != flip.end())
      return transfer(waves(omega), response, load, 0.0);
  }
  // H = R^T T G'(0) T^* F with T = i on u_x: the rotations cancel on the diagonal blocks, so
  // H = 1/2 (R_x^T W_xx F_x + R_s^T W_ss F_s), W = Y^{-1/2} B^{-1} = U S^{-1} U^H B^{-1},
  // S = T^{1/2}: the loads' u_x and u_s parts as separate columns.
  const Eigen::MatrixXd r = project(response), f = project(load);
  const int c = static_cast<int>(f.cols());
  Eigen::MatrixXcd g = Eigen::MatrixXcd::Zero(m, 2 * c);
  g.topLeftCorner(mx, c) = f.topRows(mx).cast<cdouble>();
  g.bottomRightCorner(ms, c) = f.bottomRows(ms).cast<cdouble>();
  // Y^{-1/2} = D U S^{-1} U^H D^{-1}
  Eigen::MatrixXcd w = u.adjoint() * (d.cwiseInverse().asDiagonal() * pencil_solve(g));
  principal_sqrt_upper(t).triangularView<Eigen::Upper>().solveInPlace(w);
  w = d.asDiagonal() * (u * w);
  return 0.5 * (r.topRows(mx).cast<cdouble>().transpose() * w.topLeftCorner(mx, c) +
                r.bottomRows(ms).cast<cdouble>().transpose() * w.bottomRightCorner(ms, c));
}

}  // namespace rollnoise::dynamics
