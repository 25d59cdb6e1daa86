#include "noise/band_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/assert.hpp"
#include "noise/bands.hpp"

namespace rollnoise::noise {

namespace {

// The cell of sample i: from the midpoint with the previous sample to the midpoint with the next,
// the outer cells reaching the band edges [lo, hi) (as band_mean weighs them).
double cell_width_in_band(const std::vector<double>& f, std::size_t i, double lo, double hi) {
  const double left = i > 0 ? std::max(lo, 0.5 * (f[i - 1] + f[i])) : lo;
  const double right = i + 1 < f.size() ? std::min(hi, 0.5 * (f[i] + f[i + 1])) : hi;
  return std::max(0.0, right - left);
}

// Samples to refine in one band [lo, hi) for one sampled power p: where it and its neighbours
// differ by more than options.ratio and its cell can matter to the band (header).
void flag_band(const std::vector<double>& f, const std::vector<double>& p, double lo, double hi,
               const BandRefinementOptions& o, std::vector<char>& flagged) {
  const auto first = std::lower_bound(f.begin(), f.end(), lo) - f.begin();
  const auto last = std::lower_bound(f.begin(), f.end(), hi) - f.begin();
  double integral = 0.0;
  for (auto i = first; i < last; ++i) integral += p[i] * cell_width_in_band(f, i, lo, hi);
  if (!(integral > 0.0)) return;
  for (auto i = first; i < last; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    double low = p[k], high = p[k];
    if (k > 0) low = std::min(low, p[k - 1]), high = std::max(high, p[k - 1]);
    if (k + 1 < f.size()) low = std::min(low, p[k + 1]), high = std::max(high, p[k + 1]);
    if (high <= o.ratio * low) continue;
    if (high * cell_width_in_band(f, k, lo, hi) < o.share * integral) continue;
    flagged[k] = 1;
  }
}

std::vector<std::size_t> order_of(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<std::size_t> idx(a.size() + b.size());
  std::iota(idx.begin(), idx.end(), 0);
  auto freq = [&](std::size_t k) { return k < a.size() ? a[k] : b[k - a.size()]; };
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t x, std::size_t y) { return freq(x) < freq(y); });
  return idx;
}

// The entries of a and b in `order` (moved: a line's matrices are not copied).
template <class T>
std::vector<T> gathered(std::vector<T>&& a, std::vector<T>&& b, const std::vector<std::size_t>& order) {
  if (a.empty() && b.empty()) return {};
  ROLLNOISE_ASSERT(a.size() + b.size() == order.size(),
                   "merged: one entry per frequency is needed");
  std::vector<T> out;
  out.reserve(order.size());
  for (std::size_t k : order) out.push_back(std::move(k < a.size() ? a[k] : b[k - a.size()]));
  return out;
}

// The per-frequency vectors of two loop results (LoopResult, ContactSetLoopResult) in one order.
template <class Result>
Result merged_per_frequency(Result&& a, Result&& b) {
  const auto order = order_of(a.frequency, b.frequency);
  Result out;
  out.frequency = gathered(std::move(a.frequency), std::move(b.frequency), order);
  out.force = gathered(std::move(a.force), std::move(b.force), order);
  out.wheel_velocity = gathered(std::move(a.wheel_velocity), std::move(b.wheel_velocity), order);
  out.rail_velocity = gathered(std::move(a.rail_velocity), std::move(b.rail_velocity), order);
  return out;
}

}  // namespace

std::vector<double> refinement_frequencies(const std::vector<double>& f,
                                           const std::vector<std::vector<double>>& powers,
                                           const std::vector<double>& centres,
                                           const BandRefinementOptions& options) {
  std::vector<char> flagged(f.size(), 0);
  for (const auto& p : powers) {
    ROLLNOISE_ASSERT(p.size() == f.size(), "band refinement: one power per frequency is needed");
    for (double c : centres) {
      const auto e = third_octave_edges(c);
      flag_band(f, p, e[0], e[1], options, flagged);
    }
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!flagged[i]) continue;
    double w = std::numeric_limits<double>::infinity();
    if (i > 0) w = std::min(w, f[i] - f[i - 1]);
    if (i + 1 < f.size()) w = std::min(w, f[i + 1] - f[i]);
    if (!(w > 1e-9 * f[i]) || !std::isfinite(w)) continue;  // resolved to round-off already
    if (i > 0) out.push_back(f[i] - w / 3.0);
    if (i + 1 < f.size()) out.push_back(f[i] + w / 3.0);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::vector<double>> sampled_powers(const LoopResult& r) {
  std::vector<std::vector<double>> out;
  for (const auto* v : {&r.force, &r.wheel_velocity, &r.rail_velocity}) {
    if (v->empty()) continue;
    for (int i = 0; i < 4; ++i) {
      std::vector<double> p(v->size());
      for (std::size_t k = 0; k < v->size(); ++k) p[k] = std::norm((*v)[k](i));
      out.push_back(std::move(p));
    }
  }
  return out;
}

std::vector<std::vector<double>> sampled_powers(const ContactSetLoopResult& r) {
  std::vector<std::vector<double>> out;
  for (const auto* v : {&r.force, &r.wheel_velocity, &r.rail_velocity}) {
    if (v->empty()) continue;
    const Eigen::Index rows = v->front().rows(), cols = v->front().cols();
    for (Eigen::Index i = 0; i < rows; ++i)
      for (Eigen::Index e = 0; e < cols; ++e) {
        std::vector<double> p(v->size());
        for (std::size_t k = 0; k < v->size(); ++k) p[k] = std::norm((*v)[k](i, e));
        out.push_back(std::move(p));
      }
  }
  return out;
}

LoopResult merged(LoopResult a, LoopResult b) { return merged_per_frequency(std::move(a), std::move(b)); }

LoopVariants merged(LoopVariants a, LoopVariants b) {
  LoopVariants out;
  const bool uncoupled = a.has_uncoupled(), baseline = a.has_baseline();
  out.main = merged(std::move(a.main), std::move(b.main));
  if (uncoupled) out.uncoupled = merged(std::move(a.uncoupled), std::move(b.uncoupled));
  if (baseline) out.baseline = merged(std::move(a.baseline), std::move(b.baseline));
  return out;
}

ContactSetLoopResult merged(ContactSetLoopResult a, ContactSetLoopResult b) {
  Eigen::MatrixXd rho = std::move(a.rho);
  ContactSetLoopResult out = merged_per_frequency(std::move(a), std::move(b));
  out.rho = std::move(rho);
  return out;
}

}  // namespace rollnoise::noise
