#include "nss/step_solver.hpp"

#include <algorithm>

#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "linalg/cholesky_solve.hpp"

namespace rollnoise::nss {

StepSolver::StepSolver(const OperatorFactory& make, int threads) {
  for (int t = 0; t < std::max(threads, 1); ++t) lanes_.push_back(make());
}

StepSolver::~StepSolver() = default;

void StepSolver::for_columns(Eigen::Index n, const std::function<void(const OperatorSet&, Eigen::Index)>& f) const {
  // one lane (operator set) per thread: the thread's own FFT buffers; the columns are independent
  parallel_for(static_cast<std::size_t>(n), static_cast<int>(lanes_.size()),
               [&](std::size_t j, int worker) { f(lanes_[worker], static_cast<Eigen::Index>(j)); });
}

Eigen::MatrixXd StepSolver::apply_K1(const Eigen::MatrixXd& X) const {
  Eigen::MatrixXd Y(X.rows(), X.cols());
  for_columns(X.cols(), [&](const OperatorSet& l, Eigen::Index j) { l.K1->apply(X.col(j).data(), Y.col(j).data()); });
  return Y;
}

// ---- dense Cholesky ----

DenseCholeskyStep::DenseCholeskyStep(Eigen::MatrixXd K0, const OperatorFactory& make, int threads)
    : StepSolver(make, threads), K0_(std::move(K0)) {
  llt_ = std::make_unique<Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>>>(K0_);
  if (llt_->info() != Eigen::Success)
    throw NumericalError("linear contact model: the reduced matrix K0 = D + Pi' A Pi/dt is not positive definite");
}

DenseCholeskyStep::~DenseCholeskyStep() = default;

Eigen::MatrixXd DenseCholeskyStep::apply_K0(const Eigen::MatrixXd& X) const {
  const Eigen::MatrixXd LtX = K0_.triangularView<Eigen::Lower>().transpose() * X;
  return K0_.triangularView<Eigen::Lower>() * LtX;
}

Eigen::MatrixXd DenseCholeskyStep::solve(Eigen::MatrixXd B, const Eigen::MatrixXd*) const {
  linalg::cholesky_solve_in_place(K0_, B);
  return B;
}

Eigen::MatrixXd DenseCholeskyStep::factor() const {
  // K0 holds the factor in its lower triangle; its strict upper triangle was never written.
  return K0_.triangularView<Eigen::Lower>();
}

double DenseCholeskyStep::rcond() const { return llt_->rcond(); }

// ---- matrix-free PCG ----

PcgStep::PcgStep(Eigen::VectorXd d, Eigen::VectorXd w, double tolerance, const OperatorFactory& make, int threads)
    : StepSolver(make, threads), d_(std::move(d)), w_(std::move(w)), tolerance_(tolerance) {}

Eigen::MatrixXd PcgStep::apply_K0(const Eigen::MatrixXd& X) const {
  Eigen::MatrixXd Y(X.rows(), X.cols());
  for_columns(X.cols(), [&](const OperatorSet& l, Eigen::Index j) { apply_K0(l, X.col(j), Y.col(j)); });
  return Y;
}

Eigen::MatrixXd PcgStep::solve(Eigen::MatrixXd B, const Eigen::MatrixXd* start) const {
  Eigen::MatrixXd X = start ? *start : Eigen::MatrixXd::Zero(B.rows(), B.cols());
  for_columns(B.cols(), [&](const OperatorSet& l, Eigen::Index j) { pcg(l, B.col(j), X.col(j)); });
  return X;
}

void PcgStep::apply_K0(const OperatorSet& lane, const Eigen::Ref<const Eigen::VectorXd>& x,
                       Eigen::Ref<Eigen::VectorXd> y) const {
  // y = K0 x = Pi' A Pi x / dt + D x for one column, with the lane's FFT operator.
  lane.A->apply(x.data(), y.data());
  y += d_.cwiseProduct(x);
}

void PcgStep::pcg(const OperatorSet& lane, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> x) const {
  // Preconditioned conjugate gradients (Saad, Alg. 9.1) for K0 x = b, M^{-1} = W G W; stops at
  // |b - K0 x|_2 <= tolerance |b|_2.
  ++solves_;
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    x.setZero();
    return;
  }
  Eigen::VectorXd r(b.size()), q(b.size()), z(b.size()), wv(b.size());
  apply_K0(lane, x, q);
  r = b - q;
  auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    wv = w_.cwiseProduct(v);
    lane.G->apply(wv.data(), out.data());
    out.array() *= w_.array();
  };
  if (r.norm() <= tolerance_ * bnorm) return;
  precondition(r, z);
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  const int max_iterations = 20000;
  for (int it = 1; it <= max_iterations; ++it) {
    ++iterations_;
    apply_K0(lane, p, q);
    const double alpha = rz / p.dot(q);
    x += alpha * p;
    r -= alpha * q;
    if (r.norm() <= tolerance_ * bnorm) return;
    precondition(r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  throw NumericalError("linear contact model: PCG on K0 did not converge (matrix-free path)");
}

}  // namespace rollnoise::nss
