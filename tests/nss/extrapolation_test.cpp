// Richardson extrapolation with the observed order (nss/extrapolation.hpp) on sequences with a
// known limit: the order and the limit are recovered, the error estimate covers a higher-order
// remainder, and oscillating, out-of-range or two-grid sequences use the assumed order.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "nss/extrapolation.hpp"

using namespace rollnoise;
using C = std::complex<double>;

namespace {

const std::vector<double> kH = {1.0e-3, 1.0e-3 / 1.5, 0.5e-3};  // factors 1, 1.5, 2

std::vector<C> sequence(C limit, C c, double p, C d = 0.0, double q = 0.0) {
  std::vector<C> v;
  for (double h : kH) v.push_back(limit + c * std::pow(h / kH[0], p) + d * std::pow(h / kH[0], q));
  return v;
}

}  // namespace

TEST(Richardson, ObservedOrderAndLimitOfAPowerLawAreRecoveredFromThreeGrids) {
  const C limit(2.0e5, -2.3e6), c(3.0e4, 1.0e5);
  for (double p : {0.7, 1.0, 1.7, 2.0, 3.5}) {
    const auto r = nss::richardson(kH, sequence(limit, c, p));
    EXPECT_TRUE(r.observed) << p;
    EXPECT_NEAR(r.order, p, 1e-8) << p;
    EXPECT_LT(std::abs(r.value - limit), 1e-8 * std::abs(limit)) << p;
  }
}

TEST(Richardson, ErrorEstimateCoversAHigherOrderRemainder) {
  const C limit(1.0, -3.0);
  for (double d : {-0.3, 0.3}) {
    const auto v = sequence(limit, C(0.2, 0.1), 2.0, d * C(0.2, 0.1), 3.0);
    const auto r = nss::richardson(kH, v);
    EXPECT_LT(std::abs(r.value - limit), std::abs(v.back() - limit)) << d;
    EXPECT_LE(std::abs(r.value - limit), r.error) << d;
  }
}

TEST(Richardson, OscillatingOrOutOfRangeSequencesFallBackToTheAssumedOrderOnTheTwoFinestGrids) {
  const C limit(1.0, 0.0);
  const std::vector<C> oscillating = {limit + 0.1, limit - 0.05, limit + 0.02};
  const std::vector<C> too_fast = sequence(limit, C(0.1, 0.0), 6.0);
  for (const auto& v : {oscillating, too_fast}) {
    const auto r = nss::richardson(kH, v, {1.0});
    EXPECT_FALSE(r.observed);
    EXPECT_EQ(r.order, 1.0);
    // (R2) with p = 1 on the two finest grids, and the error estimate with Fs = 3
    const C expected = v[2] + (v[2] - v[1]) * (kH[2] / (kH[1] - kH[2]));
    EXPECT_LT(std::abs(r.value - expected), 1e-14);
    EXPECT_NEAR(r.error, 3.0 * std::abs(expected - v[2]), 1e-14);
  }
  const auto two = nss::richardson({kH[0], kH[2]}, {C(1.4), C(1.1)}, {2.0});
  EXPECT_FALSE(two.observed);
  EXPECT_NEAR(two.value.real(), 1.1 - 0.3 / 3.0, 1e-14);  // h ratio 2, p = 2: v_f + (v_f - v_c) / (4 - 1)
  EXPECT_THROW(nss::richardson({1.0, 2.0}, {C(1.0), C(2.0)}), std::invalid_argument);
}
