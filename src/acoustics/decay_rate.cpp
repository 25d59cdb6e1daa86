#include "acoustics/decay_rate.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rollnoise::acoustics {

namespace {

/// 10 log10(e), as EN 15461 prints it (Formulae 1 and 2).
constexpr double kDecayConstant = 4.343;

void check_positions(const std::vector<double>& x) {
  if (x.size() < 2)
    throw std::invalid_argument(
        "decay rate: needs the direct position x_0 = 0 and at least one more along the rail");
  if (x[0] != 0.0)
    throw std::invalid_argument(
        "decay rate: the first position must be the excitation/response point, x_0 = 0 m");
  for (size_t n = 1; n < x.size(); ++n)
    if (!(x[n] > x[n - 1]) || !std::isfinite(x[n]))
      throw std::invalid_argument(
          "decay rate: positions along the rail must be finite and strictly increasing (position " +
          std::to_string(n) + ")");
}

}  // namespace

std::vector<double> en15461_positions(double sleeper_spacing) {
  if (!(sleeper_spacing > 0.0) || !std::isfinite(sleeper_spacing))
    throw std::invalid_argument("decay rate: the sleeper spacing must be positive, got " +
                                std::to_string(sleeper_spacing) + " m");
  // EN 15461 6.7, Figure 2 (header): quarter spacings to 2.5, half to 4, whole to 8, then far
  // field.
  static constexpr std::array<double, 29> kSpacings = {
      0.0, 0.25, 0.5, 0.75, 1.0,  1.25, 1.5,  1.75, 2.0,  2.25, 2.5,  3.0,  3.5,  4.0, 5.0,
      6.0, 7.0,  8.0, 10.0, 12.0, 16.0, 20.0, 24.0, 30.0, 36.0, 42.0, 48.0, 54.0, 66.0};
  std::vector<double> x;
  x.reserve(kSpacings.size());
  for (double s : kSpacings) x.push_back(s * sleeper_spacing);
  return x;
}

std::vector<double> decay_rate_intervals(const std::vector<double>& x) {
  check_positions(x);
  // A.2: from halfway to the previous position to halfway to the next; x_0 from 0; the last one
  // symmetric about itself (its interval is its distance to the previous position).
  const size_t N = x.size() - 1;
  std::vector<double> dx(x.size());
  dx[0] = 0.5 * x[1];
  for (size_t n = 1; n < N; ++n) dx[n] = 0.5 * (x[n + 1] - x[n - 1]);
  dx[N] = x[N] - x[N - 1];
  return dx;
}

Eigen::VectorXd track_decay_rate(const std::vector<double>& positions,
                                 const Eigen::MatrixXd& squared_magnitudes) {
  const std::vector<double> dx = decay_rate_intervals(positions);
  if (squared_magnitudes.rows() != static_cast<Eigen::Index>(positions.size()))
    throw std::invalid_argument("decay rate: " + std::to_string(squared_magnitudes.rows()) +
                                " rows of squared transfer magnitudes for " +
                                std::to_string(positions.size()) + " positions");
  Eigen::VectorXd rate(squared_magnitudes.cols());
  for (Eigen::Index b = 0; b < squared_magnitudes.cols(); ++b) {
    const double direct = squared_magnitudes(0, b);
    if (!(direct > 0.0) || !std::isfinite(direct))
      throw std::invalid_argument(
          "decay rate: the direct squared transfer magnitude |A(x_0)|^2 must be positive and "
          "finite (band " +
          std::to_string(b) + ")");
    // Formula (1): DR = 4.343 / Sum |A(x_n)|^2 / |A(x_0)|^2 Delta x_n.
    double sum = 0.0;
    for (size_t n = 0; n < dx.size(); ++n) {
      const double a2 = squared_magnitudes(static_cast<Eigen::Index>(n), b);
      if (!(a2 >= 0.0) || !std::isfinite(a2))
        throw std::invalid_argument(
            "decay rate: squared transfer magnitudes must be finite and >= 0 (a level in dB is "
            "not a magnitude)");
      sum += a2 / direct * dx[n];
    }
    rate[b] = kDecayConstant / sum;
  }
  return rate;
}

double track_decay_rate(const std::vector<double>& positions,
                        const std::vector<double>& squared_magnitudes) {
  const Eigen::Map<const Eigen::VectorXd> a2(squared_magnitudes.data(),
                                             static_cast<Eigen::Index>(squared_magnitudes.size()));
  return track_decay_rate(positions, Eigen::MatrixXd(a2))[0];
}

double minimum_measurable_decay_rate(const std::vector<double>& positions) {
  check_positions(positions);
  return kDecayConstant / positions.back();  // Formula 2
}

std::vector<DecayRateLimit> iso3095_decay_rate_limits() {
  // ISO 3095:2013 Figure 3, the table beside the curves (header for the source): band centre
  // (Hz), vertical and lateral lower limits (dB/m).
  return {{250.0, 2.00, 2.04},  {315.0, 2.00, 1.38},  {400.0, 6.00, 0.94},  {500.0, 6.00, 0.64},
          {630.0, 6.00, 0.43},  {800.0, 2.19, 0.29},  {1000.0, 0.80, 0.20}, {1250.0, 0.80, 0.20},
          {1600.0, 0.80, 0.32}, {2000.0, 0.80, 0.50}, {2500.0, 0.80, 0.50}, {3150.0, 0.80, 0.50},
          {4000.0, 0.80, 0.50}, {5000.0, 0.80, 0.50}};
}

}  // namespace rollnoise::acoustics
