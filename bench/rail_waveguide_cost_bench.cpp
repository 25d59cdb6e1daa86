// What the continuous waveguide rail costs in the 300 m curve case (docs/record/waveguide_rail.md
// Sec. 11, docs/record/performance_waveguide.md Sec. 1): the UIC60 section on the continuous
// support of uic60_ballasted, 30 mm mesh (the loop's), the 10 mm patch at the four wheels' contact
// points of curve_300m.
//
// RailWaveguideCurveCost/b: b = 0 the former basis (RailReduction{}: modes below 20 kHz and the
// static responses at the same seven wavenumbers), b = 1 the loop's (near_field_reduction()).
// Counters (CPU time): `dofs` n of the section, `coordinates` m of each contact point's Ritz basis
// (largest of the four), `modes_s` the one-off section modes per rail model, `basis_s` one point's
// basis, `per_frequency_ms` one frequency (the m x m wavenumber eigenproblem, Eq. W5, and the 4 x 4
// of Eq. W4), averaged over 100 Hz - 5 kHz; `direct_points` the frequencies computed directly on
// curve_300m's 864 (24 per octave, the rest interpolated); `case_rail_s` = modes_s + 4 x (basis_s
// + direct_points x per_frequency_ms), the rail's share of `rollnoise noise
// cases/curve_300m_waveguide.toml` (four contact points, each wheel's loop alone); `err_dB` the
// largest |dB| difference of the four points' 4 x 4 diagonal from the full model (n x n) at 0.3,
// 1, 2, 3.4 and 4.9 kHz. CPU time per iteration is one point's basis and the 145 frequencies.
//   build/rollnoise_bench --benchmark_filter=RailWaveguideCurveCost
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <utility>
#include <vector>

#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "fem/mesh.hpp"

using namespace rollnoise;

namespace {

// CPU seconds of this process (the machine is shared: wall time says little).
double cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

// curve_300m's contact points (offset on the rail profile, contact angle) of the four wheels.
const std::vector<std::pair<double, double>> kContacts = {
    {-0.0366, 0.524}, {-0.0024, 0.008}, {-0.0033, 0.011}, {-0.0204, 0.090}};

void RailWaveguideCurveCost(benchmark::State& state) {
  const dynamics::TrackParameters t = dynamics::uic60_ballasted();
  const dynamics::RailWaveguide full(
      fem::mesh_polygon(dynamics::uic60_outline(), 0.03), dynamics::rail_material(t, 0.3),
      dynamics::FootSupport{t.vertical_support, t.lateral_support, t.longitudinal_support,
                            t.sleeper_spacing});
  const dynamics::RailReduction reduction =
      state.range(0) == 0 ? dynamics::RailReduction{} : dynamics::near_field_reduction();
  double t0 = cpu_seconds();
  const dynamics::RailReductionModes modes = full.reduction_modes(reduction);
  const double modes_s = cpu_seconds() - t0;
  std::vector<Eigen::MatrixXd> loads;
  for (const auto& [offset, angle] : kContacts)
    loads.push_back(full.patch_loads(
        dynamics::outline_contact_point(dynamics::uic60_outline(), dynamics::kUic60HeadBottom,
                                        offset, angle),
        0.01, Eigen::Vector2d(-std::sin(angle), std::cos(angle)), dynamics::kUic60HeadBottom));
  const int direct_points = 145;  // 24 per octave over 100 Hz - 5 kHz, both ends
  double basis_s = 0.0, per_frequency_s = 0.0;
  int coordinates = 0;
  for (auto _ : state) {
    t0 = cpu_seconds();
    const dynamics::RailWaveguide r = full.reduced(reduction, loads.front(), modes);
    basis_s = cpu_seconds() - t0;
    t0 = cpu_seconds();
    for (int i = 0; i < direct_points; ++i) {
      const double f = 100.0 * std::pow(50.0, double(i) / (direct_points - 1));
      benchmark::DoNotOptimize(
          r.contact_receptance(r.waves(2.0 * M_PI * f), loads.front(), loads.front(), 0.0));
    }
    per_frequency_s = (cpu_seconds() - t0) / direct_points;
  }
  double err_db = 0.0;
  for (double f : {300.0, 1000.0, 2000.0, 3400.0, 4900.0}) {
    const dynamics::RailWaves wf = full.waves(2.0 * M_PI * f);
    for (const Eigen::MatrixXd& L : loads) {
      const dynamics::RailWaveguide r = full.reduced(reduction, L, modes);
      coordinates = std::max(coordinates, r.coordinates());
      const dynamics::Receptance4 a = full.contact_receptance(wf, L, L, 0.0),
                                  b = r.contact_receptance(r.waves(2.0 * M_PI * f), L, L, 0.0);
      for (int i = 0; i < 4; ++i)
        err_db =
            std::max(err_db, std::abs(20.0 * std::log10(std::abs(b(i, i)) / std::abs(a(i, i)))));
    }
  }
  state.counters["dofs"] = full.dofs();
  state.counters["coordinates"] = coordinates;
  state.counters["modes_s"] = modes_s;
  state.counters["basis_s"] = basis_s;
  state.counters["per_frequency_ms"] = 1e3 * per_frequency_s;
  state.counters["direct_points"] = direct_points;
  state.counters["case_rail_s"] =
      modes_s + kContacts.size() * (basis_s + direct_points * per_frequency_s);
  state.counters["err_dB"] = err_db;
}
BENCHMARK(RailWaveguideCurveCost)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
