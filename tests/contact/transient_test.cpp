// Transient rolling (paper Eq. 2): convergence to steady rolling, agreement with CONTACT's
// unsteady runs U1 and U2, and the paper's Sec. 3.1 finding that a quasi-steady model fails at 1 kHz.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "contact/creepage_history.hpp"
#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "linalg/harmonic_fit.hpp"
#include "paper_case.hpp"
#include "reference_data.hpp"

using namespace rollnoise::contact;
using rollnoise::testing::data_path;
using rollnoise::testing::num;
using rollnoise::testing::read_csv;
using namespace rollnoise::testing;

TEST(TransientRolling, ConstantCreepageFromZeroTractionsConvergesToSteadyRolling) {
  const ContactPatch& patch = coarse_patch();
  const Creepage c{0.001, 0.001, -0.053};
  const auto steady = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, c, 0.0});
  const TangentialForces fs = total_forces(patch.grid, steady.px, steady.py);
  TransientRolling rolling(patch.influence, patch.normal.pn, kMu, kSpeed, 0.0);
  // zero tractions at the start (a sudden creepage); 2a = 30 dx, so 30 steps roll one contact
  // length. The start transient decays geometrically (measured: a factor ~7 per contact length).
  int converged_at = -1;
  double err = 1.0;
  for (int k = 1; k <= 450; ++k) {
    const auto& s = rolling.step(c);
    const TangentialForces f = total_forces(patch.grid, s.px, s.py);
    err = std::max({std::abs(f.Fx / fs.Fx - 1), std::abs(f.Fy / fs.Fy - 1),
                                 std::abs(f.Mz / fs.Mz - 1)});
    if (k % 30 == 0) std::printf("  after %d contact lengths: relative force error %.2e\n", k / 30, err);
    if (err < 1e-6 && converged_at < 0) converged_at = k;
    if (err >= 1e-6) converged_at = -1;
  }
  std::printf("forces within 1e-6 of steady rolling from step %d (%.1f contact lengths)\n",
              converged_at, converged_at / 30.0);
  ASSERT_GT(converged_at, 0);
  EXPECT_LE(converged_at, 240) << "within eight contact lengths";
  EXPECT_LT(err, 1e-10) << "the steady state is the exact fixed point of the time stepping";
}

namespace {

struct UnsteadyReference {
  std::string run;
  double spin_offset;
};

class AgainstCONTACTUnsteady : public ::testing::TestWithParam<UnsteadyReference> {};

}  // namespace

TEST_P(AgainstCONTACTUnsteady, ForcesAfterTheStartWithinOnePercentOfTheVariation) {
  const auto& ref = GetParam();
  const auto series = read_csv(data_path("contact/" + ref.run + "/timeseries_coarse.csv"));
  std::map<std::string, double> amplitude;
  for (const auto& row : read_csv(data_path("contact/" + ref.run + "/harmonic_fit.csv")))
    if (row.at("grid") == "coarse") amplitude[row.at("quantity")] = num(row, "amp");
  const ContactPatch& patch = coarse_patch();
  // the creepage of each step as CONTACT used it (t_k = k dt)
  const Creepage mean{num(series[0], "cksi"), num(series[0], "ceta"), num(series[0], "cphi_rad_per_m")};
  const auto steady = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, mean, ref.spin_offset});
  TransientRolling rolling(patch.influence, patch.normal.pn, kMu, kSpeed, ref.spin_offset);
  rolling.set_tractions(steady.px, steady.py);
  double sq_x = 0, sq_y = 0;
  int n = 0;
  for (size_t k = 1; k < series.size(); ++k) {
    const auto& row = series[k];
    const auto& s = rolling.step({num(row, "cksi"), num(row, "ceta"), num(row, "cphi_rad_per_m")});
    const TangentialForces f = total_forces(patch.grid, s.px, s.py);
    if (num(row, "t_s") < 2e-3) continue;
    sq_x += std::pow(f.Fx - num(row, "Fx_N"), 2);
    sq_y += std::pow(f.Fy - num(row, "Fy_N"), 2);
    ++n;
  }
  const double rms_x = std::sqrt(sq_x / n), rms_y = std::sqrt(sq_y / n);
  std::printf("%s: RMS difference Fx %.3g N (amplitude %.1f N), Fy %.3g N\n", ref.run.c_str(), rms_x,
              amplitude["Fx_N"], rms_y);
  EXPECT_LT(rms_x, 0.01 * amplitude["Fx_N"]);
  if (amplitude.count("Fy_N")) {
    EXPECT_LT(rms_y, 0.01 * amplitude["Fy_N"]);
  }
}

INSTANTIATE_TEST_SUITE_P(Runs, AgainstCONTACTUnsteady,
                         ::testing::Values(UnsteadyReference{"U1", 1.0 / 6.0}, UnsteadyReference{"U2", 1.0 / 6.0}),
                         [](const auto& info) { return info.param.run; });

TEST(TransientRolling, QuasiSteadyModelMissesAmplitudeAndPhaseAt1kHz) {
  // Paper Sec. 3.1 / Fig. 3: xi_x = 0.001 + 5e-5 cos(2 pi 1000 t). Over the 6th period, compare the
  // transient solution with steady solutions at the instantaneous creepage.
  const ContactPatch& patch = coarse_patch();
  const auto history = CreepageHistory::harmonic({0.001, 0, 0}, {5e-5, 0, 0}, 1000.0);
  const auto steady = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, history.mean(), 0.0});
  TransientRolling rolling(patch.influence, patch.normal.pn, kMu, kSpeed, 0.0);
  rolling.set_tractions(steady.px, steady.py);
  const double dt = rolling.time_step();
  std::vector<double> t, f_transient, f_quasi;
  TangentialSolution quasi = steady;
  for (int k = 1; k * dt <= 6e-3; ++k) {
    const Creepage c = history.at(k * dt);
    const auto& s = rolling.step(c);
    if (k * dt < 5e-3) continue;
    t.push_back(k * dt);
    f_transient.push_back(total_forces(patch.grid, s.px, s.py).Fx);
    quasi = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, c, 0.0}, {}, &quasi);
    f_quasi.push_back(total_forces(patch.grid, quasi.px, quasi.py).Fx);
  }
  const auto a = rollnoise::linalg::fit_harmonic(t, f_transient, 1000.0);
  const auto b = rollnoise::linalg::fit_harmonic(t, f_quasi, 1000.0);
  const double dphase = std::remainder(a.phase - b.phase, 2 * M_PI) * 180 / M_PI;
  std::printf("1 kHz: transient %.1f N at %.1f deg, quasi-steady %.1f N at %.1f deg\n", a.amplitude,
              a.phase * 180 / M_PI, b.amplitude, b.phase * 180 / M_PI);
  EXPECT_GT(std::abs(b.amplitude / a.amplitude - 1), 0.5) << "amplitudes differ markedly";
  EXPECT_GT(std::abs(dphase), 30.0) << "phases differ markedly";
}
