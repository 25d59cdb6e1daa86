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
//  2. discrete time at the model's step dt = dx/V, with the samples u_k = (xi~(t_k), N~(t_k)) as
//     its input: x_{k+1} = Ad x_k + Bd u_k, y_k = Cd x_k + Dd u_k with Dd + Cd (zI - Ad)^{-1} Bd =
//     [-f | g] at z = e^{i w dt} over the band. Two parts in series (docs/statespace.md Sec. 3):
//     a. the recursion: the minimal realisation (linalg::eigensystem_realisation, Hankel singular
//        values to `hankel_tolerance` of the largest) of the fast sweep's Markov parameters H_j =
//        [h_j | gm_j] (-f_contact = sum_j h_j z^{-j}, so F_k = sum_j H_j v_{k-j};
//        nss/linear_model.hpp), exact up to that truncation, whose creepage input v_k is the
//        creepage of step k in the case's rolling.creepage_sampling: xi~(t_k) (contact), xi~(t_k -
//        dt/2) (midstep) or the mean of xi~ over [t_{k-1}, t_k] (average); f = f_contact S(w dt)
//        with S the sampling's factor 1, e^{-i w dt/2}, e^{-i w dt/2} sinc(w dt/2)
//        (contact::step_sampling_factor);
//     b. the sampling filter: v_k from the samples xi~(t_k) by a stable rational R(z) with
//        R(e^{i w dt}) = S(w dt) over the band. S is not a rational function of z for midstep and
//        average (e^{-i w dt/2} = z^{-1/2}, and (1 - z^{-1})/log z), so no finite realisation has
//        it at every frequency: R is fitted (linalg::fit_rational) over the fitted frequencies in
//        the bilinear variable s' = (2/dt) i tan(w dt/2) and mapped to z exactly
//        (linalg::bilinear_discretisation), one copy per creepage input (R = 1 for contact).
//     Ad, Bd, Cd, Dd are the series connection (the filter's states appended); its response is
//     compared with f and g of the sweep on the fitted frequencies (discrete_error).
#pragma once

#include <complex>
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
  linalg::RationalFit fit;        ///< continuous model, its error over the fitted frequencies
  linalg::Realisation recursion;  ///< the recursion's realisation (input: the step creepage v_k)
  /// the creepage sampling of the recursion's input v_k (the case's rolling.creepage_sampling)
  contact::CreepageSampling input_sampling = contact::CreepageSampling::contact;
  double recursion_error = 0.0;  ///< recursion x the exact factor S against f, g (the fit's norm)
  linalg::StateSpace sampling_filter;  ///< R(z), 1 x 1 discrete (order 0, D = 1 for contact)
  /// max over the fitted frequencies of |R(e^{i w dt}) - S(w dt)|
  double sampling_filter_error = 0.0;
  /// max |R(e^{i w dt})| from the band's top to the Nyquist limit (|S| <= 1 there; R is fitted in
  /// the band only and may amplify above it, docs/statespace.md Sec. 3)
  double sampling_filter_peak_gain = 1.0;
  linalg::StateSpace
      discrete;          ///< the discrete model (input: the samples xi~(t_k), N~(t_k)), step dt
  double dt = 0.0;       ///< s
  int markov_count = 0;  ///< Markov parameters realised
  double discrete_error = 0.0;  ///< the discrete model's response against f, g (the fit's norm)
  double seconds_fit = 0.0, seconds_discrete = 0.0;
};

/// [-f | g] (3 x 4) per frequency.
std::vector<Eigen::MatrixXcd> contact_transfer(const std::vector<nss::CreepMatrix>& f,
                                               const std::vector<nss::LoadVector>& g);

/// The Markov parameters H_j = [h_j | gm_j] (3 x 4) of the model's fast sweep (built by a sweep
/// first); NumericalError when the sweep fell back to the Hessenberg form (no Markov parameters).
std::vector<Eigen::MatrixXd> contact_markov_parameters(const nss::LinearContactModel& model);

/// The sampling filter R (1 x 1, discrete, step dt): stable, R(e^{2 pi i f dt}) = factor at the
/// given frequencies to o.tolerance (vector fitting in the bilinear variable; the
/// identity, order 0, when every factor is 1).
linalg::StateSpace sampling_filter(const std::vector<double>& frequency,
                                   const std::vector<std::complex<double>>& factor, double dt,
                                   const StateSpaceOptions& o);

/// The discrete model `m` (3 x 4) with R applied to each of its three creepage inputs (the series
/// connection, R's states appended): transfer m(z) diag(R, R, R, 1).
linalg::StateSpace with_sampling_filter(const linalg::StateSpace& m, const linalg::StateSpace& R);

/// `freq` is the case's frequency axis; InputError naming `frequency_key` above the Nyquist limit.
StateSpaceResult run_statespace(ContactCase c, const std::vector<double>& freq,
                                const StateSpaceOptions& o, const std::string& frequency_key);

}  // namespace rollnoise::pipeline
