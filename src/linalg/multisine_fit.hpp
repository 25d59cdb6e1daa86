// Least-squares fit of a sum of sinusoids at known frequencies,
//   q(t) ~ c0 + sum_n Re(a_n e^{i 2 pi f_n t}),
// by Eigen's column-pivoting QR on the basis [1, cos, sin]. Needs more samples than 2N + 1 and a
// record long enough to separate the frequencies (T > 1 / min spacing).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <vector>

namespace rollnoise::linalg {

/// Complex amplitudes a_n (amplitude |a_n|, phase arg a_n) at `frequencies`.
inline std::vector<std::complex<double>> fit_multisine(const std::vector<double>& t,
                                                       const std::vector<double>& q,
                                                       const std::vector<double>& frequencies) {
  const int m = static_cast<int>(t.size()), n = static_cast<int>(frequencies.size());
  Eigen::MatrixXd B(m, 2 * n + 1);
  Eigen::VectorXd y(m);
  for (int i = 0; i < m; ++i) {
    B(i, 0) = 1.0;
    for (int k = 0; k < n; ++k) {
      const double wt = 2.0 * M_PI * frequencies[k] * t[i];
      B(i, 1 + 2 * k) = std::cos(wt);
      B(i, 2 + 2 * k) = std::sin(wt);
    }
    y(i) = q[i];
  }
  const Eigen::VectorXd c = B.colPivHouseholderQr().solve(y);
  std::vector<std::complex<double>> a(n);
  for (int k = 0; k < n; ++k) a[k] = {c(1 + 2 * k), -c(2 + 2 * k)};  // a cos + b sin = Re((a - ib) e^{iwt})
  return a;
}

}  // namespace rollnoise::linalg
