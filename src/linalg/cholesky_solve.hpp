// Solves with a dense Cholesky factor for a few right-hand sides, L L' X = B in place, and the
// tall-skinny products of a Krylov basis with a block of up to 4 vectors (A' X, Y -= A C).
//
// Eigen's LLT::solve runs a blocked triangular solve tuned for many right-hand sides; for 1-3 of
// them on a large factor it is limited neither by flops nor by memory (measured 21-24 ms for
// r = 3541, 3 columns, where streaming the triangle twice at the measured 16 GB/s takes 6 ms).
// Here each pass streams the triangle once, four columns of L at a time, with the three
// right-hand sides (up to four) updated together:
//   forward  L y = b   (axpy form):  y(j..j+3) from the 4x4 diagonal block, then
//                                     y(i) -= L(i, j..j+3) y(j..j+3) for i > j+3 (vectorised);
//   backward L' x = y  (dot form):    x(j..j+3) -= L(i, j..j+3)' x(i) summed over i > j+3
//                                     (4K sums, each in 4 lanes), then the 4x4 diagonal block.
// Same operations as the textbook substitution, only regrouped (the sums in 4 partial sums): the
// rounding is of the same size (checked against LLT::solve in the nss tests). Measured 5-7 ms for
// r = 3541 with 3 columns (LLT::solve: 17-24 ms), 0.25 ms for r = 898 (0.54 ms).
// The products A' X and Y -= A C (A: n x d, X, Y: n x 3) use the same two inner loops; Eigen's
// GEMM packs A before multiplying, which for 3 columns costs more than the product (measured: the
// Gram-Schmidt of the fine-grid Krylov basis took 0.78 s with Eigen products, 0.38 s with these).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstring>
#ifdef __FMA__
#include <immintrin.h>
#endif

