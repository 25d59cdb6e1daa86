// Creepage histories xi(t) = (xi_x, xi_y, phi)(t) for transient rolling and the linear model's
// time responses: the mean plus a variation that is
//   none           constant creepage;
//   harmonic       amplitude_j cos(2 pi f t + phase_j)                       (paper Eq. 31);
//   multiharmonic  amplitude_j sum_n cos(2 pi f_n t + alpha_jn), f_n evenly spaced in
//                  [f_min, f_max], phases alpha_jn uniform in [0, 2 pi) from a seeded
//                  generator (std::mt19937_64), so a run can be repeated exactly (paper Eq. 32);
//   samples        a time series (t_i, xi_i) interpolated linearly (held constant outside).
//
// Beside the creepages, the history carries a variation of the normal load, N(t) = N_mean + dN(t)
// (N_mean is the case's contact.normal_force, not stored here), of the same kind:
//   harmonic       dN = normal_amplitude cos(2 pi f t + normal_phase);
//   multiharmonic  dN = normal_amplitude sum_n cos(2 pi f_n t + beta_n) on the same frequencies,
//                  beta_n drawn from the same generator AFTER the creepage phases (alpha_xn for
//                  all n, then alpha_yn, alpha_phi n, then beta_n: 4 count draws from
//                  mt19937_64(seed)), so a seed gives the creepage phases it gave before;
//   samples        an optional dN per sample, interpolated like the creepages.
// The transient solver (transient_rolling.hpp) uses it; the linear model's normal-load input g
// needs normal_variation, normal_amplitude, frequencies and normal_phases, as for the creepages.
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <vector>

#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

/// When the creepage of rolling step k is taken (rolling.creepage_sampling, docs/contact_model.md).
/// Paper Eq. 2 takes the slip of step k from the displacement difference (A p_k - A0 p_{k-1})/dt,
/// a one-step difference centred at t_k - dt/2 (t_k = k dt), while
///   contact  takes the creepage at t_k (CONTACT's convention, Kalker 1990 Sec. 5.3): the discrete
///            response leads the continuous one by half a step, a phase error w dt/2, first order
///            in dx (pipeline::half_step_phase_correction);
///   midstep  takes it at t_k - dt/2, where the difference is centred: the lead vanishes and f
///            converges at second order at rolling-noise frequencies (docs/accuracy.md);
///   average  takes its mean over the step, xi_k = (1/dt) int_{t_{k-1}}^{t_k} xi(t) dt
///            (CreepageHistory::step_average). The displacement difference (u_k - u_{k-1})/dt is
///            exactly the step mean of the rate du/dt; the rigid slip V xi is the other rate in
///            the slip (paper Eq. 2), and averaging it over the same step treats both terms alike.
///            For xi = xi^ e^{i w t}: xi_k = xi^ e^{i w (t_k - dt/2)} sinc(w dt/2), so
///            f_average = f_midstep sinc(w dt/2) (nss::LinearContactModel::apply_sampling): the
///            factor 1/sinc(w dt/2) that the one-step difference leaves in the midstep f cancels
///            to leading order. Still second order, with a smaller constant (docs/accuracy.md).
/// Only the creepage moves: the normal load N_k (and the pressure bound mu pn_k) stays at t_k, with
/// the traction p_k it bounds (measured: g converges at t_k and acquires a first-order error at
/// t_k - dt/2, docs/accuracy.md), in every sampling, so g does not depend on the sampling. The
/// library default (and the case key's) is average, the closest to the continuum at a given cost
/// (rollnoise bench, docs/accuracy.md Sec. 2.3); every comparison with CONTACT names contact.
enum class CreepageSampling { contact, midstep, average };

/// For xi(t) = xi^ e^{i w t} (w = 2 pi frequency), the creepage of step k in `s` is xi^ e^{i w t_k}
/// times this factor: 1 (contact), e^{-i w dt/2} (midstep), e^{-i w dt/2} sinc(w dt/2) (average;
/// sinc x = sin x / x, 1 at x = 0). The linear model's f carries it (nss::LinearContactModel).
std::complex<double> step_sampling_factor(CreepageSampling s, double frequency, double dt);

