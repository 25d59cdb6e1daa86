// The paper's form of the linear model, M(z) Q = W with M(z) = M0 - z M1 (paper Eqs. 11-24 in the
// scaled unknowns, linear_model.hpp): assembled densely, solved by a fresh complex LU per frequency
// (the reference, creep_coefficients_direct), by its Hessenberg form (the exact sweep: falling
// friction, and the fallback of the Markov routes), and in time (falling friction).

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "core/assert.hpp"
#include "linalg/hessenberg_eigenvalues.hpp"
#include "nss/linear_model.hpp"
#include "nss/linear_model_parts.hpp"

namespace rollnoise::nss {

using contact::Component;
using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

const LinearContactModel::Dense& LinearContactModel::dense() const {
  std::call_once(built_->dense_once, [this] { built_->dense = assemble_paper_form(); });
  return *built_->dense;
}

std::unique_ptr<LinearContactModel::Dense> LinearContactModel::assemble_paper_form() const {
  // M0 = C - A B/dt, M1 = -A0 B/dt on the contact elements, interleaved (x, y) per element,
  // assembled column by column (contiguous writes in the column-major matrices).
  auto d = std::make_unique<Dense>();
  const contact::Grid& g = table_.grid();
  const int m = static_cast<int>(el_.size()), n = 2 * m;
  d->M0.resize(n, n);
  d->M1.resize(n, n);
  for (int b = 0; b < m; ++b) {
    const int ixb = el_[b] % g.nx, iyb = el_[b] / g.nx;
    const Eigen::Matrix2d B = slip_[b] ? slip_traction_matrix(b) : Eigen::Matrix2d::Identity();
    double* c0x = d->M0.col(2 * b).data();
    double* c0y = d->M0.col(2 * b + 1).data();
    double* c1x = d->M1.col(2 * b).data();
    double* c1y = d->M1.col(2 * b + 1).data();
    for (int a = 0; a < m; ++a) {
      const int di = el_[a] % g.nx - ixb, dj = el_[a] / g.nx - iyb;
      const double xx = table_(Component::xx, di, dj), xy = table_(Component::xy, di, dj),
                   yy = table_(Component::yy, di, dj);
      const double xx0 = table_(Component::xx, di + 1, dj), xy0 = table_(Component::xy, di + 1, dj),
                   yy0 = table_(Component::yy, di + 1, dj);
      // -[xx xy; xy yy] B / dt, column by column
      c0x[2 * a] = -(xx * B(0, 0) + xy * B(1, 0)) / dt_;
      c0x[2 * a + 1] = -(xy * B(0, 0) + yy * B(1, 0)) / dt_;
      c0y[2 * a] = -(xx * B(0, 1) + xy * B(1, 1)) / dt_;
      c0y[2 * a + 1] = -(xy * B(0, 1) + yy * B(1, 1)) / dt_;
      c1x[2 * a] = -(xx0 * B(0, 0) + xy0 * B(1, 0)) / dt_;
      c1x[2 * a + 1] = -(xy0 * B(0, 0) + yy0 * B(1, 0)) / dt_;
      c1y[2 * a] = -(xx0 * B(0, 1) + xy0 * B(1, 1)) / dt_;
      c1y[2 * a + 1] = -(xy0 * B(0, 1) + yy0 * B(1, 1)) / dt_;
    }
    d->M0(2 * b, 2 * b) += c_[b];
    d->M0(2 * b + 1, 2 * b + 1) += c_[b];
  }
  return d;
}

CreepMatrix LinearContactModel::creep_coefficients_direct(double frequency) const {
  check_frequency(frequency);
  const Dense& d = dense();
  const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * frequency * dt_);
  const Eigen::MatrixXcd M = d.M0.cast<std::complex<double>>() - z * d.M1.cast<std::complex<double>>();
  const Eigen::MatrixXcd Q = M.partialPivLu().solve(W_.cast<std::complex<double>>());
  std::vector<CreepMatrix> f = {-(L_.transpose().cast<std::complex<double>>() * Q)};
  apply_sampling(f, {frequency});
  return f[0];
}

