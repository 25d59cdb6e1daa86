// The linear model's force response to a creepage (and normal-load) history, as `rollnoise
// response` and `validate` compute it:
//   - by the discrete-time recursion M0 Q_k = M1 Q_{k-1} + W_k (LinearContactModel::time_response,
//     docs/conventions.md Sec. 3), any history, started from rest at t_0 = 0;
//   - by harmonic synthesis (paper Eqs. 33-34, contact/harmonic_synthesis.hpp) with f and g of
//     the model, for harmonic and multiharmonic histories.
// Both include the mean force F_bar of the steady state the model linearises.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/creepage_history.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::nss {

struct LinearResponse {
  std::vector<double> time;                  ///< t_k = k dt, k = 0..steps (s)
  /// the creepage of step k incl. the mean, CreepageHistory::step_creepage(m.sampling(), k, dt):
  /// xi(t_k) (contact), xi(t_k - dt/2) (midstep) or its mean over [t_{k-1}, t_k] (average) (-, -, rad/m)
  std::vector<Eigen::Vector3d> creepage;
  std::vector<double> normal_force;          ///< N_mean + dN(t_k) (N)
  std::vector<Eigen::Vector3d> recursion;    ///< F_bar + F~_k by the recursion (N, N, N m)
  std::vector<Eigen::Vector3d> synthesis;    ///< by harmonic synthesis; empty without harmonics
  bool has_synthesis() const { return !synthesis.empty(); }
};

/// The response over steps of the model's time step dt (t_0 .. t_steps); `mean_force` F_bar
/// (Fx, Fy, Mz) and `mean_normal_force` N_mean of the steady state.
LinearResponse linear_response(const LinearContactModel& m, const Eigen::Vector3d& mean_force,
                               double mean_normal_force, const contact::CreepageHistory& h,
                               long steps);

/// Largest |recursion - synthesis| in Fx, Fy at t_k >= t_start, and the largest variation
/// |synthesis(t_k) - synthesis(t_0)| there (N): how far the recursion's start transient has
/// decayed. Zero without synthesis.
struct RecursionSynthesisGap {
  double difference = 0.0, variation = 0.0;
};
RecursionSynthesisGap recursion_synthesis_gap(const LinearResponse& r, double t_start);

}  // namespace rollnoise::nss
