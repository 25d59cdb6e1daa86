// A contact patch: the grid, the elastic constants, their influence coefficients and the solved
// normal problem. Everything downstream (steady rolling, transient rolling, the linear NSS model)
// starts from a ContactPatch.
#pragma once

#include <string>

#include "contact/hertz.hpp"
#include "contact/influence.hpp"
#include "contact/normal_solver.hpp"

namespace rollnoise::contact {

struct ContactPatch {
  Grid grid;
  Material material;
  InfluenceTable influence;
  GridField undeformed_distance;  ///< h without the approach (m)
  NormalSolution normal;

  ContactPatch(const Grid& g, const Material& m) : grid(g), material(m), influence(g, m) {}
};

/// Undeformed distance h = A x^2 + B y^2 of a Hertzian contact at the element centres.
GridField quadratic_distance(const Grid& g, double A, double B);

/// Whether the pressure pn reaches the border of the grid (an element of the outer ring carries
/// pressure), where the contact area would be cut off.
bool reaches_border(const Grid& g, const GridField& pn);

/// InputError (key "grid") if the pressure pn reaches the border of the grid, where the contact
/// area would be cut off; `context` (e.g. " at N = 1e5 N") completes the message.
void check_inside_potential_area(const Grid& g, const GridField& pn, const std::string& context);

/// Solve the normal problem for the undeformed distance h and load N on the grid, without the
/// border check (for callers that enlarge the grid when reaches_border()).
ContactPatch solve_patch_unchecked(const Grid& g, const Material& m, GridField h, double normal_force,
                                   Backend backend = Backend::Auto, const NormalSolverSettings& s = {});

/// Solve the normal problem for the undeformed distance h and load N on the grid, then
/// check_inside_potential_area.
ContactPatch solve_patch(const Grid& g, const Material& m, GridField h, double normal_force,
                         Backend backend = Backend::Auto, const NormalSolverSettings& s = {});

}  // namespace rollnoise::contact
