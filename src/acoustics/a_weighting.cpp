#include "acoustics/a_weighting.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rollnoise::acoustics {

namespace {

/// The pole frequencies f_1 ... f_4 (Hz) of IEC 61672-1:2013 Eqs. (E.1)-(E.5) (header).
struct Poles {
  double f1, f2, f3, f4;
};

Poles a_weighting_poles() {
  const double fr = 1000.0, fL = std::pow(10.0, 1.5), fH = std::pow(10.0, 3.9);
  const double D = std::sqrt(0.5);
  const double b = (fr * fr + fL * fL * fH * fH / (fr * fr) - D * (fL * fL + fH * fH)) / (1.0 - D);
  const double c = fL * fL * fH * fH;
  const double root = std::sqrt(b * b - 4.0 * c);
  const double fA = std::pow(10.0, 2.45);
  return {std::sqrt((-b - root) / 2.0), 0.5 * (3.0 - std::sqrt(5.0)) * fA,
          0.5 * (3.0 + std::sqrt(5.0)) * fA, std::sqrt((-b + root) / 2.0)};
}

}  // namespace

double a_weighting(double f) {
  if (!(f > 0.0) || !std::isfinite(f))
    throw std::invalid_argument("A-weighting: the frequency must be positive and finite, got " +
                                std::to_string(f) + " Hz");
  static constexpr double kA1000 = -2.000;  // dB, IEC 61672-1 Eq. (E.6) normalisation
  const Poles p = a_weighting_poles();
  const double f2 = f * f;
  // Eq. (E.6)
  const double response = p.f4 * p.f4 * f2 * f2 /
                          ((f2 + p.f1 * p.f1) * std::sqrt(f2 + p.f2 * p.f2) *
                           std::sqrt(f2 + p.f3 * p.f3) * (f2 + p.f4 * p.f4));
  return 20.0 * std::log10(response) - kA1000;
}

double a_weighted_total(const std::vector<double>& band_centres,
                        const std::vector<double>& band_levels) {
  if (band_centres.size() != band_levels.size())
    throw std::invalid_argument("A-weighting: " + std::to_string(band_levels.size()) +
                                " band levels for " + std::to_string(band_centres.size()) +
                                " band centres");
  if (band_centres.empty()) throw std::invalid_argument("A-weighting: no band levels given");
  double sum = 0.0;
  for (size_t b = 0; b < band_levels.size(); ++b) {
    if (!std::isfinite(band_levels[b]))
      throw std::invalid_argument("A-weighting: band level " + std::to_string(b) +
                                  " is not finite");
    sum += std::pow(10.0, (band_levels[b] + a_weighting(band_centres[b])) / 10.0);
  }
  return 10.0 * std::log10(sum);
}

}  // namespace rollnoise::acoustics
