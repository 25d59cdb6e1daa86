// Benchmarks of the linear NSS model (Google Benchmark): f_jk at 1000 frequencies (10 Hz - 10 kHz)
// on CONTACT's coarse (34 x 25, 538 contact elements) and fine (68 x 50, 2096) grids at the paper's
// mean creepages (0.001, 0.001, -0.053), by the fast sweep (Markov parameters) and by the direct
// solve (complex LU per frequency, timed on 3 frequencies and scaled to 1000).
//   build/rollnoise_bench --benchmark_filter=Creep
#include <benchmark/benchmark.h>

#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "nss/linear_model.hpp"

using namespace rollnoise;
using namespace rollnoise::contact;

namespace {

struct Setup {
  std::unique_ptr<ContactPatch> patch;
  TangentialSolution steady;
};

Setup setup(int nx, int ny) {
  const Material m{210e9, 0.28};
  const Grid g = Grid::around_ellipse(nx, ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, m);
  Setup s;
  s.patch = std::make_unique<ContactPatch>(solve_patch(g, m, quadratic_distance(g, h.A, h.B), 98100));
  s.steady = solve_steady_rolling(s.patch->influence, s.patch->normal.pn,
                                  {0.3, 13.8888888888889, {0.001, 0.001, -0.053}, 0.0});
  return s;
}

std::vector<double> thousand() {
  std::vector<double> f;
  for (int i = 0; i < 1000; ++i) f.push_back(10.0 * std::pow(1000.0, i / 999.0));
  return f;
}

void CreepFastSweep1000(benchmark::State& state) {
  const Setup s = setup(state.range(0), state.range(1));
  const auto freqs = thousand();
  size_t markov = 0;
  for (auto _ : state) {
    nss::LinearContactModel m(*s.patch, s.steady, {0.3, 13.8888888888889, 0.0});
    benchmark::DoNotOptimize(m.creep_coefficients(freqs));
    markov = m.markov_parameters().size();
  }
  state.counters["contact_elements"] = s.patch->normal.contact_elements();
  state.counters["markov_parameters"] = markov;
}
BENCHMARK(CreepFastSweep1000)->Args({34, 25})->Args({68, 50})->Unit(benchmark::kSecond)->Iterations(1);

void CreepDirectPerFrequency(benchmark::State& state) {
  const Setup s = setup(state.range(0), state.range(1));
  const nss::LinearContactModel m(*s.patch, s.steady, {0.3, 13.8888888888889, 0.0});
  for (auto _ : state) benchmark::DoNotOptimize(m.creep_coefficients_direct(1000.0));
  state.counters["contact_elements"] = s.patch->normal.contact_elements();
  state.SetLabel("x1000 for the 1000-frequency sweep");
}
BENCHMARK(CreepDirectPerFrequency)->Args({34, 25})->Args({68, 50})->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
