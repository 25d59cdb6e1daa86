#include "dynamics/track.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "dynamics/frequency_argument.hpp"
#include "dynamics/track_periodic.hpp"
#include "linalg/toeplitz_solve.hpp"

namespace rollnoise::dynamics {

// ---------------------------------------------------------------------------------------------
// Support
// ---------------------------------------------------------------------------------------------

cdouble Support::dynamic_stiffness(double omega) const {
  const cdouble kp = pad_stiffness * cdouble(1.0, pad_loss_factor);
  const cdouble kb = ballast_stiffness * cdouble(1.0, ballast_loss_factor);
  const cdouble below = kb - sleeper_mass * omega * omega;  // sleeper on ballast, seen from above
  return kp * below / (kp + below);                         // Eq. (1): pad in series
}

cdouble Support::sleeper_transfer(double omega) const {
  const cdouble kp = pad_stiffness * cdouble(1.0, pad_loss_factor);
  const cdouble kb = ballast_stiffness * cdouble(1.0, ballast_loss_factor);
  return kp / (kp + kb - sleeper_mass * omega * omega);  // the pad's force moves the sleeper
}

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
                                                 double sleeper_spacing, int supports_each_side,
                                                 DiscreteSupportSolution solution)
    : rail_(rail),
      support_(support),
      spacing_(sleeper_spacing),
      n_(supports_each_side),
      solution_(solution) {
  rail_.validate("rail");
  support_.validate("support");
  if (!(spacing_ > 0.0)) throw InputError("sleeper_spacing", "sleeper_spacing must be positive");
  if (n_ < 1) throw InputError("supports_each_side", "supports_each_side must be at least 1");
}

Eigen::Matrix2cd DiscretelySupportedRail::transfer(double frequency, double x_r, double x_e) const {
  const double omega = checked_omega(frequency);
  const Eigen::Matrix2cd H =
      solve(InfiniteBeam(rail_, omega, 0.0), support_.dynamic_stiffness(omega), x_r, x_e, false);
  if (!H.allFinite())
    throw NumericalError("DiscretelySupportedRail: non-finite receptance at f = " +
                         std::to_string(frequency) + " Hz");
  return H;
}

std::vector<Eigen::Matrix2cd> DiscretelySupportedRail::transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  const double omega = checked_omega(frequency);
  std::vector<Eigen::Matrix2cd> H =
      solve_pairs(InfiniteBeam(rail_, omega, 0.0), support_.dynamic_stiffness(omega), pairs, false);
  for (const Eigen::Matrix2cd& h : H)
    if (!h.allFinite())
      throw NumericalError("DiscretelySupportedRail: non-finite receptance at f = " +
                           std::to_string(frequency) + " Hz");
  return H;
}

Eigen::Matrix2cd DiscretelySupportedRail::solve(const InfiniteBeam& free_rail, cdouble K,
                                                double x_r, double x_e, bool dense) const {
  return solve_pairs(free_rail, K, {{x_r, x_e}}, dense).front();
}

std::vector<Eigen::Matrix2cd> DiscretelySupportedRail::solve_pairs(
    const InfiniteBeam& free_rail, cdouble K, const std::vector<std::pair<double, double>>& pairs,
    bool dense) const {
  if (solution_ == DiscreteSupportSolution::kPeriodic) {  // real frequency or Im omega <= 0
    const PeriodicallySupportedBeam track(free_rail, K, spacing_);
    std::vector<Eigen::Matrix2cd> H;
    H.reserve(pairs.size());
    for (const auto& [x_r, x_e] : pairs) H.push_back(track.transfer(x_r, x_e));
    return H;
  }
  const int m = 2 * n_ + 1;
  const Eigen::Index np = static_cast<Eigen::Index>(pairs.size());

  // Toeplitz column of S = A + K^{-1} I: g_wF(d L), d = 0 .. 2N, plus the compliance on d = 0.
  // S depends on the frequency only; each pair has its own window, so its own B_e, B_r.
  const Eigen::MatrixX2cd column = free_rail.deflection_rows(0.0, spacing_, m);
  std::vector<cdouble> t(column.col(0).data(), column.col(0).data() + m);
  t[0] += 1.0 / K;

  // B_e and B_r of each pair (rows: g_wF, g_wM of the free rail at x_n - x, over the 2N + 1
  // supports centred on the sleeper nearest the pair's midpoint); B_r = B_e for a point receptance.
  Eigen::MatrixXcd Be(m, 2 * np);
  std::vector<Eigen::MatrixXcd> Br(pairs.size());
  for (Eigen::Index p = 0; p < np; ++p) {
    const double x_r = pairs[p].first, x_e = pairs[p].second;
    const long n0 = std::lround(0.5 * (x_r + x_e) / spacing_);  // sleeper nearest the midpoint
    const double x_first = (n0 - n_) * spacing_;
    Be.middleCols(2 * p, 2) = free_rail.deflection_rows(x_first - x_e, spacing_, m);
    if (x_r != x_e) Br[p] = free_rail.deflection_rows(x_first - x_r, spacing_, m);
  }
  // X = S^{-1} B_e by Levinson's recursion, O(m^2) (linalg/toeplitz_solve.hpp), or by the dense
  // LU with pivoting where that recursion's residual check fails or `dense` is asked for.
  Eigen::MatrixXcd X;
  if (dense || !linalg::toeplitz_solve(t, Be, X)) {
    Eigen::MatrixXcd S(m, m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) S(i, j) = t[std::abs(i - j)];
    X = S.partialPivLu().solve(Be);
  }
  std::vector<Eigen::Matrix2cd> H(pairs.size());
  for (Eigen::Index p = 0; p < np; ++p) {
    const double x_r = pairs[p].first, x_e = pairs[p].second;
    const Eigen::MatrixXcd Xp = X.middleCols(2 * p, 2);
    H[p] = free_rail.transfer(x_r - x_e) -
           (x_r != x_e ? Br[p] : Eigen::MatrixXcd(Be.middleCols(2 * p, 2))).transpose() * Xp;
  }
  return H;
}

