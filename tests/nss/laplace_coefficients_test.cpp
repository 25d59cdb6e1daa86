// f(s) and g(s) at complex s (LinearContactModel::creep_coefficients_laplace,
// normal_load_coefficients_laplace; docs/squeal.md Sec. 2): on the imaginary axis they equal the
// real-frequency sweep with the sampling's factor, and the two exact routes (the Markov series,
// the Hessenberg form at complex z) agree off the axis; the contact's spectral radius agrees with
// the growth of its own recursion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "../contact/paper_case.hpp"
#include "contact/steady_rolling.hpp"
#include "nss/linear_model.hpp"
#include "support/test_helpers.hpp"

using namespace rollnoise;
using namespace rollnoise::testing;
using cd = std::complex<double>;

namespace {

nss::LinearContactModel model(const contact::Creepage& c, const contact::FallingFriction& f,
                              contact::CreepageSampling sampling) {
  const auto steady = contact::solve_steady_rolling(
      coarse_patch().influence, coarse_patch().normal.pn, {kMu, kSpeed, c, 0.0, f});
  return nss::LinearContactModel(coarse_patch(), steady,
                                 {kMu, kSpeed, 0.0, f, nss::LinearSolver::automatic, sampling});
}

using rollnoise::test_support::relative;

}  // namespace

TEST(LaplaceCoefficients, ImaginaryAxisEqualsTheSweepWithTheSamplingFactorForEveryModel) {
  const contact::Creepage mean{0.001, 0.001, -0.053};  // partial slip
  for (auto sampling : {contact::CreepageSampling::contact, contact::CreepageSampling::midstep}) {
    for (const contact::FallingFriction law :
         {contact::FallingFriction{}, contact::FallingFriction{0.5, 4.0}}) {
      const auto m = model(mean, law, sampling);
      for (double fr : {0.0, 700.0, 2500.0}) {
        const cd s(0.0, 2.0 * M_PI * fr);
        EXPECT_LT(relative(m.creep_coefficients_laplace(s), m.creep_coefficients({fr})[0]), 1e-9)
            << fr;
        EXPECT_LT(
            relative(m.normal_load_coefficients_laplace(s), m.normal_load_coefficients({fr})[0]),
            1e-9)
            << fr;
      }
    }
  }
}

TEST(LaplaceCoefficients, MarkovSeriesEqualsTheHessenbergFormOffTheAxis) {
  // Constant friction takes the Markov series (where it converges); a falling law with B = 1e-9 s/m
  // (mu changes by ~1e-10 over the slip speeds here) has no Markov parameters and takes the
  // Hessenberg form at complex z: two independent exact routes to (nearly) the same f(s), g(s).
  const contact::Creepage mean{0.001, 0.001, -0.053};
  const auto markov = model(mean, {}, contact::CreepageSampling::midstep);
  const auto hessenberg = model(mean, {0.5, 1e-9}, contact::CreepageSampling::midstep);
  ASSERT_FALSE(markov.falling_friction());
  ASSERT_TRUE(hessenberg.falling_friction());
  for (const cd s : {cd(300.0, 2.0 * M_PI * 900.0), cd(-200.0, 2.0 * M_PI * 1500.0),
                     cd(-1500.0, 2.0 * M_PI * 400.0)}) {
    const double ef =
        relative(markov.creep_coefficients_laplace(s), hessenberg.creep_coefficients_laplace(s));
    const double eg = relative(markov.normal_load_coefficients_laplace(s),
                               hessenberg.normal_load_coefficients_laplace(s));
    std::printf("s = %g%+gi: f %.2e, g %.2e\n", s.real(), s.imag(), ef, eg);
    EXPECT_LT(ef, 1e-7);
    EXPECT_LT(eg, 1e-7);
  }
}

TEST(LaplaceCoefficients, BothAtOnceEqualTheTwoCallsWithAndWithoutMarkovParameters) {
  // coefficients_laplace (squeal's loop: f and g at every s) takes both from one Hessenberg solve
  // without Markov parameters (falling friction), the series with them: the same values as the two
  // calls to rounding (1e-13 relative: the solve's columns are eliminated by the same row
  // operations and projected step by step; only the vectorised complex products may round
  // differently).
  const contact::Creepage mean{0.001, 0.001, -0.053};
  for (const contact::FallingFriction law :
       {contact::FallingFriction{}, contact::FallingFriction{0.5, 4.0}}) {
    const auto m = model(mean, law, contact::CreepageSampling::average);
    for (const cd s : {cd(300.0, 2.0 * M_PI * 900.0), cd(-200.0, 2.0 * M_PI * 1500.0)}) {
      const auto [f, g] = m.coefficients_laplace(s);
      const nss::CreepMatrix f2 = m.creep_coefficients_laplace(s);
      const nss::LoadVector g2 = m.normal_load_coefficients_laplace(s);
      EXPECT_LE((f - f2).norm(), 1e-13 * f2.norm()) << s;
      // g (dimensionless in x, y) is a sum of terms of O(mu) that cancel to ~1e-15 at some s here:
      // rounding relative to the terms, 1e-13 of max(|g|, 1)
      EXPECT_LE((g - g2).norm(), 1e-13 * std::max(g2.norm(), 1.0)) << s;
    }
  }
}

TEST(LaplaceCoefficients, SpectralRadiusSeparatesDecayingAndGrowingContactRecursions) {
  // docs/falling_friction.md Sec. 3: at (0.001, 0.001, -0.053) the recursion decays for B = 4 s/m
  // and grows for B = 10 s/m; the radius is the growth per step of the impulse response.
  const contact::Creepage mean{0.001, 0.001, -0.053};
  for (double B : {4.0, 10.0}) {
    const auto m = model(mean, {0.5, B}, contact::CreepageSampling::contact);
    const double rho = m.spectral_radius();
    std::vector<Eigen::Vector3d> xi(100, Eigen::Vector3d::Zero());
    xi[0] = Eigen::Vector3d(1e-5, 0.0, 0.0);
    const auto F = m.time_response(xi);  // 100 steps: 3.6^100 still finite
    const double measured = std::pow(F[99].norm() / F[79].norm(), 1.0 / 20.0);
    std::printf("B = %g s/m: spectral radius %.6f, impulse response growth per step %.6f\n", B, rho,
                measured);
    EXPECT_EQ(rho < 1.0, B == 4.0);
    EXPECT_NEAR(measured, rho, 1e-3 * rho);
  }
}
