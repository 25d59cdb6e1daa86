// The normal-load input of the linear NSS model (docs/nss_normal_load.md, Eqs. G1-G3):
// F~ = -f xi~ + g N~. Its limits (w -> 0 against finite differences of the steady solver at fixed
// creepage and geometry, full sliding g = F/N, full adhesion g = 0), the agreement of the fast
// sweep with the direct solve of the paper's form, and the time recursion against g.
#include <gtest/gtest.h>

#include <cmath>

#include "../contact/paper_case.hpp"
#include "contact/forces.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "nss/linear_model.hpp"

using namespace rollnoise;
using namespace rollnoise::contact;
using namespace rollnoise::testing;

namespace {

// The paper's Hertzian geometry (fixed undeformed distance h) under the load N.
ContactPatch patch_at_load(double N) {
  const ContactPatch& p = paper_patch("coarse");
  return solve_patch(p.grid, kSteel, p.undeformed_distance, N);
}

Eigen::Vector3d forces(const ContactPatch& p, const TangentialSolution& s) {
  const auto F = total_forces(p.grid, s.px, s.py);
  return {F.Fx, F.Fy, F.Mz};
}

struct MeanState {
  const ContactPatch* patch;
  TangentialSolution steady;
};

MeanState steady_at(const ContactPatch& p, const Creepage& c) {
  return {&p, solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, c, 0.0})};
}

}  // namespace

TEST(NormalLoad, ZeroFrequencyEqualsTheLoadDerivativeOfTheSteadySolverAtFixedCreepageAndGeometry) {
  // Central differences in N with the undeformed distance held: the steady solver's dF/dN at fixed
  // creepage. With a step too small to change the contact area or the adhesion/slip areas the
  // frozen-area derivative (G2 at z = 1) is the exact derivative of the discrete problem.
  for (const Creepage c : {Creepage{0.001, 0.001, -0.053}, Creepage{0.002, 0.0, 0.0}, Creepage{0.0, 0.0015, 0.3}}) {
    const ContactPatch& p = paper_patch("coarse");
    const auto mean = steady_at(p, c);
    const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
    const Eigen::Vector3cd g0 = model.normal_load_coefficients_direct(0.0);
    const double h = 1e-6 * kN;
    const ContactPatch pp = patch_at_load(kN + h), pm = patch_at_load(kN - h);
    ASSERT_EQ(pp.normal.contact_elements(), p.normal.contact_elements());
    ASSERT_EQ(pm.normal.contact_elements(), p.normal.contact_elements());
    const auto sp = steady_at(pp, c), sm = steady_at(pm, c);
    ASSERT_EQ(sp.steady.state, mean.steady.state);
    ASSERT_EQ(sm.steady.state, mean.steady.state);
    const Eigen::Vector3d fd = (forces(pp, sp.steady) - forces(pm, sm.steady)) / (2 * h);
    std::printf("xi = (%g, %g, %g): g(0) = (%.6g, %.6g, %.6g m), finite difference (%.6g, %.6g, %.6g m)\n",
                c.xi_x, c.xi_y, c.phi, g0(0).real(), g0(1).real(), g0(2).real(), fd(0), fd(1), fd(2));
    EXPECT_LT(g0.imag().norm(), 1e-10 * g0.norm());
    const double scale = std::abs(fd(0)) + std::abs(fd(1)) + 0.01 * std::abs(fd(2));  // Mz ~ 1 cm x F
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(g0(j).real(), fd(j), 1e-5 * scale * (j == 2 ? 0.01 : 1.0) + 2e-4 * std::abs(fd(j))) << j;
  }
}

