// Sums of Markov series (linalg/markov_series.hpp): Horner for many points, four per pass, against
// the one-point Horner and the direct sum.
#include "linalg/markov_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

namespace {

using cd = std::complex<double>;

// A decaying series of `n` seeded random terms, like the linear contact model's Markov parameters
// (slow decay over hundreds of steps).
template <class Term>
std::vector<Term> decaying_series(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Term> h(n);
  for (int j = 0; j < n; ++j)
    for (int e = 0; e < Term::SizeAtCompileTime; ++e) h[j].data()[e] = u(rng) * std::exp(-j / 80.0);
  return h;
}

}  // namespace

// 749 terms (the trailing outer wheel's series in curve_300m) at 4k + 1 .. 4k + 3 points as well as
// 4k (the last pass padded), on the unit circle and at |z| = 0.9 and 1.02: each sum within 1e-13
// of the largest entry of the one-point Horner's sum, and that one within 1e-12 of the direct sum.
TEST(MarkovSeries, HornerForManyPointsEqualsTheOnePointSumToRoundOff) {
  const auto h3 = decaying_series<Eigen::Matrix3d>(749, 7);
  const auto h1 = decaying_series<Eigen::Vector3d>(301, 11);
  for (std::size_t count : {1u, 2u, 3u, 4u, 5u, 37u}) {
    std::vector<cd> z;
    for (std::size_t k = 0; k < count; ++k) {
      const double radius = k % 3 == 0 ? 1.0 : (k % 3 == 1 ? 0.9 : 1.02);
      z.push_back(std::polar(radius, -0.37 * double(k) - 0.01));
    }
    const auto f3 = rollnoise::linalg::horner_many<Eigen::Matrix3cd>(h3, z);
    const auto f1 = rollnoise::linalg::horner_many<Eigen::Vector3cd>(h1, z);
    ASSERT_EQ(f3.size(), count);
    ASSERT_EQ(f1.size(), count);
    for (std::size_t k = 0; k < count; ++k) {
      const Eigen::Matrix3cd one3 = rollnoise::linalg::horner<Eigen::Matrix3cd>(h3, z[k]);
      const Eigen::Vector3cd one1 = rollnoise::linalg::horner<Eigen::Vector3cd>(h1, z[k]);
      EXPECT_LT((f3[k] - one3).cwiseAbs().maxCoeff(), 1e-13 * one3.cwiseAbs().maxCoeff())
          << count << " " << k;
      EXPECT_LT((f1[k] - one1).cwiseAbs().maxCoeff(), 1e-13 * one1.cwiseAbs().maxCoeff())
          << count << " " << k;
      Eigen::Matrix3cd direct = Eigen::Matrix3cd::Zero();
      cd power = 1.0;
      for (const auto& term : h3) {
        direct += term.cast<cd>() * power;
        power *= z[k];
      }
      EXPECT_LT((one3 - direct).cwiseAbs().maxCoeff(), 1e-12 * direct.cwiseAbs().maxCoeff());
    }
  }
}
