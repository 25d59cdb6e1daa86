#include "noise/roughness_filter.hpp"

#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

// Eq. (1a) sin(rho)/rho and Eq. (1b) 2 J1(rho)/rho; both 1 - O(rho^2) for small rho.
double transform(ContactWeighting w, double rho) {
  if (w == ContactWeighting::kElasticHalfSpace) {
    if (rho < 1e-4) return 1.0 - rho * rho / 6.0;
    return std::sin(rho) / rho;
  }
  if (rho < 1e-4) return 1.0 - rho * rho / 8.0;
  return 2.0 * gsl_sf_bessel_J1(rho) / rho;
}

// Envelope of |W|^2 for large rho: 1/(2 rho^2) resp. 4/(pi rho^3) (mean of the oscillation).
double envelope(ContactWeighting w, double rho) {
  const double e =
      w == ContactWeighting::kElasticHalfSpace ? 1.0 / (rho * rho) : 8.0 / (M_PI * rho * rho * rho);
  return std::min(1.0, e);
}

struct IsotropicArgs {
  ContactWeighting weighting;
  double ka, kb, half_power;  // half_power = (n + 1)/2
};

double isotropic_integrand(double u, void* p) {
  const auto* q = static_cast<const IsotropicArgs*>(p);
  const double w = transform(q->weighting, std::hypot(q->ka, u * q->kb));
  return std::pow(1.0 + u * u, -q->half_power) * w * w;
}

}  // namespace

void ContactFilter::validate() const {
  if (model == ContactFilterModel::kNone) return;
  if (!(a > 0.0) || !std::isfinite(a))
    throw std::invalid_argument("contact filter: semi-axis a must be positive, got " + std::to_string(a));
  if (model == ContactFilterModel::kIsotropic && (!(b >= 0.0) || !std::isfinite(b)))
    throw std::invalid_argument("contact filter: semi-axis b must be >= 0, got " + std::to_string(b));
  if (!(spectral_exponent > 0.0) || !(spectral_exponent < 10.0))
    throw std::invalid_argument("contact filter: spectral exponent n must be in (0, 10), got " +
                         std::to_string(spectral_exponent));
}

double ContactFilter::squared(double k) const {
  if (model == ContactFilterModel::kNone) return 1.0;
  const double ka = std::abs(k) * a;
  if (model == ContactFilterModel::kCorrelated || b == 0.0) {
    const double h = transform(weighting, ka);  // Eq. (2)
    return h * h;
  }
  // Eq. (3): both integrals over u in [0, inf) (the integrands are even in u).
  const double n = spectral_exponent;
  IsotropicArgs args{weighting, ka, std::abs(k) * b, 0.5 * (n + 1.0)};
  // Int_0^inf (1 + u^2)^{-(n+1)/2} du = sqrt(pi) Gamma(n/2) / (2 Gamma((n+1)/2))
  const double norm =
      0.5 * std::sqrt(M_PI) * std::exp(gsl_sf_lngamma(0.5 * n) - gsl_sf_lngamma(0.5 * (n + 1.0)));
  gsl_function F{&isotropic_integrand, &args};
  // Absolute tolerance from the envelope of |W(ka)|^2: the integral is at most of that order, and
  // 1e-7 of it is far below what any band level resolves.
  const double epsabs = 1e-7 * envelope(weighting, ka) * norm;
  constexpr std::size_t kLimit = 1000;
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(kLimit);
  double result = 0.0, error = 0.0;
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  const int status = gsl_integration_qagiu(&F, 0.0, epsabs, 1e-7, kLimit, ws, &result, &error);
  gsl_set_error_handler(old);
  gsl_integration_workspace_free(ws);
  if (status != GSL_SUCCESS && !(error <= 1e-4 * std::abs(result) + 10.0 * epsabs))
    throw NumericalError("contact filter: QAGIU failed at k = " + std::to_string(k) + " rad/m (" +
                         gsl_strerror(status) + "), result " + std::to_string(result) +
                         ", estimated error " + std::to_string(error));
  return result / norm;
}

double ContactFilter::band_db(double k0) const {
  if (model == ContactFilterModel::kNone) return 0.0;
  // Average over ln k in [ln k0 - h, ln k0 + h], h = ln(10)/20, weight k^{1-n} (dk = k dln k),
  // midpoint rule on 16 sub-intervals (|H|^2 is smooth on this scale once averaged).
  constexpr int kPoints = 16;
  const double h = std::log(10.0) / 20.0;
  const double n = spectral_exponent;
  double num = 0.0, den = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double t = -h + (i + 0.5) * (2.0 * h / kPoints);
    const double w = std::exp((1.0 - n) * t);  // (k/k0)^{1-n}
    num += w * squared(k0 * std::exp(t));
    den += w;
  }
  return 10.0 * std::log10(num / den);
}

}  // namespace rollnoise::noise
