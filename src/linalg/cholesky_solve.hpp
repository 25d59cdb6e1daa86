// Solves with a dense Cholesky factor for a few right-hand sides, L L' X = B in place, and the
// tall-skinny products of a Krylov basis with a block of 3 vectors (A' X, Y -= A C).
//
// Eigen's LLT::solve runs a blocked triangular solve tuned for many right-hand sides; for 1-3 of
// them on a large factor it is limited neither by flops nor by memory (measured 21-24 ms for
// r = 3541, 3 columns, where streaming the triangle twice at the measured 16 GB/s takes 6 ms).
// Here each pass streams the triangle once, four columns of L at a time, with the three
// right-hand sides updated together:
//   forward  L y = b   (axpy form):  y(j..j+3) from the 4x4 diagonal block, then
//                                     y(i) -= L(i, j..j+3) y(j..j+3) for i > j+3 (vectorised);
//   backward L' x = y  (dot form):    x(j..j+3) -= L(i, j..j+3)' x(i) summed over i > j+3
//                                     (12 sums, each in 4 lanes), then the 4x4 diagonal block.
// Same operations as the textbook substitution, only regrouped (the sums in 4 partial sums): the
// rounding is of the same size (checked against LLT::solve in the nss tests). Measured 5-7 ms for
// r = 3541 with 3 columns (LLT::solve: 17-24 ms), 0.25 ms for r = 898 (0.54 ms).
// The products A' X and Y -= A C (A: n x d, X, Y: n x 3) use the same two inner loops; Eigen's
// GEMM packs A before multiplying, which for 3 columns costs more than the product (measured: the
// Gram-Schmidt of the fine-grid Krylov basis took 0.78 s with Eigen products, 0.38 s with these).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cstring>

namespace rollnoise::linalg {

namespace detail {

/// x_r(i) -= sum_q c_q(i) a_r(q) for the three right-hand sides r (no aliasing: vectorised).
inline void axpy4x3(const double* __restrict c0, const double* __restrict c1, const double* __restrict c2,
                    const double* __restrict c3, int len, const double* a, const double* b, const double* d,
                    double* __restrict x0, double* __restrict x1, double* __restrict x2) {
  const double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3];
  const double b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3];
  const double d0 = d[0], d1 = d[1], d2 = d[2], d3 = d[3];
  for (int i = 0; i < len; ++i) {
    const double l0 = c0[i], l1 = c1[i], l2 = c2[i], l3 = c3[i];
    x0[i] -= l0 * a0 + l1 * a1 + l2 * a2 + l3 * a3;
    x1[i] -= l0 * b0 + l1 * b1 + l2 * b2 + l3 * b3;
    x2[i] -= l0 * d0 + l1 * d1 + l2 * d2 + l3 * d3;
  }
}

/// s[r][q] = sum_i c_q(i) x_r(i) for four columns c_q and three vectors x_r: 12 sums, each kept in
/// 4 lanes (i mod 4; GCC/Clang vector extension) so that the loop vectorises without reassociation.
inline void dot4x3(const double* c0, const double* c1, const double* c2, const double* c3, int len,
                   const double* x0, const double* x1, const double* x2, double s[3][4]) {
  using v4d = double __attribute__((vector_size(32)));
  auto load = [](const double* p) {
    v4d v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  v4d acc[12] = {};
  int i = 0;
  for (; i + 4 <= len; i += 4) {
    const v4d l0 = load(c0 + i), l1 = load(c1 + i), l2 = load(c2 + i), l3 = load(c3 + i);
    const v4d y0 = load(x0 + i), y1 = load(x1 + i), y2 = load(x2 + i);
    acc[0] += l0 * y0;
    acc[1] += l1 * y0;
    acc[2] += l2 * y0;
    acc[3] += l3 * y0;
    acc[4] += l0 * y1;
    acc[5] += l1 * y1;
    acc[6] += l2 * y1;
    acc[7] += l3 * y1;
    acc[8] += l0 * y2;
    acc[9] += l1 * y2;
    acc[10] += l2 * y2;
    acc[11] += l3 * y2;
  }
  for (; i < len; ++i) {
    const double l[4] = {c0[i], c1[i], c2[i], c3[i]}, y[3] = {x0[i], x1[i], x2[i]};
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < 4; ++q) acc[4 * r + q][0] += l[q] * y[r];
  }
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 4; ++q) {
      const v4d& a = acc[4 * r + q];
      s[r][q] = (a[0] + a[1]) + (a[2] + a[3]);
    }
}

