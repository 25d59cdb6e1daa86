// Grid refinement study of a Hertzian case (`rollnoise bench`): for each grid (nx elements
// in x, ny = nx b/a rounded, at least 4, the case's grid.scale widened on coarse grids) it times
// and measures
//  - the steady forces at the case's mean creepage (paper Eq. 3);
//  - f11, f22, f23 at the study frequencies (fast sweep of the linear model, paper Eqs. 28-30; NaN
//    above the grid's Nyquist limit V/(2 dx));
//  - the transient force response: the unsteady solver (paper Eq. 2, contact::TransientRolling)
//    started from the steady state, with the creepages varied harmonically by 5 % of their means
//    at 1 kHz (paper Sec. 3.2: amplitudes (5e-5, 5e-5, 0.0027 rad/m) on the paper's case), and the
//    complex amplitudes of Fx and Fy at 1 kHz fitted by least squares (linalg::fit_harmonic);
//  - Kalker's C11 in the full-adhesion limit (creepage 1e-6).
// grid_study_errors() turns the measurements into errors relative to the finest grid (C11 also
// against Kalker's table); the transient response is also compared with the linear model's
// prediction -f(w) xi^ on the same grid (paper Eqs. 28-30: the linear model must agree with the
// unsteady solver to ~0.1 % at non-zero mean creepage, measured in the linear-model tests), a
// consistency check that should not depend on the grid. The observed orders of convergence of
// these errors come from linalg::observed_order. The errors of f_jk at 1 kHz and above and of the
// transient response are dominated by a half-step phase lead of the time discretisation (see
// half_step_phase_correction); the "phase-corrected" errors have it removed.
//
// Length of the transient runs. The grid moves one element per step (dt = dx/V), so the cost is
// (steps) x (cost per step) with steps ~ 1/dx and the cost per step growing faster than the number
// of contact elements: the finest grid dominates. The run is
//   settle_lengths = 5 contact lengths (2a/V each) for the start transient to decay, then
//   fit_periods = 3 periods of the excitation, fitted (an integer number of periods, so the
//   harmonics that the nonlinear response generates at 2w, 3w, ... do not leak into the fit);
// on the paper's case 8.2 ms: 59 steps on 10x7, 391 on 56x41 (0.04-0.1 s per step there while
// this was written and the step was being sped up: 16-40 s of the default bench's 31-52 s). The
// variation starts from zero (phase -90 deg, xi~ = amplitude sin(w t)) so the creepage does not
// jump at t = 0. The start transient decays as the material passes through the contact (it carries
// the memory of the tractions), by about 10x per contact length: the linear model's own recursion
// (the discrete-time form M0 Q_k = M1 Q_{k-1} + W_k, docs/conventions.md Sec. 3, started from rest
// like the unsteady run), fitted over the same window, differs from its exact harmonic response
// -f(w) xi^ by 1.4e-2, 1.6e-3, 1.8e-4, 3.6e-6 and 1.2e-8 after 1, 2, 3, 5 and 8 contact lengths
// (grids 10..34; GridMeasurement::window_error). After 5 it is far below the discretisation errors
// measured here (>= 1e-3) and below the 0.1 % agreement expected between linear model and
// unsteady solver; after 3 (25 % less run time) it would mask that agreement.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <complex>
#include <limits>
#include <vector>

#include "contact/creepage_history.hpp"
#include "contact/material.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/tangential_solver.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::pipeline {

/// The Hertzian case under study.
struct GridStudyCase {
  contact::Material material;
  double normal_force = 0.0;  ///< N
  double a = 0.0, b = 0.0;    ///< Hertz semi-axes (m)
  double scale = 1.0;         ///< grid.scale: the grid spans +-scale a by +-scale b
  contact::SteadyRollingInput steady;  ///< mu, speed, mean creepage, spin offset
  contact::Backend backend = contact::Backend::Auto;
  contact::TangentialSolverSettings tangential;
  /// of the transient runs and the linear model of the measurements above (rolling.creepage_sampling);
  /// the sampling study (measure_sampling_sweeps) uses all three
  contact::CreepageSampling sampling = contact::CreepageSampling::average;
};

