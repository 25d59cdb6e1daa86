#include "fem/eigen_solve.hpp"

#include <Spectra/SymEigsSolver.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>

#include "core/assert.hpp"
#include "core/errors.hpp"

namespace rollnoise::fem {
namespace {

using SpMat = Eigen::SparseMatrix<double>;

// The rows and columns of `a` (compressed, column-major, sorted) at the free DOFs (index[dof] >= 0,
// increasing with dof): column by column, the entries stay in order (no sort).
SpMat restrict_to(const SpMat& a, const std::vector<int>& index, int nfree) {
  SpMat r(nfree, nfree);
  r.reserve(a.nonZeros());
  for (int c = 0; c < a.outerSize(); ++c) {
    if (index[c] < 0) continue;
    r.startVec(index[c]);
    for (SpMat::InnerIterator it(a, c); it; ++it)
      if (index[it.row()] >= 0) r.insertBack(index[it.row()], index[c]) = it.value();
  }
  r.finalize();
  return r;
}

// The free rows and columns of K - shift M (compressed, rows ascending) written into `out`, whose
// storage is reused from call to call (no fresh allocation and page faults per order): per free
// column, K's entries at free rows merged with M's, k - shift m where M has the entry and k where
// it has not, i.e. what restrict_to(K) - shift * restrict_to(M) gives (Eigen's sparse difference
// takes k - 0 there) without the two restricted copies and the expression's new matrix. Needs M's
// pattern within K's (the FE matrices: M couples like components of nodes that K couples); returns
// false, `out` unspecified, when an entry of M has none of K.
bool shifted_free_part(const SpMat& k, const SpMat& m, const std::vector<int>& index, int nfree,
                       double shift, SpMat& out) {
  if (!k.isCompressed() || !m.isCompressed()) return false;
  if (out.rows() != nfree || out.cols() != nfree || !out.isCompressed()) out.resize(nfree, nfree);
  out.resizeNonZeros(k.nonZeros());  // an upper bound, shrunk below (capacity kept)
  int* outer = out.outerIndexPtr();
  int* inner = out.innerIndexPtr();
  double* value = out.valuePtr();
  const int *ko = k.outerIndexPtr(), *ki = k.innerIndexPtr(), *mo = m.outerIndexPtr(),
            *mi = m.innerIndexPtr();
  const double *kv = k.valuePtr(), *mv = m.valuePtr();
  int nnz = 0;
  for (int c = 0; c < k.outerSize(); ++c) {
    if (index[c] < 0) continue;
    outer[index[c]] = nnz;
    int q = mo[c];
    const int mend = mo[c + 1];
    for (int p = ko[c]; p < ko[c + 1]; ++p) {
      const int r = ki[p];
      if (q < mend && mi[q] < r) return false;  // M has an entry K has not
      if (index[r] < 0) {
        if (q < mend && mi[q] == r) ++q;
        continue;
      }
      double a = kv[p];
      if (q < mend && mi[q] == r) a = a - shift * mv[q++];
      inner[nnz] = index[r];
      value[nnz++] = a;
    }
    if (q < mend) return false;
  }
  outer[nfree] = nnz;
  out.resizeNonZeros(nnz);
  return true;
}

// A sparse LDL^T whose symbolic analysis is kept for the next matrix of the same pattern.
class PatternLdlt {
 public:
  void factorize(const SpMat& a) {
    if (!same_pattern(a)) {
      ldlt_.analyzePattern(a);
      outer_.assign(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1);
      inner_.assign(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
    }
    ldlt_.factorize(a);
  }
  const Eigen::SimplicialLDLT<SpMat>& factors() const { return ldlt_; }

 private:
  bool same_pattern(const SpMat& a) const {
    return a.isCompressed() && static_cast<std::size_t>(a.outerSize()) + 1 == outer_.size() &&
           static_cast<std::size_t>(a.nonZeros()) == inner_.size() &&
           std::equal(outer_.begin(), outer_.end(), a.outerIndexPtr()) &&
           std::equal(inner_.begin(), inner_.end(), a.innerIndexPtr());
  }
  Eigen::SimplicialLDLT<SpMat> ldlt_;
  std::vector<SpMat::StorageIndex> outer_, inner_;
};

// x := L^{-T} x for the unit lower triangular L of a SimplicialLDLT (strictly lower part stored by
// columns, compressed, rows ascending; its matrixU() is L^T): backward, x_i -= sum_k L_ki x_k over
// the stored k > i of column i. The sum is taken in four partial sums added at the end: four
// independent chains of multiply-adds instead of one (Eigen's solve subtracts term by term, a
// chain as long as the column whose latency bounds the whole solve). The same terms in another
// order: the result differs from Eigen's matrixU().solveInPlace by round-off.
void solve_transposed_unit_lower(const SpMat& l, double* x) {
  const int* outer = l.outerIndexPtr();
  const int* inner = l.innerIndexPtr();
  const double* v = l.valuePtr();
  for (Eigen::Index i = l.cols() - 1; i >= 0; --i) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int k = outer[i];
    const int end = outer[i + 1];
    for (; k + 4 <= end; k += 4) {
      s0 += v[k] * x[inner[k]];
      s1 += v[k + 1] * x[inner[k + 1]];
      s2 += v[k + 2] * x[inner[k + 2]];
      s3 += v[k + 3] * x[inner[k + 3]];
    }
    for (; k < end; ++k) s0 += v[k] * x[inner[k]];
    x[i] -= (s0 + s1) + (s2 + s3);
  }
}

// Shift-invert in standard form. With P (K - sigma M) P^T = L D L^T (sparse LDL^T, AMD ordering
// P; D > 0 for sigma below the lowest eigenvalue) and W = P^T L^{-T} D^{-1/2},
//   K x = lambda M x,  x = W y   <=>   C y = mu y,  C = W^T M W,  mu = 1 / (lambda - sigma),
// since W^T (K - sigma M) W = I. C is symmetric positive definite, so the Lanczos recursion runs
// in the Euclidean inner product: one M product and one pair of triangular solves per step, where
// the generalised shift-invert form (operator (K - sigma M)^{-1} M, M inner products) needs an M
// product for every inner product and norm of the recursion and its re-orthogonalisation (Ericsson
// & Ruhe, Math. Comp. 35 (1980) 1251-1268, Sec. 2: the spectral transformation with the
// factorisation's triangular factor). Eigenvectors: x = W y (then x^T M x = mu for |y| = 1).
class ShiftInvertStandardForm {
 public:
  using Scalar = double;
  // `a` = K - sigma M (free DOFs, compressed), `m` = M.
  ShiftInvertStandardForm(const SpMat& a, const SpMat& m, double sigma, PatternLdlt& ldlt)
      : m_(m), ldlt_(ldlt) {
    ldlt_.factorize(a);
    const auto& f = ldlt_.factors();
    if (f.info() != Eigen::Success || !(f.vectorD().minCoeff() > 0.0))
      throw NumericalError("LDL^T factorisation of K - sigma M failed (shift " +
                           std::to_string(sigma) + ")");
    d_inv_sqrt_ = f.vectorD().cwiseSqrt().cwiseInverse();
    ROLLNOISE_ASSERT(f.matrixL().nestedExpression().isCompressed(),
                     "L of SimplicialLDLT compressed");
    z_.resize(rows());
    w_.resize(rows());
  }
  Eigen::Index rows() const { return m_.rows(); }
  Eigen::Index cols() const { return m_.cols(); }
  // y -> C y = D^{-1/2} L^{-1} P M P^T L^{-T} D^{-1/2} y. The middle factor w = P M P^T z in one
  // pass over M's columns j: (P^T z)_j = z_{p(j)} (p = P's indices), and the entry M_ij goes to
  // w_{p(i)}; each w_{p(i)} gets the terms of (M P^T z)_i in the same order (ascending j) as the
  // separate products would sum them, so the values are the same to the bit. Scratch vectors are
  // the operator's (one operator per solver, i.e. per thread).
  void perform_op(const double* x, double* y) const {
    const auto& f = ldlt_.factors();
    z_ = d_inv_sqrt_.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(x, rows()));
    solve_transposed_unit_lower(f.matrixL().nestedExpression(), z_.data());
    const int* p = f.permutationP().indices().data();
    const int* outer = m_.outerIndexPtr();
    const int* inner = m_.innerIndexPtr();
    const double* value = m_.valuePtr();
    w_.setZero();
    for (Eigen::Index j = 0; j < m_.outerSize(); ++j) {
      const double zj = z_(p[j]);
      for (int k = outer[j]; k < outer[j + 1]; ++k) w_(p[inner[k]]) += value[k] * zj;
    }
    f.matrixL().solveInPlace(w_);
    Eigen::Map<Eigen::VectorXd>(y, rows()) = d_inv_sqrt_.cwiseProduct(w_);
  }
  // x = W y for the columns y
  Eigen::MatrixXd to_shapes(const Eigen::MatrixXd& y) const {
    const auto& f = ldlt_.factors();
    Eigen::MatrixXd z = d_inv_sqrt_.asDiagonal() * y;
    f.matrixU().solveInPlace(z);
    return f.permutationPinv() * z;
  }

