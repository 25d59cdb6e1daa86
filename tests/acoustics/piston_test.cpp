// Baffled pistons by the autocorrelation form of the Rayleigh integral (acoustics/piston.hpp): the
// disc against its closed form, the rectangle's low- and high-frequency limits, a square against
// the disc of equal area, and half a sleeper (1.3 m x 0.25 m) between the squares of its two sides.
#include "acoustics/piston.hpp"

#include <gsl/gsl_sf_bessel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ac = rollnoise::acoustics;

namespace {

constexpr double kPiPiston = 3.14159265358979323846;

/// sigma = 1 - J_1(2ka)/(ka) (Kinsler et al., Fundamentals of Acoustics, Sec. 7.5).
double disc_closed_form(double ka) {
  return 1.0 - gsl_sf_bessel_J1(2.0 * ka) / ka;
}

}  // namespace

// ka 0.05 ... 50 (geometric steps of 5 %): the quadrature within 1 % of the closed form
// (measured: 1e-13).
TEST(Piston, DiscMatchesClosedForm) {
  double worst = 0.0;
  for (double ka = 0.05; ka <= 50.0; ka *= 1.05) {
    const double a = 0.3;
    const double s = ac::circular_piston_efficiency(ka / a, a);
    worst = std::max(worst, std::abs(s / disc_closed_form(ka) - 1.0));
  }
  std::printf("  disc, ka 0.05-50: largest relative error %.1e\n", worst);
  EXPECT_LT(worst, 0.01);
}

// Low k: sigma -> k^2 A / (2 pi) (1 % at k sqrt(A) = 0.1; the next term is -(k^2 A)^2 ...);
// high k: -> 1 within 2 % once k min(Lx, Ly) >= 20.
TEST(Piston, RectangleLimits) {
  for (const auto& [Lx, Ly] : {std::pair{1.0, 1.0}, {1.3, 0.25}, {0.25, 2.6}}) {
    const double A = Lx * Ly;
    const double k = 0.1 / std::sqrt(A);
    EXPECT_NEAR(ac::rectangular_piston_efficiency(k, Lx, Ly) / (k * k * A / (2.0 * kPiPiston)), 1.0,
                0.01)
        << Lx << " x " << Ly;
    for (double kmin : {20.0, 40.0, 100.0, 300.0}) {
      const double kk = kmin / std::min(Lx, Ly);
      EXPECT_NEAR(ac::rectangular_piston_efficiency(kk, Lx, Ly), 1.0, 0.02)
          << Lx << " x " << Ly << ", k min(L) = " << kmin;
    }
  }
}

// A square and the disc of equal area: the same k^2 A / (2 pi) at low k, within 1 % up to
// k sqrt(A) = 1 (measured 0.25 %), and close (a few %) through the transition.
TEST(Piston, SquareCloseToDiscOfEqualArea) {
  const double side = 1.0, radius = side / std::sqrt(kPiPiston);
  std::printf("  k sqrt(A)   square     disc\n");
  for (double k : {0.05, 0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double sq = ac::rectangular_piston_efficiency(k, side, side);
    const double disc = ac::circular_piston_efficiency(k, radius);
    std::printf("  %5.2f     %.5f   %.5f\n", k, sq, disc);
    EXPECT_NEAR(sq / disc, 1.0, k <= 1.0 ? 0.01 : 0.05) << k;
  }
}

// Half a sleeper, 1.3 m x 0.25 m (the rail's share of a 2.6 m sleeper): at or below k^2 A / (2 pi)
// (1.6 % below at 31.5 Hz, where k Lx = 0.75 already), between the 0.25 m and 1.3 m squares (of its
// short and long side) up to 500 Hz, of order 1 (0.9 ... 1.1) from 800 Hz; printed with the time
// per call.
TEST(Piston, HalfSleeperIsPlausible) {
  const double c = 343.2, Lx = 1.3, Ly = 0.25;
  std::printf("  f (Hz)  half sleeper  0.25 m square  1.3 m square  k^2 A/(2 pi)  time (us)\n");
  for (double f : {31.5, 63.0, 100.0, 200.0, 315.0, 500.0, 800.0, 1000.0, 2000.0, 5000.0}) {
    const double k = 2.0 * kPiPiston * f / c;
    const auto t0 = std::chrono::steady_clock::now();
    const double s = ac::rectangular_piston_efficiency(k, Lx, Ly);
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    const double small = ac::rectangular_piston_efficiency(k, Ly, Ly);
    const double large = ac::rectangular_piston_efficiency(k, Lx, Lx);
    const double low = k * k * Lx * Ly / (2.0 * kPiPiston);
    std::printf("  %6.1f   %.4f        %.4f         %.4f        %.4f        %.0f\n", f, s, small,
                large, low, us);
    if (f <= 500.0) {
      EXPECT_GT(s, small) << f;
      EXPECT_LT(s, large) << f;
      EXPECT_LE(s, low * 1.0001) << f;  // below the low-frequency asymptote
    } else if (f >= 800.0) {
      EXPECT_NEAR(s, 1.0, 0.1) << f;
    }
  }
}

TEST(Piston, RejectsBadInput) {
  EXPECT_THROW(ac::rectangular_piston_efficiency(0.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ac::rectangular_piston_efficiency(1.0, -1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ac::circular_piston_efficiency(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(ac::circular_piston_efficiency(std::nan(""), 1.0), std::invalid_argument);
}
