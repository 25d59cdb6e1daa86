#include "dynamics/track_beam.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace rollnoise::dynamics {
namespace {

// The root of k^2 = lambda on the side that decays towards +x for e^{i(omega t - k x)}:
// Im k < 0, or, for a wave without damping (Im k = 0), the outgoing one, Re k > 0.
cdouble decaying_root(cdouble lambda) {
  cdouble k = std::sqrt(lambda);  // principal root: Re k >= 0
  if (k.imag() > 0.0) k = -k;
  return k;
}

void require_positive(double v, const std::string& key, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(key,
                     key + ": " + what + " must be positive and finite, got " + std::to_string(v));
}

}  // namespace

void BeamSection::validate(const std::string& prefix) const {
  require_positive(youngs_modulus, prefix + ".youngs_modulus", "Young's modulus");
  require_positive(area, prefix + ".area", "cross-section area");
  require_positive(second_moment, prefix + ".second_moment", "second moment of area");
  require_positive(mass_per_length, prefix + ".mass_per_length", "mass per length");
  if (timoshenko) {
    require_positive(shear_modulus, prefix + ".shear_modulus", "shear modulus");
    require_positive(shear_coefficient, prefix + ".shear_coefficient", "shear coefficient");
  }
  if (!(loss_factor >= 0.0) || !std::isfinite(loss_factor))
    throw InputError(prefix + ".loss_factor",
                     prefix + ".loss_factor must be >= 0, got " + std::to_string(loss_factor));
}

// One path for real and complex frequency: a real omega is the complex omega + 0i, on the sheet
// Im k < 0 (no reference needed). The complex arithmetic of the zero imaginary parts adds exact
// zeros only; the products may be contracted to fused multiply-adds differently from the former
// real-valued code, so results can differ from it in the last bits (docs/record/performance.md
// Sec. 5).
InfiniteBeam::InfiniteBeam(const BeamSection& b, double omega, cdouble s) {
  init_complex(b, cdouble(omega, 0.0), s, nullptr);
}

Eigen::Matrix2cd InfiniteBeam::transfer(double x) const {
  const double ax = std::abs(x);
  const cdouble I(0.0, 1.0);
  cdouble even_w = 0.0, even_p = 0.0, odd = 0.0;
  for (int j = 0; j < 2; ++j) {
    const cdouble k = k_[j];
    const cdouble r = -I * std::exp(-I * k * ax) * inv_dp_[j];  // -i e^{-ik|x|} / P'(k)
    even_w += (d2_ * k * k + d0_) * r;
    even_p += (e2_ * k * k + e0_) * r;
    odd += g_ * k * r;
  }
  // Odd numerators: W/M = +i g k, Psi/F = -i g k, value at |x| times sign(x); zero at x = 0.
  const double sgn = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
  Eigen::Matrix2cd G;
  G(0, 0) = even_w;
  G(1, 1) = even_p;
  G(0, 1) = sgn * I * odd;
  G(1, 0) = -sgn * I * odd;
  return G;
}

InfiniteBeam::WaveAmplitudes InfiniteBeam::wave_amplitudes() const {
  const cdouble I(0.0, 1.0);
  WaveAmplitudes a;
  for (int j = 0; j < 2; ++j) {
    const cdouble k = k_[j];
    a.wF[j] = -I * (d2_ * k * k + d0_) * inv_dp_[j];
    a.wM[j] = g_ * k * inv_dp_[j];
  }
  return a;
}

// ---------------------------------------------------------------------------------------------
// The closed forms at a complex omega (docs/squeal.md Sec. 2); the real frequency is omega + 0i.
// ---------------------------------------------------------------------------------------------

InfiniteBeam::InfiniteBeam(const BeamSection& b, cdouble omega, cdouble s, cdouble s_real) {
  if (omega.imag() > 0.0) {
    const InfiniteBeam reference(b, omega.real(), s_real);
    init_complex(b, omega, s, &reference);
  } else {
    init_complex(b, omega, s, nullptr);
  }
}