/// L L' x = b for three right-hand sides x0, x1, x2 (each of length n, overwritten), L the lower
/// triangle of the column-major n x n array `L` with leading dimension `ld`.
inline void cholesky_solve3(const double* L, long ld, int n, double* x0, double* x1, double* x2) {
  int j = 0;
  for (; j + 4 <= n; j += 4) {  // forward, four columns at a time
    const double* c0 = L + ld * j;
    const double* c1 = c0 + ld;
    const double* c2 = c1 + ld;
    const double* c3 = c2 + ld;
    for (double* x : {x0, x1, x2}) {
      x[j] /= c0[j];
      x[j + 1] = (x[j + 1] - c0[j + 1] * x[j]) / c1[j + 1];
      x[j + 2] = (x[j + 2] - c0[j + 2] * x[j] - c1[j + 2] * x[j + 1]) / c2[j + 2];
      x[j + 3] = (x[j + 3] - c0[j + 3] * x[j] - c1[j + 3] * x[j + 1] - c2[j + 3] * x[j + 2]) / c3[j + 3];
    }
    const double a[4] = {x0[j], x0[j + 1], x0[j + 2], x0[j + 3]};
    const double b[4] = {x1[j], x1[j + 1], x1[j + 2], x1[j + 3]};
    const double d[4] = {x2[j], x2[j + 1], x2[j + 2], x2[j + 3]};
    axpy4x3(c0 + j + 4, c1 + j + 4, c2 + j + 4, c3 + j + 4, n - j - 4, a, b, d, x0 + j + 4, x1 + j + 4, x2 + j + 4);
  }
  for (; j < n; ++j) {  // the last n % 4 columns
    const double* c = L + ld * j;
    x0[j] /= c[j];
    x1[j] /= c[j];
    x2[j] /= c[j];
    for (int i = j + 1; i < n; ++i) {
      x0[i] -= c[i] * x0[j];
      x1[i] -= c[i] * x1[j];
      x2[i] -= c[i] * x2[j];
    }
  }
  // backward: the last n % 4 rows one by one, then four at a time
  j = n;
  for (int q = 0; q < n % 4; ++q) {
    --j;
    const double* c = L + ld * j;
    double s0 = 0, s1 = 0, s2 = 0;
    for (int i = j + 1; i < n; ++i) {
      s0 += c[i] * x0[i];
      s1 += c[i] * x1[i];
      s2 += c[i] * x2[i];
    }
    x0[j] = (x0[j] - s0) / c[j];
    x1[j] = (x1[j] - s1) / c[j];
    x2[j] = (x2[j] - s2) / c[j];
  }
  for (j -= 4; j >= 0; j -= 4) {
    const double* c0 = L + ld * j;
    const double* c1 = c0 + ld;
    const double* c2 = c1 + ld;
    const double* c3 = c2 + ld;
    double s[3][4];
    dot4x3(c0 + j + 4, c1 + j + 4, c2 + j + 4, c3 + j + 4, n - j - 4, x0 + j + 4, x1 + j + 4, x2 + j + 4, s);
    double* xs[3] = {x0, x1, x2};
    for (int r = 0; r < 3; ++r) {
      double* x = xs[r];
      x[j + 3] = (x[j + 3] - s[r][3]) / c3[j + 3];
      x[j + 2] = (x[j + 2] - s[r][2] - c2[j + 3] * x[j + 3]) / c2[j + 2];
      x[j + 1] = (x[j + 1] - s[r][1] - c1[j + 2] * x[j + 2] - c1[j + 3] * x[j + 3]) / c1[j + 1];
      x[j] = (x[j] - s[r][0] - c0[j + 1] * x[j + 1] - c0[j + 2] * x[j + 2] - c0[j + 3] * x[j + 3]) / c0[j];
    }
  }
}

}  // namespace detail

