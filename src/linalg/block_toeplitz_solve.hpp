// Solve T X = B for a block Toeplitz matrix T of m x m blocks of 4 x 4 (T_ij = t(i - j), not
// necessarily symmetric or Hermitian), for a few right-hand sides, in O(m^2) block operations
// instead of the O(m^3) of a dense LU.
//
// The block Levinson recursion (Whittle, Biometrika 50, 1963; Wiggins & Robinson, J. Geophys.
// Res. 70, 1965; Akaike, SIAM J. Appl. Math. 24, 1973), on the leading principal block
// submatrices M_k = [t(i - j)]_{i,j=0..k}. Per order k it keeps a forward and a backward predictor,
//
//   M_k [I; a_1; ...; a_k] = [V_k; 0; ...; 0],   M_k [b_0; ...; b_{k-1}; I] = [0; ...; 0; U_k],
//
// and steps to order k + 1 with the mismatches D_f = sum_j t(k + 1 - j) a_j (the last block row
// of M_{k+1} [a; 0]) and D_b = sum_j t(-1 - j) b_j (the first block row of M_{k+1} [0; b]):
//
//   a' = [a; 0] - [0; b] U_k^{-1} D_f,   b' = [0; b] - [a; 0] V_k^{-1} D_b,
//   V_{k+1} = V_k - D_b U_k^{-1} D_f,    U_{k+1} = U_k - D_f V_k^{-1} D_b,                  (L1)
//
// from V_0 = U_0 = t(0). The solution of M_k x = (y_0, ..., y_k) then grows by one block per order
// with the backward predictor of that order,
//
//   x <- [x; 0] + b^(k+1) U_{k+1}^{-1} (y_{k+1} - sum_j t(k + 1 - j) x_j).                   (L2)
//
// About 4 m^2 products of 4 x 4 blocks for (L1), done once, and m^2 block-column products per
// right-hand-side column for (L2) (the backward predictors of every order are kept: m^2 / 2
// blocks), against (2/3) (4 m)^3 complex multiply-adds for the LU.
//
// The recursion does not pivot across blocks: it needs every M_k to be regular and is only weakly
// stable for a T that is not positive definite (Bunch, SIAM J. Sci. Stat. Comput. 6, 1985;
// Cybenko 1980 for the scalar case). So, as linalg/toeplitz_solve.hpp, the solution is checked by
// the residual of one weighted combination of its columns, and solve() gives nothing when that
// relative residual exceeds the tolerance (or a pivot block is singular or not finite); the
// caller then solves densely.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <vector>

namespace rollnoise::linalg {

class BlockToeplitzSolver {
 public:
  using Block = Eigen::Matrix4cd;

  /// T with t(d) = lower[d] and t(-d) = upper[d] for d = 0 .. m - 1 (upper[0] is not read: t(0) =
  /// lower[0]); runs (L1).
  BlockToeplitzSolver(std::vector<Block> lower, std::vector<Block> upper)
      : lower_(std::move(lower)), upper_(std::move(upper)) {
    const int m = static_cast<int>(lower_.size());
    if (m == 0 || static_cast<int>(upper_.size()) != m) return;
    backward_.resize(m);
    u_inverse_.resize(m);
    std::vector<Block> a{Block::Identity()}, b{Block::Identity()};
    Block V = lower_[0], U = lower_[0];
    backward_[0] = b;
    if (!invert(U, u_inverse_[0])) return;
    for (int k = 0; k + 1 < m; ++k) {
      Block Df = Block::Zero(), Db = Block::Zero();
      for (int j = 0; j <= k; ++j) {
        Df.noalias() += lower_[k + 1 - j] * a[j];
        Db.noalias() += upper_[j + 1] * b[j];
      }
      Block v_inverse;
      if (!invert(V, v_inverse)) return;
      const Block gf = u_inverse_[k] * Df, gb = v_inverse * Db;
      std::vector<Block> a_next(k + 2), b_next(k + 2);
      for (int j = 0; j <= k + 1; ++j) {
        a_next[j] = (j <= k ? a[j] : Block::Zero()) - (j >= 1 ? b[j - 1] : Block::Zero()) * gf;
        b_next[j] = (j >= 1 ? b[j - 1] : Block::Zero()) - (j <= k ? a[j] : Block::Zero()) * gb;
      }
      V -= Db * gf;
      U -= Df * gb;
      a.swap(a_next);
      b.swap(b_next);
      backward_[k + 1] = b;
      if (!invert(U, u_inverse_[k + 1])) return;
    }
    ok_ = true;
  }

