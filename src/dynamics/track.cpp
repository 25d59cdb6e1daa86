#include "dynamics/track.hpp"

#include <Eigen/LU>
#include <cmath>
#include <vector>

#include "core/errors.hpp"

namespace rollnoise::dynamics {
namespace {

double checked_omega(double frequency) {
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw InputError("frequency", "track receptance needs a positive, finite frequency, got " +
                                      std::to_string(frequency) + " Hz");
  return angular(frequency);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Support
// ---------------------------------------------------------------------------------------------

namespace {
template <class Omega>
cdouble support_stiffness(const Support& p, Omega omega) {
  const cdouble kp = p.pad_stiffness * cdouble(1.0, p.pad_loss_factor);
  const cdouble kb = p.ballast_stiffness * cdouble(1.0, p.ballast_loss_factor);
  const cdouble below = kb - p.sleeper_mass * omega * omega;  // sleeper on ballast, seen from above
  return kp * below / (kp + below);                           // Eq. (1): pad in series
}
}  // namespace

cdouble Support::dynamic_stiffness(double omega) const { return support_stiffness(*this, omega); }

cdouble Support::dynamic_stiffness(cdouble omega) const { return support_stiffness(*this, omega); }

void Support::validate(const std::string& prefix) const {
  auto check = [&](double v, const char* name, bool allow_zero) {
    const bool ok = std::isfinite(v) && (allow_zero ? v >= 0.0 : v > 0.0);
    if (!ok)
      throw InputError(prefix + "." + name, prefix + "." + name + " must be " +
                                                (allow_zero ? "non-negative" : "positive") +
                                                ", got " + std::to_string(v));
  };
  check(pad_stiffness, "pad_stiffness", false);
  check(pad_loss_factor, "pad_loss_factor", true);
  check(sleeper_mass, "sleeper_mass", true);
  check(ballast_stiffness, "ballast_stiffness", false);
  check(ballast_loss_factor, "ballast_loss_factor", true);
}

void TrackParameters::validate() const {
  vertical.validate("rail.vertical");
  lateral.validate("rail.lateral");
  vertical_support.validate("support.vertical");
  lateral_support.validate("support.lateral");
  longitudinal_support.validate("support.longitudinal");
  if (!(sleeper_spacing > 0.0) || !std::isfinite(sleeper_spacing))
    throw InputError("sleeper_spacing",
                     "sleeper_spacing must be positive, got " + std::to_string(sleeper_spacing));
  if (!(head_height >= 0.0) || !std::isfinite(head_height))
    throw InputError("head_height",
                     "head_height must be non-negative, got " + std::to_string(head_height));
  if (supports_each_side < 1)
    throw InputError("supports_each_side", "supports_each_side must be at least 1, got " +
                                               std::to_string(supports_each_side));
}

// ---------------------------------------------------------------------------------------------
// Parameters: the built-in UIC60 track
// ---------------------------------------------------------------------------------------------

TrackParameters uic60_ballasted() {
  TrackParameters t;
  BeamSection rail;
  rail.youngs_modulus = 210e9;
  rail.shear_modulus = 81e9;
  rail.area = 7.69e-3;
  rail.mass_per_length = 60.3;
  rail.loss_factor = 0.02;
  t.vertical = rail;
  t.vertical.second_moment = 3.055e-5;
  t.vertical.shear_coefficient = 0.4;
  t.lateral = rail;
  t.lateral.second_moment = 5.13e-6;
  t.lateral.shear_coefficient = 0.5;
  t.vertical_support = {350e6, 0.25, 140.0, 100e6, 1.0};
  t.lateral_support = {50e6, 0.25, 140.0, 35e6, 1.0};
  t.longitudinal_support = {50e6, 0.25, 140.0, 35e6, 1.0};
  t.sleeper_spacing = 0.6;
  t.head_height = 0.091;
  t.supports_each_side = 60;
  return t;
}

// ---------------------------------------------------------------------------------------------
// Continuous and discrete support
// ---------------------------------------------------------------------------------------------

Eigen::Matrix2cd continuous_transfer(const BeamSection& rail, const Support& support,
                                     double sleeper_spacing, double frequency, double x) {
  const double omega = checked_omega(frequency);
  const cdouble s = support.dynamic_stiffness(omega) / sleeper_spacing;  // N/m^2
  return InfiniteBeam(rail, omega, s).transfer(x);
}

DiscretelySupportedRail::DiscretelySupportedRail(const BeamSection& rail, const Support& support,
                                                 double sleeper_spacing, int supports_each_side)
    : rail_(rail), support_(support), spacing_(sleeper_spacing), n_(supports_each_side) {
  rail_.validate("rail");
  support_.validate("support");
  if (!(spacing_ > 0.0)) throw InputError("sleeper_spacing", "sleeper_spacing must be positive");
  if (n_ < 1) throw InputError("supports_each_side", "supports_each_side must be at least 1");
}

Eigen::Matrix2cd DiscretelySupportedRail::transfer(double frequency, double x_r, double x_e) const {
  return transfer_impl(checked_omega(frequency), frequency, x_r, x_e);
}

Eigen::Matrix2cd DiscretelySupportedRail::transfer_at(cdouble omega, double x_r, double x_e) const {
  return transfer_impl(omega, std::real(omega) / (2.0 * M_PI), x_r, x_e);
}

// `frequency` (Hz) only for messages.
namespace {
// The beam at a real or complex angular frequency (foundation s; at complex omega also the
// foundation at Re omega, for the continuation of the roots: track_beam.hpp).
InfiniteBeam beam(const BeamSection& b, double omega, cdouble s, cdouble) { return InfiniteBeam(b, omega, s); }
InfiniteBeam beam(const BeamSection& b, cdouble omega, cdouble s, cdouble s_real) {
  return InfiniteBeam(b, omega, s, s_real);
}
cdouble rod(const BeamSection& b, double omega, cdouble s, cdouble) { return rod_receptance(b, omega, s, 0.0); }
cdouble rod(const BeamSection& b, cdouble omega, cdouble s, cdouble s_real) {
  return rod_receptance(b, omega, s, 0.0, s_real);
}
}  // namespace

template <class Omega>
Eigen::Matrix2cd DiscretelySupportedRail::transfer_impl(Omega omega, double frequency, double x_r,
                                                        double x_e) const {
  const InfiniteBeam free_rail = beam(rail_, omega, 0.0, 0.0);
  const cdouble K = support_.dynamic_stiffness(omega);
  const int m = 2 * n_ + 1;
  const long n0 = std::lround(0.5 * (x_r + x_e) / spacing_);  // sleeper nearest the midpoint

  // Toeplitz column of A: g_wF(d L), d = 0 .. 2N.
  std::vector<cdouble> g(m);
  for (int d = 0; d < m; ++d) g[d] = free_rail.transfer(d * spacing_)(0, 0);

  // S = A + K^{-1} I, B_e and B_r (rows: g_wF, g_wM of the free rail at x_n - x).
  Eigen::MatrixXcd S(m, m);
  Eigen::MatrixXcd Be(m, 2), Br(m, 2);
  const cdouble compliance = 1.0 / K;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) S(i, j) = g[std::abs(i - j)];
    S(i, i) += compliance;
    const double xn = (n0 - n_ + i) * spacing_;
    Be.row(i) = free_rail.transfer(xn - x_e).row(0);
    Br.row(i) = free_rail.transfer(xn - x_r).row(0);
  }
  const Eigen::MatrixXcd X = S.partialPivLu().solve(Be);
  Eigen::Matrix2cd H = free_rail.transfer(x_r - x_e) - Br.transpose() * X;
  if (!H.allFinite())
    throw NumericalError("DiscretelySupportedRail: non-finite receptance at f = " +
                         std::to_string(frequency) + " Hz");
  return H;
}

// ---------------------------------------------------------------------------------------------
// The rail's 4x4 contact-point receptance
// ---------------------------------------------------------------------------------------------

namespace {
const TrackParameters& validated(const TrackParameters& t) {
  t.validate();
  return t;
}
}  // namespace

RailModel::RailModel(const TrackParameters& track, TrackSupport support, double contact_position)
    : track_(validated(track)),
      support_(support),
      x_(contact_position),
      vertical_(track.vertical, track.vertical_support, track.sleeper_spacing,
                track.supports_each_side),
      lateral_(track.lateral, track.lateral_support, track.sleeper_spacing,
               track.supports_each_side) {
  if (!std::isfinite(x_)) throw InputError("track.position", "contact position must be finite");
}

Receptance4 RailModel::receptance(double frequency) const {
  return receptance_impl(checked_omega(frequency), frequency);
}

Receptance4 RailModel::receptance_laplace(cdouble s) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  return receptance_impl(cdouble(0.0, -1.0) * s, s.imag() / (2.0 * M_PI));  // omega = -i s
}

