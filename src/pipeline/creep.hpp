// The creep pipeline (`rollnoise creep`): case -> mean state -> linear NSS model -> creep
// coefficients f(w) and load coefficients g(w) on a frequency axis (paper Eqs. 28-30,
// docs/nss_normal_load.md), by the block Krylov sweep or a direct complex LU per frequency.
#pragma once

#include <vector>

#include "nss/linear_model.hpp"
#include "pipeline/mean_state.hpp"

namespace rollnoise::pipeline {

struct CreepResult {
  MeanState state;
  std::vector<nss::CreepMatrix> f;  ///< (N, N m, N m^2), rows Fx, Fy, Mz
  std::vector<nss::LoadVector> g;   ///< (-, -, m)
  nss::LoadVector g0;               ///< g(0), the quasi-static dF/dN, by the same method
  double seconds_state = 0.0, seconds_sweep = 0.0;
};

/// InputError naming `frequency_key` when a frequency lies above the grid's Nyquist limit
/// (checked once the contact is placed, before anything is solved).
CreepResult run_creep(ContactCase c, const std::vector<double>& freq, bool direct, const std::string& frequency_key);

}  // namespace rollnoise::pipeline
