// fem::LowestModesSolver (src/fem/eigen_solve.hpp): one solver for the orders n of a mesh keeps
// the sparse LDL^T's symbolic analysis and starts Lanczos from the previous order's count. Checked
// on a small annular section (a ring 0.1-0.5 m, 40 mm thick, 25 mm mesh: a few hundred DOFs, where
// the dense generalised eigensolver is the reference):
//  - every mode below f_max is found, with the reference's frequency to 1e-8 (relative), whatever
//    the guess of their count (0, exact, far too many: the count doubles until one exceeds f_max);
//  - the shapes are the reference's (mass-normalised, |phi^T M phi_ref| = 1 to 1e-6);
//  - a problem of another pattern through the same solver is analysed afresh and gives its modes;
//  - K - sigma M merged from the compressed K and M equals the restricted sparse difference (bits);
//  - fem::AxisymmetricOrders (K_n = c_n (K_0 + n K_1 + n^2 K_2)) equals the direct assembly of each
//    order to 1e-13 (relative to the largest entry).
#include "fem/eigen_solve.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "fem/axisymmetric.hpp"
#include "fem/mesh.hpp"

using namespace rollnoise::fem;

namespace {

using rollnoise::kPi;
constexpr double kFmax = 4000.0;  // Hz

struct Problem {
  AxisymmetricMatrices km;
  std::vector<int> fixed;
};

// The ring r = 0.1 .. 0.5 m, z = -h/2 .. h/2, clamped at the bore (segment 3), order n.
Problem ring(double h, double mesh_size, int n) {
  const std::vector<Eigen::Vector2d> section = {
      {0.1, -h / 2}, {0.5, -h / 2}, {0.5, h / 2}, {0.1, h / 2}};
  const auto mesh = mesh_polygon(section, mesh_size);
  Problem p{assemble_axisymmetric(mesh, {}, n), {}};
  for (int node : nodes_on_segments(mesh, {3}))
    for (int c = 0; c < 3; ++c) p.fixed.push_back(3 * node + c);
  return p;
}

// Reference: the dense generalised eigensolver on the free DOFs, eigenvalues (rad/s)^2 ascending.
Eigen::VectorXd dense_lambda(const Problem& p) {
  const Eigen::Index n = p.km.stiffness.rows();
  std::vector<bool> fixed(n, false);
  for (int d : p.fixed) fixed[d] = true;
  std::vector<int> free;
  for (int d = 0; d < n; ++d)
    if (!fixed[d]) free.push_back(d);
  const Eigen::MatrixXd k = p.km.stiffness, m = p.km.mass;
  const auto nf = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd kf(nf, nf), mf(nf, nf);
  for (Eigen::Index i = 0; i < nf; ++i)
    for (Eigen::Index j = 0; j < nf; ++j)
      kf(i, j) = k(free[i], free[j]), mf(i, j) = m(free[i], free[j]);
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(kf, mf).eigenvalues();
}

void expect_all_modes_below_fmax(const Modes& modes, const Eigen::VectorXd& reference, int n) {
  const double lambda_max = std::pow(2 * kPi * kFmax, 2);
  int count = 0;
  while (count < reference.size() && reference(count) <= lambda_max) ++count;
  ASSERT_GT(count, 0) << "n = " << n << ": no mode below f_max, the check would be empty";
  ASSERT_EQ(modes.omega.size(), count) << "n = " << n;
  for (int j = 0; j < count; ++j)
    EXPECT_NEAR(modes.omega(j), std::sqrt(reference(j)), 1e-8 * std::sqrt(reference(j)))
        << "n = " << n << ", mode " << j;
}

TEST(LowestModesSolver, ReusedOverOrdersFindsEveryModeBelowFmaxWhateverTheGuess) {
  LowestModesSolver solver(ring(0.04, 0.025, 0).fixed, 2 * kPi * kFmax);
  int previous = -1;
  for (int n = 0; n <= 3; ++n) {
    const Problem p = ring(0.04, 0.025, n);
    ASSERT_GE(p.km.stiffness.rows() - static_cast<Eigen::Index>(p.fixed.size()), 60)
        << "too small for the Lanczos path";
    const Eigen::VectorXd reference = dense_lambda(p);
    const Modes modes = solver.solve(p.km.stiffness, p.km.mass, previous);
    expect_all_modes_below_fmax(modes, reference, n);
    for (int guess : {0, 40})
      expect_all_modes_below_fmax(solver.solve(p.km.stiffness, p.km.mass, guess), reference, n);
    // the same shapes as a fresh solver's, mass-normalised
    const Modes fresh = lowest_modes(p.km.stiffness, p.km.mass, p.fixed, 2 * kPi * kFmax);
    ASSERT_EQ(fresh.omega.size(), modes.omega.size());
    for (int j = 0; j < modes.omega.size(); ++j)
      EXPECT_NEAR(std::abs(modes.shapes.col(j).dot(p.km.mass * fresh.shapes.col(j))), 1.0, 1e-6)
          << "n = " << n << ", mode " << j;
    previous = static_cast<int>(modes.omega.size());
  }
}

TEST(LowestModesSolver, AnotherPatternIsAnalysedAfresh) {
  const Problem p = ring(0.04, 0.025, 2);
  LowestModesSolver solver(p.fixed, 2 * kPi * kFmax);
  const Modes first = solver.solve(p.km.stiffness, p.km.mass);
  // The same problem with two explicit zeros coupling the first and the last free DOF: another
  // sparsity pattern (the old elimination tree would not hold its fill), the same modes.
  Eigen::SparseMatrix<double> k = p.km.stiffness;
  const int last = static_cast<int>(k.rows()) - 1;
  std::vector<bool> fixed(k.rows(), false);
  for (int d : p.fixed) fixed[d] = true;
  int first_free = 0;
  while (fixed[first_free]) ++first_free;
  ASSERT_FALSE(fixed[last]);
  ASSERT_EQ(k.coeff(first_free, last), 0.0) << "the DOFs are coupled already";
  k.coeffRef(first_free, last) = 0.0;
  k.coeffRef(last, first_free) = 0.0;
  k.makeCompressed();
  ASSERT_EQ(k.nonZeros(), p.km.stiffness.nonZeros() + 2);
  const Modes again = solver.solve(k, p.km.mass, static_cast<int>(first.omega.size()));
  expect_all_modes_below_fmax(again, dense_lambda(p), 2);
}

// K - sigma M on the free DOFs is merged from the full K and M in one pass when their storage is
// compressed, and formed by Eigen's restriction and sparse difference otherwise: the two give the
// same matrix, so the modes and the inertia count are the same to the bit (tolerance 0); M's
// pattern lies within K's (like components of coupled nodes), which the merge needs.
TEST(LowestModesSolver, ShiftedMatrixMergedOnTheFreeDofsEqualsTheRestrictedDifference) {
  const Problem p = ring(0.04, 0.025, 2);
  Eigen::SparseMatrix<double> k = p.km.stiffness, m = p.km.mass;
  ASSERT_TRUE(k.isCompressed() && m.isCompressed());
  LowestModesSolver merged(p.fixed, 2 * kPi * kFmax);
  const Modes a = merged.solve(k, m, 3);
  const int count_a = merged.count_below(k, m);
  k.uncompress();  // the other path
  m.uncompress();
  LowestModesSolver formed(p.fixed, 2 * kPi * kFmax);
  const Modes b = formed.solve(k, m, 3);
  const int count_b = formed.count_below(k, m);
  ASSERT_GT(a.omega.size(), 0);
  EXPECT_EQ(count_a, a.omega.size());
  EXPECT_EQ(count_a, count_b);
  EXPECT_TRUE(a.omega == b.omega);
  EXPECT_TRUE(a.shapes == b.shapes);
}

TEST(AxisymmetricOrders, EqualTheDirectAssemblyOfEachOrder) {
  const std::vector<Eigen::Vector2d> section = {
      {0.1, -0.02}, {0.5, -0.02}, {0.5, 0.02}, {0.1, 0.02}};
  const auto mesh = mesh_polygon(section, 0.025);
  const AxisymmetricOrders orders(mesh, {});
  for (int n : {0, 1, 2, 5, 10}) {
    const AxisymmetricMatrices direct = assemble_axisymmetric(mesh, {}, n),
                               parts = orders.matrices(n);
    const Eigen::MatrixXd k = direct.stiffness, m = direct.mass;
    EXPECT_LE((Eigen::MatrixXd(parts.stiffness) - k).cwiseAbs().maxCoeff(),
              1e-13 * k.cwiseAbs().maxCoeff())
        << "n = " << n;
    EXPECT_LE((Eigen::MatrixXd(parts.mass) - m).cwiseAbs().maxCoeff(),
              1e-13 * m.cwiseAbs().maxCoeff())
        << "n = " << n;
    EXPECT_EQ(parts.stiffness.nonZeros(), orders.matrices(0).stiffness.nonZeros())
        << "one pattern for every n";
  }
}

}  // namespace
