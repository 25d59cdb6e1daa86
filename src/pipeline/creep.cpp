#include "pipeline/creep.hpp"

#include <chrono>

#include "core/errors.hpp"

namespace rollnoise::pipeline {

CreepResult run_creep(ContactCase c, const std::vector<double>& freq, bool direct, const std::string& frequency_key) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  place_contact(c);
  check_nyquist(c, freq, frequency_key);
  CreepResult r;
  const auto t0 = Clock::now();
  r.state = solve_mean_state(std::move(c), true);
  check_nyquist(r.state.contact, freq, frequency_key);  // on the patch's grid
  const nss::LinearContactModel& model = *r.state.model;
  const auto t1 = Clock::now();
  if (direct) {
    for (double fr : freq) r.f.push_back(model.creep_coefficients_direct(fr));
    for (double fr : freq) r.g.push_back(model.normal_load_coefficients_direct(fr));
  } else {
    r.f = model.creep_coefficients(freq);
    r.g = model.normal_load_coefficients(freq);  // the same sweep (one more Krylov column)
  }
  r.seconds_state = seconds(t0, t1);
  r.seconds_sweep = seconds(t1, Clock::now());
  // g(0) by the same method as the sweep (one more LU when direct; else the same sweep)
  r.g0 = direct ? model.normal_load_coefficients_direct(0.0) : model.normal_load_coefficients(std::vector<double>{0.0})[0];
  return r;
}

}  // namespace rollnoise::pipeline
