// Benchmarks of the discretely supported waveguide rail (dynamics/waveguide_discrete_support.hpp):
// UIC60, the loop's 30 mm mesh, the track file's N = 60 seats each side (4(2N + 1) = 484
// unknowns in Eq. D2), the model built once outside the timing.
//
// DiscreteWaveguideContact/case/nf: RailModel::contact_transfers at nf frequencies (500 Hz up in
// steps of 250 Hz); the CPU time includes the query's Ritz basis (once per set of coupled points),
// so the cost per frequency is the difference of nf = 9 and nf = 1 divided by 8 (9 frequencies over
// 2.3 octaves are fewer than the sampling's starting grid: every one is computed directly).
//   case 1: one contact, the 300 m curve's gauge corner, loaded at the contact;
//   case 2: one rail of a coupled bogie, loaded at the contacts: the gauge corner and its flange
//           patch at 0.3 m, the trailing wheel near the crown at 2.8 m, all six pairs a <= b.
//   build/rollnoise_bench --benchmark_filter=DiscreteWaveguide
#include <benchmark/benchmark.h>

#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_discrete_support.hpp"

using namespace rollnoise;

namespace {

const dynamics::DiscreteWaveguideRailModel& rail() {
  static const dynamics::WaveguideRailOptions options;  // a named value: GCC 12 warns of the temporary
  static const dynamics::DiscreteWaveguideRailModel r(dynamics::uic60_ballasted(), options, 0.3);
  return r;
}

std::vector<dynamics::RailContactPair> pairs(int which) {
  const dynamics::RailContact corner{0.3, -0.0366, 0.524}, flange{0.3, -0.03, 1.0},
      trailing{2.8, -0.01, 0.1};
  if (which < 2) return {{corner, corner}};  // case 0 (the crown moved rigidly) is gone
  const std::vector<dynamics::RailContact> c = {corner, flange, trailing};
  std::vector<dynamics::RailContactPair> out;
  for (std::size_t a = 0; a < c.size(); ++a)
    for (std::size_t b = a; b < c.size(); ++b) out.emplace_back(c[a], c[b]);
  return out;
}

void DiscreteWaveguideContact(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0)), nf = static_cast<int>(state.range(1));
  std::vector<double> f;
  for (int i = 0; i < nf; ++i) f.push_back(500.0 + 250.0 * i);
  const std::vector<dynamics::RailContactPair> p = pairs(which);
  const dynamics::DiscreteWaveguideRailModel& r = rail();
  for (auto _ : state) benchmark::DoNotOptimize(r.contact_transfers(f, p));
  state.counters["pairs"] = static_cast<double>(p.size());
  state.counters["frequencies"] = nf;
}

}  // namespace

BENCHMARK(DiscreteWaveguideContact)
    ->ArgsProduct({{1, 2}, {1, 9}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
