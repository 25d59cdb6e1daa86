// A set of functions sampled on the real line approximated by one barycentric rational (the AAA
// algorithm; Nakatsukasa, Sete & Trefethen, SIAM J. Sci. Comput. 40, 2018, A1494-A1522, Alg. 3.1;
// for a set of functions with one denominator, Lietaert, Meerbergen, Perez & Vandereycken, IMA J.
// Numer. Anal. 42, 2022, Sec. 2):
//
//   r_k(x) = sum_j w_j F_jk / (x - x_j)  /  sum_j w_j / (x - x_j),                         (A1)
//
// the support points x_j a subset of the samples, where r_k interpolates (r_k(x_j) = F_jk). Greedy:
// the sample with the largest scaled residual max_k |r_k(x_i) - F_ik| / s_ik joins the support, and
// the weights w (|w| = 1) minimise the scaled residual's linearisation over the other samples,
//
//   min_|w|=1 || L w ||,  L_(i,k),j = (F_ik - F_jk) / ((x_i - x_j) s_ik),                  (A2)
//
// (the Loewner matrix, one block of rows per function), until every scaled residual is at most
// the tolerance or the support holds `max_terms` points. The weights are the eigenvector of the
// smallest eigenvalue of L^H L (m x m), accumulated row by row: the functions here are few samples
// of many entries (L has many rows, few columns), and the tolerances (1e-3 relative) are far above
// what squaring L's condition number loses.
#pragma once

#include <Eigen/Core>

namespace rollnoise::linalg {

/// Eq. (A1): support points x_j, weights w_j and values F_j (one row per support point, one
/// column per function).
struct BarycentricRational {
  Eigen::VectorXd support;
  Eigen::VectorXcd weights;
  Eigen::MatrixXcd values;
  /// r_k(x) for every function k (the support value where x is a support point).
  Eigen::RowVectorXcd operator()(double x) const;
};

/// Eq. (A2)'s greedy fit of the samples F (n x K) at the distinct x (n), each entry's error
/// measured against scale (n x K, > 0), to `tolerance` or `max_terms` support points (< n).
BarycentricRational aaa_fit(const Eigen::VectorXd& x, const Eigen::MatrixXcd& F,
                            const Eigen::MatrixXd& scale, double tolerance, int max_terms);

/// The largest scaled residual max_(i,k) |r_k(x_i) - F_ik| / scale_ik of `r` over the samples.
double aaa_residual(const BarycentricRational& r, const Eigen::VectorXd& x,
                    const Eigen::MatrixXcd& F, const Eigen::MatrixXd& scale);

}  // namespace rollnoise::linalg
