// Benchmarks of the contact core (Google Benchmark). Grid size and element counts are reported as
// counters with every timing:
//   build/rollnoise_bench --benchmark_filter=Steady      one steady solve of the paper's case
//   build/rollnoise_bench --benchmark_filter=HalfSpace   A*p by FFT and by dense matrix
#include <benchmark/benchmark.h>

#include <random>

#include "contact/halfspace_operator.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/creepage_history.hpp"
#include "contact/transient_rolling.hpp"

using namespace rollnoise::contact;

namespace {

const Material kSteel{210e9, 0.28};

// The paper's Hertzian case (a = 7.18 mm, b = 5.29 mm, N = 98.1 kN) on nx x ny elements over
// +-34/30 a by +-34/30 b (CONTACT's coarse 34 x 25 and fine 68 x 50 grids).
void SteadyPaperCase(benchmark::State& state) {
  const int nx = state.range(0), ny = state.range(1);
  const Grid g = Grid::around_ellipse(nx, ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  const ContactPatch patch = solve_patch(g, kSteel, quadratic_distance(g, h.A, h.B), 98100);
  const SteadyRollingInput in{0.3, 13.8888888888889, {0.001, 0.001, -0.053}, 0.0};
  TangentialSolution s;
  for (auto _ : state) {
    s = solve_steady_rolling(patch.influence, patch.normal.pn, in);
    benchmark::DoNotOptimize(s.px.data());
  }
  state.counters["grid_elements"] = g.size();
  state.counters["contact_elements"] = patch.normal.contact_elements();
  state.counters["adhesion"] = s.count(ElementState::adhesion);
  state.counters["slip"] = s.count(ElementState::slip);
  state.counters["newton_iterations"] = s.iterations;
  state.counters["gmres_iterations"] = s.linear_iterations;
  state.counters["lu_factorisations"] = s.factorisations;
}
BENCHMARK(SteadyPaperCase)->Args({34, 25})->Args({68, 50})->Unit(benchmark::kMillisecond)->Iterations(1);

void NormalPaperCase(benchmark::State& state) {
  const int nx = state.range(0), ny = state.range(1);
  const Grid g = Grid::around_ellipse(nx, ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  const auto hq = quadratic_distance(g, h.A, h.B);
  int it = 0, nc = 0;
  for (auto _ : state) {
    const ContactPatch patch = solve_patch(g, kSteel, hq, 98100);
    it = patch.normal.iterations;
    nc = patch.normal.contact_elements();
  }
  state.counters["grid_elements"] = g.size();
  state.counters["contact_elements"] = nc;
  state.counters["cg_iterations"] = it;
}
BENCHMARK(NormalPaperCase)->Args({34, 25})->Args({68, 50})->Args({136, 100})->Unit(benchmark::kMillisecond);

void HalfSpaceProduct(benchmark::State& state) {
  const int n = state.range(0);
  const Backend backend = state.range(1) ? Backend::Fft : Backend::Dense;
  const Grid g = Grid::around_ellipse(n, n, 5e-3, 5e-3, 1.1);
  const InfluenceTable t(g, kSteel);
  const HalfSpaceOperator A(t, Problem::Tangential, 0, backend);
  std::vector<double> p(A.size()), u(A.size());
  std::mt19937 rng(1);
  for (auto& v : p) v = std::uniform_real_distribution<double>(0, 1)(rng);
  for (auto _ : state) {
    A.apply(p.data(), u.data());
    benchmark::DoNotOptimize(u.data());
  }
  state.counters["unknowns"] = A.size();
  state.SetLabel(backend == Backend::Fft ? "fft" : "dense");
}
BENCHMARK(HalfSpaceProduct)->ArgsProduct({{8, 16, 24, 32, 48}, {0, 1}})->Unit(benchmark::kMicrosecond);

// Transient rolling (paper Sec. 3.1 excitation, from the steady state): 10 periods at 1 kHz.
// Reported per step and for the whole run.
void TransientTenPeriods1kHz(benchmark::State& state) {
  const int nx = state.range(0), ny = state.range(1);
  const Grid g = Grid::around_ellipse(nx, ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, kSteel);
  const ContactPatch patch = solve_patch(g, kSteel, quadratic_distance(g, h.A, h.B), 98100);
  const double V = 13.8888888888889;
  const auto history = CreepageHistory::harmonic({0.001, 0, 0}, {5e-5, 0, 0}, 1000.0);
  const auto steady = solve_steady_rolling(patch.influence, patch.normal.pn, {0.3, V, history.mean(), 0.0});
  long steps = 0, newton = 0, gmres = 0, lu = 0;
  for (auto _ : state) {
    TransientRolling rolling(patch.influence, patch.normal.pn, 0.3, V, 0.0);
    rolling.set_tractions(steady.px, steady.py);
    steps = static_cast<long>(0.01 / rolling.time_step());
    for (long k = 1; k <= steps; ++k) {
      const auto& s = rolling.step(history.at(k * rolling.time_step()));
      newton += s.iterations, gmres += s.linear_iterations, lu += s.factorisations;
    }
  }
  state.counters["newton_iterations"] = newton;
  state.counters["gmres_iterations"] = gmres;
  state.counters["lu_factorisations"] = lu;
  state.counters["grid_elements"] = g.size();
  state.counters["contact_elements"] = patch.normal.contact_elements();
  state.counters["steps"] = steps;
  // printed as a time per step (the inverse of steps per second)
  state.counters["per_step"] =
      benchmark::Counter(steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(TransientTenPeriods1kHz)->Args({34, 25})->Args({68, 50})->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace


