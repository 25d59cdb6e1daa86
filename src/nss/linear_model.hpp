// The linear non-steady-state (NSS) tangential contact model (Baeza, Bruni, Giner-Navarro, Liu;
// paper Eqs. 6-30; ../shared/DESIGN.md Sec. 3).
//
// Around a steady solution (p_bar, s_bar) at the mean creepage, with the adhesion and slip areas
// frozen, small creepage variations xi~ e^{i w t} give
//
//   S~ = W~ + (A - z A0) P~ / dt,   z = e^{-i w dt},  dt = dx / V                (paper Eq. 11)
//
// with W~ = V (xi~x U1 + xi~y U2 + phi~ Usp), Usp_e = (-y_e, x_e + spin_offset dx) (Eq. 20-21).
// Adhesion elements: S~_e = 0, unknown P~_e. Slip elements: P~_e = K_e S~_e with the derivative of
// -mu pn s/|s| (paper Eq. 9), K_e = -(mu pn/|s_bar|) t t^T, t = (s2, -s1)/|s_bar|.
//
// Unknowns and scaling. The paper's unknowns are P~ (adhesion) and S~ (slip). K_e grows like
// 1/|s_bar|, which blows up for slip elements next to the adhesion area. We scale the slip unknown to
// a traction, q_e = (mu pn_e/|s_bar_e|) S~_e, so that P~_e = B_e q_e with B_e = -t t^T (bounded) and
// S~_e = c_e q_e with c_e = |s_bar_e|/(mu pn_e). This is a column scaling of the paper's system (the
// same solution) that keeps every column of the order of the elastic compliance; as |s_bar| -> 0 the
// element tends continuously to adhesion across t. c_e is floored at 1e-12 times the self-compliance
// A_ee/dt so that the pencil stays regular when |s_bar| underflows.
//
// With Q = (p~ for adhesion, q for slip), P~ = B Q, S~ = C Q:
//   M(z) Q = W~,  M(z) = M0 - z M1,  M0 = C - A B/dt,  M1 = -A0 B/dt.
// (The paper prints "+" in Eqs. 14, 22, 24, which with its own Eqs. 9 and 11 gives -f; this sign
// is the consistent one, checked against CONTACT: DESIGN.md Sec. 3.)
// Outputs F~x = dx dy U1' P~, F~y = dx dy U2' P~, M~z = dx dy Usp0' P~ with Usp0_e = (-y_e, x_e): the
// spin offset belongs to the input only. Creep coefficients: F~ = -f xi~ (Eqs. 28-30), rows Fx, Fy,
// Mz, columns xi_x, xi_y, phi.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::nss {

using CreepMatrix = Eigen::Matrix3cd;

struct LinearModelInput {
  double mu = 0.3;           ///< friction coefficient
  double speed = 0.0;        ///< rolling speed V (m/s)
  double spin_offset = 0.0;  ///< as in the steady solution (grid.spin_offset)
};

class LinearContactModel {
 public:
  /// `mean` is the steady solution at the mean creepage on `patch` (same mu, speed, spin offset).
  LinearContactModel(const contact::ContactPatch& patch, const contact::TangentialSolution& mean,
                     const LinearModelInput& in);

  int unknowns() const { return static_cast<int>(M0_.rows()); }
  int adhesion_elements() const { return n_adhesion_; }
  int slip_elements() const { return n_slip_; }
  double time_step() const { return dt_; }
  /// Highest frequency the grid resolves: V / (2 dx) (w dt = pi) (Hz).
  double nyquist_frequency() const { return 0.5 / dt_; }

  /// f(omega) by a fresh complex LU of M(z) (the reference; O(n^3) per frequency).
  CreepMatrix creep_coefficients_direct(double frequency) const;

  /// f at many frequencies (the default, fast): from the Markov parameters (impulse response) of
  /// the discrete-time system,  f(w) = -sum_j h_j z^j,  h_j = L' (M0^{-1} M1)^j M0^{-1} W,
  /// computed with the one real LU of M0 until they have decayed to round-off (the contact
  /// forgets its past within a few contact lengths: |h_j| falls by ~1e-14 in 16 contact lengths on
  /// the paper's grid, by ~1e-12 at zero mean creepage), then O(J) per frequency. If they have not
  /// decayed within `max_contact_lengths`, it falls back to creep_coefficients_hessenberg().
  /// Throws InputError above the Nyquist limit.
  std::vector<CreepMatrix> creep_coefficients(const std::vector<double>& frequencies,
                                              int max_contact_lengths = 60) const;

  /// f at many frequencies by the reduced pencil: one Hessenberg reduction of M0^{-1} M1 (real),
  /// then an O(n^2) Hessenberg solve per frequency. Exact (no truncation), slower.
  std::vector<CreepMatrix> creep_coefficients_hessenberg(const std::vector<double>& frequencies) const;

  /// The Markov parameters used by creep_coefficients (empty until first used).
  const std::vector<Eigen::Matrix3d>& markov_parameters() const { return markov_; }

  /// Force variations (Fx, Fy, Mz) at t_k = k dt for the creepage variations at t_k (k = 0, 1, ...)
  /// by the discrete-time recursion M0 Q_k = M1 Q_{k-1} + W_k, Q_{-1} = 0 (one factorisation).
  std::vector<Eigen::Vector3d> time_response(const std::vector<Eigen::Vector3d>& creepage_variation) const;

  /// Throw InputError (key "frequency") unless 0 <= f <= Nyquist.
  void check_frequency(double frequency) const;

 private:
  void reduce() const;  // lazily builds the Hessenberg form for the sweeps

  double dt_ = 0.0, speed_ = 0.0;
  int steps_per_contact_length_ = 1;
  mutable std::vector<Eigen::Matrix3d> markov_;
  int n_adhesion_ = 0, n_slip_ = 0;
  Eigen::MatrixXd M0_, M1_;
  Eigen::MatrixXd W_;  ///< n x 3 inputs per unit creepage: V U1, V U2, V Usp
  Eigen::MatrixXd L_;  ///< n x 3 outputs: dx dy B' U1, B' U2, B' Usp0
  Eigen::PartialPivLU<Eigen::MatrixXd> lu0_;
  // reduced pencil: M0^{-1} M1 = Q H Q'
  mutable bool reduced_ = false;
  mutable Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> H_;
  mutable Eigen::MatrixXd Rhat_, Lhat_;  ///< Q' M0^{-1} W, Q' L
};

}  // namespace rollnoise::nss
