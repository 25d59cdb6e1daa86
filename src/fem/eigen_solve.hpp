// The lowest modes of K phi = omega^2 M phi (K, M symmetric, M positive definite, K positive
// definite once the fixed DOFs are removed) by Spectra's sparse shift-invert Lanczos (Debian
// libspectra-dev), in standard form with the LDL^T factors of K - sigma M (Euclidean inner
// products: no M product in the Lanczos recursion): all modes with omega <= omega_max,
// mass-normalised.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

namespace rollnoise::fem {

/// Modes: omega (rad/s, ascending) and the shapes (columns, full DOF vectors with zeros at the
/// fixed DOFs) normalised to phi^T M phi = 1.
struct Modes {
  Eigen::VectorXd omega;
  Eigen::MatrixXd shapes;
};

/// All modes with omega <= omega_max, the DOFs `fixed` held at zero, of a sequence of problems
/// with one sparsity pattern (the orders n of one axisymmetric mesh). Shift sigma slightly below 0
/// (K - sigma M positive definite); the number of requested modes starts at the expected count plus
/// two (8 when unknown) and doubles until one mode exceeds omega_max. The sparse LDL^T's symbolic
/// analysis (AMD ordering, elimination tree) is done once for the pattern and reused by every
/// problem with the same pattern (re-done when it differs): per problem one numeric factorisation.
/// One solver per thread (it holds the factorisation): the orders n may run on several.
class LowestModesSolver {
 public:
  LowestModesSolver(std::vector<int> fixed, double omega_max);
  ~LowestModesSolver();
  LowestModesSolver(const LowestModesSolver&) = delete;
  LowestModesSolver& operator=(const LowestModesSolver&) = delete;

  /// The modes of K phi = omega^2 M phi; `expected` a guess of their count (e.g. the previous
  /// order's), < 0 unknown. Throws NumericalError when Spectra does not converge.
  Modes solve(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
              int expected = -1);

  /// The number of eigenvalues omega^2 < omega_max^2 of the same problem without solving it, by
  /// Sylvester's law of inertia: the negative pivots of the LDL^T of K - omega_max^2 M (free DOFs;
  /// one numeric factorisation on the shared symbolic analysis, no pivoting). -1 when the
  /// factorisation meets a zero pivot. A guess of solve()'s mode count (equal to it unless an
  /// eigenvalue lies within round-off of omega_max^2): what lets the orders n run in parallel.
  int count_below(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass);

 private:
  struct Factorisation;
  std::vector<int> fixed_;
  double omega_max_;
  std::unique_ptr<Factorisation> factorisation_;
};

/// One problem: LowestModesSolver(fixed, omega_max).solve(stiffness, mass).
Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const std::vector<int>& fixed,
                   double omega_max);

}  // namespace rollnoise::fem
