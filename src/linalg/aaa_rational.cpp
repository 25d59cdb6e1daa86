#include "linalg/aaa_rational.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"

namespace rollnoise::linalg {

Eigen::RowVectorXcd BarycentricRational::operator()(double x) const {
  const Eigen::Index m = support.size();
  Eigen::VectorXcd c(m);
  for (Eigen::Index j = 0; j < m; ++j) {
    if (x == support(j)) return values.row(j);
    c(j) = weights(j) / (x - support(j));
  }
  return (c.transpose() * values) / c.sum();
}

double aaa_residual(const BarycentricRational& r, const Eigen::VectorXd& x,
                    const Eigen::MatrixXcd& F, const Eigen::MatrixXd& scale) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    worst = std::max(worst,
                     ((r(x(i)) - F.row(i)).cwiseAbs().array() / scale.row(i).array()).maxCoeff());
  return worst;
}

BarycentricRational aaa_fit(const Eigen::VectorXd& x, const Eigen::MatrixXcd& F,
                            const Eigen::MatrixXd& scale, double tolerance, int max_terms) {
  const Eigen::Index n = x.size(), K = F.cols();
  if (n < 2 || F.rows() != n || scale.rows() != n || scale.cols() != K || max_terms < 1 ||
      max_terms >= n)
    throw NumericalError(
        "aaa_fit: at least 2 samples, one row of F and of scale per sample, "
        "1 <= max_terms < samples");
  if (!((scale.array() > 0.0).all())) throw NumericalError("aaa_fit: scales must be > 0");
  std::vector<Eigen::Index> support;
  std::vector<char> in_support(n, 0);
  BarycentricRational r;
  // the first support point: the sample farthest from the mean, as Alg. 3.1 starts from r = mean F
  Eigen::VectorXd residual(n);
  {
    const Eigen::RowVectorXcd mean = F.colwise().mean();
    for (Eigen::Index i = 0; i < n; ++i)
      residual(i) = ((F.row(i) - mean).cwiseAbs().array() / scale.row(i).array()).maxCoeff();
  }
  while (true) {
    Eigen::Index next = 0;
    residual.maxCoeff(&next);
    if (!(residual(next) > tolerance) || static_cast<int>(support.size()) >= max_terms) break;
    support.push_back(next);
    in_support[next] = 1;
    const Eigen::Index m = static_cast<Eigen::Index>(support.size());
    // L^H L of Eq. (A2) over the samples outside the support
    Eigen::MatrixXcd gram = Eigen::MatrixXcd::Zero(m, m);
    Eigen::MatrixXcd rows(K, m);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (in_support[i]) continue;
      for (Eigen::Index j = 0; j < m; ++j) {
        const Eigen::Index s = support[j];
        rows.col(j) = ((F.row(i) - F.row(s)).transpose().array() /
                       (scale.row(i).transpose().array() * (x(i) - x(s))))
                          .matrix();
      }
      gram.noalias() += rows.adjoint() * rows;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eig(gram);
    r.support.resize(m);
    r.values.resize(m, K);
    for (Eigen::Index j = 0; j < m; ++j) {
      r.support(j) = x(support[j]);
      r.values.row(j) = F.row(support[j]);
    }
    r.weights = eig.eigenvectors().col(0);  // the smallest eigenvalue's
    for (Eigen::Index i = 0; i < n; ++i)
      residual(i) =
          in_support[i]
              ? 0.0
              : ((r(x(i)) - F.row(i)).cwiseAbs().array() / scale.row(i).array()).maxCoeff();
  }
  if (support.empty()) {  // every sample within the tolerance of the mean: a constant
    r.support = x.head(1);
    r.weights = Eigen::VectorXcd::Ones(1);
    r.values = F.colwise().mean();
  }
  return r;
}

}  // namespace rollnoise::linalg