// ---------------------------------------------------------------------------------------------
// The rail's 4x4 contact-point receptance
// ---------------------------------------------------------------------------------------------

Receptance4 rail_receptance4(const Eigen::Matrix2cd& Hv, const Eigen::Matrix2cd& Hl, cdouble rod,
                             double h) {
  Receptance4 R = Receptance4::Zero();
  R(kZ, kZ) = Hv(0, 0);
  R(kZ, kX) = -h * Hv(0, 1);
  R(kX, kZ) = -h * Hv(1, 0);
  R(kX, kX) = rod + h * h * Hv(1, 1);
  R(kY, kY) = Hl(0, 0);
  R(kY, kRotZ) = Hl(0, 1);
  R(kRotZ, kY) = Hl(1, 0);
  R(kRotZ, kRotZ) = Hl(1, 1);
  return R;
}


// ---------------------------------------------------------------------------------------------
// Complex frequency (docs/squeal.md Sec. 2): Eqs. (1), (2) and the contact-point receptance for a
// complex omega = -i s, written out separately from the real-frequency functions above (which keep
// their code and bits). The foundation at Re omega is passed on for the continuation of the
// wavenumber roots (track_beam.hpp).
// ---------------------------------------------------------------------------------------------

cdouble Support::dynamic_stiffness(cdouble omega) const {
  const cdouble kp = pad_stiffness * cdouble(1.0, pad_loss_factor);
  const cdouble kb = ballast_stiffness * cdouble(1.0, ballast_loss_factor);
  const cdouble below = kb - sleeper_mass * omega * omega;
  return kp * below / (kp + below);
}

Eigen::Matrix2cd DiscretelySupportedRail::transfer_at(cdouble omega, double x_r, double x_e) const {
  // For a decaying s (Im omega > 0) the continued roots have Im k > 0: the free rail's waves grow
  // along the supported stretch and S is singular to round-off (condition 1e24-1e30 at 8 kHz and
  // 5 % damping with N = 60). There the dense LU with pivoting is kept as it was (its result is
  // not reliable either: docs/record/performance.md Sec. 3); elsewhere Levinson's O(m^2) solve.
  if (solution_ == DiscreteSupportSolution::kPeriodic && omega.imag() > 0.0) {
    // The periodic solution has no ends to reflect from: its closed forms are continued, the
    // decaying multipliers followed from Re omega up to omega in steps of 0.5 % of Re omega in
    // Im omega (each the one of mu, 1/mu nearest the previous step's; track_periodic.hpp P1).
    const double wr = omega.real();
    const int steps =
        std::clamp(static_cast<int>(std::ceil(omega.imag() / (0.005 * std::abs(wr)))), 1, 64);
    PeriodicallySupportedBeam track(InfiniteBeam(rail_, wr, 0.0), support_.dynamic_stiffness(wr),
                                    spacing_);
    for (int step = 1; step <= steps; ++step) {
      const cdouble w(wr, omega.imag() * step / steps);
      track = PeriodicallySupportedBeam(InfiniteBeam(rail_, w, 0.0, 0.0),
                                        support_.dynamic_stiffness(w), spacing_, &track);
    }
    const Eigen::Matrix2cd H = track.transfer(x_r, x_e);
    if (!H.allFinite())
      throw NumericalError("DiscretelySupportedRail: non-finite receptance at complex frequency");
    return H;
  }
  const Eigen::Matrix2cd H = solve(InfiniteBeam(rail_, omega, 0.0, 0.0),
                                   support_.dynamic_stiffness(omega), x_r, x_e, omega.imag() > 0.0);
  if (!H.allFinite())
    throw NumericalError("DiscretelySupportedRail: non-finite receptance at complex frequency");
  return H;
}

}  // namespace rollnoise::dynamics
