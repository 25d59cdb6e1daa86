// The linear model against the unsteady solver on the same history (`rollnoise validate`; paper
// Sec. 3, Figs. 7-10): errors of the linear force history over the analysis window t >= t_start,
// after the start transient, where both runs started from the same steady state.
//
//   RMS error      e_j = sqrt(sum_k (q_lin - q_uns)^2 / sum_k (q_uns - mean q_uns)^2) per force
//                  component j (Fx, Fy, Mz): the RMS error relative to the RMS variation;
//   spectra        Hann-windowed amplitude spectra of both (nss/spectrum.hpp);
//   per frequency  complex amplitudes a_n of both at the excited frequencies by a least-squares
//                  multisine fit (linalg/multisine_fit.hpp), amplitude error |a_lin|/|a_uns| - 1 and
//                  phase error arg a_lin - arg a_uns wrapped to (-180, 180] deg; only when the
//                  window holds more than 2N + 1 samples and resolves the frequencies (length x
//                  spacing >= 1; one frequency: at least one period).
//   not excited    a component whose RMS variation in the unsteady run is at most 1e-9 of the
//                  force scale max(|mean Fx|, |mean Fy|, RMS variation of Fx, Fy) is not excited
//                  (e.g. Fy under a pure xi_x variation, or every component at zero amplitude): its
//                  variation is round-off of the solvers (tolerance 1e-12), and errors relative to
//                  it mean nothing. Its errors are NaN, and `excited` says so.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <vector>

#include "nss/spectrum.hpp"

namespace rollnoise::nss {

struct ValidationErrors {
  std::vector<double> time;                 ///< the analysed t_k >= t_start (s)
  Eigen::Vector3d rms_relative = Eigen::Vector3d::Zero();  ///< e_j above (NaN when not excited)
  std::array<bool, 3> excited = {false, false, false};     ///< see "not excited" above
  std::array<Spectrum, 3> unsteady_spectrum, linear_spectrum;  ///< Fx, Fy, Mz
  bool fitted = false;                      ///< per-frequency errors computed
  /// 3 x frequencies, row-major (Fx, Fy, Mz): relative amplitude error, phase error (deg); NaN
  /// for a component that is not excited
  std::vector<double> amplitude_error, phase_error;
};

/// Samples of `time` at t >= t_start (the analysis needs at least 8).
std::size_t analysed_samples(const std::vector<double>& time, double t_start);

/// `time` t_k = k dt with the unsteady and linear forces (Fx, Fy, Mz) at each t_k; `frequencies`
/// the excited ones (increasing, evenly spaced; may be empty).
ValidationErrors compare_linear_unsteady(const std::vector<double>& time,
                                         const std::vector<Eigen::Vector3d>& unsteady,
                                         const std::vector<Eigen::Vector3d>& linear, double t_start,
                                         const std::vector<double>& frequencies, double dt);

}  // namespace rollnoise::nss
