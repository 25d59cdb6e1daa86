// Benchmarks of the linear NSS model (Google Benchmark): f_jk at 1000 frequencies (10 Hz - 10 kHz)
// on CONTACT's coarse (34 x 25, 538 contact elements) and fine (68 x 50, 2096) grids at the paper's
// mean creepages (0.001, 0.001, -0.053), by the fast sweep (block Krylov reduced model, model set-up
// included; also at full adhesion, its slowest case), by the exact Markov recursion, and by the direct solve (complex LU per frequency,
// timed on one frequency: x1000 for a sweep). CreepDirectPerFrequency also reports the largest
// relative difference (Frobenius) of the fast sweep from the direct solve at 4 frequencies from
// 10 Hz to Nyquist (counter fast_vs_direct).
//   build/rollnoise_bench --benchmark_filter=Creep
#include <benchmark/benchmark.h>

#include <chrono>

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

Setup setup(int nx, int ny, const Creepage& mean = {0.001, 0.001, -0.053}) {
  const Material m{210e9, 0.28};
  const Grid g = Grid::around_ellipse(nx, ny, 7.18e-3, 5.29e-3, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(7.18e-3, 5.29e-3, 98100, m);
  Setup s;
  s.patch = std::make_unique<ContactPatch>(solve_patch(g, m, quadratic_distance(g, h.A, h.B), 98100));
  s.steady = solve_steady_rolling(s.patch->influence, s.patch->normal.pn,
                                  {0.3, 13.8888888888889, mean, 0.0});
  return s;
}

std::vector<double> thousand() {
  std::vector<double> f;
  for (int i = 0; i < 1000; ++i) f.push_back(10.0 * std::pow(1000.0, i / 999.0));
  return f;
}

// Args: nx, ny, mean state (0: the paper's (0.001, 0.001, -0.053); 1: full adhesion, the slowest
// to converge: 3 contact lengths of block steps and r = n).
void CreepFastSweep1000(benchmark::State& state) {
  const Setup s = state.range(2) == 1 ? setup(state.range(0), state.range(1), {0, 0, 0})
                                      : setup(state.range(0), state.range(1));
  const auto freqs = thousand();
  size_t markov = 0;
  nss::SweepInfo info;
  double setup = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    nss::LinearContactModel m(*s.patch, s.steady, {0.3, 13.8888888888889, 0.0});
    setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    benchmark::DoNotOptimize(m.creep_coefficients(freqs));
    benchmark::DoNotOptimize(m.normal_load_coefficients(freqs));  // the same Markov run (G3)
    markov = m.markov_parameters().size();
    info = m.sweep_info();
  }
  state.counters["contact_elements"] = s.patch->normal.contact_elements();
  state.counters["markov_parameters"] = markov;
  state.counters["constructor_s"] = setup;
  state.counters["block_steps"] = info.block_steps;
  state.counters["reduced_dim"] = info.reduced_dimension;
  state.counters["error_estimate"] = info.error_estimate;
  state.counters["krylov"] = info.method == nss::SweepInfo::Method::krylov;
  state.counters["factor_s"] = info.factor_seconds;
  state.counters["krylov_s"] = info.krylov_seconds;
  state.counters["check_s"] = info.check_seconds;
}
BENCHMARK(CreepFastSweep1000)
    ->Args({34, 25, 0})
    ->Args({68, 50, 0})
    ->Args({34, 25, 1})
    ->Args({68, 50, 1})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

void CreepExactMarkovSweep1000(benchmark::State& state) {
  const Setup s = setup(state.range(0), state.range(1));
  const auto freqs = thousand();
  for (auto _ : state) {
    nss::LinearContactModel m(*s.patch, s.steady, {0.3, 13.8888888888889, 0.0});
    benchmark::DoNotOptimize(m.creep_coefficients_markov(freqs));
  }
}
BENCHMARK(CreepExactMarkovSweep1000)->Args({34, 25})->Args({68, 50})->Unit(benchmark::kSecond)->Iterations(1);

void CreepDirectPerFrequency(benchmark::State& state) {
  const Setup s = setup(state.range(0), state.range(1));
  const nss::LinearContactModel m(*s.patch, s.steady, {0.3, 13.8888888888889, 0.0});
  (void)m.creep_coefficients_direct(0.0);  // assembles the paper's dense form outside the timing
  for (auto _ : state) benchmark::DoNotOptimize(m.creep_coefficients_direct(1000.0));
  const std::vector<double> check = {10.0, 1000.0, 10000.0, m.nyquist_frequency()};
  const auto fast = m.creep_coefficients(check);
  double worst = 0.0;
  for (size_t i = 0; i < check.size(); ++i) {
    const auto direct = m.creep_coefficients_direct(check[i]);
    worst = std::max(worst, (fast[i] - direct).norm() / direct.norm());
  }
  state.counters["fast_vs_direct"] = worst;
  state.counters["contact_elements"] = s.patch->normal.contact_elements();
  state.SetLabel("x1000 for the 1000-frequency sweep");
}
BENCHMARK(CreepDirectPerFrequency)->Args({34, 25})->Args({68, 50})->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
