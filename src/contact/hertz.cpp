#include "contact/hertz.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"

namespace rollnoise::contact {
namespace {

// Dimensionless shape functions for the major semi-axis `major` along the direction of the smaller
// curvature: A_small = k_s * N / (E* major^3), A_large = k_l * N / (E* major^3), delta = k_d N/(E* major),
// from Johnson's Eqs. 4.39-4.40 with p0 = 3N/(2 pi major minor).
struct Shape {
  double small, large, approach;
};

Shape shape(double e) {
  const double k = std::sqrt(1.0 - e * e);  // minor / major
  if (e < 1e-4) {  // circle: A = B = 3N/(8 E* a^3), delta = 3N/(4 E* a)
    return {3.0 / 8.0, 3.0 / 8.0, 3.0 / 4.0};
  }
  const double K = gsl_sf_ellint_Kcomp(e, GSL_PREC_DOUBLE);
  const double E = gsl_sf_ellint_Ecomp(e, GSL_PREC_DOUBLE);
  // p0 b / (a^2 e^2) with p0 = 3N/(2 pi a b): 3N / (2 pi a^3 e^2)
  const double f = 3.0 / (2.0 * M_PI * e * e);
  return {f * (K - E), f * (E / (k * k) - K), 3.0 / (2.0 * M_PI) * K};
}

HertzContact assemble(double a, double b, double N, const Material& m) {
  const double Es = m.contact_modulus();
  const bool x_major = a >= b;
  const double major = x_major ? a : b, minor = x_major ? b : a;
  const double e = std::sqrt(std::max(0.0, 1.0 - (minor / major) * (minor / major)));
  const Shape s = shape(e);
  HertzContact h;
  h.a = a;
  h.b = b;
  h.normal_force = N;
  h.p0 = 3.0 * N / (2.0 * M_PI * a * b);
  const double scale = N / (Es * major * major * major);
  h.A = (x_major ? s.small : s.large) * scale;
  h.B = (x_major ? s.large : s.small) * scale;
  // delta = p0 minor K / E* = 3N K / (2 pi major E*)
  h.approach = s.approach * N / (Es * major);
  return h;
}

}  // namespace

HertzContact hertz_from_semi_axes(double a, double b, double normal_force, const Material& m) {
  // contracts: contact.a, contact.b, contact.normal_force are positive where read (schema), a
  // patch's semi-axes and a wheel's load are positive where the pipeline makes them
  if (!(a > 0.0)) throw std::invalid_argument("Hertz: semi-axis a must be positive");
  if (!(b > 0.0)) throw std::invalid_argument("Hertz: semi-axis b must be positive");
  if (!(normal_force > 0.0)) throw std::invalid_argument("Hertz: normal force must be positive");
  return assemble(a, b, normal_force, m);
}

HertzContact hertz_from_curvatures(double A, double B, double normal_force, const Material& m) {
  if (!(A > 0.0) || !(B > 0.0))
    throw InputError("contact.curvature", "both curvature coefficients must be positive");
  if (!(normal_force > 0.0)) throw std::invalid_argument("Hertz: normal force must be positive");
  const double ratio = std::max(A, B) / std::min(A, B);  // large / small >= 1
  double e = 0.0;
  const Shape near_circle = shape(1e-4);
  if (ratio > near_circle.large / near_circle.small) {
    // Solve large(e)/small(e) = ratio for the eccentricity (Brent's method, GSL).
    struct P {
      double ratio;
    } par{ratio};
    gsl_function F;
    F.function = [](double ee, void* v) {
      const Shape s = shape(ee);
      return s.large / s.small - static_cast<P*>(v)->ratio;
    };
    F.params = &par;
    gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double lo = 1e-4, hi = 1.0 - 1e-15;
    gsl_root_fsolver_set(solver, &F, lo, hi);
    for (int it = 0; it < 200; ++it) {
      gsl_root_fsolver_iterate(solver);
      lo = gsl_root_fsolver_x_lower(solver);
      hi = gsl_root_fsolver_x_upper(solver);
      if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
    }
    e = gsl_root_fsolver_root(solver);
    gsl_root_fsolver_free(solver);
  }
  const Shape s = shape(e);
  // small curvature coefficient = s.small N / (E* major^3)
  const double major = std::cbrt(s.small * normal_force / (m.contact_modulus() * std::min(A, B)));
  const double minor = major * std::sqrt(1.0 - e * e);
  const bool x_major = A <= B;
  return assemble(x_major ? major : minor, x_major ? minor : major, normal_force, m);
}

}  // namespace rollnoise::contact
