// The wear transfer of the linearised contact (nss/wear_transfer.hpp, docs/corrugation.md): its
// limits against what is known without it.
//  - pure rolling (no creepage, no spin): no element slips, so neither term of (W1) exists and the
//    first-order wear is zero, exactly, although the tractions vary;
//  - the Hertzian limit in full sliding along x: the wear per passage is the passage average (W3)
//    of mu pn |s|, i.e. the Fourier transform of the Hertzian line load q(x) = (3N / 4a)(1 -
//    x^2/a^2) (the lateral integral of Hertz's elliptical pressure, Johnson 1985, Contact
//    Mechanics, Ch. 4), whose zeros lie at tan(ka) = ka (lambda = 1.398 a, 0.813 a, ...): the
//    patch's filtering of wavelengths near and below its length (Hempelmann & Knothe 1996, Wear
//    191; Grassie & Kalousek 1993, Proc. IMechE F 207);
//  - time domain: the unsteady solver over a small harmonic creepage gives the same harmonic of the
//    wear along the rail (2 %, 2 degrees), in partial and in full slip;
//  - time domain through a rail roughness with a wheel mass: the unsteady solver with the exact
//    normal problem at every step gives the contact force and the wear of the command's linear
//    chain (W6, the loop, W5 with the roughness's own pressure W8) within 2 % and 2 degrees;
//  - the rail roughness filter (W6) of a Hertzian patch: the flat-punch average sin(ka)/(ka);
//  - energy: at w -> 0 the frictional power variation of the whole patch equals the derivative of
//    the steady solver's sum of -p . s dx dy (central differences in creepage and load).
#include "nss/wear_transfer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "../contact/paper_case.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/roughness_rolling.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "core/constants.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/loop.hpp"
#include "pipeline/corrugation.hpp"

using namespace rollnoise;
using namespace rollnoise::contact;
using namespace rollnoise::testing;

namespace {

// sum of -p . s dx dy: the frictional power of a steady solution (W)
double frictional_power(const ContactPatch& p, const TangentialSolution& s) {
  double D = 0.0;
  for (int k = 0; k < p.grid.size(); ++k) D -= s.px[k] * s.sx[k] + s.py[k] * s.sy[k];
  return D * p.grid.element_area();
}

TangentialSolution steady_solution(const ContactPatch& p, const Creepage& c) {
  return solve_steady_rolling(p.influence, p.normal.pn, {kMu, kSpeed, c, 0.0});
}

// The paper's Hertzian geometry under the load N (the undeformed distance held).
ContactPatch paper_patch_at(double N) {
  const ContactPatch& p = paper_patch("coarse");
  return solve_patch(p.grid, kSteel, p.undeformed_distance, N);
}

// Fourier transform of (3 / 4a)(1 - x^2/a^2) on |x| < a at u = k a, normalised to 1 at u = 0.
double hertz_line_load_transform(double u) {
  if (std::abs(u) < 1e-6) return 1.0;
  return 3.0 * (std::sin(u) - u * std::cos(u)) / (u * u * u);
}

}  // namespace

TEST(WearTransfer, PureRollingWithoutSpinHasNoSteadySlipTermAndWearsNothing) {
  const ContactPatch& p = paper_patch("coarse");
  const TangentialSolution s = steady_solution(p, {0.0, 0.0, 0.0});
  const nss::LinearContactModel model(p, s, {kMu, kSpeed, 0.0});
  ASSERT_EQ(model.slip_elements(), 0);
  // the tractions do vary (the contact is a spring), but nothing slips
  double traction = 0.0, steady_slip_term = 0.0;
  model.element_impulse_response([&](int, const Eigen::MatrixXd& P, const Eigen::MatrixXd&) {
    traction = std::max(traction, P.cwiseAbs().maxCoeff());
    for (std::size_t a = 0; a < model.elements().size(); ++a) {
      const int k = model.elements()[a];
      steady_slip_term += std::abs(s.sx[k] * P(2 * a, 0)) + std::abs(s.sy[k] * P(2 * a + 1, 1));
    }
  });
  EXPECT_GT(traction, 1e6);
  EXPECT_EQ(steady_slip_term, 0.0);
  const nss::WearTransfer T(model, s, kSpeed, kMu, {});
  for (const nss::WearRow& t : T.depth({0.0, 100.0, 1000.0, 3000.0})) EXPECT_EQ(t.norm(), 0.0);
}

