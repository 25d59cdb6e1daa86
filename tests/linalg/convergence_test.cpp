// linalg::observed_order: the one-term error model e_i = C (dx_i^p - dx_ref^p) against the finest
// grid recovers the order of a known power law, where a straight log-log slope does not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "linalg/convergence.hpp"

using rollnoise::linalg::observed_order;

namespace {

// Errors against the finest grid of q_h = q + c dx^p (+ a small seeded relative perturbation).
std::vector<double> errors_against_finest(const std::vector<double>& dx, double p, double noise) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-noise, noise);
  const double q = 1.0, c = 3.0;
  std::vector<double> qh;
  for (double h : dx) qh.push_back(q + c * std::pow(h, p) * (1.0 + u(rng)));
  std::vector<double> e;
  for (double v : qh) e.push_back(std::abs(v - qh.back()) / std::abs(qh.back()));
  return e;
}

const std::vector<double> kDx = {2e-3, 1.4e-3, 1e-3, 0.7e-3, 0.5e-3};

}  // namespace

TEST(ObservedOrder, RecoversFirstAndSecondOrderPowerLaws) {
  for (double p : {1.0, 2.0}) {
    const auto o = observed_order(kDx, errors_against_finest(kDx, p, 0.0));
    EXPECT_NEAR(o.p, p, 0.002) << "p = " << p;  // the scan's resolution
    EXPECT_EQ(o.points, 4);
    EXPECT_LT(o.scatter, 1.01);
    // the estimated own error of the reference grid is c dx_ref^p / q
    EXPECT_NEAR(o.error_at(kDx.back()) / (3.0 * std::pow(kDx.back(), p)), 1.0, 0.02);
  }
}

TEST(ObservedOrder, LogLogSlopeAgainstFinestGridOverestimatesTheOrder) {
  // Why the model subtracts dx_ref^p: the slope of log e through the two coarsest grids is steeper
  // than p, because e falls to zero at the reference.
  const auto e = errors_against_finest(kDx, 1.0, 0.0);
  const double slope = std::log(e[0] / e[1]) / std::log(kDx[0] / kDx[1]);
  EXPECT_GT(slope, 1.2);
  EXPECT_NEAR(observed_order(kDx, e).p, 1.0, 0.002);
}

TEST(ObservedOrder, PerturbedPowerLawKeepsItsOrderAndShowsScatter) {
  const auto o = observed_order(kDx, errors_against_finest(kDx, 1.5, 0.05));
  EXPECT_NEAR(o.p, 1.5, 0.3);
  EXPECT_GT(o.scatter, 1.0);
}

TEST(ObservedOrder, NoOrderFromFewerThanTwoGridsBesidesTheReference) {
  const std::vector<double> dx = {1e-3, 0.5e-3};
  const auto o = observed_order(dx, {0.1, 0.0});
  EXPECT_EQ(o.points, 1);
  EXPECT_TRUE(std::isnan(o.p));
}
