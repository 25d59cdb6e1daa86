// The waveguide rail loaded at the contact on the noise case's frequency grid
// (WaveguideRailModel::contact_receptances): the cost of the direct evaluation at every frequency
// against a coarse logarithmic grid interpolated in ln f, and the interpolation's error.
//
// RailContactGrid/p: the 300 m curve's gauge-corner contact (offset -36.6 mm, 0.524 rad), the
// default waveguide (30 mm mesh, 10 mm patch), on the 864 frequencies of curve_300m (1/3-octave
// bands 100 Hz - 5 kHz, 48 per band); p points per octave (0: every frequency directly). Counters:
// `points` evaluated directly, `err_dB` the largest |dB| difference of the four diagonal terms
// against the direct evaluation, `err_rel` the largest ||R_i - R_d|| / ||R_d|| (Frobenius) over
// the grid, `err_dB_<term>` per diagonal term and `worst_Hz` where the largest is; `err_band_dB`
// the largest error of the 1/3-octave band levels of the diagonal terms (mean |R_ii|^2 over each
// band's 48 samples, as the loop's bands average). CPU time includes the contact's Ritz basis
// (one-off, ~2.5 s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <complex>
#include <vector>

#include "dynamics/track.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "noise/bands.hpp"

using namespace rollnoise;

namespace {

constexpr double kOffset = -0.0366, kAngle = 0.524;

const std::vector<double>& curve_grid() {
  static const std::vector<double> f =
      noise::band_frequencies(noise::third_octave_centres(100.0, 5000.0), 48);
  return f;
}

// The direct evaluation on the whole grid, once (the reference of every p).
const std::vector<dynamics::Receptance4>& direct() {
  static const std::vector<dynamics::Receptance4> r = [] {
    dynamics::WaveguideRailOptions o;
    o.sampling.per_octave = 0;
    const dynamics::WaveguideRailModel rail(dynamics::uic60_ballasted(), o);
    return rail.contact_receptances(curve_grid(), kOffset, kAngle);
  }();
  return r;
}

void RailContactGrid(benchmark::State& state) {
  dynamics::WaveguideRailOptions o;
  o.sampling = {static_cast<int>(state.range(0)), 0.0};  // the fixed grid, no refinement
  std::vector<dynamics::Receptance4> r;
  for (auto _ : state) {
    const dynamics::WaveguideRailModel rail(dynamics::uic60_ballasted(), o);
    r = rail.contact_receptances(curve_grid(), kOffset, kAngle);
  }
  const std::vector<dynamics::Receptance4>& d = direct();
  double err_db = 0.0, err_rel = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    err_rel = std::max(err_rel, (r[k] - d[k]).norm() / d[k].norm());
    for (int i = 0; i < 4; ++i)
      err_db = std::max(err_db, std::abs(20.0 * std::log10(std::abs(r[k](i, i)) /
                                                            std::abs(d[k](i, i)))));
  }
  // The same on the band levels: mean |R_ii|^2 over each 1/3-octave band's 48 samples.
  double err_band_db = 0.0;
  const char* names[4] = {"n", "x", "t", "spin"};
  double err_term[4] = {0.0, 0.0, 0.0, 0.0}, worst_f = 0.0;
  for (int i = 0; i < 4; ++i)
    for (std::size_t k = 0; k < d.size(); ++k) {
      const double e = std::abs(20.0 * std::log10(std::abs(r[k](i, i)) / std::abs(d[k](i, i))));
      if (e > err_term[i]) err_term[i] = e;
      if (e >= err_db) worst_f = curve_grid()[k];
    }
  for (std::size_t b = 0; b + 48 <= d.size(); b += 48)
    for (int i = 0; i < 4; ++i) {
      double pr = 0.0, pd = 0.0;
      for (std::size_t k = b; k < b + 48; ++k)
        pr += std::norm(r[k](i, i)), pd += std::norm(d[k](i, i));
      err_band_db = std::max(err_band_db, std::abs(10.0 * std::log10(pr / pd)));
    }
  for (int i = 0; i < 4; ++i) state.counters[std::string("err_dB_") + names[i]] = err_term[i];
  state.counters["worst_Hz"] = worst_f;
  state.counters["err_band_dB"] = err_band_db;
  const double hi = curve_grid().back(), lo = curve_grid().front();
  state.counters["frequencies"] = static_cast<double>(d.size());
  state.counters["points"] = o.sampling.per_octave > 0
                                 ? std::ceil(o.sampling.per_octave * std::log2(hi / lo)) + 1
                                 : d.size();
  state.counters["err_dB"] = err_db;
  state.counters["err_rel"] = err_rel;
}
BENCHMARK(RailContactGrid)
    ->Arg(0)
    ->Arg(12)
    ->Arg(24)
    ->Arg(36)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
