// Observed orders of convergence of the linear model and the unsteady solver under grid
// refinement (pipeline/grid_study.hpp, as `rollnoise bench` measures them), on the paper's Hertzian case
// (a = 7.18 mm, b = 5.29 mm, N = 98.1 kN, V = 50 km/h, mean creepages of Sec. 3.2) on coarse grids
// nx = 10, 14, 20, 28, 40 (the last the reference; about 2 s).
//
// Why these orders. The contact elements are piecewise constant and the grid moves one element
// per time step, dt = dx/V, so space and time are refined together. The displacement difference
// (A p_k - A0 p_{k-1})/dt of paper Eq. 2 is a one-step difference centred at t_k - dt/2 while the
// creepage is taken at t_k: the discrete response leads the converged one by half a step, a phase
// error w dt/2 = pi f dx/V, FIRST order in dx (pipeline::half_step_phase_correction). At 1 kHz it
// dominates the errors of f_jk and of the transient response (10.9 deg on 20x15), so both converge
// at first order. Once that lead is removed, what is left of the one-step difference is the
// truncation error of a difference centred at t_k - dt/2, O((w dt)^2): SECOND order. At 5 kHz
// (w dt = 2 pi f dx/V from 2.9 on 14x10 to 1.3 on 28x21) the time discretisation dominates the
// error, so the phase-corrected f11/f22 converge at about second order there (2.6 measured here);
// at 1 kHz that remainder is small and mixed with the irregular spatial error (not asserted). The
// intervals allow for the higher-order terms still visible on grids this coarse (the fit uses the
// grids 10..28 against 40x29).
// (The steady forces are not asserted: the set of elements in contact changes irregularly with dx
// and their errors scatter about any power law by a factor ~1.4.)
#include <gtest/gtest.h>

#include <vector>

#include "linalg/convergence.hpp"
#include "pipeline/grid_study.hpp"

using namespace rollnoise;

namespace {

struct Study {
  std::vector<pipeline::GridMeasurement> grids;
  pipeline::GridStudyErrors errors;
};

const Study& paper_study() {
  static const Study s = [] {
    pipeline::GridStudyCase c;
    c.material = {210e9, 0.28};
    c.normal_force = 98100;
    c.a = 7.18e-3, c.b = 5.29e-3;
    c.scale = 34.0 / 30.0;
    c.steady = {0.3, 13.8888888888889, {0.001, 0.001, -0.053}, 0.0};
    c.sampling = contact::CreepageSampling::contact;  // the transient runs and f of the assertions below
    const pipeline::GridStudySettings settings;
    const auto e = pipeline::grid_study_excitation(c, settings);
    Study st;
    for (int nx : {10, 14, 20, 28, 40}) st.grids.push_back(pipeline::measure_grid(c, settings, e, nx));
    // C11's table value does not enter the errors asserted here
    st.errors = pipeline::grid_study_errors(st.grids, settings, c.steady.speed, 1.0, c.sampling);
    return st;
  }();
  return s;
}

}  // namespace

TEST(GridStudy, CreepCoefficientsAt1kHzConvergeAtFirstOrder) {
  const auto& err = paper_study().errors;  // frequencies 100 Hz, 1 kHz, 5 kHz
  const auto o = linalg::observed_order(err.dx, err.f[1]);
  EXPECT_EQ(o.points, 4);
  EXPECT_GE(o.p, 0.8);
  EXPECT_LE(o.p, 1.3);
  EXPECT_LT(o.scatter, 1.1);  // a clean power law
}

TEST(GridStudy, TransientResponseAt1kHzConvergesAtFirstOrder) {
  const auto& err = paper_study().errors;
  const auto o = linalg::observed_order(err.dx, err.transient);
  EXPECT_EQ(o.points, 4);
  EXPECT_GE(o.p, 0.8);
  EXPECT_LE(o.p, 1.3);
  EXPECT_LT(o.scatter, 1.1);
}

TEST(GridStudy, PhaseCorrectedCreepCoefficientsAt5kHzConvergeAtSecondOrder) {
  const auto& err = paper_study().errors;
  const auto raw = linalg::observed_order(err.dx, err.f[2]);
  const auto corrected = linalg::observed_order(err.dx, err.f_direct_corrected[2]);
  EXPECT_GE(corrected.points, 3);  // the coarsest grids do not resolve 5 kHz (Nyquist V/(2 dx))
  EXPECT_GE(corrected.p, 1.7);
  EXPECT_LE(corrected.p, 2.8);
  // the half-step lead is what holds the raw coefficients to first order
  EXPECT_LT(raw.p, 1.5);
}

TEST(GridStudy, TransientAgreesWithLinearModelOnEveryGrid) {
  // the consistency check of the bench: the unsteady run and -f(w) xi^ on the same grid agree to
  // well below 0.1 % (the start transient has decayed, window_error), whatever the grid's own error
  const auto& err = paper_study().errors;
  for (size_t i = 0; i < err.transient_vs_linear.size(); ++i) EXPECT_LT(err.transient_vs_linear[i], 1e-3) << i;
  EXPECT_LT(err.window_error, 1e-4);
}

