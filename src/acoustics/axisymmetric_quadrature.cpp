#include "acoustics/axisymmetric_quadrature.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "linalg/gauss_legendre.hpp"

namespace rollnoise::acoustics {

AxisymmetricQuadratureRule axisymmetric_gauss_legendre(int n) {
  if (n < 1)
    throw std::invalid_argument("Gauss-Legendre rule: at least 1 point, got " + std::to_string(n));
  const linalg::GaussRule rule = linalg::gauss_legendre_01(n);
  return {Eigen::Map<const Eigen::VectorXd>(rule.nodes.data(), n),
          Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), n)};
}

AxisymmetricQuadratureRule axisymmetric_log_gauss(int n) {
  if (n < 1 || n > 24)
    throw std::invalid_argument("logarithmic Gauss rule: 1 to 24 points, got " + std::to_string(n));
  // Monic shifted Legendre polynomials pi_k on [0, 1]: pi_{k+1} = (t - a_k) pi_k - b_k pi_{k-1},
  // a_k = 1/2, b_k = k^2 / (4 (4 k^2 - 1)); pi_k = P*_k (k!)^2 / (2k)!.
  const int m = 2 * n;
  std::vector<double> a(m, 0.5), b(m, 0.0), nu(m);
  for (int k = 1; k < m; ++k) b[k] = double(k) * k / (4.0 * (4.0 * k * k - 1.0));
  double monic = 1.0;  // (k!)^2 / (2k)!
  nu[0] = 1.0;
  for (int k = 1; k < m; ++k) {
    monic *= double(k) * k / ((2.0 * k - 1.0) * (2.0 * k));
    nu[k] = monic * ((k % 2) ? -1.0 : 1.0) / (double(k) * (k + 1));
  }
  // Modified Chebyshev algorithm (Gautschi 2004, Algorithm 2.1): sigma_{k,l} = int pi_k^~ pi_l,
  // pi^~ the monic orthogonal polynomials of the weight.
  std::vector<double> alpha(n), beta(n);
  std::vector<double> sig_prev(m + 1, 0.0), sig(nu.begin(), nu.end()), sig_next(m + 1, 0.0);
  sig.resize(m + 1, 0.0);
  alpha[0] = a[0] + nu[1] / nu[0];
  beta[0] = nu[0];
  for (int k = 1; k < n; ++k) {
    for (int l = k; l <= m - k - 1; ++l) {
      sig_next[l] = sig[l + 1] - (alpha[k - 1] - a[l]) * sig[l] - beta[k - 1] * sig_prev[l] +
                    b[l] * sig[l - 1];
    }
    alpha[k] = a[k] + sig_next[k + 1] / sig_next[k] - sig[k] / sig[k - 1];
    beta[k] = sig_next[k] / sig[k - 1];
    sig_prev.swap(sig);
    sig.swap(sig_next);
  }
  // Golub-Welsch: nodes the eigenvalues of the Jacobi matrix, weights beta_0 v_0j^2.
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    jacobi(k, k) = alpha[k];
    if (k + 1 < n) jacobi(k, k + 1) = jacobi(k + 1, k) = std::sqrt(beta[k + 1]);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobi);
  AxisymmetricQuadratureRule rule{eig.eigenvalues(), Eigen::VectorXd(n)};
  for (int j = 0; j < n; ++j)
    rule.weights(j) = beta[0] * eig.eigenvectors()(0, j) * eig.eigenvectors()(0, j);
  return rule;
}

AxisymmetricEllipticKE axisymmetric_elliptic_ke(double m1) {
  if (!(m1 > 0.0 && m1 <= 1.0))
    throw std::invalid_argument("complete elliptic integrals: complementary parameter m1 = " +
                                std::to_string(m1) + " outside (0, 1]");
  const double pi = 3.14159265358979323846;
  double a = 1.0, b = std::sqrt(m1);
  double c2 = 1.0 - m1;   // c_0^2 = m
  double sum = 0.5 * c2;  // sum_j 2^{j-1} c_j^2
  double power = 0.5;
  for (int it = 0; it < 64; ++it) {
    const double c = 0.5 * (a - b);
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
    power *= 2.0;
    sum += power * c * c;
    if (std::abs(c) <= 1e-17 * a) break;
  }
  AxisymmetricEllipticKE ke;
  ke.K = pi / (2.0 * a);
  ke.E = ke.K * (1.0 - sum);
  return ke;
}

void axisymmetric_cos_sin(int n, const double* x, double* cos_x, double* sin_x) {
  constexpr double two_over_pi = 0.636619772367581343076;
  // pi/2 = p1 + p2 + p3, p1 and p2 with short mantissas (Cephes DP1..DP3, doubled)
  constexpr double p1 = 1.57079625129699707031e+00, p2 = 7.54978941586159635336e-08,
                   p3 = 5.39030285815811905290e-15;
  for (int i = 0; i < n; ++i) {
    const double q = std::nearbyint(x[i] * two_over_pi);
    const double r = ((x[i] - q * p1) - q * p2) - q * p3;
    const double r2 = r * r;
    const double sin_r =
        r + r * r2 *
                (((((1.58962301576546568060e-10 * r2 - 2.50507477628578072866e-8) * r2 +
                    2.75573136213857245213e-6) *
                       r2 -
                   1.98412698295895385996e-4) *
                      r2 +
                  8.33333333332211858878e-3) *
                     r2 -
                 1.66666666666666307295e-1);
    const double cos_r =
        1.0 - 0.5 * r2 +
        r2 * r2 *
            (((((-1.13585365213876817300e-11 * r2 + 2.08757008419747316778e-9) * r2 -
                2.75573141792967388112e-7) *
                   r2 +
               2.48015872888517045348e-5) *
                  r2 -
              1.38888888888730564116e-3) *
                 r2 +
             4.16666666666665929218e-2);
    // quadrant q mod 4: sin x = sin r, cos r, -sin r, -cos r; cos x = cos r, -sin r, -cos r, sin r
    const double quadrant = q - 4.0 * std::floor(0.25 * q);
    const bool odd = quadrant == 1.0 || quadrant == 3.0;
    const double s = odd ? cos_r : sin_r, c = odd ? sin_r : cos_r;
    sin_x[i] = quadrant >= 2.0 ? -s : s;
    cos_x[i] = (quadrant == 1.0 || quadrant == 2.0) ? -c : c;
  }
}

}  // namespace rollnoise::acoustics
