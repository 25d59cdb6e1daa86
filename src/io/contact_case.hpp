// The contact part of a case: material, friction, speed, geometry, grid, mean creepage and solver
// settings, read and checked from a case file.
#pragma once

#include <memory>
#include <string>

#include "contact/grid.hpp"
#include "contact/halfspace_operator.hpp"
#include "contact/material.hpp"
#include "contact/normal_solver.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/case_reader.hpp"

namespace rollnoise::io {

struct ContactCase {
  contact::Material material;
  double mu = 0.3;
  double speed = 0.0;
  std::string geometry = "hertz";
  double normal_force = 0.0;
  double a = 0.0, b = 0.0;  ///< hertz semi-axes (m)
  contact::Grid grid;
  double spin_offset = 0.0;
  contact::Creepage creepage;
  contact::Backend backend = contact::Backend::Auto;
  /// profiles: the wheel-rail pair and its contact point (the grid is chosen around it)
  std::shared_ptr<const geometry::WheelRailPair> profiles;
  geometry::ContactGeometry contact_point;
  geometry::GridOptions grid_options;
  contact::NormalSolverSettings normal;
  contact::TangentialSolverSettings tangential;

  contact::SteadyRollingInput steady_input() const {
    return {mu, speed, creepage, spin_offset};
  }
};

/// Read and check the contact keys of a case. Throws InputError naming the key.
ContactCase read_contact_case(const CaseReader& r);

/// Solve the normal problem of the case (Hertzian or profile geometry). With profiles the grid may
/// be enlarged when the patch reaches its border: use the returned patch's grid.
contact::ContactPatch solve_case_patch(const ContactCase& c);

}  // namespace rollnoise::io