TEST(WearTransfer, HertzianFullSlidingFollowsTheTransformOfTheHertzianLineLoadWithin1Percent) {
  // nu = 0 (no coupling of x and y: the slip stays along x), xi_x = 0.02 beyond saturation (full
  // sliding), contact sampling (no half-step delay): a creepage variation changes |s| by V xi~
  // everywhere and at once, so D~ = mu pn V xi~ and (W3) is the transform of the line load.
  const Material steel0{210e9, 0.0};
  const double a = 7.18e-3, b = 5.29e-3;
  const Grid g = Grid::around_ellipse(68, 50, a, b, 34.0 / 30.0);
  const HertzContact h = hertz_from_semi_axes(a, b, kN, steel0);
  const ContactPatch p = solve_patch(g, steel0, quadratic_distance(g, h.A, h.B), kN);
  const TangentialSolution s = steady_solution(p, {0.02, 0.0, 0.0});
  const nss::LinearContactModel model(p, s, {kMu, kSpeed, 0.0, CreepageSampling::contact});
  ASSERT_EQ(model.adhesion_elements(), 0);
  const nss::WearLaw law;
  const nss::WearTransfer T(model, s, kSpeed, kMu, law);
  // T(0): the uniform depth K mu N / w_b per unit xi_x
  const double t0 = law.coefficient * kMu * p.normal.force / T.band_width();
  std::vector<double> u, f;
  for (double x = 0.25; x <= 9.0; x += 0.25)
    u.push_back(x), f.push_back(x / a * kSpeed / (2 * kPi));
  const auto t = T.depth(f);
  EXPECT_NEAR(T.depth({0.0})[0](0).real(), t0, 1e-6 * t0);
  double worst = 0.0, worst_phase = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double ref = hertz_line_load_transform(u[i]);
    const std::complex<double> x = t[i](0) / t0;
    worst = std::max(worst, std::abs(x - ref));
    if (std::abs(ref) > 0.05)  // the phase: 0 or 180 degrees with the sign of the transform
      worst_phase =
          std::max(worst_phase, std::abs(std::arg(x * (ref > 0 ? 1.0 : -1.0))) * 180 / kPi);
    std::printf("ka = %5.2f  lambda/a = %6.3f  T/T(0) = %+.4f %+.4fi  Hertz line load %+.4f\n",
                u[i], 2 * kPi / u[i], x.real(), x.imag(), ref);
  }
  std::printf("largest difference %.2e of T(0), phase %.2f deg\n", worst, worst_phase);
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(worst_phase, 1.0);
}

