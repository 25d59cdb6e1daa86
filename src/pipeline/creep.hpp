// The creep pipeline (`rollnoise creep`): case -> mean state -> linear NSS model -> creep
// coefficients f(w) and load coefficients g(w) on a frequency axis (paper Eqs. 28-30,
// docs/nss_normal_load.md), by the block Krylov sweep or a direct complex LU per frequency.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nss/linear_model.hpp"
#include "pipeline/mean_contact.hpp"

namespace rollnoise::pipeline {

/// `creep --extrapolate` (run_creep_extrapolated): the grids and what the extrapolation did.
struct CreepExtrapolation {
  std::vector<double> factors;  ///< refinement of the case's grid: nx, ny scaled by these
  std::vector<int> nx, ny;      ///< the grids, coarse to fine (of the solved patches)
  std::vector<double> dx;       ///< m
  std::vector<std::vector<nss::CreepMatrix>> f;  ///< f on each grid (as CreepResult::f)
  std::vector<std::vector<nss::LoadVector>> g;   ///< g on each grid
  /// per frequency: the estimated error of the extrapolated f and g (units of f, g; Roache's grid
  /// convergence index, nss/extrapolation.hpp) and the order used for each entry
  std::vector<Eigen::Matrix3d> f_error, f_order;
  std::vector<Eigen::Vector3d> g_error, g_order;
  double assumed_order = 0.0;  ///< 2 (average, midstep) or 1 (contact): two grids and the fall-back
  long observed = 0, assumed = 0;  ///< entries (f and g, all frequencies) with an observed / assumed order
};

struct CreepResult {
  MeanContact state;  ///< the case as run, patch, steady state and linear model
  std::vector<nss::CreepMatrix> f;  ///< (N, N m, N m^2), rows Fx, Fy, Mz
  std::vector<nss::LoadVector> g;   ///< (-, -, m)
  nss::LoadVector g0;               ///< g(0), the quasi-static dF/dN, by the same method
  double seconds_state = 0.0, seconds_sweep = 0.0;
  /// --extrapolate: f, g and g0 above are the extrapolated ones, `state` the case's grid
  std::optional<CreepExtrapolation> extrapolation;
};

/// InputError naming `frequency_key` when a frequency lies above the Nyquist limit of the patch's
/// grid (checked once, before steady rolling and the model are solved).
CreepResult run_creep(ContactCase c, const std::vector<double>& freq, bool direct, const std::string& frequency_key);

/// Grid-converged f and g (`creep --extrapolate`, docs/accuracy.md): run_creep on the case's grid
/// with nx and ny scaled by each of `factors` (2 or 3, strictly increasing, in (0, 8]) over the same
/// potential contact area (profiles: the grid placed around the contact point, which the normal
/// problem may enlarge at the same dx),
/// then per frequency and entry Richardson extrapolation (nss::richardson) with the observed order
/// (three grids, within [0.5, 4]) or the sampling's order (2 average and midstep, 1 contact). The mean state
/// is the first grid's. InputError naming `factors_key` for bad factors or a grid too coarse for
/// the patch or too large (limits.memory), naming `frequency_key` for a frequency above any grid's
/// Nyquist limit; all before anything is solved.
CreepResult run_creep_extrapolated(ContactCase c, const std::vector<double>& freq, bool direct,
                                   const std::string& frequency_key, const std::vector<double>& factors,
                                   const std::string& factors_key);

}  // namespace rollnoise::pipeline
