// Transient rolling (paper Eq. 2) under a prescribed normal-load history N(t): the constant load
// takes the old path, the pressure depends on the load alone, full slip follows the load
// quasi-statically (F = mu N direction), and a stepped load leads to the steady state at the new
// load, with elements entering or leaving the contact area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/creepage_history.hpp"
#include "contact/forces.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "core/errors.hpp"
#include "paper_case.hpp"

using namespace rollnoise::contact;
using namespace rollnoise::testing;

namespace {

TransientRolling with_normal_load(const ContactPatch& patch) {
  TransientRolling r(patch.influence, patch.normal.pn, kMu, kSpeed, 0.0);
  r.set_normal_problem(patch.undeformed_distance, kN);
  return r;
}

double max_abs(const GridField& f) {
  double m = 0;
  for (double v : f) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

TEST(TransientNormalLoad, ConstantLoadThroughTheLoadPathIsBitIdenticalToTheOldPath) {
  const ContactPatch& patch = coarse_patch();
  const auto history =
      CreepageHistory::harmonic({0.001, 0.001, -0.053}, {5e-5, 5e-5, 0.0027}, 1000.0);
  const auto steady =
      solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, history.mean(), 0.0});
  TransientRolling old_path(patch.influence, patch.normal.pn, kMu, kSpeed, 0.0);
  TransientRolling new_path = with_normal_load(patch);
  old_path.set_tractions(steady.px, steady.py);
  new_path.set_tractions(steady.px, steady.py);
  const double dt = old_path.time_step();
  for (int k = 1; k <= 60; ++k) {
    const Creepage c = history.at(k * dt);
    const auto& a = old_path.step(c);
    const auto& b = new_path.step(c, kN + history.normal_variation(k * dt));
    ASSERT_EQ(a.px, b.px) << "step " << k;
    ASSERT_EQ(a.py, b.py) << "step " << k;
    ASSERT_EQ(a.state, b.state) << "step " << k;
  }
  EXPECT_EQ(new_path.normal_solves(), 0);
}

TEST(TransientNormalLoad, PressureDependsOnTheLoadAloneAndReturnsToTheMeanPatch) {
  // Quasi-identical bodies: pn_k is the static normal solution at N_k, whatever the loads before.
  const ContactPatch& patch = coarse_patch();
  TransientRolling rolling = with_normal_load(patch);
  const Creepage c{0.001, 0, 0};
  for (double N : {1.1 * kN, 0.95 * kN, 1.02 * kN, kN}) rolling.step(c, N);
  EXPECT_EQ(rolling.normal_solves(), 4);
  double diff = 0;
  for (size_t k = 0; k < patch.normal.pn.size(); ++k)
    diff = std::max(diff, std::abs(rolling.pressure()[k] - patch.normal.pn[k]));
  std::printf("pressure after loads 1.1, 0.95, 1.02, 1 N: max |pn - pn(N)| / max pn = %.2e\n",
              diff / max_abs(patch.normal.pn));
  EXPECT_LT(diff / max_abs(patch.normal.pn), 1e-10);  // the normal solver's tolerance is 1e-12
}

TEST(TransientNormalLoad, SlowLoadVariationInFullSlipKeepsTheSteadyForceToLoadRatio) {
  // xi_x = 0.01 saturates the paper's contact (3 mu N / (C11 G a b) ~ 0.0064): full slip. The load
  // varies by 20 % at 50 Hz, 1/19 of V/(2a) = 967 Hz, over half a period (area +6 %, new elements).
  const ContactPatch& patch = coarse_patch();
  const Creepage c{0.01, 0, 0};
  const auto steady = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, c, 0.0});
  const double ratio = total_forces(patch.grid, steady.px, steady.py).Fx / kN;
  ASSERT_EQ(steady.count(ElementState::adhesion), 0) << "the steady state is in full slip";
  // sin, so that the load starts at its mean without a jump
  const auto history = CreepageHistory::harmonic(c, {0, 0, 0}, 50.0, {}, 0.2 * kN, -M_PI / 2);
  TransientRolling rolling = with_normal_load(patch);
  rolling.set_tractions(steady.px, steady.py);
  const double dt = rolling.time_step();
  double worst = 0, n_peak = 0, ratio_peak = 0;
  int elements_max = 0;
  for (int k = 1; k * dt <= 0.01; ++k) {
    const double N = kN + history.normal_variation(k * dt);
    const auto& s = rolling.step(c, N);
    EXPECT_EQ(s.count(ElementState::adhesion), 0) << "full slip at step " << k;
    const double r = total_forces(patch.grid, s.px, s.py).Fx / N;
    worst = std::max(worst, std::abs(r / ratio - 1));
    if (N > n_peak) n_peak = N, ratio_peak = r;
    elements_max = std::max(elements_max, s.count(ElementState::slip));
  }
  // The steady ratio itself changes slightly with the load (the slip direction turns by the
  // Poisson coupling A_xy, more at larger tractions): compare at the peak load with steady rolling
  // at that load, where the quasi-static transient must agree much more closely.
  const ContactPatch peak = solve_patch(patch.grid, kSteel, patch.undeformed_distance, n_peak);
  const auto steady_peak =
      solve_steady_rolling(peak.influence, peak.normal.pn, {kMu, kSpeed, c, 0.0});
  const double ratio_steady_peak =
      total_forces(peak.grid, steady_peak.px, steady_peak.py).Fx / n_peak;
  std::printf(
      "steady Fx/N = %.6f; 50 Hz load 1 +- 0.2 N: max |Fx(t)/N(t) / (Fx/N) - 1| = %.2e (steady at "
      "%.4f N: %.2e); at that peak Fx/N differs from steady rolling at the peak load by %.2e; up "
      "to %d "
      "elements in contact (%d at N)\n",
      ratio, worst, n_peak / kN, ratio_steady_peak / ratio - 1, ratio_peak / ratio_steady_peak - 1,
      elements_max, patch.normal.contact_elements());
  EXPECT_GT(n_peak, 1.19 * kN);
  EXPECT_GT(elements_max, patch.normal.contact_elements()) << "elements entered the contact";
  EXPECT_LT(worst, 1e-4);  // measured 2.4e-5, the steady ratio's own change from N to 1.2 N
  EXPECT_LT(std::abs(ratio_peak / ratio_steady_peak - 1), 1e-6);  // measured 7.4e-8
}