/// The case-key spelling of a sampling ("contact", "midstep", "average").
const char* sampling_name(CreepageSampling s);

/// The instant the creepage of step k is taken: k dt (contact) or (k - 1/2) dt (midstep; for
/// average the centre of the step it averages over) (s).
inline double sampling_time(CreepageSampling s, long k, double dt) {
  return s == CreepageSampling::contact ? static_cast<double>(k) * dt : (static_cast<double>(k) - 0.5) * dt;
}

class CreepageHistory {
 public:
  enum class Kind { constant, harmonic, multiharmonic, samples };

  static CreepageHistory constant(const Creepage& mean);
  /// phase in radians per component; normal_amplitude (N) and normal_phase (rad) of the load.
  static CreepageHistory harmonic(const Creepage& mean, const std::array<double, 3>& amplitude,
                                  double frequency, const std::array<double, 3>& phase = {},
                                  double normal_amplitude = 0.0, double normal_phase = 0.0);
  /// normal_amplitude (N) per frequency, with its own seeded phases (see above).
  static CreepageHistory multiharmonic(const Creepage& mean, const std::array<double, 3>& amplitude,
                                       double f_min, double f_max, int count, std::uint64_t seed,
                                       double normal_amplitude = 0.0);
  /// `t` increasing; `values` one creepage per time; `normal` empty or one load variation dN (N)
  /// per time.
  static CreepageHistory samples(const Creepage& mean, std::vector<double> t,
                                 std::vector<Creepage> values, std::vector<double> normal = {});

  Kind kind() const { return kind_; }
  const Creepage& mean() const { return mean_; }
  /// Creepage at time t (s).
  Creepage at(double t) const;
  /// The variation at time t (creepage minus mean).
  std::array<double, 3> variation(double t) const;
  /// The mean creepage over [t0, t1] (t1 > t0), exact: harmonic and multiharmonic analytically (the
  /// mean of cos(w t + a) over the interval is cos(w (t0 + t1)/2 + a) sinc(w (t1 - t0)/2)); samples
  /// by integrating the linear interpolant (held constant outside) piece by piece.
  Creepage step_average(double t0, double t1) const;
  /// step_average minus the mean.
  std::array<double, 3> step_average_variation(double t0, double t1) const;
  /// The creepage of rolling step k (t_k = k dt) in `sampling`: at(k dt), at((k - 1/2) dt), or
  /// step_average((k - 1) dt, k dt).
  Creepage step_creepage(CreepageSampling sampling, long k, double dt) const;
  /// step_creepage minus the mean (the linear model's input).
  std::array<double, 3> step_variation(CreepageSampling sampling, long k, double dt) const;

  // The harmonic content (harmonic: one frequency; multiharmonic: count), for output and for the
  // harmonic synthesis of the linear model (paper Eqs. 33-34).
  const std::vector<double>& frequencies() const { return freq_; }
  /// phase[j][n] of component j at frequency n (rad).
  const std::array<std::vector<double>, 3>& phases() const { return phase_; }
  const std::array<double, 3>& amplitude() const { return amp_; }

  /// The normal-load variation dN(t) = N(t) - N_mean (N).
  double normal_variation(double t) const;
  /// Whether dN is not identically zero (a non-zero amplitude or a non-zero sample).
  bool has_normal_variation() const;
  /// harmonic, multiharmonic: the amplitude of dN per frequency (N); 0 otherwise.
  double normal_amplitude() const { return normal_amp_; }
  /// harmonic, multiharmonic: the phase of dN at each of frequencies() (rad); empty otherwise.
  const std::vector<double>& normal_phases() const { return normal_phase_; }
  /// multiharmonic: the seed of the random phases; 0 otherwise (no randomness).
  std::uint64_t seed() const { return seed_; }

 private:
  Kind kind_ = Kind::constant;
  Creepage mean_;
  std::array<double, 3> amp_{};
  std::vector<double> freq_;
  std::array<std::vector<double>, 3> phase_;
  std::vector<double> t_;
  std::vector<Creepage> values_;
  double normal_amp_ = 0.0;
  std::vector<double> normal_phase_;
  std::vector<double> normal_values_;  // samples: dN per time, or empty
  std::uint64_t seed_ = 0;
};

}  // namespace rollnoise::contact
