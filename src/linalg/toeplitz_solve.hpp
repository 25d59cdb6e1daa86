// Solve T X = B for a symmetric (complex, not necessarily Hermitian) Toeplitz matrix T, given by
// its first column t (T_ij = t_|i-j|), and a few right-hand sides B, in O(m^2) operations.
//
// Levinson's algorithm (N. Levinson, J. Math. Phys. 25, 1947; Golub & Van Loan, Matrix
// Computations, 4th ed., Alg. 4.7.1 (Durbin) and 4.7.2 (Levinson)), on the normalised matrix
// T / t_0 with r_k = t_k / t_0. It uses only T = T^T and the persymmetry E T E = T (E the
// exchange matrix), so it holds for a complex symmetric T as for a real one, with no conjugation.
// Per order k = 1 .. m-1, with y the solution of the Yule-Walker system T_k y = -r(1:k):
//   beta_k = (1 - alpha_{k-1}^2) beta_{k-1},
//   mu     = (b_{k+1} - r(1:k)^T E x) / beta_k,   x <- [x + mu E y; mu],
//   alpha  = -(r_{k+1} + r(1:k)^T E y) / beta_k,  y <- [y + alpha E y; alpha].
// About 3 m^2 complex multiply-adds for the Durbin part and 2 m^2 per right-hand side, against
// (2/3) m^3 for a dense LU.
//
// Levinson's recursion does not pivot: it needs every leading principal submatrix to be regular
// and is only weakly stable for an indefinite T (Cybenko, SIAM J. Sci. Stat. Comput. 1, 1980). So
// the solution is checked by the residual of one weighted combination of its columns (m^2
// multiply-adds for all of them, below) and `toeplitz_solve` returns false when that relative
// residual exceeds `tolerance` (or a pivot beta_k vanishes); the caller then solves densely.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <vector>

namespace rollnoise::linalg {

namespace toeplitz_detail {
// The complex product without the Annex G recovery of infinities (which blocks inlining and
// vectorisation of the inner loops); the solution is checked by its residual anyway.
inline std::complex<double> mul(std::complex<double> a, std::complex<double> b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}
}  // namespace toeplitz_detail

/// X = T^{-1} B for the symmetric Toeplitz T with first column `t` (m x m, m = t.size()).
/// Returns false (X unspecified) when a Levinson pivot vanishes, X is not finite, or the residual
/// ||T X w - B w|| of the combination w_j = (1 + 0.618 j) / ||b_j|| exceeds `tolerance`.
inline bool toeplitz_solve(const std::vector<std::complex<double>>& t, const Eigen::MatrixXcd& B,
                           Eigen::MatrixXcd& X, double tolerance = 1e-11) {
  using C = std::complex<double>;
  using toeplitz_detail::mul;
  const int m = static_cast<int>(t.size());
  const int nrhs = static_cast<int>(B.cols());
  X.resize(m, nrhs);
  if (m == 0 || t[0] == C(0.0)) return false;
  const C t0 = t[0];
  std::vector<C> r(m), y(m), z(m);
  for (int k = 1; k < m; ++k) r[k - 1] = t[k] / t0;  // r_1 .. r_{m-1} at r[0 .. m-2]
  for (int j = 0; j < nrhs; ++j) X(0, j) = B(0, j) / t0;
  if (m > 1) y[0] = -r[0];
  C alpha = m > 1 ? -r[0] : C(0.0), beta = 1.0;
  for (int k = 1; k < m; ++k) {
    beta *= (1.0 - alpha * alpha);
    if (!(std::abs(beta) > 1e-300) || !std::isfinite(std::abs(beta))) return false;
    for (int j = 0; j < nrhs; ++j) {
      C dot = 0.0;  // r(1:k)^T E x(1:k)
      for (int i = 0; i < k; ++i) dot += mul(r[i], X(k - 1 - i, j));
      const C mu = (B(k, j) / t0 - dot) / beta;
      for (int i = 0; i < k; ++i) X(i, j) += mul(mu, y[k - 1 - i]);
      X(k, j) = mu;
    }
    if (k < m - 1) {
      C dot = 0.0;  // r(1:k)^T E y(1:k)
      for (int i = 0; i < k; ++i) dot += mul(r[i], y[k - 1 - i]);
      alpha = -(r[k] + dot) / beta;
      for (int i = 0; i < k; ++i) z[i] = y[i] + mul(alpha, y[k - 1 - i]);
      for (int i = 0; i < k; ++i) y[i] = z[i];
      y[k] = alpha;
    }
  }
  // The residual check on one combination of the columns, c = sum_j w_j x_j with w_j = (1 + j
  // phi) / ||b_j|| (phi the golden ratio's fractional part: distinct weights, so that two columns'
  // errors do not cancel by symmetry): ||T c - B w|| <= tolerance, i.e. the columns' relative
  // residuals, weighted, sum to no more than the tolerance. One O(m^2) product for all the columns
  // (m^2 per column before): an unstable recursion's residual in one column is cancelled by the
  // others' only by coincidence, and then the pivot check above still stands.
  Eigen::VectorXcd w = Eigen::VectorXcd::Zero(nrhs);
  for (int j = 0; j < nrhs; ++j) {
    const double bn = B.col(j).norm();
    if (bn > 0.0) w(j) = (1.0 + 0.6180339887498949 * j) / bn;
  }
  const Eigen::VectorXcd c = X * w, bw = B * w;
  double res2 = 0.0;
  for (int i = 0; i < m; ++i) {  // (T c)_i = sum_l t_|i-l| c_l
    C s = -bw(i);
    for (int l = 0; l < m; ++l) s += mul(t[std::abs(i - l)], c(l));
    res2 += std::norm(s);
  }
  if (!std::isfinite(res2) || !X.allFinite() || res2 > tolerance * tolerance) return false;
  return true;
}

}  // namespace rollnoise::linalg
