// The default 920 mm wheel's FE modes (dynamics/wheel_fe.hpp): meshing, 11 orders n = 0..10, all
// modes up to 6 kHz, tread shapes. Element and DOF counts reported with the timing:
//   build/rollnoise_bench --benchmark_filter=WheelFe
#include <benchmark/benchmark.h>

#include <string>

#include "dynamics/wheel_fe.hpp"
#include "io/wheel_section_file.hpp"

using namespace rollnoise;

namespace {

// Argument: the mesh size in mm (12, 8).
void WheelFeModes920mm(benchmark::State& state) {
  const auto section = io::read_wheel_section(std::string(ROLLNOISE_SOURCE_DIR) +
                                              "/models/wheel/wheel_920mm_section.csv");
  dynamics::WheelFeOptions o;
  o.mesh_size = state.range(0) * 1e-3;
  o.n_max = 10;
  o.f_max = 6000.0;
  dynamics::WheelFeModes w;
  for (auto _ : state) {
    w = dynamics::wheel_fe_modes(section, o);
    benchmark::DoNotOptimize(w.modes.data());
  }
  state.counters["mesh_size_mm"] = state.range(0);
  state.counters["triangles"] = w.mesh.triangles.size();
  state.counters["dofs_per_order"] = 3 * w.mesh.nodes.size();
  state.counters["modes"] = w.modes.size();
}
BENCHMARK(WheelFeModes920mm)->Arg(12)->Arg(8)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
