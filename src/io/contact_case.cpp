#include "io/contact_case.hpp"

#include <cmath>
#include <sstream>

#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "geometry/profile.hpp"
#include "io/profile_file.hpp"

namespace rollnoise::io {

ContactCase read_contact_case(const CaseReader& r) {
  ContactCase c;
  c.material.E = r.real("material.E");
  c.material.nu = r.real("material.nu");
  if (!(c.material.nu >= 0.0 && c.material.nu < 0.5))
    r.fail("material.nu", "must lie in [0, 0.5)");
  c.mu = r.real("friction.mu");
  c.speed = r.real("rolling.speed");
  c.geometry = r.string("contact.geometry");
  c.normal_force = r.real("contact.normal_force");
  const auto cr = r.real3("creepage.mean");
  c.creepage = {cr[0], cr[1], cr[2]};
  c.spin_offset = r.real("grid.spin_offset");

  const long nx = r.integer("grid.nx"), ny = r.integer("grid.ny");
  // nx, ny >= 2 (schema); compared by division: nx * ny overflows a long for absurd inputs
  if (nx > 40000 / ny) r.fail("grid.nx", "nx*ny above 40000 elements is not supported");
  if (c.geometry == "hertz") {
    c.a = r.real("contact.a");
    c.b = r.real("contact.b");
    if (r.has("grid.x_min")) {
      c.grid.nx = nx, c.grid.ny = ny;
      const double x0 = r.real("grid.x_min"), x1 = r.real("grid.x_max");
      const double y0 = r.real("grid.y_min"), y1 = r.real("grid.y_max");
      if (!(x1 > x0)) r.fail("grid.x_max", "must be larger than grid.x_min");
      if (!(y1 > y0)) r.fail("grid.y_max", "must be larger than grid.y_min");
      c.grid.x_min = x0, c.grid.y_min = y0;
      c.grid.dx = (x1 - x0) / nx, c.grid.dy = (y1 - y0) / ny;
      if (!(x0 < -c.a && x1 > c.a)) r.fail("grid.x_min", "the grid must cover -a..a");
      if (!(y0 < -c.b && y1 > c.b)) r.fail("grid.y_min", "the grid must cover -b..b");
    } else {
      const double scale = r.real("grid.scale");
      if (!(scale > 1.0))
        r.fail("grid.scale", "must exceed 1 so that the potential contact area covers the patch");
      c.grid = contact::Grid::around_ellipse(nx, ny, c.a, c.b, scale);
    }
    // A grid too coarse for the patch: fewer than 4 elements across an axis of the ellipse.
    if (2.0 * c.a / c.grid.dx < 4.0)
      r.fail("grid.nx", "too coarse for the patch: fewer than 4 elements across 2a");
    if (2.0 * c.b / c.grid.dy < 4.0)
      r.fail("grid.ny", "too coarse for the patch: fewer than 4 elements across 2b");
  } else {  // profiles: the right wheel of a wheelset on track (src/geometry, docs/geometry.md)
    const auto wheel = read_profile(resolve_model_file(r, "contact.wheel_profile"), geometry::ProfileKind::Wheel);
    const auto rail = read_profile(resolve_model_file(r, "contact.rail_profile"), geometry::ProfileKind::Rail);
    c.profiles = std::make_shared<const geometry::WheelRailPair>(wheel, rail);
    c.contact_point = geometry::find_contact(
        *c.profiles, {r.real("contact.lateral_displacement"), r.real("contact.yaw")});
    c.grid_options.nx = static_cast<int>(nx);
    c.grid_options.scale = std::max(1.25, r.real("grid.scale"));
    c.grid = geometry::choose_grid(*c.profiles, c.contact_point, c.normal_force, c.material, c.grid_options);
    const auto hz = geometry::hertz_estimate(c.contact_point, c.normal_force, c.material, c.grid_options);
    c.a = hz.a, c.b = hz.b;  // Hertz's estimate from the curvatures at the contact point
  }

  const std::string infl = r.string("solver.influence");
  c.backend = infl == "fft"     ? contact::Backend::Fft
              : infl == "dense" ? contact::Backend::Dense
                                : contact::Backend::Auto;
  c.normal.tolerance = r.real("solver.normal_tolerance");
  c.tangential.tolerance = r.real("solver.tangential_tolerance");
  c.tangential.max_iterations = static_cast<int>(r.integer("solver.max_iterations"));
  return c;
}

contact::ContactPatch solve_case_patch(const ContactCase& c) {
  if (c.profiles)
    return geometry::solve_wheel_rail_patch(*c.profiles, c.contact_point, c.normal_force, c.material,
                                            c.grid_options);
  const contact::HertzContact hz = contact::hertz_from_semi_axes(c.a, c.b, c.normal_force, c.material);
  return contact::solve_patch(c.grid, c.material, contact::quadratic_distance(c.grid, hz.A, hz.B),
                              c.normal_force, c.backend, c.normal);
}

}  // namespace rollnoise::io
