// A sweep of steady rolling solutions over case points (`rollnoise steady --sweep`): the normal
// problem of the base case is reused at every point that does not change it (same grid,
// material, load and semi-axes), and each point starts from the previous solution when both
// share the patch.
#pragma once

#include <functional>
#include <vector>

#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::pipeline {

/// n points from lo to hi, equally spaced (lo alone when n = 1): the values of a lo:hi:n sweep.
std::vector<double> linear_points(double lo, double hi, long n);

/// Called after each point with its index, case and solution (for a progress table).
using SweepObserver = std::function<void(std::size_t, const ContactCase&, const contact::TangentialSolution&)>;

/// Steady rolling at every point (placed cases); `base`/`patch`: the base case and its patch.
std::vector<contact::TangentialSolution> steady_sweep(const ContactCase& base, const contact::ContactPatch& patch,
                                                      const std::vector<ContactCase>& points,
                                                      const SweepObserver& observe = {});

}  // namespace rollnoise::pipeline