struct GridStudySettings {
  std::vector<double> frequencies = {100.0, 1000.0, 5000.0};  ///< f_jk at these (Hz)
  double transient_frequency = 1000.0;  ///< Hz, as paper Sec. 3.1/3.2
  double relative_amplitude = 0.05;     ///< variation / mean creepage, paper Sec. 3.2
  double settle_lengths = 5.0;          ///< contact lengths 2a/V before the fit window
  int fit_periods = 3;                  ///< periods in the fit window
  // the sampling study (measure_sampling_sweeps)
  std::vector<double> accuracy_frequencies = {1000.0, 5000.0};  ///< f11, f22, f23 compared at these (Hz)
  int sweep_count = 1000;  ///< frequencies of the timed sweep, log-spaced over [100 Hz, 5 kHz] (Nyquist-capped)
};

/// The harmonic creepage variation of the transient runs: relative_amplitude of each mean
/// component (paper Sec. 3.2); at zero mean creepage 5e-5 in xi_x (paper Sec. 3.1's amplitude).
/// Phase -90 deg: xi~(t) = amplitude sin(w t), no jump at t = 0.
struct GridStudyExcitation {
  std::array<double, 3> amplitude{};
  std::array<double, 3> phase{};
  contact::CreepageHistory history;
  Eigen::Vector3cd xi_hat;  ///< complex amplitudes amplitude_j e^{i phase_j}
  double duration = 0.0;    ///< settle_lengths 2a/V + fit_periods / f (s)
};
GridStudyExcitation grid_study_excitation(const GridStudyCase& c, const GridStudySettings& s);

/// The samplings of the sampling study, in the order of GridMeasurement::sampling.
inline constexpr std::array<contact::CreepageSampling, 3> kStudySamplings = {
    contact::CreepageSampling::contact, contact::CreepageSampling::midstep, contact::CreepageSampling::average};

/// One creepage sampling's sweep on one grid (the sampling study, measure_sampling_sweeps below).
struct SamplingSweep {
  double seconds = 0.0;        ///< linear model set-up + sweep of sweep_count frequencies (s)
  std::vector<nss::CreepMatrix> f;  ///< at the accuracy frequencies (NaN above Nyquist)
};

struct GridMeasurement {
  int nx = 0, ny = 0, contact = 0;  ///< grid and elements in contact
  double dx = 0.0;                  ///< m
  /// run times (s): normal problem; normal + steady problem; linear model set-up + sweep; C11;
  /// transient run
  double t_normal = 0.0, t_steady = 0.0, t_creep = 0.0, t_kalker = 0.0, t_transient = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< steady (Fx, Fy, Mz)
  std::vector<nss::CreepMatrix> f;  ///< at the study frequencies (NaN above Nyquist)
  double c11 = 0.0;            ///< -Fx / (G a b xi_x) at xi_x = 1e-6
  long steps = 0;              ///< of the transient run (0: 1 kHz above Nyquist)
  /// complex amplitudes X of (Fx, Fy) at the transient frequency, F(t) ~ mean + Re(X e^{i w t}) (N)
  Eigen::Vector2cd transient = Eigen::Vector2cd::Constant(std::numeric_limits<double>::quiet_NaN());
  /// -f(w) xi^, the linear model's prediction of `transient` on the same grid
  Eigen::Vector2cd linear = Eigen::Vector2cd::Constant(std::numeric_limits<double>::quiet_NaN());
  /// the linear recursion from rest fitted over the window, relative to -f(w) xi^
  double window_error = std::numeric_limits<double>::quiet_NaN();
  /// the sampling study, indexed as kStudySamplings: [0] contact, [1] midstep, [2] average
  /// (measure_sampling_sweeps, below)
  std::array<SamplingSweep, 3> sampling;
};

/// InputError naming --nx unless `grids` holds at least two grids, strictly increasing (the last is
/// the reference the others are compared with), each fine enough for the patch (at least 4
/// elements across 2a and 2b, as for a case's grid.nx / grid.ny).
void check_study_grids(const GridStudyCase& c, const std::vector<int>& grids);

/// The grid with nx elements in x: ny = nx b/a rounded (at least 4); coarse grids need a wider
/// margin around the ellipse (at least ~1.25 elements each side).
contact::Grid study_grid(const GridStudyCase& c, int nx, int* ny);

/// Everything above on the grid with `nx` elements in x.
GridMeasurement measure_grid(const GridStudyCase& c, const GridStudySettings& s,
                             const GridStudyExcitation& e, int nx);

