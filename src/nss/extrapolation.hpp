// Richardson extrapolation of grid-dependent results to the continuum (dx -> 0), with an error
// estimate: `rollnoise creep --extrapolate` and the accuracy table of `rollnoise bench`
// (docs/accuracy.md).
//
// Model. On a grid of element length h a result behaves as v(h) = v* + C h^p + o(h^p) (the grid is
// refined in x and y together, and the time step dt = dx/V with it). p is 2 for the creep
// coefficients with midstep or average creepage sampling and 1 with CONTACT's (the half-step phase lead,
// contact/creepage_history.hpp).
//   Three grids h1 > h2 > h3 (any ratios): the OBSERVED order p solves
//       |v1 - v2| / |v2 - v3| = (h1^p - h2^p) / (h2^p - h3^p)                                 (R1)
//   (bisection; the right side increases with p), accepted when it lies in [min_order, max_order]
//   (default [0.5, 4]) and the two differences point the same way (Re((v1 - v2) conj(v2 - v3)) > 0:
//   monotone convergence; complex values are extrapolated as such, with one real order). Otherwise
//   (oscillating or stagnating differences, round-off in an entry that vanishes by symmetry) the
//   ASSUMED order is used on the two finest grids, and the result says so (observed = false).
//   Two grids: the assumed order.
//   Extrapolated value:  v* = v_f + (v_f - v_c) h_f^p / (h_c^p - h_f^p)                         (R2)
//   (v_f, v_c the two finest grids), Richardson 1911; Roache 1998, "Verification and Validation in
//   Computational Science and Engineering", Sec. 5.
//   Error estimate: Roache's grid convergence index with the larger of the two corrections,
//       E = Fs max(|v*(p) - v_f|, |v*(p_assumed) - v_f|),  Fs = 1.25 with an observed order, 3
//   with an assumed one                                                                         (R3)
//   (Roache 1994, J. Fluids Eng. 116:405-413; the max over the observed and the theoretical order
//   as in Eca & Hoekstra 2014, J. Comput. Phys. 262:104-130, when an observed order above the
//   theoretical one would shrink the band). E bounds the error of the finest grid with a safety
//   factor; as the error estimate of the extrapolated value it is conservative (v* removes the
//   leading term the bound is made of). Where the error is not a clean power law (creep
//   coefficients at <= 1 kHz on grids finer than ~30 elements over 2a: the irregular error of the
//   contact-area boundary, 0.1-0.4 %, docs/accuracy.md) v* is no better than v_f, and E says so.
#pragma once

#include <complex>
#include <vector>

namespace rollnoise::nss {

struct RichardsonSettings {
  double assumed_order = 2.0;  ///< used with two grids and as the fall-back
  double min_order = 0.5, max_order = 4.0;  ///< range an observed order must lie in
};

struct RichardsonResult {
  std::complex<double> value;  ///< v*, (R2)
  double error = 0.0;          ///< Fs |v* - v_f|, same units as v
  double order = 0.0;          ///< the order used
  bool observed = false;       ///< the order is the observed one (three grids, within range)
};

/// `h` the element lengths (2 or 3, strictly decreasing, > 0), `v` the results on them.
/// std::invalid_argument otherwise (a programming error: callers validate their grids).
RichardsonResult richardson(const std::vector<double>& h, const std::vector<std::complex<double>>& v,
                            const RichardsonSettings& s = {});

}  // namespace rollnoise::nss