namespace {

class SteppedLoad : public ::testing::TestWithParam<double> {};

}  // namespace

TEST_P(SteppedLoad, HeldLoadReachesTheSteadyStateAtTheNewLoad) {
  const double N1 = kN * (1 + GetParam());
  const ContactPatch& patch = coarse_patch();
  const ContactPatch patch1 = solve_patch(patch.grid, kSteel, patch.undeformed_distance, N1);
  const Creepage c{0.001, 0.001, -0.053};
  const auto steady0 =
      solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, c, 0.0});
  const auto steady1 =
      solve_steady_rolling(patch1.influence, patch1.normal.pn, {kMu, kSpeed, c, 0.0});
  const TangentialForces fs = total_forces(patch.grid, steady1.px, steady1.py);
  TransientRolling rolling = with_normal_load(patch);
  rolling.set_tractions(steady0.px, steady0.py);
  // the step at k = 1, then held: 2a = 30 dx, so 30 steps roll one contact length
  const auto& first = rolling.step(c, N1);
  const GridField& pn1 = rolling.pressure();
  EXPECT_EQ(std::count_if(pn1.begin(), pn1.end(), [](double p) { return p > 0; }),
            patch1.normal.contact_elements());
  int changed = 0;
  for (size_t k = 0; k < first.px.size(); ++k) {
    const bool in1 = pn1[k] > 0;
    if (in1 != (patch.normal.pn[k] > 0)) ++changed;
    if (!in1) {  // out of contact at the new load: no traction
      EXPECT_EQ(first.px[k], 0.0);
      EXPECT_EQ(first.py[k], 0.0);
      EXPECT_EQ(first.state[k], static_cast<std::int8_t>(ElementState::exterior));
    } else {
      EXPECT_LE(std::hypot(first.px[k], first.py[k]), kMu * pn1[k] * (1 + 1e-12));
    }
  }
  double err = 1;
  for (int k = 2; k <= 300; ++k) {
    const auto& s = rolling.step(c, N1);
    const TangentialForces f = total_forces(patch.grid, s.px, s.py);
    err = std::max(
        {std::abs(f.Fx / fs.Fx - 1), std::abs(f.Fy / fs.Fy - 1), std::abs(f.Mz / fs.Mz - 1)});
  }
  std::printf(
      "load stepped by %+.0f %%: %d elements entered or left; after 10 contact lengths the "
      "forces are within %.2e of steady rolling at the new load\n",
      100 * GetParam(), changed, err);
  EXPECT_GT(changed, 0);
  EXPECT_LT(err, 1e-6);
  EXPECT_EQ(rolling.normal_solves(), 1);
}

INSTANTIATE_TEST_SUITE_P(Loads, SteppedLoad, ::testing::Values(0.2, -0.2),
                         [](const auto& info) { return info.param > 0 ? "Up20" : "Down20"; });

TEST(TransientNormalLoad, NonPositiveLoadIsAnInputErrorNamingTheKey) {
  const ContactPatch& patch = coarse_patch();
  TransientRolling rolling = with_normal_load(patch);
  for (double N : {0.0, -kN, std::nan("")}) {
    try {
      rolling.step({0.001, 0, 0}, N);
      ADD_FAILURE() << "no error for N = " << N;
    } catch (const rollnoise::InputError& e) {
      EXPECT_EQ(e.key(), "excitation.normal_amplitude");
    }
  }
  TransientRolling without(patch.influence, patch.normal.pn, kMu, kSpeed, 0.0);
  EXPECT_THROW(without.step({0.001, 0, 0}, 1.1 * kN), std::logic_error)
      << "needs set_normal_problem";
}
