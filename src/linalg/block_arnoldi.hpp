// The block Arnoldi process in an inner product given by a symmetric positive definite matrix K0
// (the linear contact model's Krylov reduced model, nss/markov_sweep.cpp): the basis V of the
// Krylov space of N = K0^{-1} K1, orthonormal in <u, v> = u' K0 v, and the projection H = V' K1 V
// (block upper Hessenberg), with the Markov parameters of the projected system.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <functional>
#include <vector>

#include "linalg/cholesky_solve.hpp"
#include "linalg/markov_series.hpp"

namespace rollnoise::linalg {

// Orthonormalise the block X (K0 X = Z) in the K0 inner product: X' Z = R' R (Cholesky), X <- X R^{-1},
// Z <- Z R^{-1}. Returns false when the block has (numerically) lost rank (smallest eigenvalue of
// X' Z below 1e-24 `scale`): a breakdown of the block process.
inline bool normalise_in_K0(Eigen::MatrixXd& X, Eigen::MatrixXd& Z, double scale, Eigen::MatrixXd& R) {
  Eigen::MatrixXd G = X.transpose() * Z;
  G = 0.5 * (G + G.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(G, Eigen::EigenvaluesOnly);
  if (!(es.eigenvalues()(0) > 1e-24 * scale)) return false;
  const Eigen::LLT<Eigen::MatrixXd> g(G);
  if (g.info() != Eigen::Success) return false;
  R = g.matrixU();
  X = R.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(X);
  Z = R.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(Z);
  return true;
}

// The block Arnoldi process on N = K0^{-1} K1 in the K0 inner product (nss/markov_sweep.cpp, step 2): the basis V (r x d, V' K0 V = I) grows by blocks of p columns, Y = K0 V alongside, and H
// holds the Gram-Schmidt coefficients (the projection V' K1 V, block upper Hessenberg with upper
// triangular subdiagonal blocks R). The caller forms the new block X = N V_{k-1} (K1 products and
// K0 solves); this class only orthonormalises, stores and projects.
class BlockArnoldi {
 public:
  using Product = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;
  /// With `k0` (K0 X for a block X), Y = K0 V is not stored: the Gram-Schmidt coefficients are
  /// V' (K0 X) and K0 X is recomputed after each pass (memory r d instead of 2 r d).
  BlockArnoldi(int rows, int block, int capacity, Product k0 = nullptr)
      : r_(rows), p_(block), cap_(capacity), k0_(std::move(k0)), V_(rows, capacity),
        Y_(rows, k0_ ? 0 : capacity), H_(Eigen::MatrixXd::Zero(capacity, capacity)) {}

  /// The first block from X0 = K0^{-1} B (Z0 = B): X0 = V_0 R0. False on a breakdown.
  bool start(Eigen::MatrixXd X, Eigen::MatrixXd Z) {
    const Eigen::MatrixXd G0 = X.transpose() * Z;
    if (!normalise_in_K0(X, Z, G0.diagonal().maxCoeff(), R0_)) return false;
    V_.leftCols(p_) = X;
    if (!k0_) Y_.leftCols(p_) = Z;
    d_ = p_;
    return true;
  }

  /// The newest block V_{k-1} of the basis (k - 1 steps done).
  Eigen::Ref<const Eigen::MatrixXd> last_block() const { return V_.middleCols(d_ - p_, p_); }

  /// Block step k: orthogonalise X = N V_{k-1} (Z = K0 X = K1 V_{k-1}) against the basis, normalise
  /// it and append it. The column block k-1 of H is complete either way, so the square model of
  /// the first k blocks (model_dimension()) exists; false on a breakdown (nothing appended).
  bool extend(Eigen::MatrixXd X, Eigen::MatrixXd Z) {
    const Eigen::VectorXd norm0 = (X.transpose() * Z).diagonal();  // squared K0-norms
    const double scale = norm0.maxCoeff();
    const int d = d_;
    grow(d + p_);
    const Eigen::MatrixXd C = gram_schmidt(X, Z, norm0);
    Eigen::MatrixXd R;
    const bool ok = normalise_in_K0(X, Z, scale, R);
    H_.block(0, d - p_, d, p_) = C;
    if (ok) {
      H_.block(d, d - p_, p_, p_) = R;
      V_.middleCols(d, p_) = X;
      if (!k0_) Y_.middleCols(d, p_) = Z;
      d_ += p_;
    }
    model_d_ = d;
    return ok;
  }

  /// Dimension of the square reduced model after the last step (p k after k steps).
  int model_dimension() const { return model_d_; }

  /// Markov parameters of the reduced model of the first dk basis vectors: h_j = (V' L)' H^j e_1 R0
  /// (exact for j < dk / p), until they decay (markov_sequence); false if they do not.
  bool markov_parameters(int dk, const Eigen::MatrixXd& L, int quiet_steps, int max_steps,
                         std::vector<Eigen::MatrixXd>& h) const {
    const int p = p_;
    const Eigen::MatrixXd Hk = H_.topLeftCorner(dk, dk);
    Eigen::MatrixXd S0 = Eigen::MatrixXd::Zero(dk, p);
    S0.topRows(p) = R0_;
    const Eigen::MatrixXd Lh = V_.leftCols(dk).transpose() * L;
    // S -> H S with H block upper Hessenberg whose subdiagonal blocks R are upper triangular:
    // column c has non-zeros in rows <= c + p only, so columns q..q+3 in rows < q + p + 4.
    return linalg::markov_sequence(
        Lh, S0,
        [&](const Eigen::MatrixXd& S) {
          Eigen::MatrixXd next = Eigen::MatrixXd::Zero(dk, p);
          linalg::subtract_product(Hk, dk, dk, -S, next, [p](int q) { return q + p + 4; });
          return next;
        },
        quiet_steps, max_steps, h);
  }

 private:
  // Block classical Gram-Schmidt in the K0 inner product against the d_ basis vectors, repeated
  // once when a column lost more than half of its squared norm ("twice is enough", Kahan-Parlett):
  // one pass leaves the new column orthogonal to O(eps / ratio); away from cancellation one pass
  // is as good as two. The rolling step mostly transports the traction into new directions
  // (ratios ~0.9-1), with strong cancellation about once per contact length. Returns the
  // coefficients C = V' K0 X (the new column block of H).
  Eigen::MatrixXd gram_schmidt(Eigen::MatrixXd& X, Eigen::MatrixXd& Z, const Eigen::VectorXd& norm0) const {
    const int d = d_;
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(d, p_);
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::MatrixXd Ci = k0_ ? linalg::transposed_product(V_, d, Z)   // V' K0 X
                                     : linalg::transposed_product(Y_, d, X);  // Y' X
      linalg::subtract_product(V_, r_, d, Ci, X);                             // X -= V Ci
      if (k0_)
        Z = k0_(X);
      else
        linalg::subtract_product(Y_, r_, d, Ci, Z);  // Z -= Y Ci
      C += Ci;
      const Eigen::VectorXd norm1 = (X.transpose() * Z).diagonal();
      if (pass == 0 && (norm1.array() > 0.5 * norm0.array()).all()) break;
    }
    return C;
  }

  void grow(int need) {
    if (need <= cap_) return;
    const int c = std::max(need, p_ * ((cap_ / p_) * 3 / 2 + 1));
    V_.conservativeResize(Eigen::NoChange, c);
    if (!k0_) Y_.conservativeResize(Eigen::NoChange, c);
    H_.conservativeResize(c, c);
    H_.rightCols(c - cap_).setZero();
    H_.bottomRows(c - cap_).setZero();
    cap_ = c;
  }

  int r_, p_, cap_;
  Product k0_;
  int d_ = 0;        // basis vectors so far
  int model_d_ = 0;  // dimension of the square model after the last step
  Eigen::MatrixXd V_, Y_, H_, R0_;
};

}  // namespace rollnoise::linalg