  /// Whether (L1) ran through (every pivot block regular and finite).
  bool ok() const { return ok_; }
  int blocks() const { return static_cast<int>(lower_.size()); }
  /// T itself (4 m x 4 m), for a dense solve where solve() gives nothing.
  Eigen::MatrixXcd dense() const {
    const int m = blocks();
    Eigen::MatrixXcd T(4 * m, 4 * m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        T.block<4, 4>(4 * i, 4 * j) = i >= j ? lower_[i - j] : upper_[j - i];
    return T;
  }

  /// X = T^{-1} B (B: 4 m rows) by (L2), if the recursion ran and the residual ||T c - B w|| of
  /// the combination c = X w, w_j = (1 + 0.618 j) / ||b_j||, is at most `tolerance`.
  std::optional<Eigen::MatrixXcd> solve(const Eigen::MatrixXcd& B, double tolerance = 1e-10) const {
    const int m = blocks();
    if (!ok_ || B.rows() != 4 * m) return std::nullopt;
    const int nc = static_cast<int>(B.cols());
    Eigen::MatrixXcd X = Eigen::MatrixXcd::Zero(4 * m, nc);
    X.topRows(4) = u_inverse_[0] * B.topRows(4);
    Eigen::MatrixXcd r(4, nc);
    for (int k = 0; k + 1 < m; ++k) {
      r = B.middleRows(4 * (k + 1), 4);
      for (int j = 0; j <= k; ++j) r.noalias() -= lower_[k + 1 - j] * X.middleRows(4 * j, 4);
      const Eigen::MatrixXcd step = u_inverse_[k + 1] * r;
      const std::vector<Block>& b = backward_[k + 1];
      for (int j = 0; j <= k; ++j) X.middleRows(4 * j, 4).noalias() += b[j] * step;
      X.middleRows(4 * (k + 1), 4) = step;
    }
    if (!X.allFinite() || residual(X, B) > tolerance) return std::nullopt;
    return X;
  }

 private:
  static bool invert(const Block& M, Block& inverse) {
    const Eigen::FullPivLU<Block> lu(M);
    if (!lu.isInvertible()) return false;
    inverse = lu.inverse();
    return inverse.allFinite();
  }

  // ||T c - B w|| for one weighted combination of the columns (toeplitz_solve.hpp's check).
  double residual(const Eigen::MatrixXcd& X, const Eigen::MatrixXcd& B) const {
    const int m = blocks();
    Eigen::VectorXcd w = Eigen::VectorXcd::Zero(B.cols());
    for (int j = 0; j < B.cols(); ++j) {
      const double bn = B.col(j).norm();
      if (bn > 0.0) w(j) = (1.0 + 0.6180339887498949 * j) / bn;
    }
    const Eigen::VectorXcd c = X * w;
    Eigen::VectorXcd res = -(B * w);
    for (int i = 0; i < m; ++i)
      for (int l = 0; l < m; ++l)
        res.segment<4>(4 * i).noalias() +=
            (i >= l ? lower_[i - l] : upper_[l - i]) * c.segment<4>(4 * l);
    const double n = res.norm();
    return std::isfinite(n) ? n : INFINITY;
  }

  std::vector<Block> lower_, upper_;
  std::vector<std::vector<Block>> backward_;  // per order k: b^(k)_0 .. b^(k)_k (the last I)
  std::vector<Block> u_inverse_;              // U_k^{-1}
  bool ok_ = false;
};

}  // namespace rollnoise::linalg
