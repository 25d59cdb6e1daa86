#include "pipeline/transient.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "contact/forces.hpp"
#include "contact/rolling_history.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "core/errors.hpp"

namespace rollnoise::pipeline {

long transient_steps(const ContactCase& c, double duration, double dx) {
  const double dt = dx / c.speed;
  const double count = std::floor(duration / dt + 1e-9);
  check_size(c.limits, "transient.duration", count, "time steps of dt = dx/V", transient_bytes(count));
  const long steps = std::lround(count);
  if (steps < 1)
    throw InputError("transient.duration", "shorter than one time step dx/V = " + std::to_string(dt) + " s");
  return steps;
}

std::vector<double> normal_load_series(const contact::CreepageHistory& h, double normal_mean, double dt, long steps) {
  const std::string key =
      h.kind() == contact::CreepageHistory::Kind::samples ? "excitation.file" : "excitation.normal_amplitude";
  std::vector<double> N(steps + 1);
  for (long k = 0; k <= steps; ++k) {
    N[k] = normal_mean + h.normal_variation(k * dt);
    const std::string at = " at t = " + std::to_string(k * dt) + " s";
    if (!std::isfinite(N[k])) throw InputError(key, "the normal load is not finite" + at);
    if (!(N[k] > 0.0))
      throw InputError(key, "the total normal load contact.normal_force + variation is " + std::to_string(N[k]) +
                                " N" + at + "; it must stay positive");
  }
  return N;
}

void check_excitation_nyquist(const ContactCase& c, const contact::CreepageHistory& h) {
  check_nyquist(c, h.frequencies(), h.frequencies().size() == 1 ? "excitation.frequency" : "excitation.f_max");
}

void check_transient(const ContactCase& c, const TransientInput& in) {
  check_excitation_nyquist(c, in.history);
  const long steps = transient_steps(c, in.duration, c.grid.dx);
  normal_load_series(in.history, c.normal_force, c.grid.dx / c.speed, steps);
  for (double t : in.snapshots)
    if (t < 0 || t > in.duration) throw InputError("transient.snapshots", "times must lie in [0, duration]");
}

namespace {

// Zero tractions on the contact area (adhesion), no slip: the start of a run from rest.
contact::TangentialSolution zero_tractions(const contact::ContactPatch& patch) {
  const int n = patch.grid.size();
  contact::TangentialSolution s;
  s.px.assign(n, 0.0);
  s.py.assign(n, 0.0);
  s.sx = s.px, s.sy = s.px;
  s.state.assign(n, 0);
  for (int k = 0; k < n; ++k)
    if (patch.normal.pn[k] > 0) s.state[k] = 1;
  return s;
}

}  // namespace

TransientResult run_transient(const ContactCase& c, const TransientInput& in, const StepObserver& observe) {
  TransientResult r;
  r.patch = std::make_unique<contact::ContactPatch>(solve_patch(c));
  const contact::ContactPatch& patch = *r.patch;
  const contact::Grid& g = patch.grid;
  r.dt = g.dx / c.speed;
  ContactCase on_patch = c;
  on_patch.grid = g;
  check_excitation_nyquist(on_patch, in.history);  // profiles may have enlarged the grid
  r.steps = transient_steps(c, in.duration, g.dx);
  r.load = normal_load_series(in.history, c.normal_force, r.dt, r.steps);
  r.varying_load = in.history.has_normal_variation();
  const std::vector<double>& load = r.load;
  if (r.varying_load) {  // the contact area at the largest load must fit the grid: check before running
    const double n_max = *std::max_element(load.begin(), load.end());
    try {
      contact::solve_patch(g, c.material, patch.undeformed_distance, n_max, c.backend, c.normal);
    } catch (const InputError& e) {
      throw InputError(in.history.kind() == contact::CreepageHistory::Kind::samples ? "excitation.file"
                                                                                     : "excitation.normal_amplitude",
                       "at the largest normal load " + std::to_string(n_max) + " N: " + e.what());
    }
  }

  contact::TransientRolling rolling(patch.influence, patch.normal.pn, c.mu, c.speed, c.spin_offset, c.backend,
                                    c.tangential);
  rolling.set_falling_friction(c.falling);
  if (r.varying_load) rolling.set_normal_problem(patch.undeformed_distance, c.normal_force, c.normal);
  contact::TangentialSolution start = zero_tractions(patch);
  if (in.from_steady) {
    start = contact::solve_steady_rolling(patch.influence, patch.normal.pn, c.steady_input(), c.tangential);
    rolling.set_tractions(start.px, start.py);
  }

  std::vector<long> snap_step;
  for (double t : in.snapshots) snap_step.push_back(std::lround(t / r.dt));
  auto record = [&](long k, const contact::Creepage& xi, const contact::TangentialSolution& s) {
    const auto f = contact::total_forces(g, s.px, s.py);
    r.time.push_back(k * r.dt);
    r.creepage.insert(r.creepage.end(), {xi.xi_x, xi.xi_y, xi.phi});
    r.force.insert(r.force.end(), {f.Fx, f.Fy, f.Mz});
    r.n_adhesion.push_back(s.count(contact::ElementState::adhesion));
    r.n_slip.push_back(s.count(contact::ElementState::slip));
    for (std::size_t i = 0; i < snap_step.size(); ++i)
      if (snap_step[i] == k) r.snapshots.push_back({i, k * r.dt, xi, s});
  };
  record(0, in.history.step_creepage(c.sampling, 0, r.dt), start);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double> fixed_load;  // empty: the normal problem stays that of the patch
  contact::roll(rolling, in.history, c.sampling, r.dt, r.steps, r.varying_load ? load : fixed_load,
                [&](long k, const contact::Creepage& xi, const contact::TangentialSolution& s) {
                  r.newton += s.iterations;
                  r.factorisations += s.factorisations;
                  r.gmres += s.linear_iterations;
                  record(k, xi, s);
                  if (observe) observe(k);
                });
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.normal_solves = rolling.normal_solves();
  r.normal_iterations = rolling.normal_iterations();
  r.normal_seconds = rolling.normal_seconds();
  return r;
}

}  // namespace rollnoise::pipeline
