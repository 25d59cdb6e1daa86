// The lowest modes of K phi = omega^2 M phi (K, M symmetric, M positive definite, K positive
// definite once the fixed DOFs are removed) by Spectra's sparse shift-invert Lanczos (Debian
// libspectra-dev): all modes with omega <= omega_max, mass-normalised.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

namespace rollnoise::fem {

/// Modes: omega (rad/s, ascending) and the shapes (columns, full DOF vectors with zeros at the
/// fixed DOFs) normalised to phi^T M phi = 1.
struct Modes {
  Eigen::VectorXd omega;
  Eigen::MatrixXd shapes;
};

/// All modes with omega <= omega_max, the DOFs `fixed` held at zero. Shift sigma = 0 (K is
/// nonsingular with the supports); the number of requested modes grows until one exceeds omega_max.
/// Throws NumericalError when Spectra does not converge.
Modes lowest_modes(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const std::vector<int>& fixed,
                   double omega_max);

}  // namespace rollnoise::fem
