// Restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad, Iterative Methods for
// Sparse Linear Systems, 2nd ed., Alg. 9.5), for dense Eigen operators.
//
// Solves A x = b for x, with the preconditioner M ~ A applied as x = M^{-1} y: the Krylov space is
// built on A M^{-1}, so the residual that is minimised is the true one. Used for the Newton steps of
// the steady tangential problem, preconditioned by the LU factors of an earlier Jacobian.
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace rollnoise::linalg {

struct GmresResult {
  int iterations = 0;
  double relative_residual = 0.0;
  bool converged = false;
};

/// `apply(v)` returns A v; `precondition(v)` returns M^{-1} v. x holds the start on entry.
template <class Apply, class Precondition>
GmresResult gmres(const Apply& apply, const Precondition& precondition, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x, double tolerance, int max_iterations) {
  GmresResult res;
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    x.setZero();
    res.converged = true;
    return res;
  }
  const int m = max_iterations;
  Eigen::VectorXd r = b - apply(x);
  double beta = r.norm();
  res.relative_residual = beta / bnorm;
  if (res.relative_residual <= tolerance) {
    res.converged = true;
    return res;
  }
  Eigen::MatrixXd V(b.size(), m + 1), H = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd cs(m), sn(m), g = Eigen::VectorXd::Zero(m + 1);
  V.col(0) = r / beta;
  g(0) = beta;
  int k = 0;
  for (; k < m; ++k) {
    Eigen::VectorXd w = apply(precondition(V.col(k)));
    for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
      H(i, k) = w.dot(V.col(i));
      w -= H(i, k) * V.col(i);
    }
    H(k + 1, k) = w.norm();
    if (H(k + 1, k) > 0.0) V.col(k + 1) = w / H(k + 1, k);
    for (int i = 0; i < k; ++i) {  // apply the earlier Givens rotations
      const double t = cs(i) * H(i, k) + sn(i) * H(i + 1, k);
      H(i + 1, k) = -sn(i) * H(i, k) + cs(i) * H(i + 1, k);
      H(i, k) = t;
    }
    const double d = std::hypot(H(k, k), H(k + 1, k));
    cs(k) = H(k, k) / d;
    sn(k) = H(k + 1, k) / d;
    H(k, k) = d;
    H(k + 1, k) = 0.0;
    g(k + 1) = -sn(k) * g(k);
    g(k) = cs(k) * g(k);
    res.relative_residual = std::abs(g(k + 1)) / bnorm;
    if (res.relative_residual <= tolerance || H(k, k) == 0.0) {
      ++k;
      break;
    }
  }
  const Eigen::VectorXd y = H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  x += precondition(V.leftCols(k) * y);
  res.iterations = k;
  res.converged = res.relative_residual <= tolerance;
  return res;
}

}  // namespace rollnoise::linalg
