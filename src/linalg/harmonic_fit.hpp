// Least-squares fit q(t) ~ mean + amplitude cos(2 pi f t + phase) (the fit used for CONTACT's
// reference runs, tests/data/contact/U1/harmonic_fit.csv), by Eigen's QR on the 3-column basis
// [1, cos, sin].
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace rollnoise::linalg {

struct HarmonicFit {
  double mean = 0.0, amplitude = 0.0, phase = 0.0;  ///< phase in rad, in (-pi, pi]
  double rms_residual = 0.0;
};

inline HarmonicFit fit_harmonic(const std::vector<double>& t, const std::vector<double>& q,
                                double frequency) {
  const int n = static_cast<int>(t.size());
  Eigen::MatrixXd B(n, 3);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) {
    const double wt = 2.0 * M_PI * frequency * t[i];
    B(i, 0) = 1.0, B(i, 1) = std::cos(wt), B(i, 2) = std::sin(wt);
    y(i) = q[i];
  }
  const Eigen::Vector3d c = B.colPivHouseholderQr().solve(y);
  HarmonicFit f;
  f.mean = c(0);
  // a cos + b sin = A cos(wt + phase) with A cos(phase) = a, -A sin(phase) = b
  f.amplitude = std::hypot(c(1), c(2));
  f.phase = std::atan2(-c(2), c(1));
  f.rms_residual = std::sqrt((B * c - y).squaredNorm() / n);
  return f;
}

}  // namespace rollnoise::linalg
