#include "contact/creepage_history.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/errors.hpp"

namespace rollnoise::contact {

CreepageHistory CreepageHistory::constant(const Creepage& mean) {
  CreepageHistory h;
  h.mean_ = mean;
  return h;
}

CreepageHistory CreepageHistory::harmonic(const Creepage& mean,
                                          const std::array<double, 3>& amplitude, double frequency,
                                          const std::array<double, 3>& phase) {
  if (!(frequency > 0.0)) throw InputError("excitation.frequency", "must be positive");
  CreepageHistory h;
  h.kind_ = Kind::harmonic;
  h.mean_ = mean;
  h.amp_ = amplitude;
  h.freq_ = {frequency};
  for (int j = 0; j < 3; ++j) h.phase_[j] = {phase[j]};
  return h;
}

CreepageHistory CreepageHistory::multiharmonic(const Creepage& mean,
                                               const std::array<double, 3>& amplitude,
                                               double f_min, double f_max, int count,
                                               std::uint64_t seed) {
  if (!(f_min > 0.0)) throw InputError("excitation.f_min", "must be positive");
  if (!(f_max >= f_min)) throw InputError("excitation.f_max", "must not be below excitation.f_min");
  if (count < 1) throw InputError("excitation.count", "must be at least 1");
  CreepageHistory h;
  h.kind_ = Kind::multiharmonic;
  h.mean_ = mean;
  h.amp_ = amplitude;
  h.freq_.resize(count);
  for (int n = 0; n < count; ++n)
    h.freq_[n] = count == 1 ? f_min : f_min + (f_max - f_min) * n / double(count - 1);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 2.0 * M_PI);
  for (int j = 0; j < 3; ++j) {
    h.phase_[j].resize(count);
    for (int n = 0; n < count; ++n) h.phase_[j][n] = U(rng);
  }
  return h;
}

CreepageHistory CreepageHistory::samples(const Creepage& mean, std::vector<double> t,
                                         std::vector<Creepage> values) {
  if (t.size() < 2 || t.size() != values.size())
    throw InputError("excitation.file", "a creepage time series needs at least two samples");
  for (size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw InputError("excitation.file", "times must increase (row " + std::to_string(i + 1) + ")");
  CreepageHistory h;
  h.kind_ = Kind::samples;
  h.mean_ = mean;
  h.t_ = std::move(t);
  h.values_ = std::move(values);
  return h;
}

std::array<double, 3> CreepageHistory::variation(double t) const {
  std::array<double, 3> v{};
  switch (kind_) {
    case Kind::constant:
      break;
    case Kind::harmonic:
    case Kind::multiharmonic:
      for (size_t n = 0; n < freq_.size(); ++n) {
        const double wt = 2.0 * M_PI * freq_[n] * t;
        for (int j = 0; j < 3; ++j)
          if (amp_[j] != 0.0) v[j] += amp_[j] * std::cos(wt + phase_[j][n]);
      }
      break;
    case Kind::samples: {
      const Creepage c = at(t);
      v = {c.xi_x - mean_.xi_x, c.xi_y - mean_.xi_y, c.phi - mean_.phi};
      break;
    }
  }
  return v;
}

Creepage CreepageHistory::at(double t) const {
  if (kind_ == Kind::samples) {
    if (t <= t_.front()) return values_.front();
    if (t >= t_.back()) return values_.back();
    const size_t i = std::upper_bound(t_.begin(), t_.end(), t) - t_.begin();
    const double w = (t - t_[i - 1]) / (t_[i] - t_[i - 1]);
    const Creepage &a = values_[i - 1], &b = values_[i];
    return {a.xi_x + w * (b.xi_x - a.xi_x), a.xi_y + w * (b.xi_y - a.xi_y), a.phi + w * (b.phi - a.phi)};
  }
  const auto v = variation(t);
  return {mean_.xi_x + v[0], mean_.xi_y + v[1], mean_.phi + v[2]};
}

}  // namespace rollnoise::contact