 private:
  const SpMat& m_;  // compressed (restrict_to's result)
  PatternLdlt& ldlt_;
  Eigen::VectorXd d_inv_sqrt_;
  mutable Eigen::VectorXd z_, w_;  // perform_op's scratch
};

// The converged Ritz pairs, ascending.
std::pair<Eigen::VectorXd, Eigen::MatrixXd> ascending(const Eigen::VectorXd& lambda,
                                                      const Eigen::MatrixXd& v) {
  std::vector<int> order(lambda.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda(a) < lambda(b); });
  Eigen::VectorXd l(order.size());
  Eigen::MatrixXd vs(v.rows(), order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    l(i) = lambda(order[i]), vs.col(i) = v.col(order[i]);
  return {l, vs};
}

// The Lanczos shift, below zero: K - sigma M is positive definite even with rigid-body modes.
double lanczos_shift() {
  return -std::pow(2 * 3.14159265358979323846 * 10.0, 2);
}

// Eigenpairs (ascending) of the reduced problem (free DOFs: `shifted` = K - sigma M with sigma =
// lanczos_shift(), M, and K itself made by `stiffness` for the dense path only): Spectra's
// shift-invert Lanczos for nev modes, nev from the expected count and doubled until one exceeds
// lambda_max, or a dense solve when the requested count reaches half the problem.
std::pair<Eigen::VectorXd, Eigen::MatrixXd> solve_reduced(const SpMat& shifted,
                                                          const std::function<SpMat()>& stiffness,
                                                          const SpMat& m, double lambda_max,
                                                          int expected, PatternLdlt& ldlt) {
  const int n = static_cast<int>(m.rows());
  const double sigma = lanczos_shift();
  std::optional<ShiftInvertStandardForm> op;  // factorised once, for every nev tried
  for (int nev = std::min(expected >= 0 ? expected + 2 : 8, n);; nev = std::min(2 * nev, n)) {
    // dense: cheaper than Lanczos with most of the spectrum, and for all modes (omega_max infinite)
    if (nev > n / 2 || n < 60 || !std::isfinite(lambda_max)) {
      const Eigen::MatrixXd kd = stiffness(), md = m;
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(kd, md);
      if (dense.info() != Eigen::Success)
        throw NumericalError("dense generalised eigen solve of the FE model failed");
      return {dense.eigenvalues(), dense.eigenvectors()};
    }
    // Krylov dimension: 2 nev + 1 and at least 13 (measured on the 920 mm wheel, 8787 DOFs, n =
    // 0..10: the fewest operator applications; bench/wheel_fe_bench.cpp)
    const int ncv = std::min(n, std::max(2 * nev + 1, 13));
    if (!op) op.emplace(shifted, m, sigma, ldlt);
    Spectra::SymEigsSolver<ShiftInvertStandardForm> solver(*op, nev, ncv);
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-10);
    if (solver.info() != Spectra::CompInfo::Successful)
      throw NumericalError("Spectra shift-invert Lanczos did not converge (" + std::to_string(nev) +
                           " modes, " + std::to_string(n) + " DOFs)");
    const Eigen::VectorXd lambda = sigma + solver.eigenvalues().cwiseInverse().array();
    if (lambda.maxCoeff() > lambda_max || nev == n - 1)
      return ascending(lambda, op->to_shapes(solver.eigenvectors()));
  }
}

}  // namespace

