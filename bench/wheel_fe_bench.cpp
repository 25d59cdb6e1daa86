// The default 920 mm wheel's FE modes (dynamics/wheel_fe.hpp): meshing, 11 orders n = 0..10, all
// modes up to 6 kHz, tread shapes; and the stages of it, to see where the time goes. Element and
// DOF counts reported with the timing (docs/record/fe_wheel.md Sec. 3, "Speed"):
//   build/rollnoise_bench --benchmark_filter=WheelFe
// The noise case it is compared with: NoiseCaseCurve300m* (bench/noise_case_bench.cpp).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "dynamics/wheel_fe.hpp"
#include "fem/axisymmetric.hpp"
#include "fem/eigen_solve.hpp"
#include "fem/mesh.hpp"
#include "io/wheel_section_file.hpp"

using namespace rollnoise;

namespace {

constexpr double kPi = 3.14159265358979323846;

dynamics::WheelSection section_920mm() {
  return io::read_wheel_section(std::string(ROLLNOISE_SOURCE_DIR) +
                                "/models/wheel/wheel_920mm_section.csv");
}

// The whole computation (what `rollnoise modes` and the FE wheel of a case do once per wheel).
// Argument: the mesh size in mm (12, 8).
void WheelFeModes920mm(benchmark::State& state) {
  const auto section = section_920mm();
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

// Stage 1: meshing the section with gmsh (6-node triangles).
void WheelFeStageMesh920mm(benchmark::State& state) {
  const auto section = section_920mm();
  fem::QuadraticTriangleMesh mesh;
  for (auto _ : state) {
    mesh = fem::mesh_polygon(section.outline, state.range(0) * 1e-3);
    benchmark::DoNotOptimize(mesh.nodes.data());
  }
  state.counters["mesh_size_mm"] = state.range(0);
  state.counters["triangles"] = mesh.triangles.size();
}
BENCHMARK(WheelFeStageMesh920mm)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(3);

// Stage 2: K and M of the 11 orders n = 0..10, from the three order-independent parts assembled
// once (fem::AxisymmetricOrders, what wheel_fe_modes does) ...
void WheelFeStageAssembly920mm(benchmark::State& state) {
  const auto mesh = fem::mesh_polygon(section_920mm().outline, state.range(0) * 1e-3);
  for (auto _ : state) {
    const fem::AxisymmetricOrders orders(mesh, {});
    for (int n = 0; n <= 10; ++n) benchmark::DoNotOptimize(orders.matrices(n).stiffness.nonZeros());
  }
  state.counters["mesh_size_mm"] = state.range(0);
  state.counters["dofs_per_order"] = 3 * mesh.nodes.size();
}
BENCHMARK(WheelFeStageAssembly920mm)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(3);

// ... against assembling each order on its own (fem::assemble_axisymmetric).
void WheelFeStageAssemblyEachOrder920mm(benchmark::State& state) {
  const auto mesh = fem::mesh_polygon(section_920mm().outline, state.range(0) * 1e-3);
  for (auto _ : state)
    for (int n = 0; n <= 10; ++n)
      benchmark::DoNotOptimize(fem::assemble_axisymmetric(mesh, {}, n).stiffness.nonZeros());
  state.counters["mesh_size_mm"] = state.range(0);
  state.counters["dofs_per_order"] = 3 * mesh.nodes.size();
}
BENCHMARK(WheelFeStageAssemblyEachOrder920mm)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(3);

// Stage 3: the eigen solves (all modes to 6 kHz) of the 11 orders, the bore clamped.
void WheelFeStageEigen920mm(benchmark::State& state) {
  const auto section = section_920mm();
  const auto mesh = fem::mesh_polygon(section.outline, state.range(0) * 1e-3);
  std::vector<int> fixed;
  for (int node : fem::nodes_on_segments(mesh, section.bore_segments))
    for (int c = 0; c < 3; ++c) fixed.push_back(3 * node + c);
  const fem::AxisymmetricOrders orders(mesh, {});
  std::vector<fem::AxisymmetricMatrices> km;
  for (int n = 0; n <= 10; ++n) km.push_back(orders.matrices(n));
  double modes = 0;
  for (auto _ : state) {
    fem::LowestModesSolver solver(fixed, 2 * kPi * 6000.0);
    int previous = -1;
    modes = 0;
    for (const auto& k : km) {
      previous = static_cast<int>(solver.solve(k.stiffness, k.mass, previous).omega.size());
      modes += previous;
    }
  }
  state.counters["mesh_size_mm"] = state.range(0);
  state.counters["dofs_per_order"] = 3 * mesh.nodes.size();
  state.counters["modes"] = modes;
}
BENCHMARK(WheelFeStageEigen920mm)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
