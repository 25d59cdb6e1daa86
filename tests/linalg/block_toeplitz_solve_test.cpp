// The block Levinson solver (linalg/block_toeplitz_solve.hpp, Eqs. L1-L2): a complex,
// non-symmetric block Toeplitz system solved as a dense LU solves it, for several right-hand
// sides; a matrix whose first block is singular (regular as a whole: Levinson cannot pivot across
// blocks) is refused rather than solved wrongly.
#include "linalg/block_toeplitz_solve.hpp"

#include <gtest/gtest.h>

#include <random>

namespace la = rollnoise::linalg;
using Block = la::BlockToeplitzSolver::Block;

namespace {

// t(d) decaying as 0.6^|d| with a dominant t(0), complex and without symmetry (seeded).
struct RandomToeplitz {
  std::vector<Block> lower, upper;
  Eigen::MatrixXcd dense;
};
RandomToeplitz random_toeplitz(int m, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n;
  auto block = [&](double scale) {
    Block b;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) b(i, j) = {scale * n(rng), scale * n(rng)};
    return b;
  };
  RandomToeplitz t;
  for (int d = 0; d < m; ++d) {
    t.lower.push_back(block(std::pow(0.6, d)));
    t.upper.push_back(block(std::pow(0.6, d)));
  }
  t.lower[0] += 6.0 * Block::Identity();
  t.upper[0] = t.lower[0];
  t.dense.resize(4 * m, 4 * m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      t.dense.block<4, 4>(4 * i, 4 * j) = i >= j ? t.lower[i - j] : t.upper[j - i];
  return t;
}

}  // namespace

// m = 40 blocks (160 unknowns), 5 right-hand sides: the solution of the dense LU within 1e-12 of
// its largest entry, and the residual check passes.
TEST(BlockToeplitzSolve, SolvesANonSymmetricComplexSystemAsTheDenseLuDoes) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const RandomToeplitz t = random_toeplitz(40, seed);
    std::mt19937 rng(seed + 100);
    std::normal_distribution<double> n;
    Eigen::MatrixXcd B(160, 5);
    for (int i = 0; i < B.size(); ++i) B(i) = {n(rng), n(rng)};
    const la::BlockToeplitzSolver solver(t.lower, t.upper);
    ASSERT_TRUE(solver.ok());
    const std::optional<Eigen::MatrixXcd> X = solver.solve(B);
    ASSERT_TRUE(X.has_value());
    const Eigen::MatrixXcd reference = t.dense.partialPivLu().solve(B);
    EXPECT_LE((*X - reference).cwiseAbs().maxCoeff(), 1e-12 * reference.cwiseAbs().maxCoeff())
        << "seed " << seed;
  }
}

// t(0) singular (its first row and column zero), the whole T regular: the recursion stops at the
// first pivot and solve() gives nothing, so that the caller's dense solve takes over.
TEST(BlockToeplitzSolve, RefusesASingularLeadingBlock) {
  RandomToeplitz t = random_toeplitz(10, 7);
  t.lower[0].row(0).setZero();
  t.lower[0].col(0).setZero();
  t.upper[0] = t.lower[0];
  const la::BlockToeplitzSolver solver(t.lower, t.upper);
  EXPECT_FALSE(solver.ok());
  EXPECT_FALSE(solver.solve(Eigen::MatrixXcd::Ones(40, 1)).has_value());
}
