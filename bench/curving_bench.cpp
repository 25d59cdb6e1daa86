// What the bogie's equilibrium costs against the contact states it replaces (issue 49's bar: at
// most 2x): the quasi-static estimate plus the four wheels' contacts (curve.creepage =
// "estimate": noise::curve_contact_state, then bogie_wheel_contacts of the three other wheels),
// against noise::curve_contact_state with curve.creepage = "equilibrium" (solve_bogie_equilibrium
// from the estimate's state; the four contacts come with its solution). The linear contact models
// that both then build are not timed here.
//   rollnoise_bench --benchmark_filter=CurveContactStates
// Arg: the curve radius (m) of cases/curve_<R>m.toml; 0 the estimate, 1 the equilibrium. Counters:
// `nx` the case's elements along the patch (grid.nx), `elements` the four wheels' patches' element
// counts summed, `evaluations` axle contact-force evaluations of the equilibrium (two wheels each).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/curve_setup.hpp"
#include "vehicle/bogie_equilibrium.hpp"
#include "vehicle/curve_state.hpp"

using namespace rollnoise;

namespace {

void CurveContactStates(benchmark::State& state) {
  const int radius = static_cast<int>(state.range(0));
  const bool equilibrium = state.range(1) == 1;
  const std::string path =
      std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_" + std::to_string(radius) + "m.toml";
  const io::CaseReader reader = io::CaseReader::from_file(
      path, {equilibrium ? "curve.creepage=\"equilibrium\"" : "curve.creepage=\"estimate\""});
  const io::NoiseInputs in = io::read_noise_inputs(reader);
  const noise::CurveStateInput ci = pipeline::curve_state_input(in.contact, in.noise);
  int evaluations = 0, elements = 0;
  for (auto _ : state) {
    const noise::CurveContactState s = noise::curve_contact_state(ci);
    const std::vector<noise::WheelContact> others =
        noise::bogie_wheel_contacts(ci, s,
                                    {noise::WheelId::leading_inner, noise::WheelId::trailing_outer,
                                     noise::WheelId::trailing_inner});
    benchmark::DoNotOptimize(others);
    if (s.equilibrium) evaluations = s.equilibrium->contact_evaluations;
    elements = s.loaded->patch->grid.size();
    for (const noise::WheelContact& w : others) elements += w.loaded->patch->grid.size();
  }
  state.counters["nx"] = ci.grid.nx;
  state.counters["elements"] = elements;
  state.counters["evaluations"] = evaluations;
}

}  // namespace

BENCHMARK(CurveContactStates)
    ->ArgsProduct({{300, 500, 1000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
