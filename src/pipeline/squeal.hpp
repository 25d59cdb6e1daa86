// `rollnoise squeal` (docs/squeal.md): the linear stability of the closed wheel-rail-contact loop
// at the curve's mean contact state, assembled exactly as the noise loop assembles it
// (noise_pipeline.hpp stages 1 and 3: curve state, contact patch, normal stiffness, steady rolling,
// the linear NSS model), then continued to complex frequency (noise/stability.hpp):
//   wheel: rigid wheelset + all modes of the modes file (mode shapes moved and rotated into the
//          contact frame), exact in s;
//   rail:  the case's track model at complex frequency;
//   contact: Hertz spring k_N, alpha_c,t = (V/s) f(s)^{-1}, and alpha_c,tn = -alpha_c,tt g(s) when
//          noise.normal_coupling = "on", f(s) and g(s) from the model
//          (nss::LinearContactModel::creep_coefficients_laplace: the Markov series or the Hessenberg
//          form at complex z, with the case's creepage sampling); with falling friction the
//          contact's own stability (spectral radius of M0^{-1} M1 < 1) is checked first.
// Route 2 (Newton with homotopy continuation on (S3)) for every wheel mode with
// noise.band_min <= f_n <= noise.band_max. The contact law enters only through f and g, so any
// friction law whose linearisation the NSS model carries is handled the same way.
#pragma once

#include <vector>

#include "linalg/vector_fitting.hpp"
#include "noise/stability.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

struct SquealResult {
  /// as run: curve state, placed case, patch, k_N, steady state, model and the contact's transfer;
  /// the leading outer wheel's (a Hertzian case with per-wheel states: its own Hertz state with the
  /// load transfer, pipeline/squeal_hertz_wheels.hpp)
  MeanContact mean;
  /// The case as the curve placed it (resolve_curve: the static wheel load Q), from which the
  /// per-wheel Hertz states of squeal_wheelsets start.
  ContactCase curve_case;
  /// `mean` is the per-wheel run's leading outer wheel state (has_hertz_wheel_states): reused there.
  bool mean_is_leading_outer_wheel = false;
  bool coupled = false;                 ///< g in the loop (noise.normal_coupling and slip elements)
  double min_sigma = 0.0;               ///< the contact series converge for Re s above this (1/s)
  std::vector<noise::ModeRoot> roots;   ///< route 2, one per wheel mode in the band
  int route = 2;                        ///< whose roots `roots` are (1: route 1's, `--route 1`)
  double seconds_contact = 0.0;         ///< curve state, patch, steady rolling, linear model, Markov parameters
  double seconds_roots = 0.0;           ///< route 2
  long evaluations = 0;                 ///< evaluations of the loop matrix at complex s
  /// of M0^{-1} M1, when checked (the model without Markov parameters: falling friction); else -1
  double contact_spectral_radius = -1.0;
  int unstable_count() const;
};

/// The whole command (with the NSS model; with noise.contact_model = "kalker" the contact is
/// Kalker's constant f, g = 0). The contact is the leading outer wheel's: the curve's state, or in a
/// Hertzian case whose per-wheel states squeal_wheelsets computes (noise.squeal_wheelsets = "on")
/// that wheel's Hertz state with the load transfer, the same as /squeal/wheels/leading_outer's. InputError (noise.band_max) when no mode lies in the band or the band
/// exceeds the grid's Nyquist limit.
/// route2 = false: everything but route 2's roots (`--route 1`).
SquealResult run_squeal(ContactCase c, const NoiseCase& nc, const noise::StabilityOptions& options = {},
                        bool route2 = true);

/// The linearised contact's own stability: InputError (friction.decay) naming the growth rate when
/// the spectral radius of M0^{-1} M1 (`radius`, time step `dt` s) is >= 1.
void check_contact_stability(double radius, double dt);

/// The mean-contact options of squeal: the model with noise.contact_model = "nss", the transfer,
/// the band's wheel modes checked against the Nyquist limit naming noise.band_max.
MeanContactOptions squeal_contact_options(const NoiseCase& nc, const std::vector<double>& in_band);

/// The leading outer wheel's contact point of a mean contact (wheelset 0, side +1, at the rail's
/// position).
noise::ContactPoint squeal_point(const NoiseCase& nc, const MeanContact& mean);

/// The loop at complex s of a mean contact with its transfer: the loop of one contact
/// (noise::laplace_loop), as the wheelsets' loops of squeal_wheels.hpp with one contact.
noise::LaplaceLoop squeal_loop(const NoiseCase& nc, const MeanContact& mean);

