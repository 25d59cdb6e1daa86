// The paper's form of the linear model, M(z) Q = W with M(z) = M0 - z M1 (paper Eqs. 11-24 in the
// scaled unknowns, linear_model.hpp): assembled densely, solved by a fresh complex LU per frequency
// (the reference, creep_coefficients_direct), by its Hessenberg form (the exact sweep: falling
// friction, and the fallback of the Markov routes), and in time (falling friction).

#include <Eigen/Eigenvalues>
#include <cmath>

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

// Solve (I - z H) X = R for upper Hessenberg H: Gaussian elimination with row interchanges between
// neighbouring rows (the only candidates for a pivot in a Hessenberg matrix), then back substitution.
Eigen::MatrixXcd solve_shifted_hessenberg(const RowMajorMatrix& H, std::complex<double> z, const Eigen::MatrixXd& R) {
  using cd = std::complex<double>;
  const int n = static_cast<int>(H.rows());
  // T = I - z H as real times real: (-z) * H.cast<cd>() is not vectorised (the cast) and called
  // libgcc's __muldc3 for each of the n^2 entries, a quarter of squeal's time on squeal_150m; the
  // same numbers (a real h times z: (-Re z) h + i (-Im z) h, the zero parts exact).
  Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> T(n, n);
  T.real() = -z.real() * H;
  T.imag() = -z.imag() * H;
  T.diagonal().array() += 1.0;
  Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> X = R.cast<cd>();
  for (int k = 0; k + 1 < n; ++k) {
    if (std::abs(T(k + 1, k)) > std::abs(T(k, k))) {
      T.row(k).tail(n - k).swap(T.row(k + 1).tail(n - k));
      X.row(k).swap(X.row(k + 1));
    }
    const cd mult = T(k + 1, k) / T(k, k);
    if (mult != cd(0.0)) {
      T.row(k + 1).tail(n - k - 1) -= mult * T.row(k).tail(n - k - 1);
      X.row(k + 1) -= mult * X.row(k);
    }
  }
  // back substitution with the upper triangle left by the elimination (Eigen's blocked triangular
  // solve: a row-by-row product with the 2-5 columns of X was a quarter of squeal's time)
  T.triangularView<Eigen::Upper>().solveInPlace(X);
  return X;
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
  const Eigen::MatrixXcd X = solve_shifted_hessenberg(form.H, z, form.Rhat.middleCols(first, count));
  const Eigen::MatrixXcd LX = form.Lhat.transpose().cast<std::complex<double>>() * X;
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
