// Track models: the rail (Timoshenko beam, track_beam.hpp) on a two-layer support of rail pads,
// sleepers and ballast, continuous or discrete, and the rail's 4x4 receptance at the contact point.
//
// Support of one rail seat (Thompson 2009, Ch. 3; Knothe & Grassie 1993): pad
// k_p(1 + i eta_p) in series with the sleeper mass m_s on the ballast k_b(1 + i eta_b). Its dynamic
// stiffness, the force on the rail per unit rail displacement at the seat, is
//
//   K(omega) = k_p* (k_b* - m_s omega^2) / (k_p* + k_b* - m_s omega^2).                    (1)
//
// Continuous support (Thompson 2009, Ch. 3; Grassie et al. 1982): the support smeared along the
// rail, foundation stiffness per length s = K(omega)/L with L the sleeper spacing, solved in closed
// form by InfiniteBeam.
//
// Discrete support (receptance superposition; Heckl, Acustica 81, 1995; Thompson 2009, Ch. 3;
// Wu & Thompson, JSV 224, 1999): supports at x_n = n L act on the free rail with forces
// R_n = -K w(x_n). With g(x) the free rail's Green's function (InfiniteBeam with s = 0) and the
// load u = (F, M) at x_e,
//
//   w(x_n) = G_w(x_n - x_e) u + sum_m g_wF(x_n - x_m) R_m   =>   (A + K^{-1} I) R = -B_e u,
//
// A_nm = g_wF(x_n - x_m) (symmetric Toeplitz), B_e rows (g_wF, g_wM)(x_n - x_e). The response at
// x_r is then
//
//   H(x_r, x_e) = G(x_r - x_e) - B_r^T (A + K^{-1} I)^{-1} B_e,                              (2)
//
// reciprocal by construction (H(x_e, x_r) = H(x_r, x_e)^T).
//
// The infinite periodic track (the default, DiscreteSupportSolution::kPeriodic): Eq. (2) with all
// the supports n = ... -1, 0, 1 ..., solved exactly by the Floquet waves of the periodic rail in
// O(1) per frequency and pair (track_periodic.hpp; Mead 1970/1996, Heckl 2002).
//
// The truncated track (kTruncated, kept for tests and comparisons): the 2N + 1 supports nearest
// the load; beyond them the rail is free. Waves reflected at the ends of the supported stretch
// return attenuated by |mu|^{2N} (mu the slowest decaying Floquet wave; N = 60: 72 m of track),
// so it tends to the periodic solution as N grows (tests/dynamics/track_periodic_test.cpp).
//
// Solution of the truncated (2). S = A + K^{-1} I is a complex symmetric Toeplitz matrix (A_nm depends on
// |n - m| only, as the supports are periodic), so S^{-1} B_e is found by Levinson's recursion in
// O(m^2) operations, m = 2N + 1 (linalg/toeplitz_solve.hpp; Golub & Van Loan, Matrix Computations,
// 4th ed., Alg. 4.7.2), instead of a dense LU in O(m^3): the same truncated model, equal to the
// LU's result to round-off (largest relative difference 2e-12 over 20 Hz-8 kHz, both bending
// planes, point and 2.5 m transfer receptances; DiscreteTrack.ToeplitzSolveEqualsDenseLuOfEq2-
// ToRoundOff). The recursion does not pivot; its residual is checked and the dense LU solves where
// the check fails, and at a complex omega with Im omega > 0, where the continued wavenumbers grow
// along the rail and S is singular to round-off (transfer_at). Point receptances reuse B_e as B_r.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/rail_contact.hpp"
#include "dynamics/rail_surface_spectrum.hpp"
#include "dynamics/receptance.hpp"
#include "dynamics/track_beam.hpp"

namespace rollnoise::dynamics {

/// One rail seat: rail pad, sleeper (the share of one rail), ballast.
struct Support {
  double pad_stiffness = 0.0;        ///< k_p (N/m)
  double pad_loss_factor = 0.0;      ///< eta_p (-)
  double sleeper_mass = 0.0;         ///< m_s (kg), 0 for pads directly on the ballast spring
  double ballast_stiffness = 0.0;    ///< k_b (N/m)
  double ballast_loss_factor = 0.0;  ///< eta_b (-)

