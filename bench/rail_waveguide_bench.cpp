// Benchmarks of the waveguide rail (dynamics/rail_waveguide.hpp) on the supported UIC60 section.
//
// RailWaveguideReceptancePerFrequency/h: the full model (n = 3 x nodes coordinates; h = 40 mm: 86
// triangles, 207 nodes, n = 621): the waves of one frequency (the n x n eigenproblem in k^2,
// LAPACK zgeev, and the residue norms) and the 4x4 contact receptance from them.
// RailWaveguideReducedPerFrequency/h: the same on the reduced model (RailReduction's default
// basis; counter `coordinates` = m); counter `setup_s` is the one-off cost of the basis (once per
// track). Multiply the time per frequency by 864 (curve_300m's frequencies) for a curve.
// RailWaveguideMeshConvergence/h: the reduced model's receptance at 5 kHz of a 10 mm load patch
// at the crown (vertical, lateral, longitudinal, spin) and at the 300 m curve's gauge-corner
// contact (normal), as counters in dB re 1 m/N (rad/(N m) for the spin).
//   build/rollnoise_bench --benchmark_filter=RailWaveguide
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <string>

#include "dynamics/beam_rail_model.hpp"
#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "fem/mesh.hpp"
#include "noise/loop.hpp"

using namespace rollnoise;

