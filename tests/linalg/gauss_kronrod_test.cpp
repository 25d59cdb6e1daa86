// The 21-point Gauss-Kronrod rule (linalg/gauss_kronrod.hpp): exact degrees and its Gauss part.
#include "linalg/gauss_kronrod.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "linalg/gauss_legendre.hpp"

// The Kronrod weights integrate t^n, t = 2x - 1, over [0, 1] (1 / (n + 1) for even n, 0 for odd)
// for n <= 31 (its degree), the Gauss weights for n <= 19, both within 1e-15, and neither beyond
// (t^32, t^20: errors above 1e-13 and 1e-6); the Gauss nodes and weights are GSL's 10-point rule's
// within 1e-15.
TEST(GaussKronrod, IntegratesPolynomialsToItsDegreeAndHoldsGslsGaussRule) {
  const rollnoise::linalg::GaussKronrod21 r = rollnoise::linalg::gauss_kronrod_21_01();
  auto moment = [&](const auto& w, int n) {
    double s = 0.0;
    for (std::size_t i = 0; i < r.nodes.size(); ++i) s += w[i] * std::pow(2 * r.nodes[i] - 1, n);
    return s;
  };
  auto exact = [](int n) { return n % 2 == 0 ? 1.0 / (n + 1) : 0.0; };
  for (int n = 0; n <= 31; ++n) EXPECT_NEAR(moment(r.kronrod, n), exact(n), 1e-15) << n;
  for (int n = 0; n <= 19; ++n) EXPECT_NEAR(moment(r.gauss, n), exact(n), 1e-15) << n;
  EXPECT_GT(std::abs(moment(r.kronrod, 32) - exact(32)), 1e-13);
  EXPECT_GT(std::abs(moment(r.gauss, 20) - exact(20)), 1e-6);
  const rollnoise::linalg::GaussRule g = rollnoise::linalg::gauss_legendre_01(10);
  std::size_t j = 0;
  for (std::size_t i = 0; i < r.nodes.size(); ++i) {
    if (r.gauss[i] == 0.0) continue;
    EXPECT_NEAR(r.nodes[i], g.nodes[j], 1e-15);
    EXPECT_NEAR(r.gauss[i], g.weights[j], 1e-15);
    ++j;
  }
  EXPECT_EQ(j, 10u);
}
