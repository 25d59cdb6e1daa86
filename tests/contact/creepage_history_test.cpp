// Creepage histories: paper Eqs. 31-32 and sampled series.
#include "contact/creepage_history.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

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
#ifndef NDEBUG  // a contract (io/excitation.cpp checks the file's times, naming excitation.file)
  EXPECT_THROW(CreepageHistory::samples({}, {0.0, 0.0}, {{}, {}}), std::logic_error);
#endif
}

TEST(CreepageHistory, HarmonicNormalLoadIsAmplitudeCosineWithItsOwnPhase) {
  const auto h =
      CreepageHistory::harmonic({0.001, 0, 0}, {5e-5, 0, 0}, 1000.0, {}, 981.0, M_PI / 3);
  EXPECT_TRUE(h.has_normal_variation());
  EXPECT_EQ(h.normal_amplitude(), 981.0);
  ASSERT_EQ(h.normal_phases().size(), 1u);
  for (double t : {0.0, 1.3e-4, 7.7e-4})
    EXPECT_NEAR(h.normal_variation(t), 981.0 * std::cos(2 * M_PI * 1000.0 * t + M_PI / 3), 1e-10);
  EXPECT_FALSE(
      CreepageHistory::harmonic({0.001, 0, 0}, {5e-5, 0, 0}, 1000.0).has_normal_variation());
  EXPECT_FALSE(CreepageHistory::constant({0.001, 0, 0}).has_normal_variation());
  EXPECT_EQ(CreepageHistory::constant({0.001, 0, 0}).normal_variation(1e-3), 0.0);
}

TEST(CreepageHistory, MultiharmonicNormalPhasesFollowTheUnchangedCreepagePhasesOfTheSeed) {
  // The generator use documented in the header: 3 x count creepage phases, then count load phases.
  const int count = 50;
  const auto h = CreepageHistory::multiharmonic({0.001, 0, 0}, {1e-6, 1e-6, 5e-6}, 100, 5000, count,
                                                11, 200.0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.0, 2.0 * M_PI);
  for (int j = 0; j < 3; ++j)
    for (int n = 0; n < count; ++n) ASSERT_EQ(h.phases()[j][n], U(rng)) << j << " " << n;
  for (int n = 0; n < count; ++n) ASSERT_EQ(h.normal_phases()[n], U(rng)) << n;
  const auto without =
      CreepageHistory::multiharmonic({0.001, 0, 0}, {1e-6, 1e-6, 5e-6}, 100, 5000, count, 11);
  EXPECT_EQ(without.phases(), h.phases());
  EXPECT_EQ(without.at(3e-3).xi_x, h.at(3e-3).xi_x);
  EXPECT_FALSE(without.has_normal_variation());
  double sum = 0;
  const double t = 2.1e-3;
  for (int n = 0; n < count; ++n)
    sum += std::cos(2 * M_PI * h.frequencies()[n] * t + h.normal_phases()[n]);
  EXPECT_NEAR(h.normal_variation(t), 200.0 * sum, 1e-9);
}

TEST(CreepageHistory, SampledNormalLoadIsInterpolatedLikeTheCreepages) {
  const auto h = CreepageHistory::samples(
      {0, 0, 0}, {0.0, 1.0, 3.0}, {{0, 0, 0}, {1e-3, 0, 0}, {0, 0, 0}}, {0.0, 100.0, -300.0});
  EXPECT_TRUE(h.has_normal_variation());
  EXPECT_NEAR(h.normal_variation(0.5), 50.0, 1e-12);
  EXPECT_NEAR(h.normal_variation(2.0), -100.0, 1e-12);
  EXPECT_EQ(h.normal_variation(9.0), -300.0);
  EXPECT_FALSE(CreepageHistory::samples({0, 0, 0}, {0.0, 1.0}, {{}, {}}).has_normal_variation());
#ifndef NDEBUG  // contracts: io checks the case's values naming excitation.* (tests/cli BadNormalLoadTest)
  EXPECT_THROW(CreepageHistory::harmonic({0, 0, 0}, {0, 0, 0}, 1000.0, {}, INFINITY), std::logic_error);
  EXPECT_THROW(CreepageHistory::harmonic({0, 0, 0}, {0, 0, 0}, 0.0, {}), std::logic_error);
#endif
}
