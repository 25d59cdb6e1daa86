#include "dynamics/track_periodic.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace rollnoise::dynamics {
namespace {

// The root of mu^2 - eta mu + 1 = 0 with |mu| <= 1: mu = 2 / (eta + sqrt(eta^2 - 4)) with the
// square root's sign that makes the denominator the larger (no cancellation).
cdouble decaying_multiplier(cdouble eta) {
  const cdouble root = std::sqrt(eta * eta - 4.0);
  const cdouble den = std::abs(eta + root) >= std::abs(eta - root) ? eta + root : eta - root;
  return 2.0 / den;
}

// mu^n for an integer n >= 0.
cdouble power(cdouble mu, long n) {
  return n == 0 ? cdouble(1.0) : std::pow(mu, static_cast<int>(n));
}

}  // namespace

PeriodicallySupportedBeam::PeriodicallySupportedBeam(const InfiniteBeam& free_rail, cdouble K,
                                                     double spacing,
                                                     const PeriodicallySupportedBeam* reference)
    : free_(free_rail),
      amp_(free_rail.wave_amplitudes()),
      L_(spacing),
      k_(free_rail.wavenumbers()) {
  const cdouble I(0.0, 1.0);
  const auto& A = amp_.wF;
  // P1: eta^2 + b eta + c = 0, alpha_j = K A_j (z_j - 1/z_j).
  std::array<cdouble, 2> eta_j, alpha;
  for (int j = 0; j < 2; ++j) {
    z_[j] = std::exp(-I * k_[j] * L_);
    eta_j[j] = z_[j] + 1.0 / z_[j];
    alpha[j] = K * A[j] * (z_[j] - 1.0 / z_[j]);
  }
  const cdouble b = alpha[0] + alpha[1] - eta_j[0] - eta_j[1];
  const cdouble c = eta_j[0] * eta_j[1] - alpha[0] * eta_j[1] - alpha[1] * eta_j[0];
  const cdouble disc = std::sqrt(b * b - 4.0 * c);
  const cdouble qq = -0.5 * (std::abs(b + disc) >= std::abs(b - disc) ? b + disc : b - disc);
  if (std::abs(qq) == 0.0)
    throw NumericalError("PeriodicallySupportedBeam: degenerate Floquet relation (eta = 0 twice)");
  const std::array<cdouble, 2> eta = {qq, c / qq};
  for (int q = 0; q < 2; ++q) {
    mu_[q] = decaying_multiplier(eta[q]);
    if (reference) {  // the one of mu, 1/mu nearest the real-frequency waves (continuation)
      double best = 1e300;
      const cdouble candidates[2] = {mu_[q], 1.0 / mu_[q]};
      for (const cdouble r : reference->mu_)
        for (const cdouble m : candidates)
          if (std::abs(m - r) < best) best = std::abs(m - r), mu_[q] = m;
    }
  }
  // P2's matrix: rows j (n >= 1) and 2 + j (n <= 0), columns a_1, a_2, c_1, c_2.
  Eigen::Matrix4cd M;
  for (int j = 0; j < 2; ++j)
    for (int q = 0; q < 2; ++q) {
      const cdouble near = A[j] / (mu_[q] - z_[j]), far = A[j] / (1.0 - z_[j] * mu_[q]);
      M(j, q) = -near;
      M(j, 2 + q) = far;
      M(2 + j, q) = far;
      M(2 + j, 2 + q) = -near;
    }
  system_.compute(M);
}

Eigen::Matrix2cd PeriodicallySupportedBeam::transfer(double x_r, double x_e) const {
  const cdouble I(0.0, 1.0);
  const auto& A = amp_.wF;
  const auto& B = amp_.wM;
  // The load's span [0, L): shift both points by whole spans (periodicity).
  double shift = std::floor(x_e / L_);
  double xe = x_e - shift * L_;
  if (xe >= L_) xe -= L_, shift += 1.0;
  if (xe < 0.0) xe = 0.0;
  const double xr = x_r - shift * L_;

  // P2: the amplitudes (a_1, a_2, c_1, c_2) per load column (F, M).
  Eigen::Matrix<cdouble, 4, 2> rhs;
  for (int j = 0; j < 2; ++j) {
    const cdouble right = std::exp(I * k_[j] * xe), left = std::exp(I * k_[j] * (L_ - xe));
    rhs(j, 0) = -right * A[j];
    rhs(j, 1) = -right * B[j];
    rhs(2 + j, 0) = -left * A[j];
    rhs(2 + j, 1) = left * B[j];
  }
  const Eigen::Matrix<cdouble, 4, 2> v = system_.solve(rhs);
  auto reaction = [&](long m) -> Eigen::RowVector2cd {  // R_m per (F, M)
    Eigen::RowVector2cd r = Eigen::RowVector2cd::Zero();
    for (int q = 0; q < 2; ++q)
      r += m >= 1 ? power(mu_[q], m - 1) * v.row(q) : power(mu_[q], -m) * v.row(2 + q);
    return r;
  };

  // P3: per wave j, P_j = sum over the sleepers with x_m <= x_r of e^{-i k_j |x_r - x_m|} R_m,
  // N_j over those with x_m > x_r; the tails m <= lo (left waves) and m >= hi (right waves) in
  // closed form, the sleepers between term by term.
  const long r = static_cast<long>(std::floor(xr / L_));
  const long lo = std::min(0L, r), hi = std::max(1L, r + 1);
  Eigen::Matrix2cd H = free_.transfer(x_r - x_e);
  for (int j = 0; j < 2; ++j) {
    Eigen::RowVector2cd P = Eigen::RowVector2cd::Zero(), N = Eigen::RowVector2cd::Zero();
    const cdouble left_first = std::exp(-I * k_[j] * (xr - lo * L_));
    const cdouble right_first = std::exp(-I * k_[j] * (hi * L_ - xr));
    for (int q = 0; q < 2; ++q) {
      const cdouble ratio = 1.0 / (1.0 - z_[j] * mu_[q]);
      P += left_first * power(mu_[q], -lo) * ratio * v.row(2 + q);
      N += right_first * power(mu_[q], hi - 1) * ratio * v.row(q);
    }
    for (long m = lo + 1; m < hi; ++m) {
      const double d = xr - m * L_;
      const cdouble e = std::exp(-I * k_[j] * std::abs(d));
      (d >= 0.0 ? P : N) += e * reaction(m);
    }
    H.row(0) += A[j] * (P + N);
    H.row(1) -= B[j] * (P - N);
  }
  return H;
}

}  // namespace rollnoise::dynamics
