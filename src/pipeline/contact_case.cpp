#include "pipeline/contact_case.hpp"

#include <algorithm>
#include <cstdio>

#include "contact/hertz.hpp"
#include "core/errors.hpp"

namespace rollnoise::pipeline {

ContactCase placed_contact_at(ContactCase c, const geometry::ContactGeometry& point, double normal_force) {
  c.contact_point = point;
  c.normal_force = normal_force;
  c.grid = geometry::choose_grid(*c.profiles, c.contact_point, c.normal_force, c.material, c.grid_options);
  const auto hz = geometry::hertz_estimate(c.contact_point, c.normal_force, c.material, c.grid_options);
  c.a = hz.a, c.b = hz.b;  // Hertz's estimate from the curvatures at the contact point
  c.placed = true;
  check_contact_size(c);
  return c;
}

ContactCase placed_contact(ContactCase c) {
  if (c.placed || !c.profiles) {
    check_contact_size(c);
    return c;
  }
  const geometry::ContactGeometry point = geometry::find_contact(*c.profiles, c.wheelset);
  const double normal_force = c.normal_force;
  return placed_contact_at(std::move(c), point, normal_force);
}

double nyquist_frequency(const ContactCase& c) { return 0.5 * c.speed / c.grid.dx; }

void check_nyquist(const ContactCase& c, const std::vector<double>& freq, const std::string& key) {
  const double fn = nyquist_frequency(c);
  double worst = 0.0;
  for (double f : freq) worst = std::max(worst, f);
  // the same relative margin as the linear model's own check (nss/linear_model.cpp)
  if (!(worst > fn * (1 + 1e-12))) return;
  char msg[200];
  std::snprintf(msg, sizeof msg, "%.6g Hz is above the grid's Nyquist limit V/(2 dx) = %.6g Hz: refine grid.nx or lower it",
                worst, fn);
  throw InputError(key, msg);
}

contact::ContactPatch solve_patch(const ContactCase& c) {
  if (c.profiles)
    return geometry::solve_wheel_rail_patch(*c.profiles, c.contact_point, c.normal_force, c.material,
                                            c.grid_options);
  const contact::HertzContact hz = contact::hertz_from_semi_axes(c.a, c.b, c.normal_force, c.material);
  return contact::solve_patch(c.grid, c.material, contact::quadratic_distance(c.grid, hz.A, hz.B),
                              c.normal_force, c.backend, c.normal);
}

}  // namespace rollnoise::pipeline
