// The cost of a noise case against a steady Hertzian solve (issue 25's speed targets), and of the
// two kernels that dominated it: the contact search on the profiles (WheelRailPair::minimum_gap)
// and the discretely supported rail per frequency (Eq. (2) of dynamics/track.hpp).
//   build/rollnoise_bench --benchmark_filter='NoiseCase|SteadyHertz|MinimumGap|DiscreteRail'
// Counters: `elements` (contact grid nx x ny of the case), `frequencies` (of the noise case),
// `supports` (2N + 1 of the rail), `samples` (wheel profile samples scanned per minimum_gap).
// The noise case also reports its stage times (contact = curve state, patch and NSS sweep;
// structures = wheel and rail receptances) as counters in seconds.
#include <benchmark/benchmark.h>

#include <string>

#include "contact/steady_rolling.hpp"
#include "dynamics/track.hpp"
#include "geometry/s1002.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "io/noise_case.hpp"
#include "io/profile_file.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/noise_pipeline.hpp"

using namespace rollnoise;

namespace {

std::string source_path(const char* relative) {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/" + relative;
}

// rollnoise noise cases/curve_300m.toml without writing the output: curve state (bogie estimate
// on the S1002/UIC60 profiles), the patch, the NSS sweep, the receptances, the loop, the bands.
void NoiseCaseCurve300m(benchmark::State& state) {
  const io::CaseReader reader = io::CaseReader::from_file(source_path("cases/curve_300m.toml"), {});
  double elements = 0, frequencies = 0, contact_s = 0, structures_s = 0;
  for (auto _ : state) {
    io::NoiseInputs in = io::read_noise_inputs(reader);
    const pipeline::NoiseResult r = pipeline::run_noise(std::move(in.contact), in.noise);
    elements = r.mean.contact().grid.nx * r.mean.contact().grid.ny;
    frequencies = static_cast<double>(r.axis.frequency.size());
    contact_s = r.seconds_contact;
    structures_s = r.seconds_structures;
  }
  state.counters["elements"] = elements;
  state.counters["frequencies"] = frequencies;
  state.counters["contact_s"] = contact_s;
  state.counters["structures_s"] = structures_s;
}
BENCHMARK(NoiseCaseCurve300m)->Unit(benchmark::kMillisecond)->Iterations(3);

// rollnoise steady cases/hertz_paper.toml without the output: the normal problem and one steady
// rolling solve.
void SteadyHertzPaper(benchmark::State& state) {
  const io::CaseReader reader = io::CaseReader::from_file(source_path("cases/hertz_paper.toml"), {});
  int elements = 0;
  for (auto _ : state) {
    io::ContactCase cc = io::read_contact_case(reader);
    cc = pipeline::placed_contact(std::move(cc));
    const contact::ContactPatch patch = pipeline::solve_patch(cc);
    const auto s = contact::solve_steady_rolling(patch.influence, patch.normal.pn,
                                                 cc.steady_input(), cc.tangential);
    benchmark::DoNotOptimize(s);
    elements = patch.grid.nx * patch.grid.ny;
  }
  state.counters["elements"] = elements;
}
BENCHMARK(SteadyHertzPaper)->Unit(benchmark::kMillisecond)->Iterations(10);

// One contact search of the S1002 wheel on the UIC60 rail at a yawed, rolled pose.
void MinimumGapS1002Uic60(benchmark::State& state) {
  const geometry::WheelRailPair pair(
      io::read_profile(source_path("models/profiles/MBench_S1002_v3.prw")),
      io::read_profile(source_path("models/profiles/MBench_UIC60_v3.prr")));
  const geometry::WheelsetPose pose{6.2e-3, -0.46, 2e-3, 7.8e-3};
  for (auto _ : state) benchmark::DoNotOptimize(pair.minimum_gap(pose));
  state.counters["samples"] = static_cast<double>(pair.wheel_table().s.size());
}
BENCHMARK(MinimumGapS1002Uic60)->Unit(benchmark::kMicrosecond);

// The vertical point receptance of the UIC60 ballasted track at mid-span (N = 60: 121 supports)
// at one frequency.
void DiscreteRailPointReceptance(benchmark::State& state) {
  const dynamics::TrackParameters t = dynamics::uic60_ballasted();
  const dynamics::DiscretelySupportedRail rail(t.vertical, t.vertical_support, t.sleeper_spacing,
                                               t.supports_each_side);
  for (auto _ : state) benchmark::DoNotOptimize(rail.point(1000.0, 0.3));
  state.counters["supports"] = 2 * t.supports_each_side + 1;
}
BENCHMARK(DiscreteRailPointReceptance)->Unit(benchmark::kMicrosecond);

}  // namespace
