#include "noise/bands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/assert.hpp"
#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

void check_increasing(const std::vector<double>& f) {
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (!(f[k] > 0.0) || !std::isfinite(f[k]))
      throw std::invalid_argument("band levels need positive frequencies");
    if (k > 0 && !(f[k] > f[k - 1]))
      throw std::invalid_argument("band levels need strictly increasing frequencies");
  }
}

// Cell of sample k: between the midpoints to its neighbours; the outer samples get a cell
// symmetric about them.
std::array<double, 2> cell(const std::vector<double>& f, std::size_t k) {
  const std::size_t n = f.size();
  double lo, hi;
  if (n == 1) return {f[0], f[0]};
  lo = k > 0 ? 0.5 * (f[k - 1] + f[k]) : f[0] - 0.5 * (f[1] - f[0]);
  hi = k + 1 < n ? 0.5 * (f[k] + f[k + 1]) : f[n - 1] + 0.5 * (f[n - 1] - f[n - 2]);
  return {lo, hi};
}

// Mean over the band by the midpoint rule on cells: the samples inside the band split it at the
// midpoints between neighbours, the outer cells reach the band edges.
double weighted_mean(const std::vector<double>& f, const std::vector<double>& v, double centre,
                     int* count) {
  const auto e = third_octave_edges(centre);
  std::size_t first = f.size(), last = 0;
  for (std::size_t k = 0; k < f.size(); ++k)
    if (f[k] >= e[0] && f[k] < e[1]) {
      first = std::min(first, k);
      last = k;
    }
  if (first == f.size()) {
    std::ostringstream s;
    s << "band levels: no narrow-band frequency in the 1/3-octave band at " << centre << " Hz";
    throw std::invalid_argument(s.str());
  }
  if (count) *count = static_cast<int>(last - first + 1);
  double sum = 0.0;
  for (std::size_t k = first; k <= last; ++k) {
    const double lo = k == first ? e[0] : 0.5 * (f[k - 1] + f[k]);
    const double hi = k == last ? e[1] : 0.5 * (f[k] + f[k + 1]);
    sum += (hi - lo) * v[k];
  }
  return sum / (e[1] - e[0]);
}

}  // namespace

std::array<double, 2> third_octave_edges(double centre) {
  return {centre * std::pow(10.0, -0.05), centre * std::pow(10.0, 0.05)};
}

std::vector<double> band_frequencies(const std::vector<double>& centres, int points_per_band) {
  ROLLNOISE_ASSERT(points_per_band >= 1, "at least one frequency per band (noise.points_per_band, checked by io)");
  std::vector<double> out;
  for (double c : centres) {
    if (!(c > 0.0)) throw std::invalid_argument("band centres must be positive");
    const auto e = third_octave_edges(c);
    const double df = (e[1] - e[0]) / points_per_band;
    for (int i = 0; i < points_per_band; ++i) out.push_back(e[0] + (i + 0.5) * df);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<double> covered_centres(const std::vector<double>& f, int min_points) {
  check_increasing(f);
  std::vector<double> out;
  if (f.empty()) return out;
  const double lo = cell(f, 0)[0], hi = cell(f, f.size() - 1)[1];
  const int n0 = static_cast<int>(std::floor(10.0 * std::log10(f.front() / 1000.0))) - 1;
  const int n1 = static_cast<int>(std::ceil(10.0 * std::log10(f.back() / 1000.0))) + 1;
  for (int n = n0; n <= n1; ++n) {
    const double c = 1000.0 * std::pow(10.0, n / 10.0);
    const auto e = third_octave_edges(c);
    if (e[0] < lo * (1 - 1e-12) || e[1] > hi * (1 + 1e-12)) continue;
    const auto count =
        std::count_if(f.begin(), f.end(), [&](double x) { return x >= e[0] && x < e[1]; });
    if (count >= min_points) out.push_back(c);
  }
  return out;
}

double band_mean(const std::vector<double>& f, const std::vector<double>& values, double centre) {
  check_increasing(f);
  ROLLNOISE_ASSERT(values.size() == f.size(), "band mean: one value per frequency is needed");
  return weighted_mean(f, values, centre, nullptr);
}

std::vector<double> transfer_band_levels(const std::vector<double>& f,
                                         const std::vector<cdouble>& H,
                                         const std::vector<double>& centres,
                                         const std::vector<double>& roughness_levels,
                                         double reference) {
  check_increasing(f);
  ROLLNOISE_ASSERT(H.size() == f.size(), "band levels: one transfer value per frequency is needed");
  ROLLNOISE_ASSERT(roughness_levels.size() == centres.size(), "band levels: one roughness level per band is needed");
  std::vector<double> h2(H.size());
  for (std::size_t k = 0; k < H.size(); ++k) h2[k] = std::norm(H[k]);
  std::vector<double> out;
  for (std::size_t b = 0; b < centres.size(); ++b) {
    const double mean = weighted_mean(f, h2, centres[b], nullptr);
    const double ratio = mean * kRoughnessReference * kRoughnessReference / (reference * reference);
    out.push_back(roughness_levels[b] + (ratio > 0.0 ? 10.0 * std::log10(ratio)
                                                     : -std::numeric_limits<double>::infinity()));
  }
  return out;
}

BandLevels band_levels(const LoopResult& r, const std::vector<double>& centres,
                       const std::vector<double>& roughness_levels) {
  BandLevels out;
  out.centre = centres;
  out.roughness_level = roughness_levels;
  const std::size_t n = r.frequency.size();
  auto component = [&](const std::vector<Vector4c>& v, int i) {
    std::vector<cdouble> h(n);
    for (std::size_t k = 0; k < n; ++k) h[k] = v[k](i);
    return h;
  };
  out.force_level.assign(centres.size(), {});
  for (int i = 0; i < 4; ++i) {
    const auto L = transfer_band_levels(r.frequency, component(r.force, i), centres,
                                        roughness_levels, kForceReference);
    for (std::size_t b = 0; b < centres.size(); ++b) out.force_level[b][i] = L[b];
  }
  if (r.wheel_velocity.size() == n && r.rail_velocity.size() == n && n > 0) {
    out.velocity_level.assign(centres.size(), {});
    for (int s = 0; s < 2; ++s)
      for (int i = 0; i < 4; ++i) {
        const auto L = transfer_band_levels(
            r.frequency, component(s == 0 ? r.wheel_velocity : r.rail_velocity, i), centres,
            roughness_levels, kVelocityReference);
        for (std::size_t b = 0; b < centres.size(); ++b) out.velocity_level[b][s][i] = L[b];
      }
  }
  for (double c : centres) {
    const auto e = third_octave_edges(c);
    out.samples.push_back(static_cast<int>(std::count_if(
        r.frequency.begin(), r.frequency.end(), [&](double x) { return x >= e[0] && x < e[1]; })));
  }
  return out;
}

BandLevels band_levels(const LoopResult& r, const std::vector<double>& centres,
                       const ContactRoughness& roughness) {
  return band_levels(r, centres, roughness.levels(centres));
}

}  // namespace rollnoise::noise
