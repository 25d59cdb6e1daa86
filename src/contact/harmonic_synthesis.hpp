// Harmonic synthesis: the response of a linear contact model to the harmonic content of a
// creepage history (paper Eqs. 33-34, with the normal-load input of docs/nss_normal_load.md Eq. G2),
//
//   F(t_k) = F_bar - Re sum_n (f(w_n) xi^_n - g(w_n) N^_n) e^{i w_n t_k},   t_k = k dt,
//
// xi^_n = (a_j e^{i alpha_jn})_j the complex amplitudes of the creepage variation at f_n
// (CreepageHistory::amplitude, phases), N^_n = a_N e^{i beta_n} those of the normal load
// (normal_amplitude, normal_phases), f(w) the creep coefficients (F~ = -f xi~, paper Eqs. 28-30)
// and g(w) the normal-load coefficients. Used by `rollnoise response` and `validate` beside the
// discrete-time recursion (nss/linear_response.hpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/creepage_history.hpp"

namespace rollnoise::contact {

/// Forces (Fx, Fy, Mz) at t_k = k dt, k = 0..steps, incl. `mean_force`. `f` (and `g`, used only
/// when the history has a normal-load variation) hold one coefficient per history frequency.
std::vector<Eigen::Vector3d> harmonic_synthesis(const CreepageHistory& h,
                                                const std::vector<Eigen::Matrix3cd>& f,
                                                const std::vector<Eigen::Vector3cd>& g,
                                                const Eigen::Vector3d& mean_force, double dt,
                                                long steps);

}  // namespace rollnoise::contact
