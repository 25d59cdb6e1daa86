// The continuous waveguide rail's frequency sampling (waveguide_frequency_sampling.hpp,
// docs/record/waveguide_rail.md Sec. 8.1, docs/record/performance_waveguide.md Sec. 2) on the
// noise case's grid: how many frequencies are computed directly and how far the interpolated
// receptance is from the direct one, at curve_300m's four contact points.
//
// WaveguideSampling/p/t: starting grid p points per octave, Eq. (F1) tolerance t x 1e-4 (t = 0:
// the fixed grid of p per octave, no refinement; the loop's: 4/300); the default waveguide (UIC60,
// 30 mm mesh: 225 nodes, n = 675; near_field_reduction(): m = 86; 10 mm patch) on the 864
// frequencies of curve_300m (1/3-octave bands 100 Hz - 5 kHz, 48 per band). The direct values of
// all 864 frequencies are computed once per point (~5 s each, not timed) and the sampler reads
// them, so the counters are the sampler's alone: `evaluations` direct frequencies summed over the
// four points (the eigenproblems the case solves), `max_points` of one point, `err_dB` the largest
// |dB| difference of a diagonal term from the direct value (narrow band), `err_rel` the largest Eq.
// (F1) error over the grid, `err_band_dB` the largest error of a 1/3-octave band level of a
// diagonal term (mean |R_ii|^2 over the band's 48 samples, as the loop's bands average).
//
// WaveguideCaseRailCost/a: what the rail of `rollnoise noise cases/curve_300m_waveguide.toml`
// (four contact points, each wheel's loop alone) costs, computed as the loop computes it, CPU
// time: the section modes once (`modes_s`), per point its Ritz basis (`bases_s`, the four) and the
// sampled frequencies (a = 0: the fixed grid of 24 per octave, as before; a = 1: the loop's
// adaptive sampling), each one m x m wavenumber eigenproblem and Eq. W4 (`evaluations` summed over
// the points, `per_frequency_ms`; a = 2: the adaptive sampling with the point receptance by Eq. W6,
// the Schur form instead of the waves, as the loop computes it since session 38); `case_rail_s`
// the whole (iteration CPU time).
//   build/rollnoise_bench --benchmark_filter='WaveguideSampling|WaveguideCaseRailCost'
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <utility>
#include <vector>

#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_frequency_sampling.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "fem/mesh.hpp"
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
          err_db = std::max(
              err_db, std::abs(20.0 * std::log10(std::abs(r[k](i, i)) / std::abs(d[k](i, i)))));
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
    ->Args({12, 0})
    ->Args({4, 1000})
    ->Args({4, 500})
    ->Args({4, 300})
    ->Args({4, 100})
    ->Args({6, 300})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// CPU seconds of this process (the machine is shared: wall time says little).
double sampling_cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

void WaveguideCaseRailCost(benchmark::State& state) {
  const dynamics::TrackParameters t = dynamics::uic60_ballasted();
  dynamics::WaveguideRailOptions o;  // the loop's: 30 mm mesh, 10 mm patch, near-field basis
  if (state.range(0) == 0) o.sampling = {24, 0.0};
  const std::vector<double>& f = sampling_grid();
  double modes_s = 0.0, bases_s = 0.0, frequencies_s = 0.0;
  int evaluations = 0, dofs = 0, coordinates = 0;
  for (auto _ : state) {
    double t0 = sampling_cpu_seconds();
    const dynamics::RailWaveguide full(
        fem::mesh_polygon(dynamics::uic60_outline(), o.mesh_size), dynamics::rail_material(t, 0.3),
        dynamics::FootSupport{t.vertical_support, t.lateral_support, t.longitudinal_support,
                              t.sleeper_spacing});
    const dynamics::RailReductionModes modes = full.reduction_modes(o.contact_reduction);
    modes_s = sampling_cpu_seconds() - t0;
    bases_s = frequencies_s = 0.0;
    evaluations = 0;
    for (const auto& point : kSamplingContacts) {
      t0 = sampling_cpu_seconds();
      const Eigen::MatrixXd loads =
          dynamics::contact_point_loads(full, dynamics::uic60_outline(), o, {point});
      const dynamics::RailWaveguide r = full.reduced(o.contact_reduction, loads, modes);
      const double t1 = sampling_cpu_seconds();
      bases_s += t1 - t0;
      int points = 0;
      benchmark::DoNotOptimize(dynamics::sample_receptances(
          f,
          [&](double fq) {
            const double w = 2.0 * M_PI * fq;
            return std::vector<dynamics::Receptance4>{
                state.range(0) == 2 ? dynamics::Receptance4(r.point_transfer(w, loads, loads))
                                    : r.contact_receptance(r.waves(w), loads, loads, 0.0)};
          },
          o.sampling, &points));
      frequencies_s += sampling_cpu_seconds() - t1;
      evaluations += points;
      dofs = full.dofs();
      coordinates = std::max(coordinates, r.coordinates());
    }
  }
  state.counters["dofs"] = dofs;
  state.counters["coordinates"] = coordinates;
  state.counters["modes_s"] = modes_s;
  state.counters["bases_s"] = bases_s;
  state.counters["evaluations"] = evaluations;
  state.counters["per_frequency_ms"] = 1e3 * frequencies_s / evaluations;
  state.counters["case_rail_s"] = modes_s + bases_s + frequencies_s;
}
BENCHMARK(WaveguideCaseRailCost)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
