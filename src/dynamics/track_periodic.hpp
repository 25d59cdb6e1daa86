// The infinite, periodically supported rail: the Timoshenko beam (track_beam.hpp) on rail seats
// of dynamic stiffness K(omega) (track.hpp Eq. 1) at x_n = n L, n = ... -1, 0, 1 ..., solved
// exactly (no truncation of the track), in O(1) per frequency and pair of points.
//
// Method: the infinite Toeplitz system of Eq. (2) of track.hpp, (A + K^{-1} I) R = -B_e u, by
// its Floquet (Bloch) waves (Mead, JSV 11, 1970 and JSV 190, 1996: the waves in a periodic
// structure; Heckl, JSV 252, 2002, for the periodically supported Timoshenko beam; Wu & Thompson,
// JSV 224, 1999, and Thompson, Railway Noise and Vibration, 2009, Sec. 3.6, for the rail).
// The free rail's Green's function is a sum of two waves (track_beam.hpp):
//   g_wF(x) = sum_j A_j e^{-i k_j |x|},  g_wM(x) = sgn(x) sum_j B_j e^{-i k_j |x|},
// so its samples at the sleepers are geometric, g_wF(d L) = sum_j A_j z_j^|d|, z_j = e^{-i k_j L}
// (|z_j| < 1 with damping), and every lattice sum is a geometric series.
//
// P1. Floquet multipliers. The symbol of the Toeplitz matrix, S(zeta) = K^{-1} + sum_d g_wF(dL)
//     zeta^{-d}, is (the geometric series summed) with eta = zeta + 1/zeta, eta_j = z_j + 1/z_j,
//       S = K^{-1} + sum_j A_j (z_j - 1/z_j) / (eta - eta_j)
//     [ = K^{-1} - i sum_j A_j sin(k_j L) / (cos theta - cos k_j L) at zeta = e^{i theta}: the
//     dispersion relation of the periodically supported beam, Mead 1970]. S = 0 is a quadratic in
//     eta:  (eta - eta_1)(eta - eta_2) + K sum_j A_j (z_j - 1/z_j)(eta - eta_other) = 0,
//     with two roots eta_q, each giving a reciprocal pair of multipliers mu + 1/mu = eta_q; the
//     decaying wave of each pair has |mu_q| < 1 (at a complex omega with Im omega > 0 the one
//     nearest the real-frequency wave, the continuation InfiniteBeam uses for k).
// P2. Reactions. A load u = (F, M) at x_e in the span [0, L) (periodicity: any x_e is shifted
//     there with x_r) drives on each side the two decaying Floquet waves only:
//       R_n = sum_q a_q mu_q^{n-1} (n >= 1),   R_n = sum_q c_q mu_q^{-n} (n <= 0).
//     In row n of the system the lattice sums of these give terms in mu_q^n, which vanish by
//     S(mu_q) = 0, and terms in z_j^n, which must cancel the load's z_j^n; for n >= 1 and n <= 0
//     (rows divided by z_j^{|n|}) that is, for j = 1, 2,
//       A_j [ -sum_q a_q / (mu_q - z_j) + sum_q c_q / (1 - z_j mu_q) ] = -e^{ i k_j x_e} (A_j F +
//       B_j M) A_j [  sum_q a_q / (1 - z_j mu_q) - sum_q c_q / (mu_q - z_j) ] = -e^{i k_j (L -
//       x_e)} (A_j F - B_j M),
//     four equations for (a_1, a_2, c_1, c_2) per load column (a 4x4 LU per frequency).
// P3. Response (Eq. 2 of track.hpp, the infinite sum): (w, psi)(x_r) = G(x_r - x_e) u +
//     sum_m (g_wF, -g_wM)(x_r - x_m) R_m, each wave j summed over the sleepers: the few between
//     x_r and the load span term by term, the two tails in closed form (ratio z_j mu_q).
// The result is the limit N -> infinity of the truncated solve (track.hpp), reciprocal
// (H(x_r, x_e) = H(x_e, x_r)^T) and periodic (H(x_r + L, x_e + L) = H(x_r, x_e)) by construction.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>

#include "dynamics/track_beam.hpp"

namespace rollnoise::dynamics {

/// The infinite periodically supported beam at one (real or complex) frequency.
class PeriodicallySupportedBeam {
 public:
  /// `free_rail`: the free beam (foundation 0) at omega; `K`: the rail seat's stiffness K(omega)
  /// (N/m); `spacing`: L (m). `reference`: the same beam at the real frequency Re omega, for the
  /// continuation of the multipliers at Im omega > 0 (P1); nullptr otherwise.
  PeriodicallySupportedBeam(const InfiniteBeam& free_rail, cdouble K, double spacing,
                            const PeriodicallySupportedBeam* reference = nullptr);

  /// (w, psi) at x_r per (F, M) at x_e (m along the rail, x = 0 over a sleeper).
  Eigen::Matrix2cd transfer(double x_r, double x_e) const;

  /// The decaying Floquet multipliers mu_q (P1): the waves change by mu_q per span.
  const std::array<cdouble, 2>& floquet_multipliers() const { return mu_; }

 private:
  InfiniteBeam free_;
  InfiniteBeam::WaveAmplitudes amp_;
  double L_;
  std::array<cdouble, 2> k_, z_, mu_;
  Eigen::PartialPivLU<Eigen::Matrix4cd> system_;  // P2's 4x4
};

}  // namespace rollnoise::dynamics
