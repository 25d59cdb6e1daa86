// Types shared by the wheel and track models.
//
// A receptance is the complex displacement amplitude per unit force amplitude for harmonic motion
// e^{i omega t} (m/N, rad/N, m/(N m), rad/(N m)). The contact-point receptances of the wheel and
// the rail are 4x4 matrices in the order of rollnoise's contact degrees of freedom
//
//   0: z  (normal / vertical displacement, force Fz)
//   1: x  (longitudinal, rolling direction; force Fx)
//   2: y  (lateral; force Fy)
//   3: rotation about z (spin; moment Mz)
//
// (docs/noise_loop.md). Each structure's receptance relates the displacement of that
// structure to the force applied *to that structure*, both along the same axes; the sign change
// between the force on the wheel and the force on the rail belongs to the coupled loop.
#pragma once

#include <Eigen/Core>
#include <complex>

namespace rollnoise::dynamics {

using cdouble = std::complex<double>;
using Receptance4 = Eigen::Matrix<cdouble, 4, 4>;

/// Index of each contact degree of freedom in a Receptance4.
enum Dof : int { kZ = 0, kX = 1, kY = 2, kRotZ = 3 };

/// omega = 2 pi f.
inline double angular(double frequency_hz) {
  return 2.0 * M_PI * frequency_hz;
}

}  // namespace rollnoise::dynamics