TEST(WearTransfer, FrictionalPowerAtZeroFrequencyIsTheSteadySolversDerivativeWithin1e4) {
  // Central differences with steps small enough to keep the adhesion and slip areas: the frozen
  // areas of the linear model are then the exact linearisation of the discrete problem.
  const ContactPatch& p = paper_patch("coarse");
  const Creepage c{0.001, 0.001, -0.053};
  const TangentialSolution s = steady_solution(p, c);
  const nss::LinearContactModel model(p, s, {kMu, kSpeed, 0.0, CreepageSampling::contact});
  ASSERT_GT(model.slip_elements(), 0);
  ASSERT_GT(model.adhesion_elements(), 0);
  const nss::WearRow D = nss::WearTransfer(model, s, kSpeed, kMu, {}).power({0.0})[0];
  const double steps[] = {1e-8, 1e-8, 1e-6};
  for (int j = 0; j < 3; ++j) {
    Creepage cp = c, cm = c;
    double* xp[] = {&cp.xi_x, &cp.xi_y, &cp.phi};
    double* xm[] = {&cm.xi_x, &cm.xi_y, &cm.phi};
    *xp[j] += steps[j];
    *xm[j] -= steps[j];
    const TangentialSolution sp = steady_solution(p, cp), sm = steady_solution(p, cm);
    ASSERT_EQ(sp.state, s.state);
    ASSERT_EQ(sm.state, s.state);
    const double fd = (frictional_power(p, sp) - frictional_power(p, sm)) / (2 * steps[j]);
    std::printf("dD/dxi_%d: linear model %.8g, finite difference %.8g W\n", j, D(j).real(), fd);
    EXPECT_NEAR(D(j).real(), fd, 1e-4 * std::abs(fd));
    EXPECT_LT(std::abs(D(j).imag()), 1e-10 * std::abs(fd));
  }
  const double h = 1e-6 * kN;
  const ContactPatch pp = paper_patch_at(kN + h), pm = paper_patch_at(kN - h);
  ASSERT_EQ(pp.normal.contact_elements(), p.normal.contact_elements());
  const TangentialSolution sp = steady_solution(pp, c), sm = steady_solution(pm, c);
  ASSERT_EQ(sp.state, s.state);
  ASSERT_EQ(sm.state, s.state);
  const double fd = (frictional_power(pp, sp) - frictional_power(pm, sm)) / (2 * h);
  std::printf("dD/dN: linear model %.8g, finite difference %.8g W/N\n", D(3).real(), fd);
  EXPECT_NEAR(D(3).real(), fd, 1e-4 * std::abs(fd));
}

TEST(WearTransfer, ArchardsLawIsFrictionalWorkWithKOverMuH) {
  nss::WearLaw archard;
  archard.kind = nss::WearLaw::Kind::archard;
  archard.coefficient = 1e-4;
  archard.hardness = 2.8e9;
  EXPECT_DOUBLE_EQ(archard.depth_per_energy(0.3), 1e-4 / (0.3 * 2.8e9));
  EXPECT_DOUBLE_EQ(nss::WearLaw{}.depth_per_energy(0.3), 6.75e-13);
}