/// The half-step phase lead. The displacement difference (A p_k - A0 p_{k-1})/dt of paper Eq. 2 is
/// a one-step difference, centred at t_k - dt/2, while the creepage is taken at t_k (CONTACT's
/// convention, docs/conventions.md Sec. 3): the discrete response leads the grid-converged one by
/// dt/2, a phase error of w dt/2 = pi f dx/V, first order in dx (10.9 deg at 1 kHz on 20x15,
/// 2.6 deg on 80x59; the phase of f11 at 1 kHz minus that shift is -85.3 +- 0.1 deg on all grids
/// from 28x21 to 80x59 (-85.05 on 20x15), while the raw phase runs from -74.2 (20x15) to -82.6 deg
/// (80x59)). It dominates the errors of f_jk at 1 kHz and above and of the transient response.
/// Multiplying by e^{-i w dt/2} = e^{-i pi f dx/V} removes it.
inline std::complex<double> half_step_phase_correction(double frequency, double dx, double speed) {
  return std::polar(1.0, -M_PI * frequency * dx / speed);
}

// ---- Creepage sampling against the continuum (rolling.creepage_sampling; docs/accuracy.md) ----
//
// Beside the measurements above (made with the case's sampling), every grid builds the linear
// model with each sampling of kStudySamplings (contact/creepage_history.hpp), and times a sweep of
// sweep_count frequencies (model set-up, Cholesky factor and Krylov model included: what `creep`
// costs on that grid), and keeps f at the accuracy frequencies. sampling_accuracy() compares them
// with the grid-converged f: Richardson extrapolation (nss/extrapolation.hpp) of one sampling's
// values on the three finest grids that resolve the frequency, with their observed order. Every
// sampling is extrapolated (contact with the fall-back order 1, midstep and average 2); the
// converged f is that of the second-order sampling whose extrapolation has the smaller estimated
// error (Roache's index, largest over f11, f22, f23, relative), the others' distance from it is
// reported as a check.

/// The sweeps of `r`'s grid for every sampling into r.sampling (kStudySamplings order).
void measure_sampling_sweeps(const GridStudyCase& c, const GridStudySettings& s, const contact::ContactPatch& patch,
                             const contact::TangentialSolution& steady, GridMeasurement& r);

struct SamplingAccuracy {
  /// per accuracy frequency: the converged f (Richardson) and its estimated error (Roache's index,
  /// absolute, per entry), the order used for f11, f22, f23, and the sampling it was extrapolated
  /// from (an index into kStudySamplings)
  std::vector<nss::CreepMatrix> converged;
  std::vector<Eigen::Matrix3d> converged_error;
  std::vector<Eigen::Vector3d> order;
  std::vector<int> reference;
  /// spread[sampling][frequency]: |R_sampling - R_reference| / |R_reference| of f11, f22, f23, the
  /// samplings' extrapolations against the converged f (0 for the reference itself)
  std::array<std::vector<Eigen::Vector3d>, 3> spread;
  /// error[sampling][frequency][entry f11, f22, f23][grid]: |f - f_converged| / |f_converged|
  std::array<std::vector<std::array<std::vector<double>, 3>>, 3> error;
};
/// With only two grids resolving an accuracy frequency, the assumed order 2; with fewer, NaN.
SamplingAccuracy sampling_accuracy(const std::vector<GridMeasurement>& grids, const GridStudySettings& s);

/// Errors of each grid (coarse to fine, the last the reference), all relative.
struct GridStudyErrors {
  std::vector<double> dx;            ///< m
  std::vector<double> force, mz;     ///< steady |(Fx, Fy) - ref| / |ref|, |Mz - ref| / |ref|
  /// per study frequency, per grid: largest error of f11, f22, f23; of f11, f22 phase-corrected;
  /// of f23 (NaN above Nyquist)
  std::vector<std::vector<double>> f, f_direct_corrected, f23;
  std::vector<double> transient, transient_corrected;  ///< |X - X_ref| / |X_ref| (Fx, Fy)
  std::vector<double> c11;            ///< |C11 / C11_ref - 1|
  std::vector<double> c11_table;      ///< |C11 / Kalker's table - 1|
  std::vector<double> transient_vs_linear;  ///< |X - (-f(w) xi^)| / |-f(w) xi^|, same grid
  double window_error = 0.0;          ///< largest finite GridMeasurement::window_error
};
/// `sampling`: the case's (GridStudyCase::sampling); the phase-corrected errors remove the half-step
/// lead of CONTACT's sampling and equal the plain ones with midstep and average.
GridStudyErrors grid_study_errors(const std::vector<GridMeasurement>& grids,
                                  const GridStudySettings& s, double speed, double c11_table,
                                  contact::CreepageSampling sampling);

}  // namespace rollnoise::pipeline
