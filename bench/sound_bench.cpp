// Benchmarks of the sound radiation (docs/sound.md), Google Benchmark; the boundary elements and
// the frequency reported as counters with every timing:
//   build/rollnoise_bench --benchmark_filter=Sound
//   SoundWheelBem/f: the 920 mm FE wheel's modes (8 mm mesh, n = 2..8) through the axisymmetric BEM
//                    at one frequency f (Hz): every order's P_n in one call (the wheel's table is
//                    109 such calls for 100 Hz - 5 kHz);
//   SoundRailBem/f:  the UIC60 section's 2D BEM, vertical and lateral rigid motion, at f (Hz);
//   SoundRailLineGram/nf: the rail's line Gram matrices (S2, S3) of two contact positions 2.5 m
//   apart
//                    on the periodically supported beam, at nf frequencies;
//   SoundRailSectionGram/f: the waveguide's deforming section (R2 of rail_section_sound.hpp), the
//                    discretely supported UIC60 waveguide (30 mm mesh) under two contacts 2.5 m
//                    apart at f (Hz): one wave solution and the adaptive wavenumber integral (the
//                    table of P_2D outside the timing).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "dynamics/beam_rail_model.hpp"
#include "dynamics/rail_section.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_discrete_support.hpp"
#include "dynamics/wheel_fe.hpp"
#include "io/wheel_section_file.hpp"
#include "pipeline/rail_section_sound.hpp"
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
  const dynamics::BeamRailModel rail(dynamics::uic60_ballasted(), dynamics::TrackSupport::kDiscrete,
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

void SoundRailSectionGram(benchmark::State& state) {
  const double f = static_cast<double>(state.range(0));
  const acoustics::Fluid fluid;
  dynamics::WaveguideRailOptions o;
  o.mesh_size = 0.03;
  o.sampling.per_octave = 0;
  const dynamics::DiscreteWaveguideRailModel rail(dynamics::uic60_ballasted(), o, 0.3);
  const pipeline::SectionRadiationTable table = pipeline::section_radiation_table(
      dynamics::uic60_outline(), false, 2 * kPi * f / fluid.sound_speed, fluid, 1);
  const dynamics::SurfaceSpectra spectra =
      rail.surface_spectra({{0.0, 0.0, 0.3}, {-0.03, 0.5, 2.8}}, table.pieces, table.patterns);
  double evaluations = 0.0, waves = 0.0;
  for (auto _ : state) {
    dynamics::SurfaceSpectrum s = spectra(f);
    waves = static_cast<double>(s.wavenumbers.size());
    evaluations = 0.0;
    const auto at = s.at;
    s.at = [&](const std::vector<double>& k) {
      evaluations += static_cast<double>(k.size());
      return at(k);
    };
    benchmark::DoNotOptimize(pipeline::section_gram(s, table, f, 2.5, fluid).data());
  }
  state.counters["elements"] = static_cast<double>(table.pieces.size());
  state.counters["patterns"] = static_cast<double>(table.patterns.cols());
  state.counters["waves"] = waves;
  state.counters["kappas"] = evaluations;
}
BENCHMARK(SoundRailSectionGram)->Arg(250)->Arg(1000)->Arg(5000)->Unit(benchmark::kMillisecond);

}  // namespace
