// One step of the linear model's reduced recursion, (K0 - z K1) pi = b (linear_model.hpp, "the
// reduced, symmetric form"): apply K0, apply K1, solve K0 x = b with an optional starting guess.
// The interface follows MFEM's Solver: an operator with a solve whose initial guess is used only
// where the solver is iterative (MFEM's iterative_mode; here uses_initial_guess()).
//
// Two implementations:
//   DenseCholeskyStep  K0 assembled densely and factored once (Cholesky, in place); its solves
//                      stream the factor once for all columns (linalg::cholesky_solve_in_place);
//   PcgStep            K0 applied by FFT (D + Pi' A Pi/dt) and solved by preconditioned CG
//                      (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., Alg. 9.1) with
//                      the preconditioner M^{-1} = W Pi' (C/dt + cbar I)^{-1} Pi W (linear_model.hpp,
//                      docs/contact_model.md Sec. 5).
// K1 = Pi' A0 Pi/dt is an FFT convolution on both.
//
// Threads. The columns of a block are independent in K1 X, K0 X and the solves, so for_columns
// shares them out round-robin among threads; every thread has its own copies of the FFT operators
// (an FFT operator's work arrays serve one caller), made by the OperatorSet factory (its clones).
// Every column goes through the same operations as in a serial run, so the results are identical
// to the last bit for any number of threads (tests/nss/matrix_free_test.cpp).
#pragma once

#include <Eigen/Dense>
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "contact/element_operator.hpp"

namespace rollnoise::nss {

/// The FFT operators one thread uses (K1; on the matrix-free path also the compliance part of K0
/// and the preconditioner's circulant inverse).
struct OperatorSet {
  std::unique_ptr<contact::ElementOperator> K1;  ///< Pi' A0 Pi / dt (shift 1)
  std::unique_ptr<contact::ElementOperator> A;   ///< Pi' A Pi / dt (shift 0), matrix-free only
  std::unique_ptr<contact::ElementOperator> G;   ///< Pi' (C/dt + cbar I)^{-1} Pi, matrix-free only
};
/// Builds one more OperatorSet (a clone of the first for another thread).
using OperatorFactory = std::function<OperatorSet()>;

class StepSolver {
 public:
  /// `threads` >= 1 operator sets from `make`, one per thread (the first serves the caller).
  StepSolver(const OperatorFactory& make, int threads);
  virtual ~StepSolver();
  StepSolver(const StepSolver&) = delete;
  StepSolver& operator=(const StepSolver&) = delete;

  /// K1 X, the columns in parallel.
  Eigen::MatrixXd apply_K1(const Eigen::MatrixXd& X) const;
  /// K0 X.
  virtual Eigen::MatrixXd apply_K0(const Eigen::MatrixXd& X) const = 0;
  /// K0^{-1} B, from `start` where uses_initial_guess() (zero if null); the guess is ignored
  /// otherwise.
  virtual Eigen::MatrixXd solve(Eigen::MatrixXd B, const Eigen::MatrixXd* start = nullptr) const = 0;
  /// Whether solve() starts from the given guess (an iterative solver; MFEM's iterative_mode).
  virtual bool uses_initial_guess() const = 0;
  /// Whether K0 is applied by FFT and solved iteratively (the matrix-free path).
  virtual bool matrix_free() const = 0;
  /// Iterative solves so far: columns solved and iterations in all (0 for a direct solver).
  long solves() const { return solves_.load(); }
  long iterations() const { return iterations_.load(); }

 protected:
  /// f(lane, j) for the columns j < n, shared out round-robin among min(lanes, n) threads (the
  /// caller is lane 0). The first exception of any thread is rethrown after all have finished.
  void for_columns(Eigen::Index n, const std::function<void(const OperatorSet&, Eigen::Index)>& f) const;
  std::vector<OperatorSet> lanes_;
  mutable std::atomic<long> solves_{0}, iterations_{0};
};

/// K0 = D + Pi' A Pi / dt assembled densely (its lower triangle), factored by Cholesky in place.
class DenseCholeskyStep final : public StepSolver {
 public:
  /// `K0` holds the lower triangle of the matrix; throws NumericalError unless it is positive definite.
  DenseCholeskyStep(Eigen::MatrixXd K0, const OperatorFactory& make, int threads);
  ~DenseCholeskyStep() override;
  /// L (L' X), L the factor.
  Eigen::MatrixXd apply_K0(const Eigen::MatrixXd& X) const override;
  /// linalg::cholesky_solve_in_place: streams the factor once per pass for all columns, serial
  /// (two threads with two columns each would stream it twice).
  Eigen::MatrixXd solve(Eigen::MatrixXd B, const Eigen::MatrixXd* start = nullptr) const override;
  bool uses_initial_guess() const override { return false; }
  bool matrix_free() const override { return false; }
  /// The Cholesky factor L (lower triangular, a copy).
  Eigen::MatrixXd factor() const;
  /// Eigen's LLT::rcond of K0 (Hager-Higham 1-norm estimate).
  double rcond() const;

 private:
  Eigen::MatrixXd K0_;  // holds the Cholesky factor after construction
  std::unique_ptr<Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>>> llt_;
};

/// K0 x = D x + Pi' A Pi x / dt by FFT, K0^{-1} by preconditioned CG.
class PcgStep final : public StepSolver {
 public:
  /// `d`: D (c_e on slip unknowns, 0 on adhesion ones); `w`: the preconditioner's scaling (1 on
  /// adhesion unknowns); stops at |b - K0 x|_2 <= tolerance |b|_2.
  PcgStep(Eigen::VectorXd d, Eigen::VectorXd w, double tolerance, const OperatorFactory& make, int threads);
  Eigen::MatrixXd apply_K0(const Eigen::MatrixXd& X) const override;
  Eigen::MatrixXd solve(Eigen::MatrixXd B, const Eigen::MatrixXd* start = nullptr) const override;
  bool uses_initial_guess() const override { return true; }
  bool matrix_free() const override { return true; }

 private:
  void apply_K0(const OperatorSet& lane, const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;
  void pcg(const OperatorSet& lane, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> x) const;
  Eigen::VectorXd d_, w_;
  double tolerance_ = 0.0;
};

}  // namespace rollnoise::nss
