// Creepage histories xi(t) = (xi_x, xi_y, phi)(t) for transient rolling and the linear model's
// time responses: the mean plus a variation that is
//   none           constant creepage;
//   harmonic       amplitude_j cos(2 pi f t + phase_j)                       (paper Eq. 31);
//   multiharmonic  amplitude_j sum_n cos(2 pi f_n t + alpha_jn), f_n evenly spaced in
//                  [f_min, f_max], phases alpha_jn uniform in [0, 2 pi) from a seeded
//                  generator (std::mt19937_64), so a run can be repeated exactly (paper Eq. 32);
//   samples        a time series (t_i, xi_i) interpolated linearly (held constant outside).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

class CreepageHistory {
 public:
  enum class Kind { constant, harmonic, multiharmonic, samples };

  static CreepageHistory constant(const Creepage& mean);
  /// phase in radians per component.
  static CreepageHistory harmonic(const Creepage& mean, const std::array<double, 3>& amplitude,
                                  double frequency, const std::array<double, 3>& phase = {});
  static CreepageHistory multiharmonic(const Creepage& mean, const std::array<double, 3>& amplitude,
                                       double f_min, double f_max, int count, std::uint64_t seed);
  /// `t` increasing; `values` one creepage per time.
  static CreepageHistory samples(const Creepage& mean, std::vector<double> t,
                                 std::vector<Creepage> values);

  Kind kind() const { return kind_; }
  const Creepage& mean() const { return mean_; }
  /// Creepage at time t (s).
  Creepage at(double t) const;
  /// The variation at time t (creepage minus mean).
  std::array<double, 3> variation(double t) const;

  // The harmonic content (harmonic: one frequency; multiharmonic: count), for output and for the
  // harmonic synthesis of the linear model (paper Eqs. 33-34).
  const std::vector<double>& frequencies() const { return freq_; }
  /// phase[j][n] of component j at frequency n (rad).
  const std::array<std::vector<double>, 3>& phases() const { return phase_; }
  const std::array<double, 3>& amplitude() const { return amp_; }

 private:
  Kind kind_ = Kind::constant;
  Creepage mean_;
  std::array<double, 3> amp_{};
  std::vector<double> freq_;
  std::array<std::vector<double>, 3> phase_;
  std::vector<double> t_;
  std::vector<Creepage> values_;
};

}  // namespace rollnoise::contact
