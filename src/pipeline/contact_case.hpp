// The contact part of a case as plain data (read by io/contact_case.hpp, nothing solved), and the
// first steps of every pipeline on it:
//
//   placed_contact      profiles: the contact point of the wheelset position, the grid chosen
//                       around it and Hertz's semi-axes from the curvatures there (geometry only,
//                       milliseconds); the Hertzian case is placed when read;
//   check_nyquist       the frequencies a command will evaluate against the grid's Nyquist limit
//                       V/(2 dx) (one rolling step dx/V per time step, docs/conventions.md Sec. 3),
//                       before anything is solved;
//   solve_patch         the normal problem of the case.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact/creepage_history.hpp"
#include "contact/grid.hpp"
#include "contact/halfspace_operator.hpp"
#include "contact/material.hpp"
#include "contact/normal_solver.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "geometry/wheel_rail.hpp"
#include "nss/linear_model.hpp"
#include "pipeline/limits.hpp"

namespace rollnoise::pipeline {

struct ContactCase {
  contact::Material material;
  double mu = 0.3;                  ///< friction.mu: mu_s with falling friction
  contact::FallingFriction falling;  ///< friction.law = "falling": A, B (default: constant mu)
  double speed = 0.0;
  std::string geometry = "hertz";  ///< "hertz" or "profiles"
  double normal_force = 0.0;
  double a = 0.0, b = 0.0;  ///< Hertz semi-axes (m); profiles: Hertz's estimate at the contact point
  contact::Grid grid;       ///< Hertzian: from the case; profiles: chosen by placed_contact
  double spin_offset = 0.0;
  contact::Creepage creepage;
  /// rolling.creepage_sampling: when the creepage of a rolling step is taken (transient, linear model)
  contact::CreepageSampling sampling = contact::CreepageSampling::average;
  contact::Backend backend = contact::Backend::Auto;
  nss::LinearSolver linear_solver = nss::LinearSolver::automatic;  ///< solver.linear_model
  int threads = 0;  ///< solver.threads: of the linear model (0: one per hardware thread, at most 4)
  /// profiles: the wheel-rail pair, the wheelset position the contact point is found at, and
  /// (after placed_contact) the contact point.
  std::shared_ptr<const geometry::WheelRailPair> profiles;
  geometry::WheelsetPosition wheelset;
  geometry::ContactGeometry contact_point;
  bool placed = false;  ///< the grid, a, b (and with profiles the contact point) are set
  geometry::GridOptions grid_options;
  contact::NormalSolverSettings normal;
  contact::TangentialSolverSettings tangential;
  Limits limits;  ///< [limits]: memory and step counts a run may use (pipeline/limits.hpp)

  contact::SteadyRollingInput steady_input() const { return {mu, speed, creepage, spin_offset, falling}; }
};

/// The case placed. Profiles: the contact point found at `c.wheelset`, the grid chosen around it and
/// a, b from Hertz's estimate. Hertzian cases are placed when read; a placed case is returned
/// unchanged. Either way InputError naming grid.nx when the contact problem on the grid exceeds
/// limits.memory (check_contact_size), before anything is solved.
[[nodiscard]] ContactCase placed_contact(ContactCase c);

/// Profiles: the case placed at the contact point given (the curve contact state found it) with
/// its normal force; the grid and a, b follow as in placed_contact.
[[nodiscard]] ContactCase placed_contact_at(ContactCase c, const geometry::ContactGeometry& point, double normal_force);

/// The grid's Nyquist limit V/(2 dx) (Hz): one rolling step dx/V per time step.
double nyquist_frequency(const ContactCase& c);

/// InputError naming `key` when a frequency lies above the Nyquist limit. The mean-contact stage
/// (pipeline/mean_contact.hpp) calls it once, on the patch's final grid (profiles may enlarge it).
void check_nyquist(const ContactCase& c, const std::vector<double>& freq, const std::string& key);

/// The normal problem of the case (placed). With profiles the grid is enlarged when the contact
/// area reaches its border: use the returned patch's grid.
contact::ContactPatch solve_patch(const ContactCase& c);

}  // namespace rollnoise::pipeline
