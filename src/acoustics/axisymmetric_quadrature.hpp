// Quadrature rules and special functions of the axisymmetric boundary elements
// (acoustics/axisymmetric_bem.hpp): Gauss-Legendre, Gauss with the weight ln(1/t), the complete
// elliptic integrals K and E of a parameter given by its complement, and cos and sin of a block.
#pragma once

#include <Eigen/Core>

namespace rollnoise::acoustics {

/// Nodes and weights of a rule on [0, 1]: int_0^1 w(t) f(t) dt ~ sum_j weights_j f(nodes_j).
struct AxisymmetricQuadratureRule {
  Eigen::VectorXd nodes;
  Eigen::VectorXd weights;
};

/// Gauss-Legendre on [0, 1] (w = 1), exact for polynomials of degree <= 2 n - 1; n >= 1; ascending
/// (GSL's tables, linalg/gauss_legendre.hpp).
AxisymmetricQuadratureRule axisymmetric_gauss_legendre(int n);

/// Gauss rule of the logarithmic weight w(t) = ln(1/t) on [0, 1], exact for polynomials of degree
/// <= 2 n - 1; 1 <= n <= 24. Recurrence coefficients by the modified Chebyshev algorithm from the
/// modified moments against the shifted Legendre polynomials,
///   int_0^1 P*_0 ln(1/t) dt = 1,  int_0^1 P*_k ln(1/t) dt = (-1)^k / (k (k + 1))  (k >= 1),
/// which is well conditioned (Gautschi, Orthogonal Polynomials: Computation and Approximation,
/// 2004, Sec. 2.1.7 and Example 2.27); nodes and weights from the Jacobi matrix (Golub & Welsch,
/// Math. Comp. 23, 1969).
AxisymmetricQuadratureRule axisymmetric_log_gauss(int n);

/// The complete elliptic integrals of the first and second kind,
///   K(m) = int_0^{pi/2} (1 - m sin^2 t)^{-1/2} dt,  E(m) = int_0^{pi/2} (1 - m sin^2 t)^{1/2} dt,
/// of the parameter m = 1 - m1, given by its complement m1 in (0, 1] so that the logarithmic end
/// m -> 1 (K ~ ln(4 / sqrt(m1))) keeps full relative accuracy. By the arithmetic-geometric mean
/// (Abramowitz & Stegun 17.6.1-17.6.4): K = pi / (2 a_N), E = K (1 - sum_j 2^{j-1} c_j^2),
/// a_0 = 1, b_0 = sqrt(m1), c_0 = sqrt(m).
struct AxisymmetricEllipticKE {
  double K = 0.0;
  double E = 0.0;
};
AxisymmetricEllipticKE axisymmetric_elliptic_ke(double m1);

/// cos(x_i) and sin(x_i) of a block of n arguments (|x_i| < 1e6), to ~2e-16 absolute: the phase
/// factors e^{-ikR} of the kernels, ~4x faster than the C library's sin and cos. Cody-Waite
/// reduction x = r + q pi/2 with pi/2 in three parts (q pi/2 exact for |q| < 2^26), then the
/// minimax polynomials of Cephes (S. L. Moshier, Methods and Programs for Mathematical Functions,
/// 1989; sin.c) on |r| <= pi/4 and the quadrant's swap and signs.
void axisymmetric_cos_sin(int n, const double* x, double* cos_x, double* sin_x);

}  // namespace rollnoise::acoustics
