// The continuous waveguide rail's frequency sampling (waveguide_frequency_sampling.hpp,
// docs/models.md Sec. 2.5b, docs/performance.md Sec. 9) on the noise case's grid: how many
// frequencies are computed directly and how far the interpolated receptance is from the direct
// one, at curve_300m's four contact points.
//
// WaveguideSampling/p/t: starting grid p points per octave, Eq. (F1) tolerance t x 1e-4 (t = 0:
// the fixed grid of p per octave, no refinement); the default waveguide (UIC60, 30 mm mesh: 225
// nodes, n = 675; near_field_reduction(): m = 86; 10 mm patch) on the 864 frequencies of
// curve_300m (1/3-octave bands 100 Hz - 5 kHz, 48 per band). The direct values of all 864
// frequencies are computed once per point (~5 s each, not timed) and the sampler reads them, so
// the counters are the sampler's alone: `evaluations` direct frequencies summed over the four
// points (the eigenproblems the case solves), `max_points` of one point, `err_dB` the largest |dB|
// difference of a diagonal term from the direct value (narrow band), `err_rel` the largest Eq.
// (F1) error over the grid, `err_band_dB` the largest error of a 1/3-octave band level of a
// diagonal term (mean |R_ii|^2 over the band's 48 samples, as the loop's bands average).
//   build/rollnoise_bench --benchmark_filter=WaveguideSampling
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "dynamics/track.hpp"
#include "dynamics/waveguide_frequency_sampling.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "noise/bands.hpp"

using namespace rollnoise;

namespace {

// curve_300m's contact points (offset on the rail profile, contact angle) of the four wheels.
const std::vector<std::pair<double, double>> kSamplingContacts = {
    {-0.0366, 0.524}, {-0.0024, 0.008}, {-0.0033, 0.011}, {-0.0204, 0.090}};

const std::vector<double>& sampling_grid() {
  static const std::vector<double> f =
      noise::band_frequencies(noise::third_octave_centres(100.0, 5000.0), 48);
  return f;
}

// Every point's 4x4 computed directly at every frequency, once.
const std::vector<std::vector<dynamics::Receptance4>>& direct_at_points() {
  static const std::vector<std::vector<dynamics::Receptance4>> r = [] {
    dynamics::WaveguideRailOptions o;
    o.sampling.per_octave = 0;
    const dynamics::WaveguideRailModel rail(dynamics::uic60_ballasted(), o);
    std::vector<std::vector<dynamics::Receptance4>> out;
    for (const auto& [offset, angle] : kSamplingContacts)
      out.push_back(rail.contact_receptances(sampling_grid(), offset, angle));
    return out;
  }();
  return r;
}

void WaveguideSampling(benchmark::State& state) {
  const dynamics::FrequencySampling sampling{static_cast<int>(state.range(0)),
                                             1e-4 * static_cast<double>(state.range(1))};
  const std::vector<double>& f = sampling_grid();
  const auto& direct = direct_at_points();
  int evaluations = 0, max_points = 0;
  double err_db = 0.0, err_rel = 0.0, err_band_db = 0.0;
  for (auto _ : state) {
    evaluations = 0;
    for (const std::vector<dynamics::Receptance4>& d : direct) {
      auto lookup = [&](double fq) {
        const auto i = std::lower_bound(f.begin(), f.end(), fq) - f.begin();
        return std::vector<dynamics::Receptance4>{d[i]};
      };
      int points = 0;
      const std::vector<dynamics::Receptance4> r =
          dynamics::sample_receptances(f, lookup, sampling, &points).front();
      evaluations += points;
      max_points = std::max(max_points, points);
      for (std::size_t k = 0; k < f.size(); ++k) {
        const dynamics::Receptance4 e = r[k] - d[k];
        for (int i = 0; i < 4; ++i) {
          err_db = std::max(err_db, std::abs(20.0 * std::log10(std::abs(r[k](i, i)) /
                                                                std::abs(d[k](i, i)))));
          for (int j = 0; j < 4; ++j)
            err_rel = std::max(err_rel, std::abs(e(i, j)) /
                                            std::sqrt(std::abs(d[k](i, i)) * std::abs(d[k](j, j))));
        }
      }
      for (std::size_t b = 0; b + 48 <= f.size(); b += 48)
        for (int i = 0; i < 4; ++i) {
          double pr = 0.0, pd = 0.0;
          for (std::size_t k = b; k < b + 48; ++k)
            pr += std::norm(r[k](i, i)), pd += std::norm(d[k](i, i));
          err_band_db = std::max(err_band_db, std::abs(10.0 * std::log10(pr / pd)));
        }
    }
  }
  state.counters["frequencies"] = static_cast<double>(f.size());
  state.counters["evaluations"] = evaluations;
  state.counters["max_points"] = max_points;
  state.counters["err_dB"] = err_db;
  state.counters["err_rel"] = err_rel;
  state.counters["err_band_dB"] = err_band_db;
}
BENCHMARK(WaveguideSampling)
    ->Args({24, 0})
    ->Args({6, 1000})
    ->Args({4, 500})
    ->Args({4, 300})
    ->Args({4, 100})
    ->Args({3, 300})
    ->Args({2, 300})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