LoadVector LinearContactModel::normal_load_coefficients_direct(double frequency) const {
  check_frequency(frequency);
  if (!has_normal_load_input()) return LoadVector::Zero();
  const Dense& d = dense();
  // (G2): M(z) Q = (A - z A0) bN / dt = wN0 - z wN1,  g = dx dy U' bN + L' Q
  const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * frequency * dt_);
  const Eigen::MatrixXcd M = d.M0.cast<std::complex<double>>() - z * d.M1.cast<std::complex<double>>();
  const Eigen::VectorXcd rhs = wN0_.cast<std::complex<double>>() - z * wN1_.cast<std::complex<double>>();
  const Eigen::VectorXcd Q = M.partialPivLu().solve(rhs);
  return dN_.cast<std::complex<double>>() + L_.transpose().cast<std::complex<double>>() * Q;
}

const LinearContactModel::HessenbergForm& LinearContactModel::hessenberg() const {
  std::call_once(built_->hessenberg_once, [this] { built_->hessenberg = hessenberg_form(); });
  return *built_->hessenberg;
}

std::unique_ptr<LinearContactModel::HessenbergForm> LinearContactModel::hessenberg_form() const {
  const Dense& d = dense();
  // (M0 - z M1)^{-1} = (I - z N)^{-1} M0^{-1},  N = M0^{-1} M1 = Q H Q' (real Hessenberg form)
  auto form = std::make_unique<HessenbergForm>();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu0(d.M0);
  const Eigen::MatrixXd N = lu0.solve(d.M1);
  const Eigen::HessenbergDecomposition<Eigen::MatrixXd> hd(N);
  form->H = hd.matrixH();
  Eigen::MatrixXd inputs(W_.rows(), 5);  // the creepages, then wN0 and wN1 of (G2)
  inputs << W_, wN0_, wN1_;
  // Q' applied as its Householder reflectors (O(n^2) per column; forming Q is O(n^3)).
  form->Rhat = hd.matrixQ().transpose() * lu0.solve(inputs);
  form->Lhat = hd.matrixQ().transpose() * L_;
  return form;
}

