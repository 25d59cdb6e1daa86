// Benchmarks of the sound radiation (docs/sound.md), Google Benchmark; the boundary elements and
// the frequency reported as counters with every timing:
//   build/rollnoise_bench --benchmark_filter=Sound
//   SoundWheelBem/f: the 920 mm FE wheel's modes (8 mm mesh, n = 2..8) through the axisymmetric BEM
//                    at one frequency f (Hz): every order's P_n in one call (the wheel's table is
//                    109 such calls for 100 Hz - 5 kHz);
//   SoundRailBem/f:  the UIC60 section's 2D BEM, vertical and lateral rigid motion, at f (Hz);
//   SoundRailLineGram/nf: the rail's line Gram matrices (S2, S3) of two contact positions 2.5 m
//   apart
//                    on the periodically supported beam, at nf frequencies.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "dynamics/rail_section.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel_fe.hpp"
#include "io/wheel_section_file.hpp"
#include "pipeline/sound_power.hpp"
#include "pipeline/sound_radiation.hpp"

using namespace rollnoise;

namespace {

const dynamics::WheelFeModes& bench_wheel() {
  static const dynamics::WheelFeModes w =
      dynamics::wheel_fe_modes(io::read_wheel_section(std::string(ROLLNOISE_SOURCE_DIR) +
                                                      "/models/wheel/wheel_920mm_section.csv"),
                               dynamics::WheelFeOptions{});
  return w;
}

void SoundWheelBem(benchmark::State& state) {
  const dynamics::WheelFeModes& w = bench_wheel();
  const std::vector<double> grid = {static_cast<double>(state.range(0))};
  pipeline::WheelRadiation r;
  for (auto _ : state) {
    r = pipeline::wheel_radiation(w, 2, grid, acoustics::Fluid{}, 1);
    benchmark::DoNotOptimize(r.efficiency.data());
  }
  state.counters["elements"] = r.elements;
  state.counters["modes"] = static_cast<double>(r.efficiency.size());
  state.counters["ka"] = 2 * kPi * grid[0] / acoustics::Fluid{}.sound_speed * 0.49;
}
BENCHMARK(SoundWheelBem)->Arg(500)->Arg(2000)->Arg(5000)->Unit(benchmark::kMillisecond);

void SoundRailBem(benchmark::State& state) {
  const std::vector<double> grid = {static_cast<double>(state.range(0))};
  pipeline::RailRadiation r;
  for (auto _ : state) {
    r = pipeline::rail_radiation(dynamics::uic60_outline(), false, grid, acoustics::Fluid{}, 1);
    benchmark::DoNotOptimize(r.vertical.data());
  }
  state.counters["sigma_vertical"] = r.sigma_vertical[0];
}
BENCHMARK(SoundRailBem)->Arg(500)->Arg(2000)->Arg(5000)->Unit(benchmark::kMillisecond);

void SoundRailLineGram(benchmark::State& state) {
  const dynamics::RailModel rail(dynamics::uic60_ballasted(), dynamics::TrackSupport::kDiscrete,
                                 0.3);
  std::vector<double> grid;
  const int nf = static_cast<int>(state.range(0));
  for (int i = 0; i < nf; ++i) grid.push_back(100.0 * std::pow(50.0, i / std::max(nf - 1.0, 1.0)));
  pipeline::RailLineGram g;
  for (auto _ : state) {
    g = pipeline::rail_line_gram(rail, {0.3, 2.8}, grid, 12, 1);
    benchmark::DoNotOptimize(g.z.data());
  }
  state.counters["frequencies"] = nf;
}
BENCHMARK(SoundRailLineGram)->Arg(10)->Arg(109)->Unit(benchmark::kMillisecond);

}  // namespace
