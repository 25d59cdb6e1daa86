#include "noise/contact_receptance.hpp"

#include <stdexcept>

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "core/assert.hpp"
#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

void check_common(double frequency, double normal_stiffness, double speed) {
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw std::invalid_argument("contact receptance needs a positive frequency");
  if (!(normal_stiffness > 0.0) || !std::isfinite(normal_stiffness))
    throw std::invalid_argument("contact normal stiffness must be positive");
  if (!(speed > 0.0) || !std::isfinite(speed))
    throw std::invalid_argument("contact receptance needs a positive rolling speed");
}

}  // namespace

Receptance4 contact_receptance(double frequency, double normal_stiffness, double speed,
                               const Eigen::Matrix3cd& creep) {
  return contact_receptance(frequency, normal_stiffness, speed, creep, LoadCoefficients::Zero());
}

Receptance4 contact_receptance(double frequency, double normal_stiffness, double speed,
                               const Eigen::Matrix3cd& creep, const LoadCoefficients& load) {
  check_common(frequency, normal_stiffness, speed);
  const double omega = dynamics::angular(frequency);
  const Eigen::FullPivLU<Eigen::Matrix3cd> lu(creep);
  // Reciprocal condition estimate from the pivots (relative to the largest entry).
  const double biggest = creep.cwiseAbs().maxCoeff();
  if (!(biggest > 0.0) || !creep.allFinite() || !lu.isInvertible() ||
      std::abs(lu.matrixLU()(2, 2)) < 1e-14 * biggest) {
    std::ostringstream s;
    s << "contact receptance: creep matrix f is singular or not finite at " << frequency
      << " Hz (f =\n"
      << creep << ")";
    throw NumericalError(s.str());
  }
  Receptance4 a = Receptance4::Zero();
  a(0, 0) = 1.0 / normal_stiffness;  // linearised Hertz spring
  // (C2): alpha_c,t = (V / (i omega)) f^{-1}
  a.bottomRightCorner<3, 3>() = (speed / (cdouble(0.0, 1.0) * omega)) * lu.inverse();
  if (!load.allFinite())
    throw NumericalError("contact receptance: normal-load coefficients g not finite");
  // (C3): alpha_c,tn = -alpha_c,tt g (exactly zero for g = 0)
  if (!load.isZero(0.0)) a.bottomLeftCorner<3, 1>() = -(a.bottomRightCorner<3, 3>() * load);
  return a;
}

// (C1-C3) at complex s (docs/squeal.md): the same as contact_receptance at s = i omega, written out
// separately so that the real-frequency function keeps its code and bits.
Receptance4 contact_receptance_laplace(cdouble s, double normal_stiffness, double speed,
                                       const Eigen::Matrix3cd& creep, const LoadCoefficients& load) {
  if (!(std::abs(s) > 0.0) || !std::isfinite(std::abs(s)))
    throw std::invalid_argument("contact receptance needs a finite, non-zero s");
  check_common(1.0, normal_stiffness, speed);
  const Eigen::FullPivLU<Eigen::Matrix3cd> lu(creep);
  // Reciprocal condition estimate from the pivots (relative to the largest entry).
  const double biggest = creep.cwiseAbs().maxCoeff();
  if (!(biggest > 0.0) || !creep.allFinite() || !lu.isInvertible() ||
      std::abs(lu.matrixLU()(2, 2)) < 1e-14 * biggest) {
    std::ostringstream m;
    m << "contact receptance: creep matrix f is singular or not finite at " << s.imag() / (2 * M_PI) << " Hz";
    if (s.real() != 0.0) m << " (s = " << s << " 1/s)";
    m << " (f =\n" << creep << ")";
    throw NumericalError(m.str());
  }
  Receptance4 a = Receptance4::Zero();
  a(0, 0) = 1.0 / normal_stiffness;  // linearised Hertz spring
  // (C2): alpha_c,t = (V / (i omega)) f^{-1}, i omega -> s
  a.bottomRightCorner<3, 3>() = (speed / s) * lu.inverse();
  if (!load.allFinite())
    throw NumericalError("contact receptance: normal-load coefficients g not finite");
  // (C3): alpha_c,tn = -alpha_c,tt g (exactly zero for g = 0)
  if (!load.isZero(0.0)) a.bottomLeftCorner<3, 1>() = -(a.bottomRightCorner<3, 3>() * load);
  return a;
}