namespace {

// One step of the elimination below on the columns j < len (the pointers start at the first
// column): with the pivot row p and the other row o (each either the carried row c or the next row
// of I - z H, f_j = -z h_j, h = row k+1 of H), a_q,j += p_j y_q (q < 3) and c_j := o_j - mult p_j.
// Real and imaginary parts apart, every array its own restrict parameter: the loop vectorises
// (std::complex products call libgcc's NaN-checking __muldc3, and with the sums' pointers taken
// from an array GCC gave up on the aliasing checks): 0.58 ms a call at n = 1284 against 1.8 ms.
struct Shift {
  double zr, zi;  // z
  double mr, mi;  // mult
  double yr[3], yi[3];
};
template <bool kNextRowIsPivot>
void eliminate_and_substitute(int len, const Shift& s, const double* __restrict h,
                              double* __restrict cr, double* __restrict ci, double* __restrict ar0,
                              double* __restrict ai0, double* __restrict ar1,
                              double* __restrict ai1, double* __restrict ar2,
                              double* __restrict ai2) {
  const double zr = s.zr, zi = s.zi, mr = s.mr, mi = s.mi;
  const double y0r = s.yr[0], y1r = s.yr[1], y2r = s.yr[2], y0i = s.yi[0], y1i = s.yi[1],
               y2i = s.yi[2];
  for (int j = 0; j < len; ++j) {
    const double fr = -zr * h[j], fi = -zi * h[j];
    const double pr = kNextRowIsPivot ? fr : cr[j], pi = kNextRowIsPivot ? fi : ci[j];
    const double orr = kNextRowIsPivot ? cr[j] : fr, oi = kNextRowIsPivot ? ci[j] : fi;
    ar0[j] += pr * y0r - pi * y0i;
    ai0[j] += pr * y0i + pi * y0r;
    ar1[j] += pr * y1r - pi * y1i;
    ai1[j] += pr * y1i + pi * y1r;
    ar2[j] += pr * y2r - pi * y2i;
    ai2[j] += pr * y2i + pi * y2r;
    cr[j] = orr - (mr * pr - mi * pi);
    ci[j] = oi - (mr * pi + mi * pr);
  }
}

/// (a b) for complex a, b written out (std::complex's product calls __muldc3).
inline std::complex<double> times(std::complex<double> a, std::complex<double> b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// Lhat' (I - z H)^{-1} R for upper Hessenberg H (n x n), R (n x m), Lhat (n x 3), without forming
// I - z H or a factor of it. Gaussian elimination with row interchanges between neighbouring rows
// (the only candidates for a pivot in a Hessenberg matrix) makes the rows of U and of
// Z = L^{-1} P R one at a time (P (I - z H) = L U): at step k the carried row c and the next row
// r = e_{k+1} - z H_{k+1} (formed from H's row as it is read) give the pivot row, row k of U, and
// the eliminated row c := r - (r_k / c_k) c. Then
//
//   Lhat' X = Lhat' U^{-1} Z = Y' Z,   U' Y = Lhat,
//
// whose forward substitution needs at step k just row k of U: Y_k = (Lhat_k - a_k) / U_kk, then
// a_j += U_kj Y_k for j > k (the column form of the substitution; Golub & Van Loan, Matrix
// Computations, 4th ed. 2013, Sec. 3.1.3-3.1.4 and 3.2.11 for the Hessenberg LU). So H is read
// once, nothing of size n^2 is written, and the elimination and the substitution share one pass
// over each row: the solve with the formed n x n complex matrix and its back substitution took 3.8
// ms per call at n = 1284 (~100 MB moved), this 0.6 ms.
Eigen::MatrixXcd projected_shifted_hessenberg_solve(const RowMajorMatrix& H, std::complex<double> z,
                                                    const Eigen::MatrixXd& R,
                                                    const Eigen::MatrixXd& Lhat) {
  using cd = std::complex<double>;
  ROLLNOISE_ASSERT(Lhat.cols() == 3, "the Hessenberg form's outputs are the three creep forces");
  const Eigen::Index n = H.rows(), m = R.cols();
  const double zr = z.real(), zi = z.imag();
  // the carried row and the sums a_j (one column per output), real and imaginary parts apart
  std::vector<double> cr(n), ci(n);
  Eigen::MatrixXd ar = Eigen::MatrixXd::Zero(n, 3), ai = Eigen::MatrixXd::Zero(n, 3);
  Eigen::MatrixXcd out = Eigen::MatrixXcd::Zero(3, m);
  for (Eigen::Index j = 0; j < n; ++j) cr[j] = -zr * H(0, j), ci[j] = -zi * H(0, j);
  cr[0] += 1.0;
  Eigen::RowVectorXcd zc = R.row(0).cast<cd>(), zn(m);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index tail = n - k - 1;
    cd pivot(cr[k], ci[k]), other = 0.0;  // column k of the pivot row and of the other row
    bool next_is_pivot = false;
    if (tail > 0) {
      other = -z * H(k + 1, k);  // the next row in column k (its diagonal 1 is in column k + 1)
      zn = R.row(k + 1).cast<cd>();
      if (std::norm(other) > std::norm(pivot)) {  // |.|^2: no hypot per row
        std::swap(pivot, other);
        zc.swap(zn);
        next_is_pivot = true;
      }
    }
    const cd inv = 1.0 / pivot;          // one complex division a row
    Shift sh{zr, zi, 0.0, 0.0, {}, {}};  // Y_k = (Lhat_k - a_k) / U_kk
    for (int q = 0; q < 3; ++q) {
      const cd y = times(Lhat(k, q) - cd(ar(k, q), ai(k, q)), inv);
      sh.yr[q] = y.real(), sh.yi[q] = y.imag();
      out.row(q) += y * zc;
    }
    if (tail == 0) break;
    const cd mult = times(other, inv);
    sh.mr = mult.real(), sh.mi = mult.imag();
    // column k + 1 holds the next row's diagonal 1: that column apart (the kernel's arithmetic
    // written out: with one helper for both, GCC 12 no longer vectorised the kernel), then the rest
    const double* h = &H(k + 1, 0);
    const double fr = 1.0 - zr * h[k + 1], fi = -zi * h[k + 1];
    const double pr = next_is_pivot ? fr : cr[k + 1], pi = next_is_pivot ? fi : ci[k + 1];
    const double orr = next_is_pivot ? cr[k + 1] : fr, oi = next_is_pivot ? ci[k + 1] : fi;
    for (int q = 0; q < 3; ++q) {
      ar(k + 1, q) += pr * sh.yr[q] - pi * sh.yi[q];
      ai(k + 1, q) += pr * sh.yi[q] + pi * sh.yr[q];
    }
    cr[k + 1] = orr - (sh.mr * pr - sh.mi * pi);
    ci[k + 1] = oi - (sh.mr * pi + sh.mi * pr);
    const Eigen::Index j0 = k + 2;
    const int len = static_cast<int>(n - j0);
    // the columns' pointers by offset (at k = n - 2 there are none: no element to address)
    double* const a_r = ar.data() + j0;
    double* const a_i = ai.data() + j0;
    if (len > 0 && next_is_pivot)
      eliminate_and_substitute<true>(len, sh, h + j0, cr.data() + j0, ci.data() + j0, a_r, a_i,
                                     a_r + n, a_i + n, a_r + 2 * n, a_i + 2 * n);
    else if (len > 0)
      eliminate_and_substitute<false>(len, sh, h + j0, cr.data() + j0, ci.data() + j0, a_r, a_i,
                                      a_r + n, a_i + n, a_r + 2 * n, a_i + 2 * n);
    zc = zn - mult * zc;
  }
  return out;
}

}  // namespace