namespace {

// The frictional power of an unsteady run gathered along the rail as (W4) gathers the linear one:
// the element in column i at step j is over the rail cell m = j + i - ix_min (x_0 = x(ix_min), the
// first column of the mean contact area), W[m] = sum over its steps of -p . s (W/m^2).
// A run of `lengths` contact lengths: steps = lengths Lc, Lc = the columns of the mean area.
struct RailWear {
  RailWear(const ContactPatch& p, int lengths) : g(p.grid), ix_min(g.nx) {
    for (int k = 0; k < g.size(); ++k)
      if (p.normal.pn[k] > 0.0) ix_min = std::min(ix_min, k % g.nx);
    Lc = g.nx - 2 * ix_min;
    steps = lengths * Lc;
    W.assign(steps + g.nx, 0.0);
  }
  void add(long j, const TangentialSolution& s) {
    // (an element left of the mean area that a varying load brings into contact in the first
    // steps falls before the rail's first cell: the start transient, outside the fit below)
    for (int k = 0; k < g.size(); ++k)
      if (const long m = j + k % g.nx - ix_min; m >= 0)
        W[m] -= s.px[k] * s.sx[k] + s.py[k] * s.sy[k];
  }
  // The harmonic at k = w/V on the rail cells m in [start, end) (every step that reaches them is
  // >= start - Lc, past the start transient), by least squares (constant, cos, sin): the complex
  // amplitude with the phase e^{ik (x_0 + m dx)}.
  std::complex<double> harmonic(double w, int start, int end) const {
    Eigen::MatrixXd M(end - start, 3);
    Eigen::VectorXd y(end - start);
    for (int m = start; m < end; ++m) {
      const double phase = w / kSpeed * (g.x(ix_min) + m * g.dx);
      M.row(m - start) << 1.0, std::cos(phase), std::sin(phase);
      y(m - start) = W[m];
    }
    const Eigen::Vector3d c = M.colPivHouseholderQr().solve(y);
    return {c(1), -c(2)};  // a cos + b sin = Re{(a - i b) e^{i phase}}
  }
  const Grid& g;
  int ix_min, Lc = 0, steps = 0;
  std::vector<double> W;
};

// The unsteady solver (contact/transient_rolling.hpp) rolling from the steady state under input
// `input` (0 xi_x, 1 xi_y, 2 phi, 3 the normal load N) = mean + eps cos(w t_k) (taken at t_k, as
// the linear model's "contact" sampling; the load with its normal problem solved at every step):
// the harmonic of its frictional power along the rail (RailWear), the complex amplitude of
// sum_{j + i_a = m} D_{j,a} (W/m^2) with the phase e^{ik (x_0 + m dx)}.
std::complex<double> transient_wear_harmonic(const ContactPatch& p, const Creepage& mean, int input,
                                             double eps, double f) {
  const TangentialSolution s0 = steady_solution(p, mean);
  TransientRolling tr(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  tr.set_tractions(s0.px, s0.py);
  if (input == 3) tr.set_normal_problem(p.undeformed_distance, p.normal.force);
  RailWear rail(p, 40);
  const double dt = tr.time_step(), w = 2 * kPi * f;
  for (int j = 0; j < rail.steps; ++j) {
    Creepage c = mean;
    double* component[] = {&c.xi_x, &c.xi_y, &c.phi};
    const double variation = eps * std::cos(w * j * dt);
    if (input < 3) *component[input] += variation;
    rail.add(j, input < 3 ? tr.step(c) : tr.step(c, p.normal.force + variation));
  }
  return rail.harmonic(w, 12 * rail.Lc, rail.steps);
}

}  // namespace

TEST(WearTransfer, LinearEqualsTheUnsteadySolverOverAHarmonicInputWithin2PercentAnd2Degrees) {
  // Three wavelengths across the patch length (4a, 2a, a) in partial slip (the paper's combined
  // creepage (0.001, 0.001, -0.053 rad/m): the inputs xi_x, phi and N) and in full slip (xi_x =
  // 0.01: xi_x); amplitudes 1e-3 of the mean creepage and spin, 1e-4 of the load: what remains is
  // the nonlinearity (the adhesion/slip boundary moving) and the solvers' tolerances. (A variation
  // perpendicular to the mean slip, e.g. phi or xi_y about pure xi_x, changes |s| only to second
  // order: its linear wear vanishes by symmetry and no relative comparison is meaningful there.)
  const ContactPatch& p = paper_patch("coarse");
  const double a = 7.18e-3;
  double worst_amplitude = 0.0, worst_phase = 0.0;
  for (const Creepage mean : {Creepage{0.001, 0.001, -0.053}, Creepage{0.01, 0.0, 0.0}}) {
    const double xi = mean.xi_x;
    const TangentialSolution s = steady_solution(p, mean);
    const nss::LinearContactModel model(p, s, {kMu, kSpeed, 0.0, CreepageSampling::contact});
    nss::WearLaw law;
    law.coefficient = 1.0;
    const nss::WearTransfer T(model, s, kSpeed, kMu, law);
    // (W4) without K dx dy / (w_b V): the same gathering as transient_wear_harmonic
    const double scale = p.grid.element_area() / (T.band_width() * kSpeed);
    for (const int input : {0, 2, 3}) {
      if (xi > 0.005 && input != 0) continue;
      const double eps = input == 0   ? 1e-3 * xi
                         : input == 2 ? 1e-3 * std::abs(mean.phi)
                                      : 1e-4 * kN;
      for (const double lambda : {4 * a, 2 * a, a}) {
        const double f = kSpeed / lambda;
        const std::complex<double> lin = eps * T.depth({f})[0](input) / scale;
        const std::complex<double> nl = transient_wear_harmonic(p, mean, input, eps, f);
        const double da = std::abs(nl / lin) - 1.0, dp = std::arg(nl / lin) * 180 / kPi;
        std::printf(
            "xi_x = %g, input %d, lambda = %.2f mm: linear %.5e at %7.2f deg, unsteady %.5e at "
            "%7.2f deg: %+.2e, %+.3f deg\n",
            xi, input, 1e3 * lambda, std::abs(lin), std::arg(lin) * 180 / kPi, std::abs(nl),
            std::arg(nl) * 180 / kPi, da, dp);
        worst_amplitude = std::max(worst_amplitude, std::abs(da));
        worst_phase = std::max(worst_phase, std::abs(dp));
      }
    }
  }
  EXPECT_LT(worst_amplitude, 0.02);
  EXPECT_LT(worst_phase, 2.0);
}

namespace {

// The corrugation command's linear chain (docs/corrugation.md Sec. 4) for one contact on the wheel
// mass of roughness_rolling.hpp and a rigid rail: the roughness seen through the frozen patch
// (W6), the loop (noise/loop.hpp L1) with the wheel's receptance 1/(-m w^2 + i w c) and the
// contact's (k_N, f, g: C1-C3), the inputs u and the depth G = T u + T_r (W5, W8;
// pipeline::contact_wear), per unit rail roughness. The wheel and rail hold the tangential
// directions rigidly (their tangential receptances zero), as the unsteady run holds the creepage:
// xi~ = 0 to round-off.
pipeline::ContactWear linear_roughness_wear(const ContactPatch& p,
                                            const nss::LinearContactModel& model,
                                            const nss::WearTransfer& T,
                                            const nss::RoughnessWearTransfer& Tr,
                                            const WheelMass& wheel, double lambda) {
  const double k = 2 * kPi / lambda, f = kSpeed / lambda, w = 2 * kPi * f;
  const double kN =
      normal_load_sensitivity(p.grid, HalfSpaceOperator(p.influence, Problem::Normal), p.normal)
          .stiffness();
  const Eigen::Matrix3cd creep = model.creep_coefficients({f})[0];
  const Eigen::Vector3cd load = model.normal_load_coefficients({f})[0];
  noise::Receptance4 wheel_r = noise::Receptance4::Zero(), rail_r = noise::Receptance4::Zero();
  wheel_r(0, 0) = 1.0 / std::complex<double>(-wheel.mass * w * w, w * wheel.damping);
  noise::LoopOptions options;
  options.roughness = nss::rail_roughness_filter(p, {k})[0];
  options.velocities = false;
  const noise::Vector4c F = noise::solve_contact_forces(
      wheel_r, rail_r, noise::contact_receptance(f, kN, kSpeed, creep, load), options);
  return pipeline::contact_wear(F, creep, &load, T.depth({f})[0], Tr.depth({k})[0], k, 0.0);
}

// The unsteady solver over the rail roughness r(X) = r^ cos(kX) with the wheel mass
// (contact/roughness_rolling.hpp), from the steady state at the mean creepage (held), 30 contact
// lengths: the harmonic of its frictional power along the rail (RailWear) and of its contact force
// in time, both past the first 10 contact lengths (the start transients: the wheel's decays as
// e^{-zeta w_c t}, below 3e-4 there with the damping ratio zeta = 1/2 of the test).
struct RoughnessRun {
  std::complex<double> wear, load;
  double seconds = 0.0, solves_per_step = 0.0;
};

RoughnessRun roughness_wear_harmonic(const ContactPatch& p, const Creepage& mean,
                                     const WheelMass& wheel, double amplitude, double lambda) {
  const auto t0 = std::chrono::steady_clock::now();
  const TangentialSolution s0 = steady_solution(p, mean);
  TransientRolling tr(p.influence, p.normal.pn, kMu, kSpeed, 0.0);
  tr.set_tractions(s0.px, s0.py);
  tr.set_normal_problem(p.undeformed_distance, p.normal.force);
  RailWear rail(p, 30);
  const double w = 2 * kPi * kSpeed / lambda, dt = tr.time_step();
  RoughnessRollingInput in;
  in.creepage = mean;
  in.roughness = [&](double X) { return amplitude * std::cos(w / kSpeed * X); };
  in.wheel = wheel;
  in.approach = p.normal.approach;
  in.steps = rail.steps;
  const int start = 10 * rail.Lc;
  Eigen::MatrixXd M(rail.steps - start, 3);
  Eigen::VectorXd N(rail.steps - start);
  long solves = 0;
  roll_over_roughness(
      tr, p.grid, in, [&](long j, const RoughnessStep& r, const TangentialSolution& s) {
        rail.add(j, s);
        solves += r.normal_solves;
        if (j < start) return;
        M.row(j - start) << 1.0, std::cos(w * j * dt), std::sin(w * j * dt);
        N(j - start) = r.normal_force;
      });
  const Eigen::Vector3d c = M.colPivHouseholderQr().solve(N);
  RoughnessRun out;
  out.wear = rail.harmonic(w, start, rail.steps);
  out.load = {c(1), -c(2)};  // a cos + b sin = Re{(a - i b) e^{i w t}}
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.solves_per_step = double(solves) / rail.steps;
  return out;
}

}  // namespace

TEST(WearTransfer,
     UnsteadySolverOverARailRoughnessWithAWheelMassEqualsTheLinearChainWithin2PercentAnd2Degrees) {
  // The paper's Hertzian patch under a wheel of 600 kg (contact resonance ~250 Hz) with a dashpot
  // of damping ratio 1/2, a rail roughness of amplitude 1e-4 N/k_N (the load varies by 1.2e-4 N at
  // most), wavelengths 6a, 3a, 1.5a (322, 645, 1290 Hz; H = 0.83, 0.41, -0.21: away from the zeros
  // of sin(ka)/ka at 2a and a), in partial slip (the paper's combined creepage) and full slip (xi_x
  // = 0.01). Compared: the contact force (the loop, W6 and the structure) and the frictional work
  // along the rail against the chain with the roughness's own pressure (W8); the chain without it
  // is printed to show what W8 carries.
  const ContactPatch& p = paper_patch("coarse");
  const double a = 7.18e-3;
  const double kN =
      normal_load_sensitivity(p.grid, HalfSpaceOperator(p.influence, Problem::Normal), p.normal)
          .stiffness();
  WheelMass wheel;
  wheel.mass = 600.0;
  wheel.damping = std::sqrt(kN * wheel.mass);  // 2 zeta sqrt(k_N m), zeta = 1/2
  wheel.static_load = p.normal.force;
  const double amplitude = 1e-4 * p.normal.force / kN;
  std::printf("k_N = %.4e N/m, contact resonance %.1f Hz, roughness %.3e m\n", kN,
              std::sqrt(kN / wheel.mass) / (2 * kPi), amplitude);
  double worst_amplitude = 0.0, worst_phase = 0.0, worst_load = 0.0;
  for (const Creepage mean : {Creepage{0.001, 0.001, -0.053}, Creepage{0.01, 0.0, 0.0}}) {
    const TangentialSolution s = steady_solution(p, mean);
    const nss::LinearContactModel model(p, s, {kMu, kSpeed, 0.0, CreepageSampling::contact});
    nss::WearLaw law;
    law.coefficient = 1.0;
    const nss::WearTransfer T(model, s, kSpeed, kMu, law);
    const nss::RoughnessWearTransfer Tr(p, model, s, kSpeed, kMu, law, 2 * kPi / (1.5 * a));
    // the columns' patterns reduced to the band's rank (RoughnessWearTransfer): a basis for twice
    // the band, with more patterns, gives the same T_r within 1e-8 of it
    const nss::RoughnessWearTransfer wider(p, model, s, kSpeed, kMu, law, 4 * kPi / (1.5 * a));
    std::printf("W8: %d columns, %d patterns (%d for twice the band)\n", Tr.columns(),
                Tr.patterns(), wider.patterns());
    EXPECT_LT(Tr.patterns(), Tr.columns());
    for (const double lambda : {6 * a, 3 * a, 1.5 * a}) {
      const std::complex<double> t = Tr.depth({2 * kPi / lambda})[0],
                                 w = wider.depth({2 * kPi / lambda})[0];
      EXPECT_LE(std::abs(t - w), 1e-8 * std::abs(w)) << lambda;
    }
    // (W4) without K dx dy / (w_b V): the same gathering as RailWear
    const double scale = p.grid.element_area() / (T.band_width() * kSpeed);
    for (const double lambda : {6 * a, 3 * a, 1.5 * a}) {
      const pipeline::ContactWear lin = linear_roughness_wear(p, model, T, Tr, wheel, lambda);
      const RoughnessRun nl = roughness_wear_harmonic(p, mean, wheel, amplitude, lambda);
      const std::complex<double> wl = amplitude * lin.depth / scale, Nl = amplitude * lin.input(3);
      const std::complex<double> without = wl - amplitude * Tr.depth({2 * kPi / lambda})[0] / scale;
      const double da = std::abs(nl.wear / wl) - 1.0, dp = std::arg(nl.wear / wl) * 180 / kPi;
      std::printf(
          "xi_x = %g, lambda = %.2f mm (%.0f Hz): N~ linear %.4e N at %7.2f deg, unsteady %+.2e, "
          "%+.3f deg; wear linear %.4e at %7.2f deg, unsteady %+.2e, %+.3f deg (without W8: "
          "unsteady / linear %.2f at %+.1f deg; |xi~| %.0e; %.1f s, %.1f normal solves per step)\n",
          mean.xi_x, 1e3 * lambda, kSpeed / lambda, std::abs(Nl), std::arg(Nl) * 180 / kPi,
          std::abs(nl.load / Nl) - 1.0, std::arg(nl.load / Nl) * 180 / kPi, std::abs(wl),
          std::arg(wl) * 180 / kPi, da, dp, std::abs(nl.wear / without),
          std::arg(nl.wear / without) * 180 / kPi, lin.input.head<3>().norm(), nl.seconds,
          nl.solves_per_step);
      worst_amplitude = std::max(worst_amplitude, std::abs(da));
      worst_phase = std::max(worst_phase, std::abs(dp));
      worst_load = std::max(worst_load, std::abs(nl.load / Nl - 1.0));
    }
  }
  std::printf("largest difference: wear %.2e, %.3f deg; contact force %.2e\n", worst_amplitude,
              worst_phase, worst_load);
  EXPECT_LT(worst_amplitude, 0.02);
  EXPECT_LT(worst_phase, 2.0);
  EXPECT_LT(worst_load, 0.02);
}

TEST(WearTransfer,
     RailRoughnessFilterOfAHertzianPatchIsTheFlatPunchAverageSinKaOverKaWithin2Percent) {
  // (W6) on the paper's fine grid: the unit-load pressure of the frozen ellipse is the flat
  // punch's, whose lateral integral is uniform over |x| < a, so a roughness uniform across the rail
  // is averaged over the patch length: H = sin(ka)/(ka). The discrete punch pressure (its edge
  // singularity on 68 x 50 elements) sets the tolerance.
  const ContactPatch& p = paper_patch("fine");
  const double a = 7.18e-3;
  std::vector<double> k;
  for (double u = 0.0; u <= 9.0; u += 0.5) k.push_back(u / a);
  const auto H = nss::rail_roughness_filter(p, k);
  double worst = 0.0;
  for (std::size_t i = 0; i < k.size(); ++i) {
    const double u = k[i] * a, ref = u == 0.0 ? 1.0 : std::sin(u) / u;
    worst = std::max(worst, std::abs(H[i] - ref));
    std::printf("ka = %4.1f  H = %+.4f %+.4fi  sin(ka)/ka = %+.4f\n", u, H[i].real(), H[i].imag(),
                ref);
  }
  std::printf("largest difference %.2e\n", worst);
  EXPECT_NEAR(H[0].real(), 1.0, 1e-10);
  EXPECT_LT(worst, 0.02);
}
