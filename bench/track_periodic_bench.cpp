// The discretely supported beam rail's receptances over a noise case's frequency grid: the exact
// infinite periodic track (dynamics/track_periodic.hpp, the default) against the truncated solve
// of Eq. (2) of dynamics/track.hpp (2N + 1 = 121 supports, Levinson's recursion).
//   build/rollnoise_bench --benchmark_filter=DiscreteRailGrid
// Grid: 864 frequencies (18 third-octave bands 100 Hz - 5 kHz, 48 per band, log-spaced), both
// beams (vertical and lateral bending). Argument 0: the position pairs, 1 = the single wheel's
// point receptance at mid-span (0.3, 0.3), 4 = a four-wheel rail: points at 0.3 and 2.8 m (the
// 2.5 m wheelbase) and the two transfers. Argument 1: 0 periodic, 1 truncated (N = 60).
#include <benchmark/benchmark.h>

#include <cmath>
#include <utility>
#include <vector>

#include "dynamics/track.hpp"

namespace rollnoise {
namespace {

void DiscreteRailGrid(benchmark::State& state) {
  const dynamics::TrackParameters t = dynamics::uic60_ballasted();
  const auto solution = state.range(1) == 0 ? dynamics::DiscreteSupportSolution::kPeriodic
                                            : dynamics::DiscreteSupportSolution::kTruncated;
  const dynamics::DiscretelySupportedRail vertical(
      t.vertical, t.vertical_support, t.sleeper_spacing, t.supports_each_side, solution);
  const dynamics::DiscretelySupportedRail lateral(t.lateral, t.lateral_support, t.sleeper_spacing,
                                                  t.supports_each_side, solution);
  std::vector<std::pair<double, double>> pairs = {{0.3, 0.3}};
  if (state.range(0) == 4) pairs = {{0.3, 0.3}, {0.3, 2.8}, {2.8, 0.3}, {2.8, 2.8}};
  const int nf = 864;
  const double f0 = 100.0 * std::pow(2.0, -1.0 / 6.0), f1 = 5000.0 * std::pow(2.0, 1.0 / 6.0);
  std::vector<double> freqs(nf);
  for (int i = 0; i < nf; ++i) freqs[i] = f0 * std::pow(f1 / f0, (i + 0.5) / nf);
  for (auto _ : state)
    for (const double f : freqs) {
      benchmark::DoNotOptimize(vertical.transfers(f, pairs));
      benchmark::DoNotOptimize(lateral.transfers(f, pairs));
    }
  state.counters["frequencies"] = nf;
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.counters["supports"] = state.range(1) == 0 ? 0 : 2 * t.supports_each_side + 1;
}
BENCHMARK(DiscreteRailGrid)
    ->ArgsProduct({{1, 4}, {0, 1}})
    ->ArgNames({"pairs", "truncated"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rollnoise