namespace rollnoise::linalg {

namespace detail {

/// x_r(i) -= sum_q c_q(i) a[r][q] for the K right-hand sides r (c and x do not alias: vectorised).
template <int K>
inline void axpy4(const double* __restrict c0, const double* __restrict c1, const double* __restrict c2,
                  const double* __restrict c3, int len, const double (&a)[K][4], double* const (&x)[K]) {
  for (int r = 0; r < K; ++r) {
    double* __restrict xr = x[r];
    const double a0 = a[r][0], a1 = a[r][1], a2 = a[r][2], a3 = a[r][3];
    for (int i = 0; i < len; ++i) xr[i] -= c0[i] * a0 + c1[i] * a1 + c2[i] * a2 + c3[i] * a3;
  }
}

/// The same for K = 3 and 4 in one pass over the columns c (they are the streamed operand: the
/// factor or the Krylov basis; the x are short enough to stay in cache only for small n).
template <>
inline void axpy4<3>(const double* __restrict c0, const double* __restrict c1, const double* __restrict c2,
                     const double* __restrict c3, int len, const double (&a)[3][4], double* const (&x)[3]) {
  double* __restrict x0 = x[0];
  double* __restrict x1 = x[1];
  double* __restrict x2 = x[2];
  for (int i = 0; i < len; ++i) {
    const double l0 = c0[i], l1 = c1[i], l2 = c2[i], l3 = c3[i];
    x0[i] -= l0 * a[0][0] + l1 * a[0][1] + l2 * a[0][2] + l3 * a[0][3];
    x1[i] -= l0 * a[1][0] + l1 * a[1][1] + l2 * a[1][2] + l3 * a[1][3];
    x2[i] -= l0 * a[2][0] + l1 * a[2][1] + l2 * a[2][2] + l3 * a[2][3];
  }
}
template <>
inline void axpy4<4>(const double* __restrict c0, const double* __restrict c1, const double* __restrict c2,
                     const double* __restrict c3, int len, const double (&a)[4][4], double* const (&x)[4]) {
  double* __restrict x0 = x[0];
  double* __restrict x1 = x[1];
  double* __restrict x2 = x[2];
  double* __restrict x3 = x[3];
  for (int i = 0; i < len; ++i) {
    const double l0 = c0[i], l1 = c1[i], l2 = c2[i], l3 = c3[i];
    x0[i] -= l0 * a[0][0] + l1 * a[0][1] + l2 * a[0][2] + l3 * a[0][3];
    x1[i] -= l0 * a[1][0] + l1 * a[1][1] + l2 * a[1][2] + l3 * a[1][3];
    x2[i] -= l0 * a[2][0] + l1 * a[2][1] + l2 * a[2][2] + l3 * a[2][3];
    x3[i] -= l0 * a[3][0] + l1 * a[3][1] + l2 * a[3][2] + l3 * a[3][3];
  }
}

using v4d = double __attribute__((vector_size(32)));

/// acc + l y, fused (one rounding) where the target has FMA (see dot4).
inline v4d fused_multiply_add(v4d l, v4d y, v4d acc) {
#ifdef __FMA__
  return v4d(_mm256_fmadd_pd(l, y, acc));
#else
  return acc + l * y;
#endif
}
inline double fused_multiply_add(double l, double y, double acc) {
#ifdef __FMA__
  return std::fma(l, y, acc);
#else
  return acc + l * y;
#endif
}

/// s[r][q] = sum_i c_q(i) x_r(i) for four columns c_q and K vectors x_r: 4K sums, each kept in
/// 4 lanes (i mod 4; GCC/Clang vector extension) so that the loop vectorises without reassociation.
/// Rounding written out: every term is a fused multiply-add (where the target has FMA). Left to
/// the compiler's contraction (-ffp-contract=fast, GCC's default) the fusing depended on the code
/// the kernel was inlined into: the same product of the Krylov basis gave results differing in the
/// last bit from two callers. Fusing every term is what GCC did for the Krylov basis before.
template <int K>
inline void dot4(const double* c0, const double* c1, const double* c2, const double* c3, int len,
                 const double* const (&x)[K], double (&s)[K][4]) {
  auto load = [](const double* p) {
    v4d v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  v4d acc[K][4] = {};
  int i = 0;
  for (; i + 4 <= len; i += 4) {
    const v4d l0 = load(c0 + i), l1 = load(c1 + i), l2 = load(c2 + i), l3 = load(c3 + i);
    for (int r = 0; r < K; ++r) {  // unrolled (K is a constant)
      const v4d y = load(x[r] + i);
      acc[r][0] = fused_multiply_add(l0, y, acc[r][0]);
      acc[r][1] = fused_multiply_add(l1, y, acc[r][1]);
      acc[r][2] = fused_multiply_add(l2, y, acc[r][2]);
      acc[r][3] = fused_multiply_add(l3, y, acc[r][3]);
    }
  }
  for (; i < len; ++i) {
    const double l[4] = {c0[i], c1[i], c2[i], c3[i]};
    for (int r = 0; r < K; ++r)
      for (int q = 0; q < 4; ++q) acc[r][q][0] = fused_multiply_add(l[q], x[r][i], acc[r][q][0]);
  }
  for (int r = 0; r < K; ++r)
    for (int q = 0; q < 4; ++q) {
      const v4d& a = acc[r][q];
      s[r][q] = (a[0] + a[1]) + (a[2] + a[3]);
    }
}

/// L L' x = b for K right-hand sides x[r] (each of length n, overwritten), L the lower triangle
/// of the column-major n x n array `L` with leading dimension `ld`.
template <int K>
inline void cholesky_solve(const double* L, long ld, int n, double* const (&x)[K]) {
  int j = 0;
  for (; j + 4 <= n; j += 4) {  // forward, four columns at a time
    const double* c0 = L + ld * j;
    const double* c1 = c0 + ld;
    const double* c2 = c1 + ld;
    const double* c3 = c2 + ld;
    double a[K][4];
    for (int r = 0; r < K; ++r) {
      double* y = x[r];
      y[j] /= c0[j];
      y[j + 1] = (y[j + 1] - c0[j + 1] * y[j]) / c1[j + 1];
      y[j + 2] = (y[j + 2] - c0[j + 2] * y[j] - c1[j + 2] * y[j + 1]) / c2[j + 2];
      y[j + 3] = (y[j + 3] - c0[j + 3] * y[j] - c1[j + 3] * y[j + 1] - c2[j + 3] * y[j + 2]) / c3[j + 3];
      for (int q = 0; q < 4; ++q) a[r][q] = y[j + q];
    }
    double* tail[K];
    for (int r = 0; r < K; ++r) tail[r] = x[r] + j + 4;
    axpy4<K>(c0 + j + 4, c1 + j + 4, c2 + j + 4, c3 + j + 4, n - j - 4, a, tail);
  }
  for (; j < n; ++j) {  // the last n % 4 columns
    const double* c = L + ld * j;
    for (int r = 0; r < K; ++r) {
      double* y = x[r];
      y[j] /= c[j];
      for (int i = j + 1; i < n; ++i) y[i] -= c[i] * y[j];
    }
  }
  // backward: the last n % 4 rows one by one, then four at a time
  j = n;
  for (int q = 0; q < n % 4; ++q) {
    --j;
    const double* c = L + ld * j;
    for (int r = 0; r < K; ++r) {
      double* y = x[r];
      double sum = 0;
      for (int i = j + 1; i < n; ++i) sum += c[i] * y[i];
      y[j] = (y[j] - sum) / c[j];
    }
  }
  for (j -= 4; j >= 0; j -= 4) {
    const double* c0 = L + ld * j;
    const double* c1 = c0 + ld;
    const double* c2 = c1 + ld;
    const double* c3 = c2 + ld;
    double s[K][4];
    const double* tail[K];
    for (int r = 0; r < K; ++r) tail[r] = x[r] + j + 4;
    dot4<K>(c0 + j + 4, c1 + j + 4, c2 + j + 4, c3 + j + 4, n - j - 4, tail, s);
    for (int r = 0; r < K; ++r) {
      double* y = x[r];
      y[j + 3] = (y[j + 3] - s[r][3]) / c3[j + 3];
      y[j + 2] = (y[j + 2] - s[r][2] - c2[j + 3] * y[j + 3]) / c2[j + 2];
      y[j + 1] = (y[j + 1] - s[r][1] - c1[j + 2] * y[j + 2] - c1[j + 3] * y[j + 3]) / c1[j + 1];
      y[j] = (y[j] - s[r][0] - c0[j + 1] * y[j + 1] - c0[j + 2] * y[j + 2] - c0[j + 3] * y[j + 3]) / c0[j];
    }
  }
}

template <int K>
inline Eigen::MatrixXd transposed_product(const Eigen::MatrixXd& A, int cols, const Eigen::MatrixXd& X) {
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd C(cols, K);
  const double* a = A.data();
  const long ld = A.outerStride();
  const double* x[K];
  for (int r = 0; r < K; ++r) x[r] = X.col(r).data();
  int q = 0;
  for (; q + 4 <= cols; q += 4) {
    double s[K][4];
    dot4<K>(a + ld * q, a + ld * (q + 1), a + ld * (q + 2), a + ld * (q + 3), n, x, s);
    for (int r = 0; r < K; ++r)
      for (int k = 0; k < 4; ++k) C(q + k, r) = s[r][k];
  }
  for (; q < cols; ++q) C.row(q) = A.col(q).transpose() * X;
  return C;
}

template <int K, class RowsOf>
inline void subtract_product(const Eigen::MatrixXd& A, int rows, int cols, const Eigen::MatrixXd& C,
                             Eigen::MatrixXd& Y, const RowsOf& rows_of) {
  const double* a = A.data();
  const long ld = A.outerStride();
  double* y[K];
  for (int r = 0; r < K; ++r) y[r] = Y.col(r).data();
  int q = 0;
  for (; q + 4 <= cols; q += 4) {
    double c[K][4];
    for (int r = 0; r < K; ++r)
      for (int k = 0; k < 4; ++k) c[r][k] = C(q + k, r);
    const int len = std::min(rows, static_cast<int>(rows_of(q)));
    axpy4<K>(a + ld * q, a + ld * (q + 1), a + ld * (q + 2), a + ld * (q + 3), len, c, y);
  }
  for (; q < cols; ++q) {
    const int len = std::min(rows, static_cast<int>(rows_of(q)));
    Y.topRows(len) -= A.col(q).head(len) * C.row(q);
  }
}

}  // namespace detail

/// X := (L L')^{-1} X, with L the lower triangle of `factor` (e.g. the matrix an in-place
/// Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> has factored). Columns are taken four at a time (the
/// factor is streamed once per pass for all of them), the rest three, two or one at a time.
inline void cholesky_solve_in_place(const Eigen::MatrixXd& factor, Eigen::MatrixXd& X) {
  const int n = static_cast<int>(factor.rows());
  const long ld = factor.outerStride();
  int c = 0;
  const int cols = static_cast<int>(X.cols());
  for (; c + 4 <= cols; c += 4) {
    double* const x[4] = {X.col(c).data(), X.col(c + 1).data(), X.col(c + 2).data(), X.col(c + 3).data()};
    detail::cholesky_solve<4>(factor.data(), ld, n, x);
  }
  if (cols - c == 3) {
    double* const x[3] = {X.col(c).data(), X.col(c + 1).data(), X.col(c + 2).data()};
    detail::cholesky_solve<3>(factor.data(), ld, n, x);
  } else if (cols - c == 2) {
    double* const x[2] = {X.col(c).data(), X.col(c + 1).data()};
    detail::cholesky_solve<2>(factor.data(), ld, n, x);
  } else if (cols - c == 1) {
    double* const x[1] = {X.col(c).data()};
    detail::cholesky_solve<1>(factor.data(), ld, n, x);
  }
}

/// C = A(:, 0:cols)' X for X with 1 to 4 columns (C: cols x X.cols()), streaming A once
/// (tall-skinny products of a Krylov basis with a block of vectors; Eigen's GEMM packs A first,
/// ~2.5x slower here). Wider X: Eigen.
inline Eigen::MatrixXd transposed_product(const Eigen::MatrixXd& A, int cols, const Eigen::MatrixXd& X) {
  switch (X.cols()) {
    case 1: return detail::transposed_product<1>(A, cols, X);
    case 2: return detail::transposed_product<2>(A, cols, X);
    case 3: return detail::transposed_product<3>(A, cols, X);
    case 4: return detail::transposed_product<4>(A, cols, X);
    default: return A.leftCols(cols).transpose() * X;
  }
}

/// Y(0:rows, :) -= A(0:rows, 0:cols) C for Y with 1 to 4 columns (C: cols x Y.cols()), streaming
/// A once. `rows_of` (optional) gives, per group of 4 columns starting at q, how many leading rows
/// of A can be non-zero there (for block Hessenberg A); by default all `rows`.
template <class RowsOf>
inline void subtract_product(const Eigen::MatrixXd& A, int rows, int cols, const Eigen::MatrixXd& C,
                             Eigen::MatrixXd& Y, const RowsOf& rows_of) {
  switch (Y.cols()) {
    case 1: return detail::subtract_product<1>(A, rows, cols, C, Y, rows_of);
    case 2: return detail::subtract_product<2>(A, rows, cols, C, Y, rows_of);
    case 3: return detail::subtract_product<3>(A, rows, cols, C, Y, rows_of);
    case 4: return detail::subtract_product<4>(A, rows, cols, C, Y, rows_of);
    default: Y.topRows(rows) -= A.topLeftCorner(rows, cols) * C;
  }
}

inline void subtract_product(const Eigen::MatrixXd& A, int rows, int cols, const Eigen::MatrixXd& C,
                             Eigen::MatrixXd& Y) {
  subtract_product(A, rows, cols, C, Y, [rows](int) { return rows; });
}

}  // namespace rollnoise::linalg
