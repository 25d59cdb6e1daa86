// Shared inputs of the noise-loop tests: the UIC60 ballasted track, the 920 mm wheel of models/,
// the paper's Hertzian contact (a = 7.18 mm, b = 5.29 mm, N = 98.1 kN, docs/conventions.md Sec. 4) and
// 100 km/h.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/material.hpp"
#include "dynamics/beam_rail_model.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel.hpp"
#include "io/wheel_file.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/contact_set.hpp"
#include "noise/kalker_linear.hpp"
#include "noise/loop.hpp"

namespace noise_test {

namespace rd = rollnoise::dynamics;
namespace rc = rollnoise::contact;
namespace rn = rollnoise::noise;

inline constexpr double kSpeed = 100.0 / 3.6;  // m/s
inline constexpr double kA = 7.18e-3, kB = 5.29e-3, kN = 98.1e3;

inline std::string model_path(const std::string& rel) {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/models/" + rel;
}

inline const rd::WheelModel& wheel() {
  static const rd::WheelModel w(rollnoise::io::read_wheelset(model_path("wheel/wheelset_920mm.toml")),
                                rollnoise::io::read_wheel_modes(model_path("wheel/wheel_920mm_modes.csv")));
  return w;
}

inline const rd::RailModel& rail_continuous() {
  static const rd::BeamRailModel r(rd::uic60_ballasted(), rd::TrackSupport::kContinuous, 0.0);
  return r;
}

inline const rd::RailModel& rail_midspan() {
  static const rd::BeamRailModel r(rd::uic60_ballasted(), rd::TrackSupport::kDiscrete, 0.3);
  return r;
}

inline const rc::Material& material() {
  static const rc::Material m{210e9, 0.28};
  return m;
}

inline const rc::HertzContact& hertz() {
  static const rc::HertzContact h = rc::hertz_from_semi_axes(kA, kB, kN, material());
  return h;
}

/// Kalker's steady creep matrix of the paper's patch.
inline Eigen::Matrix3d kalker() {
  return rn::kalker_creep_matrix(kA, kB, material().shear_modulus(), material().nu);
}

/// The spring-damper stand-in for the NSS model (contact_receptance.hpp).
inline rn::CreepFunction spring_creep() {
  return rn::creep_with_tangential_stiffness(
      kalker(), rn::tangential_contact_stiffness(kA, kB, material().shear_modulus(), material().nu),
      kSpeed);
}

/// Logarithmic frequencies f_min ... f_max, n points.
inline std::vector<double> log_frequencies(double f_min, double f_max, int n) {
  std::vector<double> f(n);
  for (int k = 0; k < n; ++k) f[k] = f_min * std::pow(f_max / f_min, k / double(n - 1));
  return f;
}

/// Smallest eigenvalue of the dissipation matrix -(A - A^H)/(2i) of a receptance A (>= 0 for a
/// passive component: the power i omega F^H A F / 2 flowing in has a non-negative real part),
/// after the congruence D (.) D, D = diag(|A_ii|^{-1/2}), which keeps definiteness but removes the
/// units; relative to the largest |eigenvalue|. Any size (N = Eigen::Dynamic for MatrixXcd).
template <int N>
double relative_min_dissipation(const Eigen::Matrix<std::complex<double>, N, N>& A) {
  Eigen::Matrix<double, N, 1> d(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    d(i) = std::abs(A(i, i)) > 0 ? 1.0 / std::sqrt(std::abs(A(i, i))) : 1.0;
  const Eigen::Matrix<std::complex<double>, N, N> Ds =
      d.template cast<std::complex<double>>().asDiagonal();
  const Eigen::Matrix<std::complex<double>, N, N> D =
      Ds * (-(A - A.adjoint()) / std::complex<double>(0.0, 2.0)) * Ds;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<std::complex<double>, N, N>> es(D);
  const auto ev = es.eigenvalues();
  const double scale = ev.cwiseAbs().maxCoeff();
  return scale > 0 ? ev.minCoeff() / scale : 0.0;
}
/// The same for a dynamic-size receptance (or an expression that evaluates to one).
inline double relative_min_dissipation(const Eigen::MatrixXcd& A) {
  return relative_min_dissipation<Eigen::Dynamic>(A);
}

/// A contact of a bogie's contact set (noise/contact_set.hpp): wheelset, side, shift on the wheel,
/// offset on the rail head, contact angle and position along the rail.
inline rn::ContactPoint point(int wheelset, int side, double shift, double offset, double angle,
                              double x) {
  rn::ContactPoint c;
  c.wheelset = wheelset;
  c.side = side;
  c.position.wheel_shift_y = shift;
  c.position.rail_offset_y = offset;
  c.position.contact_angle = angle;
  c.rail_x = x;
  return c;
}

}  // namespace noise_test
