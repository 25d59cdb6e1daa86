// The eigenvalues of a real Hessenberg matrix by LAPACK's QR (linalg/hessenberg_eigenvalues.hpp):
// those of Eigen's general eigensolver for a random one (seeded), and the exact ones of a matrix
// built from known eigenvalues.
#include "linalg/hessenberg_eigenvalues.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <random>

namespace la = rollnoise::linalg;

namespace {
std::vector<std::complex<double>> sorted(const Eigen::VectorXcd& v) {
  std::vector<std::complex<double>> s(v.data(), v.data() + v.size());
  std::sort(s.begin(), s.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return s;
}
}  // namespace

// n = 300, entries N(0, 1) on and above the subdiagonal (seeded), the entries below it set to
// garbage that must not be read: every eigenvalue equal to Eigen's within 1e-9 of the spectral
// radius.
TEST(HessenbergEigenvalues, EqualEigensGeneralSolverOnARandomHessenbergMatrix) {
  const int n = 300;
  std::mt19937 rng(20261127);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd H(n, n), clean = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      H(i, j) = i <= j + 1 ? normal(rng) : 1e6;
      if (i <= j + 1) clean(i, j) = H(i, j);
    }
  const auto mine = sorted(la::hessenberg_eigenvalues(H));
  const auto eigen = sorted(Eigen::EigenSolver<Eigen::MatrixXd>(clean, false).eigenvalues());
  double radius = 0.0;
  for (const auto& e : eigen) radius = std::max(radius, std::abs(e));
  ASSERT_EQ(mine.size(), eigen.size());
  for (std::size_t k = 0; k < mine.size(); ++k)
    EXPECT_LE(std::abs(mine[k] - eigen[k]), 1e-9 * radius) << k;
}

// Q diag(blocks) Q^T reduced to Hessenberg form (Eigen's HessenbergDecomposition), with a real
// pair 0.9 e^{+-0.3 i} and the reals 0.5, -0.7, 0.2: these five to 1e-13.
TEST(HessenbergEigenvalues, RecoversKnownEigenvaluesOfASimilarityTransform) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(5, 5);
  const double r = 0.9, t = 0.3;
  D(0, 0) = D(1, 1) = r * std::cos(t);
  D(0, 1) = r * std::sin(t);
  D(1, 0) = -r * std::sin(t);
  D(2, 2) = 0.5;
  D(3, 3) = -0.7;
  D(4, 4) = 0.2;
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd V(5, 5);
  for (int i = 0; i < 25; ++i) V(i) = normal(rng);
  const Eigen::MatrixXd A = V * D * V.inverse();
  const Eigen::MatrixXd H = Eigen::HessenbergDecomposition<Eigen::MatrixXd>(A).matrixH();
  const auto mine = sorted(la::hessenberg_eigenvalues(H));
  const std::vector<std::complex<double>> exact = sorted(
      (Eigen::VectorXcd(5) << std::polar(r, -t), std::polar(r, t), 0.5, -0.7, 0.2).finished());
  for (int k = 0; k < 5; ++k) EXPECT_LE(std::abs(mine[k] - exact[k]), 1e-13) << k;
}