void InfiniteBeam::init_complex(const BeamSection& b, cdouble omega, cdouble s, const InfiniteBeam* reference) {
  const cdouble damping(1.0, b.loss_factor);
  const cdouble EI = b.youngs_modulus * b.second_moment * damping;
  const cdouble mw2 = b.mass_per_length * omega * omega;  // m' omega^2
  const cdouble q = s - mw2;                             // s - m' omega^2

  // P(k) = a k^4 + bb k^2 + c and the numerators of the inverse dynamic-stiffness matrix.
  cdouble a, bb, c;
  if (b.timoshenko) {
    const cdouble kGA = b.shear_coefficient * b.shear_modulus * b.area * damping;
    const cdouble rIw2 = b.mass_per_length * b.second_moment / b.area * omega * omega;
    a = EI * kGA;
    bb = q * EI - kGA * rIw2;
    c = q * (kGA - rIw2);
    d2_ = EI, d0_ = kGA - rIw2;  // W/F
    e2_ = kGA, e0_ = q;          // Psi/M
    g_ = kGA;                    // W/M = i g k, Psi/F = -i g k
  } else {
    a = EI, bb = 0.0, c = q;
    d2_ = 0.0, d0_ = 1.0;
    e2_ = 1.0, e0_ = 0.0;
    g_ = 1.0;
  }

  // lambda = k^2 from a lambda^2 + bb lambda + c = 0, the cancellation-free form of the quadratic
  // formula: q = -(bb + sign sqrt(bb^2 - 4ac))/2, lambda_1 = q/a, lambda_2 = c/q.
  const cdouble disc = std::sqrt(bb * bb - 4.0 * a * c);
  const cdouble qq = -0.5 * (std::real(std::conj(bb) * disc) >= 0.0 ? bb + disc : bb - disc);
  if (std::abs(qq) == 0.0)
    throw NumericalError(
        "InfiniteBeam: dispersion relation degenerate (k = 0 double root) at omega = " +
        std::to_string(std::abs(omega)) + " rad/s; add damping");
  const std::array<cdouble, 2> lambda = {qq / a, c / qq};
  const double sep = std::abs(lambda[0] - lambda[1]);
  if (!(sep > 1e-13 * (std::abs(lambda[0]) + std::abs(lambda[1]))))
    throw NumericalError("InfiniteBeam: double root of the dispersion relation at omega = " +
                         std::to_string(std::abs(omega)) + " rad/s; add damping");
  for (int j = 0; j < 2; ++j) {
    k_[j] = decaying_root(lambda[j]);
    if (reference) {  // the root of +-k_j nearest to the reference's roots (continuation, see header)
      double best = 1e300;
      for (const cdouble r : reference->k_)
        for (const cdouble k : {k_[j], -k_[j]})
          if (std::abs(k - r) < best) best = std::abs(k - r), k_[j] = k;
    }
    inv_dp_[j] = 1.0 / (2.0 * a * k_[j] * (lambda[j] - lambda[1 - j]));
  }
}

namespace {
cdouble rod_receptance_complex(const BeamSection& b, cdouble omega, cdouble s, double x, const cdouble* reference) {
  const cdouble EA = b.youngs_modulus * b.area * cdouble(1.0, b.loss_factor);
  cdouble k0 = decaying_root((b.mass_per_length * omega * omega - s) / EA);
  if (reference && std::abs(-k0 - *reference) < std::abs(k0 - *reference)) k0 = -k0;  // continuation
  if (std::abs(k0) == 0.0)
    throw NumericalError("rod_receptance: k0 = 0 (static free rod); add a foundation or damping");
  const cdouble I(0.0, 1.0);
  return -I * std::exp(-I * k0 * std::abs(x)) / (2.0 * EA * k0);
}
}  // namespace

Eigen::MatrixX2cd InfiniteBeam::deflection_rows(double x0, double step, int count) const {
  Eigen::MatrixX2cd rows(count, 2);
  const cdouble I(0.0, 1.0);
  // first index with x_n >= 0 (x_n = x0 + n step, step > 0)
  int first = 0;
  while (first < count && x0 + first * step < 0.0) ++first;
  std::array<cdouble, 2> ratio, e;
  for (int j = 0; j < 2; ++j) ratio[j] = std::exp(-I * k_[j] * step);
  auto store = [&](int n, double x) {
    cdouble w = 0.0, odd = 0.0;
    for (int j = 0; j < 2; ++j) {
      const cdouble k = k_[j];
      const cdouble r = -I * e[j] * inv_dp_[j];
      w += (d2_ * k * k + d0_) * r;
      odd += g_ * k * r;
    }
    const double sgn = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
    rows(n, 0) = w;
    rows(n, 1) = sgn * I * odd;  // W/M = +i g k, odd in x
  };
  // x >= 0: |x| grows with n
  if (first < count) {
    const double x = x0 + first * step;
    for (int j = 0; j < 2; ++j) e[j] = std::exp(-I * k_[j] * x);
    for (int n = first; n < count; ++n) {
      if (n > first)
        for (int j = 0; j < 2; ++j) e[j] *= ratio[j];
      store(n, x0 + n * step);
    }
  }
  // x < 0: |x| grows as n falls
  if (first > 0) {
    const double x = x0 + (first - 1) * step;
    for (int j = 0; j < 2; ++j) e[j] = std::exp(-I * k_[j] * std::abs(x));
    for (int n = first - 1; n >= 0; --n) {
      if (n < first - 1)
        for (int j = 0; j < 2; ++j) e[j] *= ratio[j];
      store(n, x0 + n * step);
    }
  }
  return rows;
}

cdouble rod_receptance(const BeamSection& b, double omega, cdouble s, double x) {
  return rod_receptance_complex(b, cdouble(omega, 0.0), s, x, nullptr);
}

cdouble rod_receptance(const BeamSection& b, cdouble omega, cdouble s, double x, cdouble s_real) {
  if (!(omega.imag() > 0.0)) return rod_receptance_complex(b, omega, s, x, nullptr);
  const cdouble EA = b.youngs_modulus * b.area * cdouble(1.0, b.loss_factor);
  const double w = omega.real();
  const cdouble reference = decaying_root((b.mass_per_length * w * w - s_real) / EA);
  return rod_receptance_complex(b, omega, s, x, &reference);
}

}  // namespace rollnoise::dynamics
