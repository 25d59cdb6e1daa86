// The frequency arguments of the rail models' queries, checked where they enter: a receptance at a
// real frequency f > 0, or at a Laplace variable s != 0 (squeal's continuation off the axis).
// One definition for every rail model (the beams, the continuous and the discrete waveguide).
#pragma once

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "dynamics/receptance.hpp"

namespace rollnoise::dynamics {

/// omega = 2 pi f of a finite frequency f > 0 (Hz).
inline double checked_omega(double frequency) {
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw InputError("frequency", "track receptance needs a positive, finite frequency, got " +
                                      std::to_string(frequency) + " Hz");
  return angular(frequency);
}

/// The same as a complex angular frequency (the waveguide's wave solutions take complex omega).
inline cdouble checked_complex_omega(double frequency) {
  return {checked_omega(frequency), 0.0};
}

/// The complex angular frequency omega = -i s of a finite, non-zero Laplace variable s = i omega.
inline cdouble checked_laplace(cdouble s) {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  return cdouble(0.0, -1.0) * s;
}

}  // namespace rollnoise::dynamics