struct LowestModesSolver::Factorisation {
  PatternLdlt ldlt;
  SpMat shifted;  // K - shift M on the free DOFs, its storage reused by every problem
};

LowestModesSolver::LowestModesSolver(std::vector<int> fixed, double omega_max)
    : fixed_(std::move(fixed)), omega_max_(omega_max), factorisation_(new Factorisation) {}

LowestModesSolver::~LowestModesSolver() = default;

namespace {

// index[dof]: the free DOF's number, -1 at the fixed ones; returns the count of free DOFs.
int free_index(int ndof, const std::vector<int>& fixed, std::vector<int>& index) {
  index.assign(ndof, 0);
  for (int d : fixed) index.at(d) = -1;
  int nfree = 0;
  for (int& i : index)
    if (i >= 0) i = nfree++;
  return nfree;
}

}  // namespace

int LowestModesSolver::count_below(const SpMat& stiffness, const SpMat& mass) {
  std::vector<int> index;
  const int nfree = free_index(static_cast<int>(stiffness.rows()), fixed_, index);
  const double shift = omega_max_ * omega_max_;
  SpMat& a = factorisation_->shifted;
  if (!shifted_free_part(stiffness, mass, index, nfree, shift, a)) {
    a = restrict_to(stiffness, index, nfree) - shift * restrict_to(mass, index, nfree);
    a.makeCompressed();
  }
  PatternLdlt& ldlt = factorisation_->ldlt;
  ldlt.factorize(a);
  const Eigen::VectorXd& d = ldlt.factors().vectorD();
  if (ldlt.factors().info() != Eigen::Success || (d.array() == 0.0).any()) return -1;
  return static_cast<int>((d.array() < 0.0).count());  // Sylvester: inertia(A) = inertia(D)
}

Modes LowestModesSolver::solve(const SpMat& stiffness, const SpMat& mass, int expected) {
  const int ndof = static_cast<int>(stiffness.rows());
  std::vector<int> index;
  const int nfree = free_index(ndof, fixed_, index);
  const SpMat m = restrict_to(mass, index, nfree);
  const double sigma = lanczos_shift();
  SpMat& shifted = factorisation_->shifted;
  if (!shifted_free_part(stiffness, mass, index, nfree, sigma, shifted)) {
    shifted = restrict_to(stiffness, index, nfree) - sigma * m;
    shifted.makeCompressed();
  }
  const double lambda_max = omega_max_ * omega_max_;
  const auto [lambda, vectors] = solve_reduced(
      shifted, [&] { return restrict_to(stiffness, index, nfree); }, m, lambda_max, expected,
      factorisation_->ldlt);
  int count = 0;
  while (count < lambda.size() && lambda(count) <= lambda_max) ++count;
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

Modes lowest_modes(const SpMat& stiffness, const SpMat& mass, const std::vector<int>& fixed,
                   double omega_max) {
  return LowestModesSolver(fixed, omega_max).solve(stiffness, mass);
}

}  // namespace rollnoise::fem