// The same arithmetic for a real and a complex angular frequency (`frequency` in Hz for the
// real-frequency calls, which keep their bits).
template <class Omega>
Receptance4 RailModel::receptance_impl(Omega omega, double frequency) const {
  Eigen::Matrix2cd Hv, Hl;
  if (support_ == TrackSupport::kDiscrete) {
    Hv = vertical_.transfer_impl(omega, frequency, x_, x_);
    Hl = lateral_.transfer_impl(omega, frequency, x_, x_);
  } else {
    const double L = track_.sleeper_spacing, wr = std::real(omega);
    Hv = beam(track_.vertical, omega, track_.vertical_support.dynamic_stiffness(omega) / L,
              track_.vertical_support.dynamic_stiffness(wr) / L)
             .transfer(0.0);
    Hl = beam(track_.lateral, omega, track_.lateral_support.dynamic_stiffness(omega) / L,
              track_.lateral_support.dynamic_stiffness(wr) / L)
             .transfer(0.0);
  }
  const cdouble s_x = track_.longitudinal_support.dynamic_stiffness(omega) / track_.sleeper_spacing;
  const cdouble u_rod = rod(track_.vertical, omega, s_x,
                          track_.longitudinal_support.dynamic_stiffness(std::real(omega)) / track_.sleeper_spacing);
  const double h = track_.head_height;

  Receptance4 R = Receptance4::Zero();
  R(kZ, kZ) = Hv(0, 0);
  R(kZ, kX) = -h * Hv(0, 1);
  R(kX, kZ) = -h * Hv(1, 0);
  R(kX, kX) = u_rod + h * h * Hv(1, 1);
  R(kY, kY) = Hl(0, 0);
  R(kY, kRotZ) = Hl(0, 1);
  R(kRotZ, kY) = Hl(1, 0);
  R(kRotZ, kRotZ) = Hl(1, 1);
  return R;
}

}  // namespace rollnoise::dynamics
