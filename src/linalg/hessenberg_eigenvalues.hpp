// The eigenvalues of a real upper Hessenberg matrix, by LAPACK's dhseqr (the small-bulge multishift
// QR algorithm with aggressive early deflation: Braman, Byers & Mathias, SIAM J. Matrix Anal.
// Appl. 23, 2002; Anderson et al., LAPACK Users' Guide, 3rd ed. 1999), eigenvalues only, on the
// matrix as it is (no Hessenberg reduction: it is one already).
//
// Used for the spectral radius of the linear contact model's Hessenberg form (nss/paper_form.cpp),
// where Eigen's EigenSolver first reduces the matrix to Hessenberg form again and then runs the
// plain Francis double-shift QR: measured 2.5 s against 0.35 s for n = 1284 (a random Hessenberg
// matrix; docs/record/performance.md Sec. 20).
#pragma once

#include <Eigen/Core>

namespace rollnoise::linalg {

/// The n eigenvalues of the real upper Hessenberg matrix H (entries below the subdiagonal are not
/// read). NumericalError when the QR iteration does not converge.
Eigen::VectorXcd hessenberg_eigenvalues(Eigen::MatrixXd H);

}  // namespace rollnoise::linalg