std::vector<CreepMatrix> LinearContactModel::creep_coefficients_hessenberg(
    const std::vector<double>& frequencies) const {
  for (double f : frequencies) check_frequency(f);
  std::vector<CreepMatrix> f;
  hessenberg_sweep(frequencies, &f, nullptr);
  apply_sampling(f, frequencies);
  return f;
}

void LinearContactModel::hessenberg_sweep(const std::vector<double>& frequencies, std::vector<CreepMatrix>* f,
                                          std::vector<LoadVector>* g) const {
  // (M0 - z M1)^{-1} = (I - z N)^{-1} M0^{-1}: f = -L' X(:, 0:3), g = dN + L' (X(:, 3) - z X(:, 4))
  // with (I - z H) X = Q' M0^{-1} [W, wN0, wN1] (G2).
  for (double fr : frequencies) {
    CreepMatrix fk;
    LoadVector gk;
    hessenberg_at(std::polar(1.0, -2.0 * M_PI * fr * dt_), f ? &fk : nullptr, g ? &gk : nullptr);
    if (f) f->push_back(fk);
    if (g) g->push_back(gk);
  }
}

void LinearContactModel::hessenberg_at(std::complex<double> z, CreepMatrix* f, LoadVector* g) const {
  // Any complex z (the shifted Hessenberg solve does not need |z| = 1).
  const HessenbergForm& form = hessenberg();
  const int first = f ? 0 : 3, count = (f ? 3 : 0) + (g ? 2 : 0);
  const Eigen::MatrixXcd LX =
      projected_shifted_hessenberg_solve(form.H, z, form.Rhat.middleCols(first, count), form.Lhat);
  if (f) *f = -LX.leftCols(3);
  if (g) *g = dN_.cast<std::complex<double>>() + LX.col(count - 2) - z * LX.col(count - 1);
}

double LinearContactModel::spectral_radius() const {
  // The eigenvalues of M0^{-1} M1 = Q H Q' are those of H (LAPACK's Hessenberg QR on H itself:
  // linalg/hessenberg_eigenvalues.hpp).
  std::call_once(built_->radius_once, [this] {
    built_->spectral_radius =
        linalg::hessenberg_eigenvalues(Eigen::MatrixXd(hessenberg().H)).cwiseAbs().maxCoeff();
  });
  return built_->spectral_radius;
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response_dense(const std::vector<Eigen::Vector3d>& xi,
                                                                     const std::vector<double>& dN) const {
  // The paper form in time (G2 with z the one-step delay): M0 Q_k = M1 Q_{k-1} + W xi_k +
  // wN0 N~_k - wN1 N~_{k-1},  F_k = L' Q_k + dN N~_k; one LU factorisation of M0.
  const Dense& d = dense();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(d.M0);
  std::vector<Eigen::Vector3d> F;
  F.reserve(xi.size());
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(W_.rows());
  double previous = 0.0;
  for (size_t k = 0; k < xi.size(); ++k) {
    Eigen::VectorXd rhs = d.M1 * Q + W_ * xi[k];
    if (block_ == 4) rhs += wN0_ * dN[k] - wN1_ * previous;
    Q = lu.solve(rhs);
    F.push_back(L_.transpose() * Q + dN_ * dN[k]);
    previous = dN[k];
  }
  return F;
}

}  // namespace rollnoise::nss
