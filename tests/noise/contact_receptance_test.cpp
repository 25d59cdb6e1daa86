// The contact receptance (src/noise/contact_receptance.hpp).
#include "noise/contact_receptance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "noise_fixture.hpp"

using namespace noise_test;

// alpha_c,t (i omega / V) f = I to round-off (Eq. C2), for Kalker's real f and the
// frequency-dependent spring-damper f, and alpha_c,zz = 1/k_H = 2 delta / (3 N).
TEST(ContactReceptance, TangentialBlockTimesIOmegaOverVTimesCreepIsIdentity) {
  const double kH = hertz().normal_stiffness();
  EXPECT_NEAR(kH, 1.5 * kN / hertz().approach, 1e-9 * kH);
  double worst = 0.0;
  for (const rn::CreepFunction& creep : {rn::steady_creep(kalker()), spring_creep()}) {
    for (double f : {10.0, 250.0, 1000.0, 5000.0}) {
      const Eigen::Matrix3cd fc = creep(f);
      const rn::Receptance4 a = rn::contact_receptance(f, kH, kSpeed, fc);
      const Eigen::Matrix3cd product =
          a.bottomRightCorner<3, 3>() * rd::cdouble(0.0, 2 * M_PI * f / kSpeed) * fc;
      worst = std::max(worst, (product - Eigen::Matrix3cd::Identity()).cwiseAbs().maxCoeff());
      EXPECT_DOUBLE_EQ(a(0, 0).real(), 1.0 / kH);
      EXPECT_EQ(a.row(0).tail<3>().norm() + a.col(0).tail<3>().norm(), 0.0);
    }
  }
  std::printf("max |alpha_c (i w/V) f - I| = %.2e; 1/k_H = %.4e m/N (k_H = %.4e N/m)\n", worst,
              1.0 / kH, kH);
  EXPECT_LT(worst, 1e-13);
}

// Kalker's steady coefficients make the contact a damper (creep damping f/V): dissipative, and
// the spring-damper law adds a lossless spring, so it stays dissipative.
TEST(ContactReceptance, KalkerAndSpringDamperContactsArePassive) {
  const double kH = hertz().normal_stiffness();
  for (const rn::CreepFunction& creep : {rn::steady_creep(kalker()), spring_creep()})
    for (double f : {20.0, 300.0, 2000.0, 6000.0}) {
      const rn::Receptance4 a = rn::contact_receptance(f, kH, kSpeed, creep(f));
      const Eigen::Matrix3cd t = a.bottomRightCorner<3, 3>();
      EXPECT_GT(relative_min_dissipation<3>(t), -1e-12) << f << " Hz";
    }
}

// The spring-damper law tends to Kalker's f at low frequency and to the contact spring,
// f ~ (V/(i omega)) K, at high frequency.
TEST(ContactReceptance, SpringDamperCreepLawHasKalkerAndSpringLimits) {
  const Eigen::Matrix3d K =
      rn::tangential_contact_stiffness(kA, kB, material().shear_modulus(), material().nu);
  const rn::CreepFunction creep = spring_creep();
  const Eigen::Matrix3cd low = creep(0.01);
  EXPECT_LT((low - kalker().cast<rd::cdouble>()).norm() / kalker().norm(), 1e-4);
  const double f = 1e6, omega = 2 * M_PI * f;
  const Eigen::Matrix3cd high = creep(f) * rd::cdouble(0.0, omega / kSpeed);
  EXPECT_LT((high - K.cast<rd::cdouble>()).norm() / K.norm(), 1e-2);
  // Corner frequency of the longitudinal part: omega = V K11 / f11.
  std::printf("K_x = %.3e N/m, K_rot = %.3e N m/rad; longitudinal corner V K/f11 / 2pi = %.0f Hz\n",
              K(0, 0), K(2, 2), kSpeed * K(0, 0) / kalker()(0, 0) / (2 * M_PI));
}

TEST(ContactReceptance, BadInputIsReported) {
  const double kH = hertz().normal_stiffness();
  // argument contracts (the case's frequencies and rolling.speed are checked where read)
  EXPECT_THROW(rn::contact_receptance(0.0, kH, kSpeed, kalker().cast<rd::cdouble>()),
               std::invalid_argument);
  EXPECT_THROW(rn::contact_receptance(100.0, kH, 0.0, kalker().cast<rd::cdouble>()),
               std::invalid_argument);
  EXPECT_THROW(rn::contact_receptance(100.0, kH, kSpeed, Eigen::Matrix3cd::Zero()),
               rollnoise::NumericalError);
#ifndef NDEBUG  // an internal contract (ROLLNOISE_ASSERT), checked in builds without NDEBUG
  EXPECT_THROW(rn::contact_receptances({100.0}, kH, kSpeed, rn::CreepFunction()), std::logic_error);
#endif
}
