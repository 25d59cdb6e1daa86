// Observed order of convergence under grid refinement, against the finest grid as reference.
//
// With q_h = q + c dx^p (one leading error term), the error of grid i against the finest grid is
//   e_i = |q_i - q_ref| / |q_ref| = C (dx_i^p - dx_ref^p),
// which falls faster than dx^p near the reference: a straight log-log slope through all grids
// overestimates p (by 0.4 on the paper's case, f_jk at 1 kHz). So fit that model to all grids but
// the finest, least squares in log e: for each p (scanned over [0.2, 4] in steps of 0.002), log C
// is the mean of log e_i - log(dx_i^p - dx_ref^p) (Richardson's one-term error model; fitted by
// least squares over several grids as in Eca and Hoekstra, J. Comput. Phys. 262 (2014) 104-130,
// but with the finest grid as the reference instead of an extrapolated value). This also gives the estimated error of every grid itself,
// C dx^p, including the finest grid's. `scatter` = exp(RMS residual of log e): ~1 for a clean
// power law, > 1.3 where the errors jump about with the grid (steady forces: the set of elements
// in contact changes irregularly with dx). p is NaN where the best fit lies at an end of the scan
// (no power law), or with fewer than 2 grids besides the reference.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace rollnoise::linalg {

struct ObservedOrder {
  double p = std::numeric_limits<double>::quiet_NaN();        ///< order of convergence
  double C = std::numeric_limits<double>::quiet_NaN();        ///< error constant: e ~ C dx^p
  double scatter = std::numeric_limits<double>::quiet_NaN();  ///< exp(RMS log residual), >= 1
  int points = 0;                                             ///< grids in the fit
  /// The estimated error C dx^p of a grid of spacing dx.
  double error_at(double dx) const { return C * std::pow(dx, p); }
};

/// `dx` the grid spacings, coarse to fine (the last is the reference); `err` the errors of each
/// grid against the last (non-finite or zero errors are left out of the fit).
inline ObservedOrder observed_order(const std::vector<double>& dx, const std::vector<double>& err) {
  const double kNaN = std::numeric_limits<double>::quiet_NaN();
  ObservedOrder o;
  const double href = dx.back();
  std::vector<double> h, le;
  for (size_t i = 0; i + 1 < dx.size(); ++i)
    if (std::isfinite(err[i]) && err[i] > 0 && dx[i] > href)
      h.push_back(dx[i]), le.push_back(std::log(err[i]));
  o.points = static_cast<int>(h.size());
  if (o.points < 2) return o;
  double best = std::numeric_limits<double>::infinity();
  for (double p = 0.2; p <= 4.0 + 1e-12; p += 0.002) {
    double m = 0.0, ss = 0.0;
    std::vector<double> y(h.size());
    for (size_t i = 0; i < h.size(); ++i)
      m += (y[i] = le[i] - std::log(std::pow(h[i], p) - std::pow(href, p)));
    m /= h.size();
    for (double v : y) ss += (v - m) * (v - m);
    if (ss < best) best = ss, o.p = p, o.C = std::exp(m);
  }
  o.scatter = std::exp(std::sqrt(best / h.size()));
  if (o.p < 0.2 + 1e-9 || o.p > 4.0 - 1e-9) o.p = o.C = kNaN;  // at the scan's end: no power law
  return o;
}

}  // namespace rollnoise::linalg