/// Route 1 on a case (docs/squeal.md Sec. 4): the rail's receptance alpha_r (4 x 4, contact frame)
/// and the contact's [-f | g] (3 x 4, `rollnoise statespace`'s convention, f with the model's
/// creepage sampling) fitted by linalg::fit_rational over the fit band, coupled with the wheel's
/// modal state space by noise::coupled_eigenvalues.
///  * rail: `rail_samples` points linearly spaced over [rail_fit_min, rail_fit_max], by default
///    [0.5, 2] x the band's lowest and highest wheel mode: not from 0 Hz, since a hysteretic rail
///    (k(1 + i eta)) has a complex, non-causal static limit that no real rational model reproduces;
///    the fit need only hold where the coupled roots lie (near the wheel modes);
///  * contact: `contact_samples` points over [0, rail_fit_max] (the static gain fitted; capped at the
///    grid's Nyquist frequency), the f the sweep of `noise` uses (the case's creepage sampling).
struct Route1Options {
  double fit_min = 0.0, fit_max = 0.0;  ///< Hz; 0: the defaults above
  int rail_samples = 250, contact_samples = 200;
  /// Rail samples added within +-4 % of each wheel mode of the band (the fit's least squares weigh
  /// the roots' neighbourhoods most: on curve_300m, discrete track, the error at the modes 1.9e-2 ->
  /// 9.9e-3 with the same number of poles, and radial n=7's damping ratio from 17 % off to 1.3 %).
  int samples_per_mode = 9;
  double tolerance = 1e-5;  ///< fit_rational's target (both fits)
  /// Most poles per fit. Not more: fit_rational keeps the order with the smallest error ON the
  /// axis, and on curve_300m (continuous track) its fits of the rail with 78 poles reached 2e-4
  /// there but with large cancelling residues, wrong by O(1) at the roots just off the axis (route
  /// 1 then lost the coupling: 2-4 % in frequency); with 36 poles (error ~1e-2 at the band's low
  /// end, 1e-4 near the modes) the routes agree to 1e-4.
  int max_poles = 40;
  int pole_step = 6;  ///< poles added per order step (fit_rational)
};

struct Route1Result {
  std::vector<dynamics::cdouble> eigenvalues;  ///< all finite eigenvalues of the coupled model (1/s)
  linalg::RationalFit rail, contact;           ///< the fits (their error: the fit's norm)
  double fit_min = 0.0, fit_max = 0.0;         ///< the rail's fit band (Hz)
  double rail_error_at_modes = 0.0;            ///< the rail fit's error (fit_rational's norm) at the band's f_n
  double seconds_rail = 0.0;  ///< the rail's samples (part of seconds_fit)
  double seconds_fit = 0.0, seconds_eigen = 0.0;
};

/// Route 1 at the solved stage of `r` (run_squeal's result; its Markov parameters built).
Route1Result squeal_route1(const SquealResult& r, const NoiseCase& nc, const Route1Options& o = {});

/// How far route 1's rational models are from route 2's exact parts at given complex s (the roots):
/// per s, |S(H_fit(s) - H(s))|_F / |S H(s)|_F in each fit's scaling S, for the rail (alpha_r: the
/// fit's causal continuation against the hysteretic loss factors continued as constants) and the
/// contact ([-f | g]: the fit against the Markov series).
struct Route1Deviation {
  std::vector<double> rail, contact;
};
Route1Deviation route1_deviation(const Route1Result& r1, const SquealResult& r, const NoiseCase& nc,
                                 const std::vector<dynamics::cdouble>& s);

/// The band's wheel modes as ModeRoots with s = s0 (their uncoupled roots): the reference of
/// match_route1 without route 2.
std::vector<noise::ModeRoot> uncoupled_roots(const NoiseCase& nc);

/// Route 1's eigenvalues (upper half-plane), one per reference root (route 2's roots, or
/// uncoupled_roots), assigned greedily, closest pairs first, so that no eigenvalue is taken twice;
/// as ModeRoots (s, frequency, damping ratio, unstable, the mode's label and natural frequency;
/// residual and singular ratio NaN; converged = false when none was left). With uncoupled_roots as
/// the reference, the labels of a sin/cos pair (one s0) follow the distance to s0 only.
std::vector<noise::ModeRoot> match_route1(const Route1Result& r1, const std::vector<noise::ModeRoot>& reference);

/// The agreement of two root lists of equal length (route 1 against route 2), worst over the modes.
struct RouteAgreement {
  double frequency = 0.0;               ///< max |f1 - f2| / f2
  double damping_relative = 0.0;        ///< max |zeta1 - zeta2| / |zeta2|
  double damping_absolute = 0.0;        ///< max |zeta1 - zeta2|
  double damping_beyond = 0.0;          ///< max over modes of min(rel / 0.05, abs / 1e-5): <= 1 passes
  std::size_t worst_frequency_mode = 0, worst_damping_mode = 0;
  bool distinct = true;                 ///< every route-2 root got a route-1 eigenvalue (match_route1)
  int compared = 0;                     ///< modes compared: route 2's converged roots
  /// per mode: 1 within the target below, 0 beyond it, -1 not compared (route 2 not converged)
  std::vector<int> mode_within;
  /// docs/squeal.md Sec. 4.2's target: f within 0.1 %, zeta within 5 % or 1e-5 (damping_beyond <=
  /// 1)
  bool within() const { return frequency <= 1e-3 && damping_beyond <= 1.0; }
};
/// Route 1 against route 2, mode by mode, over route 2's converged roots (a mode whose continuation
/// failed or reached another mode's root has no route-2 root of its own to compare).
RouteAgreement route_agreement(const std::vector<noise::ModeRoot>& route1, const std::vector<noise::ModeRoot>& route2);

/// Empty when the routes agree within their target; else one line for the summary and the output:
/// the modes beyond it, the worst (route 1's and route 2's f and zeta) and its likely cause
/// (docs/squeal.md Sec. 4.2): route 1's rail or contact fit, whichever deviates more from route 2's
/// part at that root (route1_deviation), and for a heavily damped root (|zeta| >= 1e-2) the rail's
/// continuation off the axis, which on a discrete track is not converged beyond zeta ~ eta_rail/2.
std::string route_warning(const RouteAgreement& agreement,
                          const std::vector<noise::ModeRoot>& route2,
                          const std::vector<noise::ModeRoot>& route1,
                          const Route1Deviation& deviation);

}  // namespace rollnoise::pipeline
