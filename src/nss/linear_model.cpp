#include "nss/linear_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/influence.hpp"
#include "core/errors.hpp"

namespace rollnoise::nss {

using contact::Component;
using contact::ElementState;

LinearContactModel::LinearContactModel(const contact::ContactPatch& patch,
                                       const contact::TangentialSolution& mean,
                                       const LinearModelInput& in)
    : dt_(patch.grid.dx / in.speed), speed_(in.speed) {
  const contact::Grid& g = patch.grid;
  const contact::InfluenceTable& A = patch.influence;
  const std::vector<int> el = contact::sweep_order(g, patch.normal.pn);
  const int m = static_cast<int>(el.size()), n = 2 * m;

  // Element blocks B_e, C_e (scaled formulation, see the header).
  std::vector<Eigen::Matrix2d> B(m);
  std::vector<double> c(m, 0.0);
  const double self = std::max(A(Component::xx, 0, 0), A(Component::yy, 0, 0)) / dt_;
  for (int a = 0; a < m; ++a) {
    const int k = el[a];
    if (mean.state[k] == static_cast<std::int8_t>(ElementState::slip)) {
      const double s1 = mean.sx[k], s2 = mean.sy[k], s = std::hypot(s1, s2);
      const Eigen::Vector2d t(s2 / s, -s1 / s);
      B[a] = -t * t.transpose();
      c[a] = std::max(s / (in.mu * patch.normal.pn[k]), 1e-12 * self);
      ++n_slip_;
    } else {
      B[a].setIdentity();
      ++n_adhesion_;
    }
  }

  // M0 = C - A B/dt, M1 = -A0 B/dt on the contact elements, interleaved (x, y) per element.
  M0_.setZero(n, n);
  M1_.setZero(n, n);
  for (int b = 0; b < m; ++b) {
    const int ixb = el[b] % g.nx, iyb = el[b] / g.nx;
    for (int a = 0; a < m; ++a) {
      const int di = el[a] % g.nx - ixb, dj = el[a] / g.nx - iyb;
      Eigen::Matrix2d Aab, A0ab;
      Aab << A(Component::xx, di, dj), A(Component::xy, di, dj), A(Component::xy, di, dj),
          A(Component::yy, di, dj);
      A0ab << A(Component::xx, di + 1, dj), A(Component::xy, di + 1, dj),
          A(Component::xy, di + 1, dj), A(Component::yy, di + 1, dj);
      M0_.block<2, 2>(2 * a, 2 * b) = -Aab * B[b] / dt_;
      M1_.block<2, 2>(2 * a, 2 * b) = -A0ab * B[b] / dt_;
    }
    M0_(2 * b, 2 * b) += c[b];
    M0_(2 * b + 1, 2 * b + 1) += c[b];
  }

  // Inputs W (per unit creepage) and outputs L.
  W_.setZero(n, 3);
  L_.setZero(n, 3);
  const double area = g.element_area();
  for (int a = 0; a < m; ++a) {
    const double x = g.x(el[a] % g.nx), y = g.y(el[a] / g.nx);
    W_(2 * a, 0) = in.speed;
    W_(2 * a + 1, 1) = in.speed;
    W_(2 * a, 2) = -in.speed * y;
    W_(2 * a + 1, 2) = in.speed * (x + in.spin_offset * g.dx);
    const Eigen::Vector2d u1(1, 0), u2(0, 1), usp0(-y, x);
    L_.block<2, 1>(2 * a, 0) = area * B[a].transpose() * u1;
    L_.block<2, 1>(2 * a, 1) = area * B[a].transpose() * u2;
    L_.block<2, 1>(2 * a, 2) = area * B[a].transpose() * usp0;
  }
  lu0_.compute(M0_);
  // steps per contact length: the extent of the contact area in x, in elements
  int ix_min = g.nx, ix_max = -1;
  for (int k : el) ix_min = std::min(ix_min, k % g.nx), ix_max = std::max(ix_max, k % g.nx);
  steps_per_contact_length_ = std::max(1, ix_max - ix_min + 1);
}

void LinearContactModel::check_frequency(double f) const {
  if (!std::isfinite(f) || f < 0.0) {
    std::ostringstream msg;
    msg << "frequency " << f << " Hz: must be finite and non-negative";
    throw InputError("frequency", msg.str());
  }
  if (f > nyquist_frequency() * (1 + 1e-12)) {
    std::ostringstream msg;
    msg << "frequency " << f << " Hz is above the grid's Nyquist limit V/(2 dx) = "
        << nyquist_frequency() << " Hz: refine the grid in x (grid.nx) or lower the frequency";
    throw InputError("frequency", msg.str());
  }
}

CreepMatrix LinearContactModel::creep_coefficients_direct(double frequency) const {
  check_frequency(frequency);
  const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * frequency * dt_);
  const Eigen::MatrixXcd M = M0_.cast<std::complex<double>>() - z * M1_.cast<std::complex<double>>();
  const Eigen::MatrixXcd Q = M.partialPivLu().solve(W_.cast<std::complex<double>>());
  return -(L_.transpose().cast<std::complex<double>>() * Q);
}

