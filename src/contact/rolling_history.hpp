// The force history of unsteady rolling (paper Eq. 2, contact::TransientRolling) under a creepage
// history: the loop shared by `rollnoise validate` and `rollnoise bench`.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "contact/creepage_history.hpp"
#include "contact/grid.hpp"
#include "contact/transient_rolling.hpp"

namespace rollnoise::contact {

/// Steps k = 1..steps of `rolling` from the state it holds, step k with the creepage
/// h.step_creepage(sampling, k, dt) (at t_k = k dt for contact, CONTACT's convention; at t_k - dt/2
/// for midstep; the mean over [t_{k-1}, t_k] for average; creepage_history.hpp) and, unless `normal_force` is empty, the normal load
/// normal_force[k] (N, at t_k in both samplings; after TransientRolling::set_normal_problem).
/// `on_step(k, xi, s)` receives each step's creepage and solution.
using StepCallback = std::function<void(long, const Creepage&, const TangentialSolution&)>;
void roll(TransientRolling& rolling, const CreepageHistory& h, CreepageSampling sampling, double dt, long steps,
          const std::vector<double>& normal_force, const StepCallback& on_step);

/// Total forces (Fx, Fy, Mz) (contact/forces.hpp) after steps k = 1..steps of `rolling` from the
/// state it holds, stepped as roll() does. `on_step(k)` is called after step k (progress output).
std::vector<Eigen::Vector3d> rolling_forces(TransientRolling& rolling, const Grid& g,
                                            const CreepageHistory& h, CreepageSampling sampling, double dt,
                                            long steps,
                                            const std::vector<double>& normal_force = {},
                                            const std::function<void(long)>& on_step = {});

}  // namespace rollnoise::contact
