#include "fem/eigen_solve.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Eigen/SparseCholesky>
#include <Spectra/SymGEigsShiftSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/errors.hpp"

namespace rollnoise::fem {
namespace {

using SpMat = Eigen::SparseMatrix<double>;

// The rows and columns of `a` at the free DOFs (index[dof] >= 0).
SpMat restrict_to(const SpMat& a, const std::vector<int>& index, int nfree) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(a.nonZeros());
  for (int c = 0; c < a.outerSize(); ++c)
    for (SpMat::InnerIterator it(a, c); it; ++it)
      if (index[it.row()] >= 0 && index[it.col()] >= 0)
        t.emplace_back(index[it.row()], index[it.col()], it.value());
  SpMat r(nfree, nfree);
  r.setFromTriplets(t.begin(), t.end());
  return r;
}

// (K - sigma M)^{-1} for Spectra's shift-invert mode by a sparse LDL^T factorisation (K - sigma M
// is symmetric positive definite for sigma below the lowest eigenvalue): the operator interface of
// Spectra::SymShiftInvert, with Eigen's SimplicialLDLT (AMD ordering) in place of its SparseLU.
class ShiftInvertLdlt {
 public:
  using Scalar = double;
  ShiftInvertLdlt(const SpMat& k, const SpMat& m) : k_(k), m_(m) {}
  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }
  void set_shift(double sigma) {
    ldlt_.compute(k_ - sigma * m_);
    if (ldlt_.info() != Eigen::Success)
      throw NumericalError("LDL^T factorisation of K - sigma M failed (shift " + std::to_string(sigma) + ")");
  }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Eigen::VectorXd>(y, rows()) = ldlt_.solve(Eigen::Map<const Eigen::VectorXd>(x, rows()));
  }

 private:
  const SpMat& k_;
  const SpMat& m_;
  Eigen::SimplicialLDLT<SpMat> ldlt_;
};

// Eigenpairs (ascending) of the reduced problem: Spectra's shift-invert Lanczos, or a dense solve
// when the requested count reaches the size of the problem.
std::pair<Eigen::VectorXd, Eigen::MatrixXd> solve_reduced(const SpMat& k, const SpMat& m,
                                                          double lambda_max) {
  const int n = static_cast<int>(k.rows());
  // Shift below zero: K - sigma M is positive definite even with rigid-body modes.
  const double sigma = -std::pow(2 * 3.14159265358979323846 * 10.0, 2);
  for (int nev = std::min(24, n);; nev = std::min(2 * nev, n)) {
    // dense: cheaper than Lanczos with most of the spectrum, and for all modes (omega_max infinite)
    if (nev > n / 2 || n < 60 || !std::isfinite(lambda_max)) {
      const Eigen::MatrixXd kd = k, md = m;
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(kd, md);
      if (dense.info() != Eigen::Success)
        throw NumericalError("dense generalised eigen solve of the FE model failed");
      return {dense.eigenvalues(), dense.eigenvectors()};
    }
    using Op = ShiftInvertLdlt;
    using BOp = Spectra::SparseSymMatProd<double>;
    Op op(k, m);
    BOp bop(m);
    const int ncv = std::min(n, std::max(2 * nev + 1, 30));
    Spectra::SymGEigsShiftSolver<Op, BOp, Spectra::GEigsMode::ShiftInvert> solver(op, bop, nev, ncv,
                                                                                  sigma);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
    if (solver.info() != Spectra::CompInfo::Successful)
      throw NumericalError("Spectra shift-invert Lanczos did not converge (" + std::to_string(nev) +
                           " modes, " + std::to_string(n) + " DOFs)");
    const Eigen::VectorXd lambda = solver.eigenvalues();
    if (lambda.maxCoeff() > lambda_max || nev == n - 1) {
      std::vector<int> order(lambda.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda(a) < lambda(b); });
      const Eigen::MatrixXd v = solver.eigenvectors();
      Eigen::VectorXd l(order.size());
      Eigen::MatrixXd vs(n, order.size());
      for (std::size_t i = 0; i < order.size(); ++i)
        l(i) = lambda(order[i]), vs.col(i) = v.col(order[i]);
      return {l, vs};
    }
  }
}

}  // namespace

Modes lowest_modes(const SpMat& stiffness, const SpMat& mass, const std::vector<int>& fixed,
                   double omega_max) {
  const int ndof = static_cast<int>(stiffness.rows());
  std::vector<int> index(ndof, 0);
  for (int d : fixed) index.at(d) = -1;
  int nfree = 0;
  for (int& i : index)
    if (i >= 0) i = nfree++;
  const SpMat k = restrict_to(stiffness, index, nfree), m = restrict_to(mass, index, nfree);
  const auto [lambda, vectors] = solve_reduced(k, m, omega_max * omega_max);
  int count = 0;
  while (count < lambda.size() && lambda(count) <= omega_max * omega_max) ++count;
  Modes modes;
  modes.omega.resize(count);
  modes.shapes = Eigen::MatrixXd::Zero(ndof, count);
  for (int j = 0; j < count; ++j) {
    modes.omega(j) = std::sqrt(std::max(lambda(j), 0.0));
    Eigen::VectorXd v = vectors.col(j);
    v /= std::sqrt(v.dot(m * v));  // phi^T M phi = 1
    for (int d = 0; d < ndof; ++d)
      if (index[d] >= 0) modes.shapes(d, j) = v(index[d]);
  }
  return modes;
}

}  // namespace rollnoise::fem