TEST(NormalLoad, FullSlidingWithoutSpinGivesTheForceToLoadRatio) {
  // All elements slip, nearly in the direction of the rigid slip: the traction is mu pn along -s,
  // so F/N does not depend on the load and g(0) = F/N. What remains is the elastic part of the
  // slip, V (A - A0) p / dx, which grows with the load and turns the slip direction slightly: for
  // a single creepage component it only shortens |s| (g = F/N to 1e-4), for combined creepages
  // it turns the force by a fraction of a degree (the finite-difference test above confirms that
  // this turn is real), so there only |g| = mu is asserted.
  const ContactPatch& p = paper_patch("coarse");
  for (const Creepage c : {Creepage{0.01, 0.0, 0.0}, Creepage{0.0, 0.01, 0.0}, Creepage{0.006, 0.008, 0.0}}) {
    const auto mean = steady_at(p, c);
    const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
    ASSERT_EQ(model.adhesion_elements(), 0);
    const Eigen::Vector3d ratio = forces(p, mean.steady) / kN;
    const Eigen::Vector3cd g0 = model.normal_load_coefficients(std::vector<double>{0.0})[0];
    std::printf("xi = (%g, %g): F/N = (%.6f, %.6f), g(0) = (%.6f, %.6f)\n", c.xi_x, c.xi_y, ratio(0), ratio(1),
                g0(0).real(), g0(1).real());
    EXPECT_NEAR(std::hypot(g0(0).real(), g0(1).real()), kMu, 1e-3 * kMu);
    if (c.xi_x == 0.0 || c.xi_y == 0.0) {
      EXPECT_NEAR(g0(0).real(), ratio(0), 5e-4 * kMu);
      EXPECT_NEAR(g0(1).real(), ratio(1), 5e-4 * kMu);
    }
  }
}

TEST(NormalLoad, FullAdhesionHasNoNormalLoadCouplingAndItVanishesWithTheCreepage) {
  const ContactPatch& p = paper_patch("coarse");
  double previous = kMu;
  for (double xi : {1e-3, 3e-4, 1e-4, 1e-9}) {
    const auto mean = steady_at(p, {xi, 0.0, 0.0});
    const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
    const double g0 = model.normal_load_coefficients_direct(0.0).norm();
    std::printf("xi_x = %g: %d slip elements, |g(0)| = %.3g\n", xi, model.slip_elements(), g0);
    EXPECT_LT(g0, previous);
    previous = g0;
    if (model.slip_elements() == 0) {
      EXPECT_FALSE(model.has_normal_load_input());
      EXPECT_EQ(g0, 0.0);
      EXPECT_EQ(model.normal_load_coefficients(std::vector<double>{0.0, 1000.0})[1].norm(), 0.0);
    }
  }
  EXPECT_EQ(previous, 0.0);  // 1e-9: full adhesion
}

