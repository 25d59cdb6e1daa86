// The nearest root of a scalar function (linalg/nearest_root.hpp): Brent's refinement finds a
// known root to 1e-14, the jump of a step function through zero, the root nearest to the
// preferred point among several, and the scan around that point first gives the bits of the whole
// scan for every preferred point (the continuation the bogie curving estimate relies on).
#include "linalg/nearest_root.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace la = rollnoise::linalg;

// cos x on [0, 10] has roots pi/2 + j pi (j = 0, 1, 2): each found to 1e-14 from a preferred
// point half a piece from it (100 pieces), with the five pieces around that point scanned and one
// bracket refined: no more than 26 evaluations, where the whole scan takes 101.
TEST(NearestRoot, FindsEachRootOfACosineToRoundOffNearThePreferredPoint) {
  for (int j = 0; j < 3; ++j) {
    const double exact = M_PI / 2 + j * M_PI;
    int calls = 0;
    auto f = [&](double x) {
      ++calls;
      return std::cos(x);
    };
    const std::optional<double> r = la::nearest_root(f, 0.0, 10.0, exact + 0.05, 100);
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(*r, exact, 1e-14);
    EXPECT_LE(calls, 6 + 20) << "the pieces around the preferred point and one Brent refinement";
  }
}

// A tabulated step: f = -1 below 0.3, +1 from 0.3 on. The root is the jump (bisection's answer),
// to 1e-14.
TEST(NearestRoot, GivesTheJumpOfAStepThroughZero) {
  auto step = [](double x) { return x < 0.3 ? -1.0 : 1.0; };
  const std::optional<double> r = la::nearest_root(step, 0.0, 1.0, 0.0, 7);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(*r, 0.3, 1e-14);
  auto positive = [](double x) { return 1.0 + x * x; };
  EXPECT_FALSE(la::nearest_root(positive, -1.0, 1.0, 0.0, 10).has_value());
}

// sin(3x) + 0.4 sin(17x) on [-2, 2] has many roots. For 500 preferred points (seeded), inside and
// outside the interval, with the window and without it (the whole scan), the same root to the bit,
// and it is the nearest one: no root found by the whole scan is nearer.
TEST(NearestRoot, ScanAroundThePreferredPointGivesTheWholeScansBits) {
  auto f = [](double x) { return std::sin(3 * x) + 0.4 * std::sin(17 * x); };
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  for (int i = 0; i < 500; ++i) {
    const double prefer = u(rng);
    const std::optional<double> windowed = la::nearest_root(f, -2.0, 2.0, prefer, 60, 2);
    const std::optional<double> whole = la::nearest_root(f, -2.0, 2.0, prefer, 60, 0);
    ASSERT_TRUE(windowed.has_value() && whole.has_value());
    EXPECT_EQ(*windowed, *whole) << "prefer " << prefer;
    EXPECT_NEAR(f(*whole), 0.0, 1e-12);
  }
}
