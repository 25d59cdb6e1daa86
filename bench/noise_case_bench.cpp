// The cost of a noise case against a steady Hertzian solve (issue 25's speed targets), and of the
// two kernels that dominated it: the contact search on the profiles (WheelRailPair::minimum_gap)
// and the discretely supported rail per frequency (Eq. (2) of dynamics/track.hpp).
//   rollnoise_bench --benchmark_filter='SpeedBars|NoiseCase|SteadyHertz|MinimumGap|DiscreteRail'
// SpeedBarsCurve300m prints issue 25's two ratios (single wheel / steady, four wheels / single).
// Counters: `elements` (contact grid nx x ny of the case), `frequencies` (of the noise case),
// `supports` (2N + 1 of the rail), `samples` (wheel profile samples scanned per minimum_gap).
// The noise case also reports its stage times (contact = curve state, patch and NSS sweep;
// structures = wheel and rail receptances) as counters in seconds.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contact/steady_rolling.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel_fe.hpp"
#include "geometry/s1002.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "io/noise_case.hpp"
#include "io/profile_file.hpp"
#include "io/wheel_fe_case.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/noise_pipeline.hpp"
#include "vehicle/curving.hpp"

using namespace rollnoise;

namespace {

std::string source_path(const char* relative) {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/" + relative;
}

// rollnoise noise cases/curve_300m.toml (`overrides`: --set strings) without writing the output:
// curve state (bogie estimate on the S1002/UIC60 profiles), each wheel's patch and NSS sweep, the
// receptances, the loops, the bands.
pipeline::NoiseResult run_curve_300m(const io::CaseReader& reader) {
  io::NoiseInputs in = io::read_noise_inputs(reader);
  return pipeline::run_noise(std::move(in.contact), in.noise);
}

// rollnoise steady cases/hertz_paper.toml without the output: the normal problem and one steady
// rolling solve. Returns the element count.
int run_steady_hertz(const io::CaseReader& reader) {
  io::ContactCase cc = io::read_contact_case(reader);
  cc = pipeline::placed_contact(std::move(cc));
  const contact::ContactPatch patch = pipeline::solve_patch(cc);
  const auto s = contact::solve_steady_rolling(patch.influence, patch.normal.pn, cc.steady_input(),
                                               cc.tangential);
  benchmark::DoNotOptimize(s);
  return patch.grid.nx * patch.grid.ny;
}

const std::vector<std::string> kSingleWheel = {"curve.wheels=[\"leading_outer\"]"};

void NoiseCaseCurve300m(benchmark::State& state, std::vector<std::string> overrides) {
  const io::CaseReader reader =
      io::CaseReader::from_file(source_path("cases/curve_300m.toml"), overrides);
  double elements = 0, frequencies = 0, contact_s = 0, wheels_s = 0;
  for (auto _ : state) {
    const pipeline::NoiseResult r = run_curve_300m(reader);
    elements = r.mean.contact().grid.nx * r.mean.contact().grid.ny;
    frequencies = static_cast<double>(r.axis.frequency.size());
    contact_s = r.seconds_contact;
    wheels_s = r.seconds_wheels;
  }
  state.counters["elements"] = elements;  // the leading outer wheel's grid
  state.counters["frequencies"] = frequencies;
  state.counters["contact_s"] = contact_s;
  state.counters["wheels_s"] = wheels_s;
}
BENCHMARK_CAPTURE(NoiseCaseCurve300m, four_wheels, std::vector<std::string>{})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(NoiseCaseCurve300m, leading_outer, kSingleWheel)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void SteadyHertzPaper(benchmark::State& state) {
  const io::CaseReader reader =
      io::CaseReader::from_file(source_path("cases/hertz_paper.toml"), {});
  int elements = 0;
  for (auto _ : state) elements = run_steady_hertz(reader);
  state.counters["elements"] = elements;
}
BENCHMARK(SteadyHertzPaper)->Unit(benchmark::kMillisecond)->Iterations(10);

// Issue 25's two speed bars in-process (no process start-up, which `perf stat` of the commands
// includes): the single-wheel noise case over the steady Hertz case (bar: <= 5) and the four-wheel
// case over the single-wheel case (bar: <= 2.5), the median of 3 runs each; the second ratio also
// for cases/curve_300m_table.toml (the mode table instead of the FE wheel; in-process the FE
// wheel's modes are computed once per process, so the FE ratios here exclude them, unlike the
// commands'; the FE modes of the case's wheel are timed alone, dynamics::wheel_fe_modes, and
// `single_with_fe_modes_over_steady` adds them to the single wheel, as the command pays them).
// The bars are wall time (the further wheels and the FE wheel's orders run on solver.threads
// threads, 0 = the hardware's: the counters ending in _wall); CPU time (std::clock: all threads of
// the process, the work) is printed beside it, its ratios without a suffix. Counters: the ratios,
// the seconds, the grid (elements of the leading outer wheel's patch, of the Hertz patch) and the
// frequency count.
struct Seconds {
  double cpu = 0, wall = 0;
};

Seconds timed(const std::function<void()>& run) {
  std::vector<double> cpu, wall;
  for (int i = 0; i < 3; ++i) {
    const std::clock_t c0 = std::clock();
    const auto w0 = std::chrono::steady_clock::now();
    run();
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  std::sort(cpu.begin(), cpu.end());
  std::sort(wall.begin(), wall.end());
  return {cpu[1], wall[1]};
}

// The bars' ratios and the seconds, from CPU (`suffix` "") or wall times ("_wall").
void bar_counters(benchmark::State& state, const std::string& suffix, double t4, double t1,
                  double th, double t4_table, double t1_table, double t_modes) {
  state.counters["single_over_steady" + suffix] = t1 / th;
  state.counters["single_with_fe_modes_over_steady" + suffix] = (t1 + t_modes) / th;
  state.counters["four_over_single" + suffix] = t4 / t1;
  state.counters["four_over_single_with_fe_modes" + suffix] = (t4 + t_modes) / (t1 + t_modes);
  state.counters["four_over_single_table" + suffix] = t4_table / t1_table;
  const std::string unit = suffix.empty() ? "_cpu_s" : "_wall_s";
  state.counters["four_table" + unit] = t4_table;
  state.counters["single_table" + unit] = t1_table;
  state.counters["four" + unit] = t4;
  state.counters["single" + unit] = t1;
  state.counters["steady" + unit] = th;
  state.counters["fe_modes" + unit] = t_modes;
}

void SpeedBarsCurve300m(benchmark::State& state) {
  const io::CaseReader four = io::CaseReader::from_file(source_path("cases/curve_300m.toml"), {});
  const io::CaseReader one =
      io::CaseReader::from_file(source_path("cases/curve_300m.toml"), kSingleWheel);
  const io::CaseReader hertz = io::CaseReader::from_file(source_path("cases/hertz_paper.toml"), {});
  // the same case with the wheel's mode table instead of the FE wheel (cases/curve_300m_table.toml)
  const io::CaseReader four_table =
      io::CaseReader::from_file(source_path("cases/curve_300m_table.toml"), {});
  const io::CaseReader one_table =
      io::CaseReader::from_file(source_path("cases/curve_300m_table.toml"), kSingleWheel);
  io::InputProblems problems;
  const std::optional<io::WheelFeCase> fe = io::read_wheel_fe_case(one, problems);
  if (!fe) state.SkipWithError("cases/curve_300m.toml has no FE wheel");
  Seconds t4, t1, th, t4_table, t1_table, t_modes;
  double elements = 0, frequencies = 0, hertz_elements = 0, dofs = 0;
  for (auto _ : state) {
    t_modes = timed([&] {
      const dynamics::WheelFeModes w = dynamics::wheel_fe_modes(fe->section, fe->options);
      dofs = 3.0 * w.mesh.nodes.size();
    });
    t4_table = timed([&] { benchmark::DoNotOptimize(run_curve_300m(four_table)); });
    t1_table = timed([&] { benchmark::DoNotOptimize(run_curve_300m(one_table)); });
    t4 = timed([&] {
      const pipeline::NoiseResult r = run_curve_300m(four);
      benchmark::DoNotOptimize(r);
    });
    t1 = timed([&] {
      const pipeline::NoiseResult r = run_curve_300m(one);
      elements = r.mean.contact().grid.nx * r.mean.contact().grid.ny;
      frequencies = static_cast<double>(r.axis.frequency.size());
    });
    th = timed([&] { hertz_elements = run_steady_hertz(hertz); });
  }
  bar_counters(state, "", t4.cpu, t1.cpu, th.cpu, t4_table.cpu, t1_table.cpu, t_modes.cpu);
  bar_counters(state, "_wall", t4.wall, t1.wall, th.wall, t4_table.wall, t1_table.wall,
               t_modes.wall);
  state.counters["fe_dofs_per_order"] = dofs;
  state.counters["elements"] = elements;
  state.counters["hertz_elements"] = hertz_elements;
  state.counters["frequencies"] = frequencies;
}
BENCHMARK(SpeedBarsCurve300m)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

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

// The curving estimate's profile table of S1002 on UIC60 (lateral -10..10 mm in 0.1 mm steps: 201
// positions, both wheels' contacts at each): `shared_pose` as built (one roll iteration per
// position, the contact points without curvatures), `two_searches` the table's work before
// 2026-11-26 (a full contact search per wheel, each with its own roll iteration and curvatures).
void ProfileCurvingTableS1002Uic60(benchmark::State& state) {
  const geometry::WheelRailPair pair(
      io::read_profile(source_path("models/profiles/MBench_S1002_v3.prw")),
      io::read_profile(source_path("models/profiles/MBench_UIC60_v3.prr")));
  const bool shared_pose = state.range(0) == 1;
  for (auto _ : state) {
    if (shared_pose) {
      benchmark::DoNotOptimize(noise::profile_curving_table(pair, 0.010, 0.1e-3));
      continue;
    }
    for (int k = -100; k <= 100; ++k) {
      benchmark::DoNotOptimize(geometry::find_contact(pair, {k * 0.1e-3, 0.0}, geometry::Side::Right));
      benchmark::DoNotOptimize(geometry::find_contact(pair, {k * 0.1e-3, 0.0}, geometry::Side::Left));
    }
  }
  state.counters["positions"] = 201;
}
BENCHMARK(ProfileCurvingTableS1002Uic60)->ArgName("shared_pose")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

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