TEST(NormalLoad, FastSweepEqualsTheDirectSolveFromZeroToNyquist) {
  // The Krylov sweep (block of 4, G3) against a complex LU of the paper's form (G2) per frequency,
  // for partial slip with spin, nearly full sliding with large spin, full sliding and few slip
  // elements; the Hessenberg fallback against both for the first state.
  const ContactPatch& p = paper_patch("coarse");
  bool first = true;
  for (const Creepage c : {Creepage{0.001, 0.001, -0.053}, Creepage{0.0, 0.002, 0.5}, Creepage{0.006, 0.0, 0.0},
                           Creepage{2e-4, 0.0, 0.0}}) {
    const auto mean = steady_at(p, c);
    const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
    std::vector<double> freq;
    for (int k = 0; k <= 6; ++k) freq.push_back(model.nyquist_frequency() * k / 6.0);
    const auto g = model.normal_load_coefficients(freq);
    double worst = 0.0;
    for (size_t k = 0; k < freq.size(); ++k) {
      const Eigen::Vector3cd gd = model.normal_load_coefficients_direct(freq[k]);
      worst = std::max(worst, (g[k] - gd).norm() / gd.norm());
    }
    std::printf("xi = (%g, %g, %g): %d slip, %d block steps, max |g - g_direct|/|g| = %.2e\n", c.xi_x, c.xi_y,
                c.phi, model.slip_elements(), model.sweep_info().block_steps, worst);
    EXPECT_LT(worst, 1e-9);
    if (first) {  // no Markov sequence decays within 0 contact lengths: the Hessenberg form
      const nss::LinearContactModel m2(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
      const auto gh = m2.normal_load_coefficients(freq, 0);
      EXPECT_EQ(m2.sweep_info().method, nss::SweepInfo::Method::hessenberg);
      for (size_t k = 0; k < freq.size(); ++k) EXPECT_LT((gh[k] - g[k]).norm(), 1e-9 * g[k].norm()) << k;
      first = false;
    }
  }
}

TEST(NormalLoad, RecursionWithALoadHistoryAgreesWithHarmonicSynthesisOfG) {
  const ContactPatch& p = paper_patch("coarse");
  const auto mean = steady_at(p, {0.001, 0.001, -0.053});
  const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
  const double dt = model.time_step();
  const std::vector<double> freq = {300.0, 1700.0};
  const std::vector<double> amp = {400.0, 150.0}, phase = {0.3, -1.1};
  const auto g = model.normal_load_coefficients(freq);
  std::vector<Eigen::Vector3d> xi;
  std::vector<double> dN;
  for (int k = 0; k < 900; ++k) {
    xi.push_back(Eigen::Vector3d::Zero());
    double v = 0.0;
    for (int n = 0; n < 2; ++n) v += amp[n] * std::cos(2 * M_PI * freq[n] * k * dt + phase[n]);
    dN.push_back(v);
  }
  const auto F = model.time_response(xi, dN);
  double err = 0, ref = 0;
  for (int k = 600; k < 900; ++k) {  // after 20 contact lengths the start has decayed
    Eigen::Vector3d syn = Eigen::Vector3d::Zero();
    for (int n = 0; n < 2; ++n)
      syn += (g[n] * amp[n] * std::polar(1.0, 2 * M_PI * freq[n] * k * dt + phase[n])).real();
    err = std::max(err, (F[k] - syn).norm());
    ref = std::max(ref, syn.norm());
  }
  std::printf("recursion vs synthesis: max error %.2e of %.4g N\n", err, ref);
  EXPECT_LT(err, 1e-8 * ref);
}

#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"

TEST(NormalLoad, ProfileContactZeroFrequencyAgreesWithFiniteLoadStepsWithinTheFrozenAreaEffect) {
  // S1002 on UIC60, wheelset displaced 4 mm towards the flange (a non-Hertzian patch). The steady
  // solver at N(1 +- e) on the same grid and undeformed distance (the geometry held): for e = 1e-6
  // the area does not change and g(0) is the exact derivative; for e = 1 % elements enter and leave
  // the contact area, which the frozen-area model ignores: the difference shows its size.
  const std::string dir = std::string(ROLLNOISE_SOURCE_DIR) + "/models/profiles/";
  const geometry::WheelRailPair pair(io::read_profile(dir + "MBench_S1002_v3.prw"),
                                     io::read_profile(dir + "MBench_UIC60_v3.prr"));
  const geometry::ContactGeometry cg = geometry::find_contact(pair, {0.004, 0.0});
  geometry::GridOptions opt;
  opt.nx = 30;
  const ContactPatch p = geometry::solve_wheel_rail_patch(pair, cg, kN, kSteel, opt);
  const Creepage c{0.001, -0.002, -0.3};
  const auto mean = steady_at(p, c);
  const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
  const Eigen::Vector3d g0 = model.normal_load_coefficients_direct(0.0).real();
  for (double e : {1e-6, 1e-2}) {
    const ContactPatch pp = solve_patch(p.grid, kSteel, p.undeformed_distance, kN * (1 + e));
    const ContactPatch pm = solve_patch(p.grid, kSteel, p.undeformed_distance, kN * (1 - e));
    const Eigen::Vector3d fd = (forces(pp, steady_at(pp, c).steady) - forces(pm, steady_at(pm, c).steady)) / (2 * e * kN);
    const double rel = (g0 - fd).head<2>().norm() / fd.head<2>().norm();
    std::printf("profile patch (%d elements, %d slip), step %g: g(0) = (%.6g, %.6g, %.4g m), finite difference "
                "(%.6g, %.6g, %.4g m), |dF| %.2e; contact elements %d -> %d / %d\n",
                p.normal.contact_elements(), model.slip_elements(), e, g0(0), g0(1), g0(2), fd(0), fd(1), fd(2), rel,
                pm.normal.contact_elements(), pp.normal.contact_elements(), p.normal.contact_elements());
    EXPECT_LT(rel, e < 1e-3 ? 1e-5 : 0.02);
  }
}

#include "contact/transient_rolling.hpp"
#include "linalg/harmonic_fit.hpp"

namespace {

// Amplitude and phase of Fx and Fy of the unsteady solver (normal problem re-solved per step)
// under N = N_bar (1 + e cos(2 pi f t)), fitted over the last `periods` periods after 10 contact
// lengths, against the linear model's g(f) N_bar e.
struct LoadResponseError {
  double amplitude[2], phase_deg[2];
};
LoadResponseError load_response_error(const Creepage& c, double e, double f) {
  const ContactPatch& p = paper_patch("coarse");
  const auto mean = steady_at(p, c);
  const nss::LinearContactModel model(p, mean.steady, {kMu, kSpeed, 0.0, CreepageSampling::contact});
  const Eigen::Vector3cd g = model.normal_load_coefficients(std::vector<double>{f})[0] * (e * kN);
  TransientRolling rolling(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  rolling.set_normal_problem(p.undeformed_distance, kN);
  rolling.set_tractions(mean.steady.px, mean.steady.py);
  const double dt = rolling.time_step(), t0 = 300 * dt;  // 10 contact lengths
  const double t1 = t0 + std::max(2.0, std::ceil(6e-3 * f)) / f;  // >= 2 periods, ~6 ms
  std::vector<double> t, F[2];
  for (int k = 1; k * dt <= t1 + 1e-12; ++k) {
    const auto& s = rolling.step(c, kN * (1 + e * std::cos(2 * M_PI * f * k * dt)));
    if (k * dt < t0) continue;
    const auto tf = total_forces(p.grid, s.px, s.py);
    t.push_back(k * dt);
    F[0].push_back(tf.Fx);
    F[1].push_back(tf.Fy);
  }
  LoadResponseError r{};
  for (int j = 0; j < 2; ++j) {
    const auto fit = linalg::fit_harmonic(t, F[j], f);
    r.amplitude[j] = std::abs(g(j)) / fit.amplitude - 1.0;
    r.phase_deg[j] = std::remainder(std::arg(g(j)) - fit.phase, 2 * M_PI) * 180 / M_PI;
  }
  return r;
}

}  // namespace

TEST(NormalLoad, LinearModelAgreesWithTheUnsteadySolverUnderAHarmonicLoad) {
  // Paper patch, coarse grid. Full sliding (xi_x = 0.006): F = -mu N s^ whatever the contact area,
  // so a 1 % load variation is linear. Partial slip (the paper's Sec. 3.2 mean state): elements at
  // the edge of the area enter and leave contact, a discrete jump that the frozen-area model does
  // not follow; the steady solver itself gives a dF/dN over +-1 % that differs from g(0) by 8.7 %
  // (5.4 % on 68 x 50), so there the linear regime is a 0.01 % load variation, and the 1 % run is
  // reported and held to the size of that jump.
  struct Case {
    Creepage c;
    double e, tol_amplitude, tol_phase;
  };
  const Case cases[] = {{{0.006, 0.0, 0.0}, 1e-2, 0.01, 1.0},
                        {{0.001, 0.001, -0.053}, 1e-4, 0.01, 1.0},
                        {{0.001, 0.001, -0.053}, 1e-2, 0.10, 2.5}};
  for (const Case& k : cases)
    for (double f : {200.0, 1000.0, 3000.0}) {
      const LoadResponseError r = load_response_error(k.c, k.e, f);
      const int components = k.c.xi_y == 0.0 ? 1 : 2;  // Fy vanishes in pure longitudinal sliding
      std::printf("xi = (%g, %g, %g), dN/N = %g, %4.0f Hz: amplitude error Fx %+.3f %%, Fy %+.3f %%; phase error "
                  "Fx %+.3f deg, Fy %+.3f deg\n",
                  k.c.xi_x, k.c.xi_y, k.c.phi, k.e, f, 100 * r.amplitude[0], 100 * r.amplitude[1], r.phase_deg[0],
                  r.phase_deg[1]);
      for (int j = 0; j < components; ++j) {
        EXPECT_LT(std::abs(r.amplitude[j]), k.tol_amplitude) << f << " Hz, component " << j;
        EXPECT_LT(std::abs(r.phase_deg[j]), k.tol_phase) << f << " Hz, component " << j;
      }
    }
}
