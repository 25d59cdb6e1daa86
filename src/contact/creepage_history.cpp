#include "contact/creepage_history.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "core/assert.hpp"

namespace rollnoise::contact {

// sin(x)/x, 1 at x = 0 (|x| < 1e-4: the series 1 - x^2/6, exact to 1e-17).
static double sinc(double x) { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

std::complex<double> step_sampling_factor(CreepageSampling s, double frequency, double dt) {
  // average: (1/dt) int_{t_k - dt}^{t_k} e^{i w t} dt = e^{i w t_k} (1 - e^{-i w dt})/(i w dt)
  //        = e^{i w t_k} e^{-i w dt/2} sin(w dt/2)/(w dt/2)
  if (s == CreepageSampling::contact) return 1.0;
  const double x = M_PI * frequency * dt;  // w dt/2
  return std::polar(s == CreepageSampling::average ? sinc(x) : 1.0, -x);
}

const char* sampling_name(CreepageSampling s) {
  switch (s) {
    case CreepageSampling::contact:
      return "contact";
    case CreepageSampling::midstep:
      return "midstep";
    case CreepageSampling::average:
      return "average";
  }
  return "contact";
}

CreepageHistory CreepageHistory::constant(const Creepage& mean) {
  CreepageHistory h;
  h.mean_ = mean;
  return h;
}

CreepageHistory CreepageHistory::harmonic(const Creepage& mean,
                                          const std::array<double, 3>& amplitude, double frequency,
                                          const std::array<double, 3>& phase,
                                          double normal_amplitude, double normal_phase) {
  ROLLNOISE_ASSERT(frequency > 0.0 && std::isfinite(normal_amplitude) && std::isfinite(normal_phase),
                   "harmonic excitation: a positive frequency, a finite load amplitude and phase");
  CreepageHistory h;
  h.kind_ = Kind::harmonic;
  h.mean_ = mean;
  h.amp_ = amplitude;
  h.freq_ = {frequency};
  for (int j = 0; j < 3; ++j) h.phase_[j] = {phase[j]};
  h.normal_amp_ = normal_amplitude;
  h.normal_phase_ = {normal_phase};
  return h;
}

CreepageHistory CreepageHistory::multiharmonic(const Creepage& mean,
                                               const std::array<double, 3>& amplitude, double f_min,
                                               double f_max, int count, std::uint64_t seed,
                                               double normal_amplitude) {
  ROLLNOISE_ASSERT(f_min > 0.0 && f_max >= f_min && count >= 1 && std::isfinite(normal_amplitude),
                   "multiharmonic excitation: 0 < f_min <= f_max, count >= 1, a finite load amplitude");
  CreepageHistory h;
  h.kind_ = Kind::multiharmonic;
  h.mean_ = mean;
  h.amp_ = amplitude;
  h.freq_.resize(count);
  for (int n = 0; n < count; ++n)
    h.freq_[n] = count == 1 ? f_min : f_min + (f_max - f_min) * n / double(count - 1);
  h.seed_ = seed;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 2.0 * M_PI);
  for (int j = 0; j < 3; ++j) {
    h.phase_[j].resize(count);
    for (int n = 0; n < count; ++n) h.phase_[j][n] = U(rng);
  }
  // the load's phases after all creepage phases, so that these do not depend on the load
  h.normal_amp_ = normal_amplitude;
  h.normal_phase_.resize(count);
  for (int n = 0; n < count; ++n) h.normal_phase_[n] = U(rng);
  return h;
}

CreepageHistory CreepageHistory::samples(const Creepage& mean, std::vector<double> t,
                                         std::vector<Creepage> values, std::vector<double> normal) {
  ROLLNOISE_ASSERT(t.size() >= 2 && t.size() == values.size() && (normal.empty() || normal.size() == t.size()),
                   "a creepage time series of two or more samples, one normal load (if any) per time");
  const auto not_increasing = [](double a, double b) { return !(b > a); };
  ROLLNOISE_ASSERT(std::adjacent_find(t.begin(), t.end(), not_increasing) == t.end(), "strictly increasing times");
  (void)not_increasing;
  CreepageHistory h;
  h.kind_ = Kind::samples;
  h.mean_ = mean;
  h.t_ = std::move(t);
  h.values_ = std::move(values);
  h.normal_values_ = std::move(normal);
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

// The sample interval of t: index i of the sample after t and the weight of sample i (t inside).
static std::pair<size_t, double> interval(const std::vector<double>& ts, double t) {
  const size_t i = std::upper_bound(ts.begin(), ts.end(), t) - ts.begin();
  return {i, (t - ts[i - 1]) / (ts[i] - ts[i - 1])};
}

double CreepageHistory::normal_variation(double t) const {
  switch (kind_) {
    case Kind::constant:
      return 0.0;
    case Kind::harmonic:
    case Kind::multiharmonic: {
      if (normal_amp_ == 0.0) return 0.0;
      double v = 0.0;
      for (size_t n = 0; n < freq_.size(); ++n)
        v += std::cos(2.0 * M_PI * freq_[n] * t + normal_phase_[n]);
      return normal_amp_ * v;
    }
    case Kind::samples: {
      if (normal_values_.empty()) return 0.0;
      if (t <= t_.front()) return normal_values_.front();
      if (t >= t_.back()) return normal_values_.back();
      const auto [i, w] = interval(t_, t);
      return normal_values_[i - 1] + w * (normal_values_[i] - normal_values_[i - 1]);
    }
  }
  return 0.0;
}

bool CreepageHistory::has_normal_variation() const {
  if (kind_ == Kind::samples)
    return std::any_of(normal_values_.begin(), normal_values_.end(),
                       [](double v) { return v != 0.0; });
  return kind_ != Kind::constant && normal_amp_ != 0.0;
}

Creepage CreepageHistory::at(double t) const {
  if (kind_ == Kind::samples) {
    if (t <= t_.front()) return values_.front();
    if (t >= t_.back()) return values_.back();
    const auto [i, w] = interval(t_, t);
    const Creepage &a = values_[i - 1], &b = values_[i];
    return {a.xi_x + w * (b.xi_x - a.xi_x), a.xi_y + w * (b.xi_y - a.xi_y), a.phi + w * (b.phi - a.phi)};
  }
  const auto v = variation(t);
  return {mean_.xi_x + v[0], mean_.xi_y + v[1], mean_.phi + v[2]};
}

std::array<double, 3> CreepageHistory::step_average_variation(double t0, double t1) const {
  std::array<double, 3> v{};
  switch (kind_) {
    case Kind::constant:
      break;
    case Kind::harmonic:
    case Kind::multiharmonic: {
      // (1/(t1-t0)) int cos(w t + a) dt = [sin(w t1 + a) - sin(w t0 + a)] / (w (t1 - t0))
      //   = cos(w tc + a) sin(w h)/(w h),  tc = (t0 + t1)/2, h = (t1 - t0)/2
      const double tc = 0.5 * (t0 + t1), h = 0.5 * (t1 - t0);
      for (size_t n = 0; n < freq_.size(); ++n) {
        const double w = 2.0 * M_PI * freq_[n], s = sinc(w * h);
        for (int j = 0; j < 3; ++j)
          if (amp_[j] != 0.0) v[j] += amp_[j] * s * std::cos(w * tc + phase_[j][n]);
      }
      break;
    }
    case Kind::samples: {
      const Creepage c = step_average(t0, t1);
      v = {c.xi_x - mean_.xi_x, c.xi_y - mean_.xi_y, c.phi - mean_.phi};
      break;
    }
  }
  return v;
}

Creepage CreepageHistory::step_average(double t0, double t1) const {
  if (kind_ != Kind::samples) {
    const auto v = step_average_variation(t0, t1);
    return {mean_.xi_x + v[0], mean_.xi_y + v[1], mean_.phi + v[2]};
  }
  // The interpolant is linear between consecutive breakpoints (t0, the sample times inside
  // (t0, t1), t1; constant outside [t_front, t_back], whose ends are sample times): the trapezoid
  // rule on each piece integrates it exactly.
  std::array<double, 3> sum{};
  double a = t0;
  Creepage ca = at(t0);
  auto piece = [&](double b, const Creepage& cb) {
    const double w = 0.5 * (b - a);
    sum[0] += w * (ca.xi_x + cb.xi_x), sum[1] += w * (ca.xi_y + cb.xi_y), sum[2] += w * (ca.phi + cb.phi);
    a = b, ca = cb;
  };
  for (size_t i = std::upper_bound(t_.begin(), t_.end(), t0) - t_.begin(); i < t_.size() && t_[i] < t1; ++i)
    piece(t_[i], values_[i]);
  piece(t1, at(t1));
  const double span = t1 - t0;
  return {sum[0] / span, sum[1] / span, sum[2] / span};
}

Creepage CreepageHistory::step_creepage(CreepageSampling sampling, long k, double dt) const {
  if (sampling == CreepageSampling::average)
    return step_average(static_cast<double>(k - 1) * dt, static_cast<double>(k) * dt);
  return at(sampling_time(sampling, k, dt));
}

std::array<double, 3> CreepageHistory::step_variation(CreepageSampling sampling, long k, double dt) const {
  if (sampling == CreepageSampling::average)
    return step_average_variation(static_cast<double>(k - 1) * dt, static_cast<double>(k) * dt);
  return variation(sampling_time(sampling, k, dt));
}

}  // namespace rollnoise::contact