namespace {

// Largest relative error of f11, f22 (and f23) of one sampling's sweeps against the finest grid, at
// the accuracy frequency i (1 kHz: 0, 5 kHz: 1).
std::vector<double> sampling_errors(const std::vector<pipeline::GridMeasurement>& grids, int sampling, size_t i,
                                    bool with_f23) {
  const auto& ref = grids.back().sampling[sampling].f[i];
  std::vector<double> e;
  for (const auto& g : grids) {
    const auto& f = g.sampling[sampling].f[i];
    double worst = std::nan("");
    for (auto [j, k] : {std::pair{0, 0}, {1, 1}, {1, 2}}) {
      if (!with_f23 && j == 1 && k == 2) continue;
      const double d = std::abs(f(j, k) - ref(j, k)) / std::abs(ref(j, k));
      if (std::isfinite(d)) worst = std::isfinite(worst) ? std::max(worst, d) : d;
    }
    e.push_back(worst);
  }
  return e;
}

}  // namespace

TEST(GridStudy, MidstepCreepCoefficientsAt1kHzConvergeAtSecondOrder) {
  // rolling.creepage_sampling = "midstep": the creepage at t_k - dt/2, where the one-step
  // difference is centred, so the half-step lead that holds CONTACT's sampling to first order is
  // gone and what is left is the O((w dt)^2) truncation: second order (the same grids and reference
  // as above; [0] contact, [1] midstep of GridMeasurement::sampling).
  const Study& st = paper_study();
  const auto mid = sampling_errors(st.grids, 1, 0, false), con = sampling_errors(st.grids, 0, 0, false);
  const auto om = linalg::observed_order(st.errors.dx, mid), oc = linalg::observed_order(st.errors.dx, con);
  for (size_t g = 0; g < mid.size(); ++g)
    std::printf("nx %d: f11/f22 at 1 kHz against %dx%d: contact %.2e, midstep %.2e\n", st.grids[g].nx,
                st.grids.back().nx, st.grids.back().ny, con[g], mid[g]);
  std::printf("observed order at 1 kHz: contact %.2f (scatter %.2f), midstep %.2f (scatter %.2f)\n", oc.p, oc.scatter,
              om.p, om.scatter);
  EXPECT_EQ(om.points, 4);
  EXPECT_GE(om.p, 1.7);
  EXPECT_LE(om.p, 2.8);
  // the contact sampling's sweeps are those asserted at first order above
  EXPECT_LT(oc.p, 1.3);
  for (size_t g = 0; g + 1 < mid.size(); ++g) EXPECT_LT(mid[g], con[g]) << st.grids[g].nx;
}

TEST(GridStudy, AverageSamplingLeavesOnlyTheSpatialErrorAt1And5kHz) {
  // rolling.creepage_sampling = "average": the step mean of the creepage, f_average = f_midstep
  // sinc(w dt/2) ([2] of GridMeasurement::sampling). At 5 kHz the midstep error is almost all the
  // factor 1/sinc(w dt/2) - 1 ~ (w dt)^2/24 of the one-step difference (7 % on 28 x 21) and
  // converges at second order (asserted above); the step mean cancels it, and what is left is the
  // spatial error of the piecewise-constant elements, which is not a power law on grids this coarse
  // (the elements in contact change irregularly with dx: 1 kHz gives no order at all, 5 kHz 0.6 with
  // the 40 x 29 reference). So asserted: on every grid, at 1 and 5 kHz, the average error of f11/f22
  // is at most that of the quasi-static coefficients (100 Hz, phase-corrected: midstep there, where
  // the time error (w dt)^2 is below 1e-3) -- no time error is left above the spatial one -- and
  // at 5 kHz below a third of the midstep error; its observed order at 5 kHz is no longer the
  // time error's second order (below 1.5).
  const Study& st = paper_study();
  const auto& spatial = st.errors.f_direct_corrected[0];  // 100 Hz
  for (size_t i : {size_t{0}, size_t{1}}) {                 // 1 kHz, 5 kHz
    const auto avg = sampling_errors(st.grids, 2, i, false), mid = sampling_errors(st.grids, 1, i, false);
    const auto oa = linalg::observed_order(st.errors.dx, avg), om = linalg::observed_order(st.errors.dx, mid);
    for (size_t g = 0; g + 1 < avg.size(); ++g) {
      std::printf("nx %d: f11/f22 at %s against %dx%d: midstep %.2e, average %.2e (100 Hz: %.2e)\n", st.grids[g].nx,
                  i == 0 ? "1 kHz" : "5 kHz", st.grids.back().nx, st.grids.back().ny, mid[g], avg[g], spatial[g]);
      if (!std::isfinite(avg[g])) continue;  // 5 kHz above the coarsest grid's Nyquist limit
      EXPECT_LE(avg[g], spatial[g]) << st.grids[g].nx << (i == 0 ? " 1 kHz" : " 5 kHz");
      if (i == 1) {
        EXPECT_LT(avg[g], mid[g] / 3) << st.grids[g].nx;
      }
    }
    std::printf("observed order: midstep %.2f (scatter %.2f, %d points), average %.2f (scatter %.2f, %d points)\n",
                om.p, om.scatter, om.points, oa.p, oa.scatter, oa.points);
    if (i == 1) {
      EXPECT_EQ(oa.points, 3);
      EXPECT_LT(oa.p, 1.5);
    }
  }
}
