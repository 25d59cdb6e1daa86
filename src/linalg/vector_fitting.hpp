// Rational approximation of a matrix-valued frequency response by vector fitting: H(s) (p x m),
// sampled at s_k = 2 pi i f_k, approximated by a model with common poles,
//
//   H(s) ~ D + sum_n R_n / (s - a_n),    Re a_n < 0 (stable), R_n (p x m), complex pairs conjugate,
//
// realised as a real state-space model x' = A x + B u, y = C x + D u (linalg/state_space.hpp).
//
// Method (why vector fitting rather than AAA: it fits all p x m entries with one common set of
// poles by linear least squares, enforces stability by flipping during the iteration, so that the
// following iterations re-fit around the flipped poles, and has no spurious Froissart doublets to
// clean up; AAA would need its poles flipped and its residues re-fitted afterwards anyway):
//  - pole relocation: B. Gustavsen, A. Semlyen, "Rational approximation of frequency domain
//    responses by vector fitting", IEEE Trans. Power Delivery 14 (1999) 1052-1061, Eqs. 3-9 with
//    the real basis of Appendix B for complex pairs; the poles of each iteration are the zeros of
//    the scaling function sigma, eig(Lambda - b c~'/d~) (their Eq. A.8);
//  - relaxation: B. Gustavsen, "Improving the pole relocating properties of vector fitting", IEEE
//    Trans. Power Delivery 21 (2006) 1587-1592, Eq. 8: sigma's constant term d~ is free, with the
//    normalisation Re sum_k sigma(s_k) = K as one more equation;
//  - the fast QR form for many entries: D. Deschrijver et al., "Macromodeling of multiport systems
//    using a fast implementation of the vector fitting method", IEEE Microwave Wireless Compon.
//    Lett. 18 (2008) 383-385: one QR per entry, only the sigma rows R22 stacked;
//  - unstable poles flipped into the left half-plane after every relocation (Gustavsen-Semlyen
//    1999, Sec. V); the residues and D by linear least squares with the final poles.
//
// Scaling and error. The entries are scaled by an IoScaling (default: equilibrate() of the peak
// magnitudes), so inputs and outputs of any units weigh alike, and each frequency is weighted by
// 1/|H_s(f_k)|_F (a relative fit). The reported error is
//   error = max_k |H_s,fit(f_k) - H_s(f_k)|_F / |H_s(f_k)|_F,   H_s = diag(1/so) H diag(1/si),
// evaluated with the realised (A, B, C, D); element_error is max_{k,i,j} |H_fit,ij - H_ij|(f_k) /
// max_k |H_ij(f_k)| (entries that vanish at every sample are fitted as 0 and skipped).
//
// Order: adaptive. Starting from one complex pair, the number of poles grows by `pole_step` (fresh
// starting poles: complex pairs with imaginary parts log-spaced over the band and real parts 1/100
// of them, Gustavsen-Semlyen Sec. IV) until the error is at most `target` or `max_poles` is
// reached; the fit with the smallest error is returned (reached_target tells).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "linalg/state_space.hpp"

namespace rollnoise::linalg {

struct RationalFitOptions {
  double target = 1e-6;  ///< error (see above) at which the order stops growing
  int max_poles = 60;    ///< most poles (a complex pair counts 2)
  int pole_step = 2;     ///< poles added per order step
  int iterations = 12;   ///< pole relocations per order (fewer once the poles stop moving)
  IoScaling scaling;     ///< empty vectors: equilibrate() of the peak magnitudes
};

struct RationalFit {
  StateSpace model;                         ///< real realisation (minimal per pole, see the .cpp)
  std::vector<std::complex<double>> poles;  ///< all poles (pairs both listed), rad/s
  double error = 0.0;                       ///< max relative error over the samples (see above)
  double element_error = 0.0;               ///< max entry error relative to the entry's peak
  double worst_frequency = 0.0;             ///< Hz, where `error` is attained
  int flipped = 0;                          ///< unstable poles flipped during the fit
  bool reached_target = false;
  IoScaling scaling;  ///< the scaling the error is measured in
};

/// Fit `H` (K samples of p x m, at `frequency` in Hz, f >= 0; the response of a real system:
/// H(-i w) = conj H(i w)) by a stable common-pole rational model. std::invalid_argument when the
/// sizes disagree or fewer than two samples are given.
RationalFit fit_rational(const std::vector<double>& frequency,
                         const std::vector<Eigen::MatrixXcd>& H,
                         const RationalFitOptions& options = {});

/// The error measure of fit_rational for any model response `Hm` against `H` in scaling `s`
/// (max over the samples of the scaled relative Frobenius error); `at` gets the sample index.
double relative_response_error(const std::vector<Eigen::MatrixXcd>& H,
                               const std::vector<Eigen::MatrixXcd>& Hm, const IoScaling& s,
                               size_t* at = nullptr);

}  // namespace rollnoise::linalg
