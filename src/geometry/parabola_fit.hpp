// Least-squares parabola through equally spaced samples (for curvatures of profiles and gaps).
#pragma once

namespace rollnoise::geometry {

/// The quadratic coefficient c2 of the least-squares parabola c0 + c1 t + c2 t^2 through f(t)
/// sampled at m equally spaced t in [-w, w]. The samples are symmetric, so sum t = sum t^3 = 0 and
/// c2 decouples from c1:  c2 = sum (t_k^2 - <t^2>) f_k / sum (t_k^2 - <t^2>)^2.
template <class F>
double quadratic_coefficient(F&& f, double w, int m = 41) {
  double mean_t2 = 0.0;
  for (int k = 0; k < m; ++k) {
    const double t = -w + 2.0 * w * k / (m - 1);
    mean_t2 += t * t / m;
  }
  double num = 0.0, den = 0.0;
  for (int k = 0; k < m; ++k) {
    const double t = -w + 2.0 * w * k / (m - 1);
    const double d = t * t - mean_t2;
    num += d * f(t);
    den += d * d;
  }
  return num / den;
}

}  // namespace rollnoise::geometry
