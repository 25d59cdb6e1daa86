// Benchmark of the waveguide rail (dynamics/rail_waveguide.hpp): the waves of one frequency (the
// n x n eigenproblem in k^2, LAPACK zgeev, and the residue norms) and the 4x4 contact receptance
// from them, on the supported UIC60 section meshed at 40 mm (86 triangles, 207 nodes, n = 621) and
// 30 mm. The counter `dofs` is n; multiply the time by the number of frequencies of a curve (864
// for curve_300m) for the cost of a receptance curve.
//   build/rollnoise_bench --benchmark_filter=RailWaveguide
#include <benchmark/benchmark.h>

#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "fem/mesh.hpp"

using namespace rollnoise;

namespace {

void RailWaveguideReceptancePerFrequency(benchmark::State& state) {
  const double h = 1e-3 * static_cast<double>(state.range(0));
  const fem::QuadraticTriangleMesh mesh = fem::mesh_polygon(dynamics::uic60_outline(), h);
  const dynamics::TrackParameters t = dynamics::uic60_ballasted();
  const dynamics::RailWaveguide rail(
      mesh, dynamics::RailMaterial{},
      dynamics::FootSupport{t.vertical_support, t.lateral_support, t.longitudinal_support,
                            t.sleeper_spacing});
  const int top = dynamics::nearest_boundary_node(mesh, Eigen::Vector2d(0.0, 0.172));
  const Eigen::MatrixXd L =
      rail.contact_loads(top, Eigen::Vector2d(0.0, 1.0), dynamics::kUic60HeadBottom);
  for (auto _ : state) {
    const dynamics::RailWaves w = rail.waves(2.0 * M_PI * 1000.0);
    benchmark::DoNotOptimize(rail.contact_receptance(w, L, L, 0.0));
  }
  state.counters["dofs"] = rail.dofs();
}
BENCHMARK(RailWaveguideReceptancePerFrequency)
    ->Arg(40)
    ->Arg(30)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace
