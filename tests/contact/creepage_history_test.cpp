// Creepage histories: paper Eqs. 31-32 and sampled series.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/creepage_history.hpp"
#include "core/errors.hpp"

using namespace rollnoise::contact;

TEST(CreepageHistory, HarmonicIsMeanPlusAmplitudeCosineWithPhase) {
  const auto h = CreepageHistory::harmonic({0.001, 0.002, -0.05}, {5e-5, 1e-5, 0.003}, 1000.0,
                                           {0.0, M_PI / 2, M_PI});
  for (double t : {0.0, 1.3e-4, 7.7e-4}) {
    const Creepage c = h.at(t);
    const double wt = 2 * M_PI * 1000.0 * t;
    EXPECT_NEAR(c.xi_x, 0.001 + 5e-5 * std::cos(wt), 1e-18);
    EXPECT_NEAR(c.xi_y, 0.002 + 1e-5 * std::cos(wt + M_PI / 2), 1e-18);
    EXPECT_NEAR(c.phi, -0.05 + 0.003 * std::cos(wt + M_PI), 1e-16);
  }
}

TEST(CreepageHistory, MultiharmonicIsReproducibleFromItsSeedAndEvenlySpaced) {
  const auto a = CreepageHistory::multiharmonic({0.001, 0, 0}, {1e-6, 1e-6, 5e-6}, 100, 5000, 1000, 7);
  const auto b = CreepageHistory::multiharmonic({0.001, 0, 0}, {1e-6, 1e-6, 5e-6}, 100, 5000, 1000, 7);
  const auto c = CreepageHistory::multiharmonic({0.001, 0, 0}, {1e-6, 1e-6, 5e-6}, 100, 5000, 1000, 8);
  ASSERT_EQ(a.frequencies().size(), 1000u);
  EXPECT_DOUBLE_EQ(a.frequencies().front(), 100.0);
  EXPECT_DOUBLE_EQ(a.frequencies().back(), 5000.0);
  EXPECT_NEAR(a.frequencies()[1] - a.frequencies()[0], 4900.0 / 999.0, 1e-9);
  EXPECT_EQ(a.at(1e-3).xi_x, b.at(1e-3).xi_x);
  EXPECT_NE(a.at(1e-3).xi_x, c.at(1e-3).xi_x);
  // Eq. 32 with random phases: the standard deviation is amplitude sqrt(N/2)
  double sq = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) sq += std::pow(a.variation(i * 1e-5)[0], 2);
  EXPECT_NEAR(std::sqrt(sq / n), 1e-6 * std::sqrt(500.0), 0.1 * 1e-6 * std::sqrt(500.0));
}

TEST(CreepageHistory, SamplesAreInterpolatedLinearlyAndHeldOutside) {
  const auto h = CreepageHistory::samples({0, 0, 0}, {0.0, 1.0, 3.0},
                                          {{0, 0, 0}, {1e-3, 2e-3, 0.1}, {3e-3, 0, -0.1}});
  EXPECT_NEAR(h.at(0.5).xi_x, 0.5e-3, 1e-15);
  EXPECT_NEAR(h.at(2.0).xi_y, 1e-3, 1e-15);
  EXPECT_NEAR(h.at(2.0).phi, 0.0, 1e-15);
  EXPECT_NEAR(h.at(5.0).xi_x, 3e-3, 1e-15);
  EXPECT_THROW(CreepageHistory::samples({}, {0.0, 0.0}, {{}, {}}), rollnoise::InputError);
}