void LinearContactModel::reduce() const {
  if (reduced_) return;
  // (M0 - z M1)^{-1} = (I - z N)^{-1} M0^{-1},  N = M0^{-1} M1 = Q H Q' (real Hessenberg form)
  const Eigen::MatrixXd N = lu0_.solve(M1_);
  const Eigen::HessenbergDecomposition<Eigen::MatrixXd> hd(N);
  H_ = hd.matrixH();
  const Eigen::MatrixXd Q = hd.matrixQ();
  Rhat_ = Q.transpose() * lu0_.solve(W_);
  Lhat_ = Q.transpose() * L_;
  reduced_ = true;
}

namespace {

// Solve (I - z H) X = R for upper Hessenberg H: Gaussian elimination with row interchanges between
// neighbouring rows (the only candidates for a pivot in a Hessenberg matrix), then back substitution.
Eigen::MatrixXcd solve_shifted_hessenberg(
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& H,
    std::complex<double> z, const Eigen::MatrixXd& R) {
  using cd = std::complex<double>;
  const int n = static_cast<int>(H.rows()), r = static_cast<int>(R.cols());
  Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> T = (-z) * H.cast<cd>();
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
  for (int k = n - 1; k >= 0; --k) {
    if (k + 1 < n) X.row(k) -= T.row(k).tail(n - k - 1) * X.bottomRows(n - k - 1);
    X.row(k) /= T(k, k);
  }
  (void)r;
  return X;
}

}  // namespace

std::vector<CreepMatrix> LinearContactModel::creep_coefficients(
    const std::vector<double>& frequencies, int max_contact_lengths) const {
  for (double f : frequencies) check_frequency(f);
  if (markov_.empty()) {
    // h_j = L' X_j, X_0 = M0^{-1} W, X_{j+1} = M0^{-1} M1 X_j, until |h_j| < 1e-15 max |h| for a
    // whole contact length.
    const int max_steps = max_contact_lengths * steps_per_contact_length_;
    Eigen::MatrixXd X = lu0_.solve(W_);
    double h_max = 0.0;
    int quiet = 0;
    std::vector<Eigen::Matrix3d> h;
    for (int j = 0; j < max_steps; ++j) {
      h.push_back(L_.transpose() * X);
      const double norm = h.back().norm();
      h_max = std::max(h_max, norm);
      quiet = norm < 1e-15 * h_max ? quiet + 1 : 0;
      if (quiet >= steps_per_contact_length_) break;
      X = lu0_.solve(M1_ * X);
    }
    if (quiet < steps_per_contact_length_) return creep_coefficients_hessenberg(frequencies);
    markov_ = std::move(h);
  }
  std::vector<CreepMatrix> out;
  out.reserve(frequencies.size());
  for (double f : frequencies) {  // Horner: sum_j h_j z^j
    const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * f * dt_);
    CreepMatrix acc = CreepMatrix::Zero();
    for (auto it = markov_.rbegin(); it != markov_.rend(); ++it) acc = acc * z + it->cast<std::complex<double>>();
    out.push_back(-acc);
  }
  return out;
}

std::vector<CreepMatrix> LinearContactModel::creep_coefficients_hessenberg(
    const std::vector<double>& frequencies) const {
  for (double f : frequencies) check_frequency(f);
  reduce();
  std::vector<CreepMatrix> out;
  out.reserve(frequencies.size());
  for (double f : frequencies) {
    const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * f * dt_);
    const Eigen::MatrixXcd X = solve_shifted_hessenberg(H_, z, Rhat_);
    out.push_back(-(Lhat_.transpose().cast<std::complex<double>>() * X));
  }
  return out;
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response(
    const std::vector<Eigen::Vector3d>& xi) const {
  std::vector<Eigen::Vector3d> F;
  F.reserve(xi.size());
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(M0_.rows());
  for (const auto& x : xi) {
    Q = lu0_.solve(M1_ * Q + W_ * x);
    F.push_back(L_.transpose() * Q);
  }
  return F;
}

}  // namespace rollnoise::nss
