#include "nss/extrapolation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rollnoise::nss {
namespace {

// (h1^p - h2^p) / (h2^p - h3^p), the right side of (R1)
double order_ratio(double h1, double h2, double h3, double p) {
  return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
}

// The observed order of (R1) in [lo, hi], or NaN when the ratio of the differences lies outside.
double observed_order(const std::vector<double>& h, double ratio, double lo, double hi) {
  if (!(ratio >= order_ratio(h[0], h[1], h[2], lo) && ratio <= order_ratio(h[0], h[1], h[2], hi)))
    return std::nan("");
  for (int it = 0; it < 100 && hi - lo > 1e-12; ++it) {
    const double mid = 0.5 * (lo + hi);
    (order_ratio(h[0], h[1], h[2], mid) < ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

RichardsonResult richardson(const std::vector<double>& h, const std::vector<std::complex<double>>& v,
                            const RichardsonSettings& s) {
  const size_t n = h.size();
  if ((n != 2 && n != 3) || v.size() != n)
    throw std::invalid_argument("richardson: two or three grids, one value each");
  for (size_t i = 0; i < n; ++i)
    if (!(h[i] > 0.0) || (i > 0 && !(h[i] < h[i - 1])))
      throw std::invalid_argument("richardson: element lengths must be positive and strictly decreasing");
  RichardsonResult r;
  r.order = s.assumed_order;
  if (n == 3) {
    const std::complex<double> d1 = v[0] - v[1], d2 = v[1] - v[2];
    // monotone convergence: both differences the same way
    if (std::abs(d2) > 0.0 && std::real(d1 * std::conj(d2)) > 0.0) {
      const double p = observed_order(h, std::abs(d1) / std::abs(d2), s.min_order, s.max_order);
      if (std::isfinite(p)) r.order = p, r.observed = true;
    }
  }
  const std::complex<double> vc = v[n - 2], vf = v[n - 1];
  auto extrapolate = [&](double p) {  // (R2)
    const double hc = std::pow(h[n - 2], p), hf = std::pow(h[n - 1], p);
    return vf + (vf - vc) * (hf / (hc - hf));
  };
  r.value = extrapolate(r.order);
  // (R3): the larger of the corrections with the observed and the assumed order
  const double correction = std::max(std::abs(r.value - vf), std::abs(extrapolate(s.assumed_order) - vf));
  r.error = (r.observed ? 1.25 : 3.0) * correction;
  return r;
}

}  // namespace rollnoise::nss