std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                             double normal_stiffness, double speed,
                                             const CreepFunction& creep) {
  ROLLNOISE_ASSERT(static_cast<bool>(creep), "contact receptance: no creep-coefficient model given");
  std::vector<Receptance4> out;
  out.reserve(frequencies.size());
  for (double f : frequencies)
    out.push_back(contact_receptance(f, normal_stiffness, speed, creep(f)));
  return out;
}

std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                             double normal_stiffness, double speed,
                                             const std::vector<Eigen::Matrix3cd>& creep) {
  return contact_receptances(frequencies, normal_stiffness, speed, creep,
                             std::vector<LoadCoefficients>(creep.size(), LoadCoefficients::Zero()));
}

std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                             double normal_stiffness, double speed,
                                             const std::vector<Eigen::Matrix3cd>& creep,
                                             const std::vector<LoadCoefficients>& load) {
  ROLLNOISE_ASSERT(creep.size() == frequencies.size() && load.size() == frequencies.size(),
                   "contact receptance: one creep matrix and one load vector per frequency are needed");
  std::vector<Receptance4> out;
  out.reserve(frequencies.size());
  for (std::size_t k = 0; k < frequencies.size(); ++k)
    out.push_back(contact_receptance(frequencies[k], normal_stiffness, speed, creep[k], load[k]));
  return out;
}

Receptance4 normal_contact_receptance(double normal_stiffness) {
  if (!(normal_stiffness > 0.0) || !std::isfinite(normal_stiffness))
    throw std::invalid_argument("contact normal stiffness must be positive");
  Receptance4 a = Receptance4::Zero();
  a(0, 0) = 1.0 / normal_stiffness;
  return a;
}

CreepFunction steady_creep(const Eigen::Matrix3d& f) {
  const Eigen::Matrix3cd fc = f.cast<cdouble>();
  return [fc](double) { return fc; };
}

Eigen::Matrix3d tangential_contact_stiffness(double a, double b, double G, double nu) {
  if (!(a > 0.0) || !(b > 0.0)) throw std::invalid_argument("semi-axes must be positive");
  if (!(G > 0.0)) throw std::invalid_argument("shear modulus must be positive");
  if (!(nu >= 0.0 && nu <= 0.5)) throw std::invalid_argument("Poisson's ratio must be in [0, 0.5]");
  const double c = std::sqrt(a * b);
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
  K(0, 0) = K(1, 1) = 4.0 * G * c / (2.0 - nu);  // Mindlin, two identical bodies
  K(2, 2) = 8.0 * G * c * c * c / 3.0;           // Lubkin, two identical bodies
  return K;
}

CreepFunction creep_with_tangential_stiffness(const Eigen::Matrix3d& steady,
                                              const Eigen::Matrix3d& stiffness, double speed) {
  if (!(speed > 0.0)) throw std::invalid_argument("rolling speed must be positive");
  const Eigen::Matrix3cd fs_inv = steady.cast<cdouble>().inverse();
  const Eigen::Matrix3cd K_inv = stiffness.cast<cdouble>().inverse();
  return [fs_inv, K_inv, speed](double frequency) {
    const cdouble iw_over_v(0.0, dynamics::angular(frequency) / speed);
    const Eigen::Matrix3cd compliance = fs_inv + iw_over_v * K_inv;
    return Eigen::Matrix3cd(compliance.inverse());
  };
}

}  // namespace rollnoise::noise
