// The state-space pipeline (`rollnoise statespace`, docs/statespace.md): the linearised contact as
// a linear time-invariant system with inputs u = (xi~x, xi~y, phi~, N~) (-, -, rad/m, N) and
// outputs y = (F~x, F~y, M~z) (N, N, N m), whose transfer matrix is [-f(w) | g(w)] (3 x 4; F~ = -f
// xi~ + g N~, paper Eqs. 28-30, docs/nss_normal_load.md):
//
//  1. continuous time: x' = A x + B u, y = C x + D u with C (sI - A)^{-1} B + D = [-f | g] at
//     s = 2 pi i f, fitted by vector fitting (linalg/vector_fitting.hpp: stable poles, order grown
//     until the error is below the tolerance) over the case's frequency axis ([frequency], the one
//     `rollnoise creep` uses) and 0 Hz: the static gain [-f(0) | g(0)] is always a fitted sample (a
//     time-domain code needs the quasi-static creep forces right), so the fitted frequencies are
//     0 Hz (when the axis starts above it) and the axis;
//  2. discrete time at the model's step dt = dx/V: x_{k+1} = Ad x_k + Bd u_k, y_k = Cd x_k + Dd
//  u_k,
//     the minimal realisation (linalg::eigensystem_realisation, Hankel singular values to
//     `hankel_tolerance` of the largest) of the fast sweep's Markov parameters H_j = [h_j | gm_j]
//     (-f = sum_j h_j z^j, g = sum_j gm_j z^j, z = e^{-i w dt}, so F_k = sum_j H_j u_{k-j};
//     nss/linear_model.hpp): the reduced model the sweep
//     builds, exact up to that truncation. Its response at z = e^{i w dt} is compared with f and g
//     of the sweep on the fitted frequencies. The Markov parameters are those of the recursion with
//     the creepage of step k as its input, whatever the sampling; f carries the sampling's factor
//     (1, exp(-i w dt/2), exp(-i w dt/2) sinc(w dt/2): contact::step_sampling_factor). The comparison
//     names the discrete model's creepage input u_k: xi~(t_k) (contact), xi~(t_k - dt/2) (midstep)
//     or the mean of xi~ over [t_{k-1}, t_k] (average); input_sampling says which, and
//     input_delay_steps the centre of the input, 0 or 0.5 steps before t_k (the normal-load input
//     is N~(t_k) in every sampling).
#pragma once

#include <string>
#include <vector>

#include "linalg/state_space.hpp"
#include "linalg/vector_fitting.hpp"
#include "pipeline/creep.hpp"

namespace rollnoise::pipeline {

struct StateSpaceOptions {
  double tolerance = 1e-5;  ///< statespace.tolerance: target of the fit error
  int max_poles = 60;       ///< statespace.max_poles
  double hankel_tolerance =
      1e-10;  ///< statespace.hankel_tolerance: relative Hankel singular value kept
};

struct StateSpaceResult {
  CreepResult creep;              ///< f, g at `frequency` (and the mean state, the linear model)
  std::vector<double> frequency;  ///< the fitted frequencies (Hz)
  double band_min = 0.0, band_max = 0.0;  ///< the case's axis (Hz)
  linalg::RationalFit fit;         ///< continuous model, its error over the fitted frequencies
  linalg::Realisation discrete;    ///< discrete model at step dt
  double dt = 0.0;                 ///< s
  int markov_count = 0;            ///< Markov parameters realised
  double discrete_error = 0.0;     ///< the discrete model's response against f, g (the fit's norm)
  /// the discrete model's creepage input u_k: xi~(t_k) (contact), xi~(t_k - dt/2) (midstep), the
  /// mean of xi~ over [t_{k-1}, t_k] (average)
  contact::CreepageSampling input_sampling = contact::CreepageSampling::contact;
  double input_delay_steps = 0.0;  ///< 0 (contact) or 0.5 (midstep, average): the centre of u_k is t_k - delay dt
  double seconds_fit = 0.0, seconds_discrete = 0.0;
};

/// [-f | g] (3 x 4) per frequency.
std::vector<Eigen::MatrixXcd> contact_transfer(const std::vector<nss::CreepMatrix>& f,
                                               const std::vector<nss::LoadVector>& g);

/// The Markov parameters H_j = [h_j | gm_j] (3 x 4) of the model's fast sweep (built by a sweep
/// first); NumericalError when the sweep fell back to the Hessenberg form (no Markov parameters).
std::vector<Eigen::MatrixXd> contact_markov_parameters(const nss::LinearContactModel& model);

/// `freq` is the case's frequency axis; InputError naming `frequency_key` above the Nyquist limit.
StateSpaceResult run_statespace(ContactCase c, const std::vector<double>& freq,
                                const StateSpaceOptions& o, const std::string& frequency_key);

}  // namespace rollnoise::pipeline
