// Checks of the exact infinite periodic track (dynamics/track_periodic.hpp, the default solution
// of DiscretelySupportedRail) against the truncated solve of Eq. (2) of track.hpp (2N + 1
// supports, Levinson / dense LU) as N grows, and of its periodicity, reciprocity and resonance.
#include "dynamics/track_periodic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <utility>
#include <vector>

#include "dynamics/track.hpp"
#include "support/test_helpers.hpp"

namespace rd = rollnoise::dynamics;
using cd = std::complex<double>;
using rollnoise::test_support::relative;

namespace {

const rd::TrackParameters& uic60() {
  static const rd::TrackParameters t = rd::uic60_ballasted();
  return t;
}

rd::DiscretelySupportedRail beam_rail(bool vertical, rd::DiscreteSupportSolution solution,
                                      int n = 60) {
  const rd::TrackParameters& t = uic60();
  return rd::DiscretelySupportedRail(vertical ? t.vertical : t.lateral,
                                     vertical ? t.vertical_support : t.lateral_support,
                                     t.sleeper_spacing, n, solution);
}

// Point receptances over a sleeper, mid-span and at an arbitrary position, and transfers over
// 0.6 m (one span), 1.5 m and 3.6 m from an arbitrary position.
const std::vector<std::pair<double, double>> kPairs = {{0.0, 0.0},   {0.3, 0.3},   {0.17, 0.17},
                                                       {0.17, 0.77}, {1.67, 0.17}, {0.41, 4.01}};

// The largest |mu| of the two decaying Floquet waves at omega (real, or complex continued from
// Re omega in one step, enough for the small Im omega used here).
double slowest_multiplier(bool vertical, cd omega) {
  const rd::TrackParameters& t = uic60();
  const rd::BeamSection& b = vertical ? t.vertical : t.lateral;
  const rd::Support& s = vertical ? t.vertical_support : t.lateral_support;
  const double wr = omega.real();
  const rd::PeriodicallySupportedBeam real(rd::InfiniteBeam(b, wr, 0.0), s.dynamic_stiffness(wr),
                                           t.sleeper_spacing);
  const rd::PeriodicallySupportedBeam p(rd::InfiniteBeam(b, omega, 0.0, 0.0),
                                        s.dynamic_stiffness(omega), t.sleeper_spacing,
                                        omega.imag() > 0.0 ? &real : nullptr);
  return std::max(std::abs(p.floquet_multipliers()[0]), std::abs(p.floquet_multipliers()[1]));
}

// The truncation's error bound: the waves reflected at the ends of the 2N + 1 supports come back
// to the load after 2N spans, attenuated by |mu|^{2N} (mu the slowest decaying Floquet wave), so
// the truncated solve differs from the infinite track by C |mu|^{2N} + round-off. C (the
// reflected wave's amplitude relative to the response) measured up to 3.6 at these points (near
// the pinned-pinned resonance, vertical beam), 5 allowed; the round-off of the truncated solve
// (Levinson, m = 401) measured up to 5e-11, 1e-10 allowed (1e-9 at complex omega).
double truncation_bound(double mu, int n, double round_off) {
  return 5.0 * std::pow(mu, 2 * n) + round_off;
}

}  // namespace

// The periodic solution is the N -> infinity limit of the truncated one: for N = 30, 60, 200 the
// difference stays within the bound above at every point and frequency, 20 Hz - 5 kHz (ratio 1.6
// and the pinned-pinned 1070 Hz), both beams, points over a sleeper / mid-span / arbitrary and
// transfers over 0.6, 1.5 and 3.6 m. Measured: 1.2e-2 at N = 60 (lateral beam, 537 Hz, |mu| =
// 0.965: 0.1 dB), 5.9e-7 at N = 200.
TEST(PeriodicTrack, IsTheLimitOfTheTruncatedSolveAsSupportsGrow) {
  std::vector<double> freqs = {1070.0};
  for (double f = 20.0; f <= 5000.0; f *= 1.6) freqs.push_back(f);
  for (const int n : {30, 60, 200}) {
    double worst = 0.0;
    for (const bool vertical : {true, false}) {
      const auto exact = beam_rail(vertical, rd::DiscreteSupportSolution::kPeriodic);
      const auto cut = beam_rail(vertical, rd::DiscreteSupportSolution::kTruncated, n);
      for (const double f : freqs) {
        const double bound =
            truncation_bound(slowest_multiplier(vertical, 2.0 * M_PI * f), n, 1e-10);
        const std::vector<Eigen::Matrix2cd> a = exact.transfers(f, kPairs);
        const std::vector<Eigen::Matrix2cd> b = cut.transfers(f, kPairs);
        for (std::size_t p = 0; p < kPairs.size(); ++p) {
          const double err = relative(b[p], a[p]);
          EXPECT_LE(err, bound) << "N = " << n << ", vertical " << vertical << ", f = " << f
                                << " Hz, pair " << p;
          worst = std::max(worst, err);
        }
      }
    }
    std::printf("truncated (N = %d) - periodic: largest relative difference %.2e\n", n, worst);
  }
}

// Squeal's continuation (docs/squeal.md Sec. 2) equals the truncated one's where that converges:
// growing (Im omega < 0, 5 % of Re omega) and lightly decaying roots (Im omega = 0.2 %, 0.5 % of
// Re omega, below eta_rail / 2 = 1 %, where the truncated continuation's reflections still decay),
// N = 120 (at Im omega > 0 the truncated solve is a dense LU: kept small), within the same bound
// with mu at the complex omega, at a point over a sleeper / mid-span and transfers over 0.6 and
// 3.6 m.
TEST(PeriodicTrack, ComplexFrequencyEqualsTheConvergedTruncatedContinuation) {
  const int n = 120;
  const std::vector<std::pair<double, double>> pairs = {
      {0.0, 0.0}, {0.3, 0.3}, {0.17, 0.77}, {0.41, 4.01}};
  for (const bool vertical : {true, false}) {
    const auto exact = beam_rail(vertical, rd::DiscreteSupportSolution::kPeriodic);
    const auto cut = beam_rail(vertical, rd::DiscreteSupportSolution::kTruncated, n);
    for (const double f : {150.0, 540.0, 1070.0, 3000.0})
      for (const double zeta : {-0.05, 0.002, 0.005}) {
        const cd omega = 2.0 * M_PI * f * cd(1.0, zeta);
        const double bound = truncation_bound(slowest_multiplier(vertical, omega), n, 1e-9);
        for (const auto& [xr, xe] : pairs)
          EXPECT_LE(relative(cut.transfer_at(omega, xr, xe), exact.transfer_at(omega, xr, xe)),
                    bound)
              << "vertical " << vertical << ", f = " << f << " Hz, zeta " << zeta << ", x = " << xr
              << ", " << xe;
      }
  }
}

// By construction the infinite track is periodic, H(x_r + n L, x_e + n L) = H(x_r, x_e), and
// reciprocal, H(x_e, x_r) = H(x_r, x_e)^T; both to round-off (1e-11 relative; the two sides take
// different spans as the load's), at real and complex omega (also at 3 % of Re omega, beyond the
// truncated continuation's reach).
TEST(PeriodicTrack, IsPeriodicAndReciprocalAtRealAndComplexFrequency) {
  const double L = uic60().sleeper_spacing;
  for (const bool vertical : {true, false}) {
    const auto rail = beam_rail(vertical, rd::DiscreteSupportSolution::kPeriodic);
    for (const double f : {63.0, 540.0, 1070.0, 3000.0})
      for (const double zeta : {0.0, -0.05, 0.03}) {
        const cd omega = 2.0 * M_PI * f * cd(1.0, zeta);
        auto H = [&](double xr, double xe) {
          return zeta == 0.0 ? rail.transfer(f, xr, xe) : rail.transfer_at(omega, xr, xe);
        };
        for (const auto& [xr, xe] : kPairs) {
          const Eigen::Matrix2cd h = H(xr, xe);
          ASSERT_TRUE(h.allFinite());
          for (const int shift : {1, -3, 7})
            EXPECT_LT(relative(H(xr + shift * L, xe + shift * L), h), 1e-11)
                << "f = " << f << ", zeta " << zeta << ", shift " << shift;
          EXPECT_LT(relative(H(xe, xr).transpose(), h), 1e-11) << "f = " << f << ", zeta " << zeta;
        }
      }
  }
}

// The pinned-pinned resonance (vertical beam, mid-span peak; a dip over the sleeper, > 5 dB
// below) where the truncated model (N = 60) puts it: same frequency on a 5 Hz grid, 700-1500 Hz.
TEST(PeriodicTrack, PinnedPinnedResonanceWhereTheTruncatedModelPutsIt) {
  const auto exact = beam_rail(true, rd::DiscreteSupportSolution::kPeriodic);
  const auto cut = beam_rail(true, rd::DiscreteSupportSolution::kTruncated, 60);
  const double mid = 0.5 * uic60().sleeper_spacing;
  double f_exact = 0.0, f_cut = 0.0, peak_exact = 0.0, peak_cut = 0.0;
  for (double f = 700.0; f <= 1500.0; f += 5.0) {
    const double a = std::abs(exact.point(f, mid)(0, 0)), b = std::abs(cut.point(f, mid)(0, 0));
    if (a > peak_exact) peak_exact = a, f_exact = f;
    if (b > peak_cut) peak_cut = b, f_cut = f;
  }
  std::printf("pinned-pinned: periodic %.0f Hz, truncated %.0f Hz\n", f_exact, f_cut);
  EXPECT_NEAR(f_exact, f_cut, 5.0);
  EXPECT_GT(rollnoise::test_support::db(peak_exact) -
                rollnoise::test_support::db(exact.point(f_exact, 0.0)(0, 0)),
            5.0);
}