namespace {

dynamics::RailWaveguide supported_uic60(double h) {
  const dynamics::TrackParameters t = dynamics::uic60_ballasted();
  return dynamics::RailWaveguide(fem::mesh_polygon(dynamics::uic60_outline(), h),
                                 dynamics::RailMaterial{},
                                 dynamics::FootSupport{t.vertical_support, t.lateral_support,
                                                       t.longitudinal_support, t.sleeper_spacing});
}

Eigen::MatrixXd crown_patch(const dynamics::RailWaveguide& rail) {
  return rail.patch_loads(Eigen::Vector2d(0.0, 0.172), 0.01, Eigen::Vector2d(0.0, 1.0),
                          dynamics::kUic60HeadBottom);
}

void RailWaveguideReceptancePerFrequency(benchmark::State& state) {
  const dynamics::RailWaveguide rail = supported_uic60(1e-3 * state.range(0));
  const Eigen::MatrixXd L = crown_patch(rail);
  for (auto _ : state) {
    const dynamics::RailWaves w = rail.waves(2.0 * M_PI * 1000.0);
    benchmark::DoNotOptimize(rail.contact_receptance(w, L, L, 0.0));
  }
  state.counters["dofs"] = rail.dofs();
}
BENCHMARK(RailWaveguideReceptancePerFrequency)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

void RailWaveguideReducedPerFrequency(benchmark::State& state) {
  const dynamics::RailWaveguide full = supported_uic60(1e-3 * state.range(0));
  const Eigen::MatrixXd L = crown_patch(full);
  const auto start = std::chrono::steady_clock::now();
  const dynamics::RailWaveguide rail = full.reduced(dynamics::RailReduction{}, L);
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (auto _ : state) {
    const dynamics::RailWaves w = rail.waves(2.0 * M_PI * 1000.0);
    benchmark::DoNotOptimize(rail.contact_receptance(w, L, L, 0.0));
  }
  state.counters["dofs"] = rail.dofs();
  state.counters["coordinates"] = rail.coordinates();
  state.counters["setup_s"] = setup;
}
BENCHMARK(RailWaveguideReducedPerFrequency)
    ->Arg(40)
    ->Arg(25)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

void RailWaveguideMeshConvergence(benchmark::State& state) {
  const dynamics::RailWaveguide full = supported_uic60(1e-3 * state.range(0));
  const double gamma = 0.52;
  const Eigen::Vector2d normal(-std::sin(gamma), std::cos(gamma));
  const Eigen::MatrixXd L = crown_patch(full);
  const Eigen::MatrixXd G =
      full.patch_loads(Eigen::Vector2d(-0.0335, 0.1665), 0.01, normal, dynamics::kUic60HeadBottom);
  Eigen::MatrixXd both(L.rows(), 8);
  both << L, G;
  const dynamics::RailWaveguide rail = full.reduced(dynamics::RailReduction{}, both);
  dynamics::Receptance4 crown, gauge;
  for (auto _ : state) {
    const dynamics::RailWaves w = rail.waves(2.0 * M_PI * 5000.0);
    crown = rail.contact_receptance(w, L, L, 0.0);
    gauge = rail.contact_receptance(w, G, G, 0.0);
  }
  auto db = [](std::complex<double> z) { return 20.0 * std::log10(std::abs(z)); };
  state.counters["dofs"] = rail.dofs();
  state.counters["coordinates"] = rail.coordinates();
  state.counters["crown_zz_dB"] = db(crown(dynamics::kZ, dynamics::kZ));
  state.counters["crown_yy_dB"] = db(crown(dynamics::kY, dynamics::kY));
  state.counters["crown_xx_dB"] = db(crown(dynamics::kX, dynamics::kX));
  state.counters["crown_spin_dB"] = db(crown(dynamics::kRotZ, dynamics::kRotZ));
  state.counters["gauge_nn_dB"] = db(gauge(dynamics::kZ, dynamics::kZ));
}
BENCHMARK(RailWaveguideMeshConvergence)
    ->Arg(40)
    ->Arg(30)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

// RailWaveguideEccentricContact/f: at f (Hz), the diagonal of the 4x4 rail receptance in the
// 300 m curve's contact frame (gauge corner (-33.5, 166.5) mm, gamma = 0.52 rad), dB re 1 m/N
// (rad/(N m) for the spin): `ecc_*` the waveguide loaded by the 10 mm patch at the contact itself,
// `moved_*` the waveguide's crown receptance moved rigidly to the contact and rotated as the loop
// does (noise::move_point, to_contact_frame), `beam_*` the Timoshenko beam moved the same way.
void RailWaveguideEccentricContact(benchmark::State& state) {
  const double f = static_cast<double>(state.range(0)), gamma = 0.52, offset = -0.0335;
  const dynamics::RailWaveguide full = supported_uic60(0.03);
  const Eigen::MatrixXd L = crown_patch(full);
  const Eigen::MatrixXd G = full.patch_loads(Eigen::Vector2d(offset, 0.1665), 0.01,
                                             Eigen::Vector2d(-std::sin(gamma), std::cos(gamma)),
                                             dynamics::kUic60HeadBottom);
  Eigen::MatrixXd both(L.rows(), 8);
  both << L, G;
  const dynamics::RailWaveguide rail = full.reduced(dynamics::RailReduction{}, both);
  const dynamics::BeamRailModel beam(dynamics::uic60_ballasted(),
                                     dynamics::TrackSupport::kContinuous, 0.0);
  dynamics::Receptance4 ecc, moved, moved_beam;
  auto to_contact = [&](const dynamics::Receptance4& r) {
    return noise::to_contact_frame(
        noise::move_point(noise::embed(r), Eigen::Vector3d(0.0, offset, 0.0)), gamma);
  };
  for (auto _ : state) {
    const dynamics::RailWaves w = rail.waves(2.0 * M_PI * f);
    ecc = rail.contact_receptance(w, G, G, 0.0);
    moved = to_contact(rail.contact_receptance(w, L, L, 0.0));
    moved_beam = to_contact(beam.receptance(f));
  }
  auto db = [](std::complex<double> z) { return 20.0 * std::log10(std::abs(z)); };
  const char* names[4] = {"n", "x", "t", "spin"};
  for (int i = 0; i < 4; ++i) {
    state.counters[std::string("ecc_") + names[i]] = db(ecc(i, i));
    state.counters[std::string("moved_") + names[i]] = db(moved(i, i));
    state.counters[std::string("beam_") + names[i]] = db(moved_beam(i, i));
  }
  state.counters["ecc_nt_dB"] = db(ecc(dynamics::kZ, dynamics::kY));
  state.counters["moved_nt_dB"] = db(moved(dynamics::kZ, dynamics::kY));
}
BENCHMARK(RailWaveguideEccentricContact)
    ->Arg(500)
    ->Arg(2000)
    ->Arg(5000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