/// X := (L L')^{-1} X, with L the lower triangle of `factor` (e.g. the matrix an in-place
/// Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> has factored). Columns are taken three at a time.
inline void cholesky_solve_in_place(const Eigen::MatrixXd& factor, Eigen::MatrixXd& X) {
  const int n = static_cast<int>(factor.rows());
  Eigen::VectorXd spare1, spare2;
  for (int c = 0; c < X.cols(); c += 3) {
    const int k = std::min<int>(3, static_cast<int>(X.cols()) - c);
    double* x0 = X.col(c).data();
    if (k < 3) spare2.setZero(n);
    if (k < 2) spare1.setZero(n);
    double* x1 = k >= 2 ? X.col(c + 1).data() : spare1.data();
    double* x2 = k >= 3 ? X.col(c + 2).data() : spare2.data();
    detail::cholesky_solve3(factor.data(), factor.outerStride(), n, x0, x1, x2);
  }
}

/// C = A(:, 0:cols)' X for X with 3 columns (C: cols x 3), streaming A once (tall-skinny products
/// of a Krylov basis with a block of 3 vectors; Eigen's GEMM packs A first, ~2.5x slower here).
inline Eigen::MatrixXd transposed_product3(const Eigen::MatrixXd& A, int cols, const Eigen::MatrixXd& X) {
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd C(cols, 3);
  const double* a = A.data();
  const long ld = A.outerStride();
  int q = 0;
  for (; q + 4 <= cols; q += 4) {
    double s[3][4];
    detail::dot4x3(a + ld * q, a + ld * (q + 1), a + ld * (q + 2), a + ld * (q + 3), n, X.col(0).data(),
                   X.col(1).data(), X.col(2).data(), s);
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k) C(q + k, r) = s[r][k];
  }
  for (; q < cols; ++q) C.row(q) = A.col(q).transpose() * X;
  return C;
}

/// Y(0:rows, :) -= A(0:rows, 0:cols) C for Y with 3 columns (C: cols x 3), streaming A once.
/// `rows_of` (optional) gives, per group of 4 columns starting at q, how many leading rows of A
/// can be non-zero there (for block Hessenberg A); by default all `rows`.
template <class RowsOf>
inline void subtract_product3(const Eigen::MatrixXd& A, int rows, int cols, const Eigen::MatrixXd& C,
                              Eigen::MatrixXd& Y, const RowsOf& rows_of) {
  const double* a = A.data();
  const long ld = A.outerStride();
  double* y0 = Y.col(0).data();
  double* y1 = Y.col(1).data();
  double* y2 = Y.col(2).data();
  int q = 0;
  for (; q + 4 <= cols; q += 4) {
    const double c0[4] = {C(q, 0), C(q + 1, 0), C(q + 2, 0), C(q + 3, 0)};
    const double c1[4] = {C(q, 1), C(q + 1, 1), C(q + 2, 1), C(q + 3, 1)};
    const double c2[4] = {C(q, 2), C(q + 1, 2), C(q + 2, 2), C(q + 3, 2)};
    const int len = std::min(rows, static_cast<int>(rows_of(q)));
    detail::axpy4x3(a + ld * q, a + ld * (q + 1), a + ld * (q + 2), a + ld * (q + 3), len, c0, c1, c2, y0, y1, y2);
  }
  for (; q < cols; ++q) {
    const int len = std::min(rows, static_cast<int>(rows_of(q)));
    Y.topRows(len) -= A.col(q).head(len) * C.row(q);
  }
}

inline void subtract_product3(const Eigen::MatrixXd& A, int rows, int cols, const Eigen::MatrixXd& C,
                              Eigen::MatrixXd& Y) {
  subtract_product3(A, rows, cols, C, Y, [rows](int) { return rows; });
}

}  // namespace rollnoise::linalg
