// Linear time-invariant state-space models: continuous x' = A x + B u, y = C x + D u, and discrete
// x_{k+1} = A x_k + B u_k, y_k = C x_k + D u_k; their frequency responses, an exact simulation of
// the continuous model under a piecewise-linear input, and the minimal realisation of a discrete
// impulse response (Markov parameters) by the Eigensystem Realization Algorithm.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace rollnoise::linalg {

struct StateSpace {
  Eigen::MatrixXd A, B, C, D;  ///< n x n, n x m, p x n, p x m
  int order() const { return static_cast<int>(A.rows()); }
  int inputs() const { return static_cast<int>(D.cols()); }
  int outputs() const { return static_cast<int>(D.rows()); }
  /// C (sI - A)^{-1} B + D (p x m).
  Eigen::MatrixXcd response(std::complex<double> s) const;
  /// Continuous model at s = 2 pi i f (f in Hz).
  Eigen::MatrixXcd frequency_response(double frequency) const;
  /// Discrete model with step dt at z = e^{i w dt}: D + C (zI - A)^{-1} B, i.e. sum_j H_j e^{-i w j
  /// dt} with the Markov parameters H_0 = D, H_j = C A^{j-1} B.
  Eigen::MatrixXcd discrete_frequency_response(double frequency, double dt) const;
  /// The discrete model's Markov parameters H_0 ... H_{count-1}.
  std::vector<Eigen::MatrixXd> markov_parameters(int count) const;
};

/// The discrete model with step dt whose transfer is the continuous model's at the bilinear
/// (Tustin) map of z: G_d(z) = G_c(s'), s' = (2/dt)(z - 1)/(z + 1), identically in z (Franklin,
/// Powell, Workman, Digital Control of Dynamic Systems, 3rd ed., Sec. 6.3.1, Eq. 6.48), so that on
/// the unit circle G_d(e^{i w dt}) = G_c(i (2/dt) tan(w dt/2)) (the frequency warped, not
/// approximated). With a = 2/dt and M = (aI - A)^{-1}: Ad = M (aI + A), Bd = sqrt(2a) M B,
/// Cd = sqrt(2a) C M, Dd = D + C M B. A stable pole (Re < 0) maps into the unit disc.
StateSpace bilinear_discretisation(const StateSpace& continuous, double dt);

/// The continuous model's output y(t_k), t_k = k h, from x(0) = 0, for the input u(t) linear
/// between the samples u_k = u(t_k) (first-order hold): exact, by the matrix exponential of the
/// augmented system [[A, B, 0], [0, 0, I], [0, 0, 0]] h (Franklin, Powell, Workman, Digital Control
/// of Dynamic Systems, 3rd ed., Sec. 6.3.2, "triangle-hold equivalent").
std::vector<Eigen::VectorXd> simulate_first_order_hold(const StateSpace& m, double h,
                                                       const std::vector<Eigen::VectorXd>& u);

/// Diagonal scalings of the outputs and inputs of a matrix-valued response H (p x m) that make its
/// entries comparable whatever their units: H_scaled = diag(1/output) H diag(1/input). From the
/// peak magnitudes P_ij = max over the samples of |H_ij| by Ruiz's equilibration (D. Ruiz, "A
/// scaling algorithm to equilibrate both rows and columns norms in matrices", RAL-TR-2001-034):
/// repeatedly divide each row and column by the square root of its largest entry, so that every
/// row and every column of the scaled P peaks at 1. A zero row or column keeps the scale 1.
/// Norms of H_scaled are invariant to a change of units of any input or output.
struct IoScaling {
  Eigen::VectorXd output, input;
};
IoScaling equilibrate(const Eigen::MatrixXd& peak);

/// Minimal realisation of a discrete impulse response by the Eigensystem Realization Algorithm
/// (Ho and Kalman 1966; Juang and Pappa, J. Guidance 8 (1985) 620-627, Eqs. 14-21): the block
/// Hankel matrix H(0) of H_1, H_2, ... (as square as the sequence allows), its SVD H(0) = U S V',
/// the order n = the singular values above `tolerance` times the largest, and
///   A = S_n^{-1/2} U_n' H(1) V_n S_n^{-1/2},  B = first m columns of S_n^{1/2} V_n',
///   C = first p rows of U_n S_n^{1/2},  D = H_0,
/// H(1) the Hankel matrix shifted by one step. `markov` holds H_0, H_1, ... (all p x m). The
/// Hankel matrices are built from the equilibrated H_j (IoScaling of their peaks), so that the
/// order test weighs every input and output alike; B and C are scaled back.
struct Realisation {
  StateSpace model;
  Eigen::VectorXd singular_values;  ///< of H(0), descending
  IoScaling scaling;                ///< of the H_j (see above)
  /// max_j |S(C A^{j-1} B - H_j)|_F / max_j |S H_j|_F over the given H_j, j >= 1, S the scaling
  double markov_error = 0.0;
};
Realisation eigensystem_realisation(const std::vector<Eigen::MatrixXd>& markov,
                                    double tolerance = 1e-10);

}  // namespace rollnoise::linalg