  /// K(omega) of Eq. (1) (N/m).
  cdouble dynamic_stiffness(double omega) const;
  /// The sleeper's displacement per the rail's at the seat, k_p* / (k_p* + k_b* - m_s omega^2)
  /// (the pad and the sleeper on the ballast of Eq. (1) in series; the sound of the sleepers).
  cdouble sleeper_transfer(double omega) const;
  /// Eq. (1) at a complex angular frequency omega = -i s (loss factors continued as constants).
  cdouble dynamic_stiffness(cdouble omega) const;
  void validate(const std::string& prefix) const;
};

/// How the discrete-support rail (DiscretelySupportedRail) solves Eq. (2): the infinite periodic
/// track exactly by its Floquet waves (track_periodic.hpp; the default), or the truncated system of
/// 2N + 1 supports (N = supports_each_side), kept for tests and comparisons.
enum class DiscreteSupportSolution { kPeriodic, kTruncated };

/// A ballasted track: the rail in both planes of bending and the supports in the three directions.
struct TrackParameters {
  BeamSection vertical;  ///< bending in the x-z plane (I about the horizontal axis)
  BeamSection lateral;   ///< bending in the x-y plane (I about the vertical axis)
  Support vertical_support;
  Support lateral_support;
  Support longitudinal_support;  ///< pad shear / sleeper / ballast in x
  double sleeper_spacing = 0.6;  ///< L (m)
  double head_height = 0.0;      ///< running surface above the vertical-bending neutral axis (m)
  int supports_each_side = 60;   ///< N of a truncated discrete model (2N + 1 supports): the
                                 ///< waveguide rail's, and the beam rail's if kTruncated
  /// The beam rail's solution of Eq. (2) (not a case key: the truncated one is for comparisons).
  DiscreteSupportSolution discrete_solution = DiscreteSupportSolution::kPeriodic;

  void validate() const;
};

/// The built-in UIC60 ballasted track, identical to models/track/uic60_ballasted.toml
/// (values and sources in docs/models.md). Track files are read by io/track_file.hpp.
TrackParameters uic60_ballasted();

/// Rail on a continuous support s = K(omega)/L: (w, psi) at x per (F, M) at 0 (see InfiniteBeam).
Eigen::Matrix2cd continuous_transfer(const BeamSection& rail, const Support& support,
                                     double sleeper_spacing, double frequency, double x);

/// Rail on discrete supports at x_n = n L, Eq. (2): the infinite periodic track exactly
/// (kPeriodic, track_periodic.hpp), or truncated to 2N + 1 supports (kTruncated).
class DiscretelySupportedRail {
 public:
  DiscretelySupportedRail(const BeamSection& rail, const Support& support, double sleeper_spacing,
                          int supports_each_side,
                          DiscreteSupportSolution solution = DiscreteSupportSolution::kPeriodic);

  /// (w, psi) at x_response per (F, M) at x_load; positions along the rail measured from a sleeper
  /// (x = 0 over a sleeper, x = L/2 at mid-span). Truncated: the 2N + 1 supports are centred on
  /// the midpoint of the two positions.
  Eigen::Matrix2cd transfer(double frequency, double x_response, double x_load) const;

  /// Point receptance matrix at x.
  Eigen::Matrix2cd point(double frequency, double x) const { return transfer(frequency, x, x); }

  /// transfer(frequency, x_r, x_e) for several (x_r, x_e) pairs at one frequency: the periodic
  /// solution's Floquet multipliers and 4x4 LU (or, truncated, one Levinson recursion on S, each
  /// pair with its own window of supports) serve all of them: equal to transfer() per pair to the
  /// last bit (truncated: unless the recursion's residual check sends them to the dense LU).
  std::vector<Eigen::Matrix2cd> transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const;

  /// Eq. (2) at a complex angular frequency omega = -i s (s the Laplace variable, 1/s; see
  /// InfiniteBeam for the continuation).
  Eigen::Matrix2cd transfer_at(cdouble omega, double x_response, double x_load) const;

  int supports_each_side() const { return n_; }
  DiscreteSupportSolution solution() const { return solution_; }

 private:
  /// Eq. (2) for the free rail and the support stiffness K at one (real or complex) frequency.
  /// `dense`: the dense LU instead of Levinson's recursion.
  Eigen::Matrix2cd solve(const InfiniteBeam& free_rail, cdouble K, double x_r, double x_e,
                         bool dense) const;
  /// solve() for several (x_r, x_e) pairs, one Toeplitz system with their B_e as columns.
  std::vector<Eigen::Matrix2cd> solve_pairs(const InfiniteBeam& free_rail, cdouble K,
                                            const std::vector<std::pair<double, double>>& pairs,
                                            bool dense) const;

  BeamSection rail_;
  Support support_;
  double spacing_;
  int n_;
  DiscreteSupportSolution solution_;
};

enum class TrackSupport { kContinuous, kDiscrete };

/// The rail's 4x4 receptance (z, x, y, rot z at the running surface; RailModel below) from the
/// vertical beam's (w, psi) per (F, M), the lateral beam's (w, psi) per (Fy, Mz), the rod's
/// receptance in x and the head height h: a point receptance or a transfer between two points.
Receptance4 rail_receptance4(const Eigen::Matrix2cd& Hv, const Eigen::Matrix2cd& Hl, cdouble rod,
                             double h);

}  // namespace rollnoise::dynamics
