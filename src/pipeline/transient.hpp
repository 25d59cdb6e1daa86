// The transient pipeline (`rollnoise transient`): unsteady rolling (paper Eq. 2) of a placed
// contact case under a creepage and normal-load history, one rolling step dx/V per time step,
// from the steady state at the mean creepage (and mean load) or from zero tractions.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "contact/creepage_history.hpp"
#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::pipeline {

/// The number of time steps dt = dx/V in `duration`; InputError naming transient.duration when
/// it is shorter than one step or beyond c.limits (steps, memory of the per-step results).
long transient_steps(const ContactCase& c, double duration, double dx);

/// The total normal load N_mean + dN(t_k) of every step k = 0..steps (N); InputError naming
/// excitation.file (sampled history) or excitation.normal_amplitude when one is not finite or
/// not positive (a patch without load has no contact).
std::vector<double> normal_load_series(const contact::CreepageHistory& h, double normal_mean, double dt, long steps);

struct TransientInput {
  contact::CreepageHistory history;
  double duration = 0.0;           ///< s
  bool from_steady = true;         ///< start from steady rolling at the mean creepage
  std::vector<double> snapshots;   ///< times (s) whose traction fields are kept
};

struct TransientSnapshot {
  std::size_t index = 0;  ///< in TransientInput::snapshots
  double time = 0.0;
  contact::Creepage creepage;
  contact::TangentialSolution solution;
};

struct TransientResult {
  std::unique_ptr<contact::ContactPatch> patch;
  double dt = 0.0;
  long steps = 0;
  bool varying_load = false;
  std::vector<double> time, creepage, force;  ///< per step: s; (-, -, rad/m); (N, N, N m)
  std::vector<double> load;  ///< normal load of every step (normal_load_series) (N)
  std::vector<int> n_adhesion, n_slip;
  std::vector<TransientSnapshot> snapshots;
  long newton = 0, factorisations = 0, gmres = 0;
  int normal_solves = 0;
  double normal_iterations = 0.0, normal_seconds = 0.0, seconds = 0.0;
};

/// InputError naming excitation.frequency (harmonic) or excitation.f_max when a frequency of the
/// history lies above the Nyquist limit of the case's grid: one step per dx/V cannot resolve it
/// (it would alias onto a lower frequency).
void check_excitation_nyquist(const ContactCase& c, const contact::CreepageHistory& h);

/// The checks of run_transient that need no solve (steps, loads, snapshot times, the excitation's
/// frequencies against the Nyquist limit) on the placed case; InputError naming the key.
void check_transient(const ContactCase& c, const TransientInput& in);

/// Called after every step k = 1..steps (for progress).
using StepObserver = std::function<void(long)>;

/// The patch of the placed case `c` is solved first, the steps and loads follow on its grid (which
/// profiles may have enlarged; check_transient gives the same errors before the solve); with a
/// varying load, InputError when the contact area at the largest load leaves the grid (before any
/// time step).
TransientResult run_transient(const ContactCase& c, const TransientInput& in, const StepObserver& observe = {});

}  // namespace rollnoise::pipeline
