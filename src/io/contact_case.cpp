#include "io/contact_case.hpp"

#include <algorithm>

#include "contact/hertz.hpp"
#include "geometry/profile.hpp"
#include "io/profile_file.hpp"

namespace rollnoise::io {
namespace {

// The semi-axes of a Hertzian case: given (contact.a, contact.b), or from the radii of wheel and
// rail at the case's load. The undeformed distance of two bodies touching at principal curvatures
// aligned with x and y is h = A x^2 + B y^2 with A = 1/(2 R_w) (the rail is straight along x) and
// B = (1/R_r + 1/R_p)/2 (Johnson 1985, Contact Mechanics, Sec. 4.1, the geometry of the gap; a concave wheel
// profile has R_p < 0); contact::hertz_from_curvatures gives a, b for the load (Sec. 4.2).
void read_hertz_semi_axes(const CaseReader& r, ContactCase& c) {
  const bool radii = r.has("contact.wheel_radius") || r.has("contact.rail_radius");
  if (!radii) {
    if (r.has("contact.wheel_profile_radius"))
      r.fail("contact.wheel_profile_radius", "is used with contact.wheel_radius and contact.rail_radius");
    c.a = r.real("contact.a");
    c.b = r.real("contact.b");
    return;
  }
  for (const char* key : {"contact.a", "contact.b"})
    if (r.has(key))
      r.fail(key, "give either the semi-axes contact.a, contact.b or the radii contact.wheel_radius, "
                  "contact.rail_radius (from which a and b follow with the load), not both");
  const double wheel = r.real("contact.wheel_radius"), rail = r.real("contact.rail_radius");
  double profile_curvature = 0.0;  // a conical tread: straight across
  if (r.has("contact.wheel_profile_radius")) {
    const double profile = r.real("contact.wheel_profile_radius");
    if (profile == 0.0) r.fail("contact.wheel_profile_radius", "must not be 0 (leave it out for a conical tread)");
    profile_curvature = 1.0 / profile;
  }
  const double A = 0.5 / wheel, B = 0.5 * (1.0 / rail + profile_curvature);
  if (!(B > 0.0))
    r.fail("contact.wheel_profile_radius",
           "a concave wheel profile must be wider than the rail head: |R_p| > contact.rail_radius (else the "
           "contact is conformal, not Hertzian)");
  if (!(c.normal_force > 0.0) || !(c.material.E > 0.0) || !(c.material.nu >= 0.0 && c.material.nu < 0.5))
    r.fail("contact.wheel_radius", "a and b from the radii need a valid contact.normal_force, material.E and material.nu");
  const contact::HertzContact hz = contact::hertz_from_curvatures(A, B, c.normal_force, c.material);
  c.a = hz.a, c.b = hz.b;
}

// The grid of a Hertzian case: given bounds or a scale around the ellipse, and at least 4
// elements across each axis of the patch.
void read_hertz_grid(const CaseReader& r, ContactCase& c, long nx, long ny) {
  read_hertz_semi_axes(r, c);
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
    if (!(scale > 1.0)) r.fail("grid.scale", "must exceed 1 so that the potential contact area covers the patch");
    c.grid = contact::Grid::around_ellipse(nx, ny, c.a, c.b, scale);
  }
  // A grid too coarse for the patch: fewer than 4 elements across an axis of the ellipse.
  if (2.0 * c.a / c.grid.dx < 4.0) r.fail("grid.nx", "too coarse for the patch: fewer than 4 elements across 2a");
  if (2.0 * c.b / c.grid.dy < 4.0) r.fail("grid.ny", "too coarse for the patch: fewer than 4 elements across 2b");
  c.placed = true;
}

// The right wheel of a wheelset on track (docs/geometry.md): profiles, wheelset position, grid
// options. The contact point and the grid are found by pipeline::placed_contact.
void read_profiles(const CaseReader& r, ContactCase& c, long nx, InputProblems& problems) {
  std::optional<geometry::Profile> wheel, rail;
  problems.check([&] {
    wheel = read_profile(resolve_model_file(r, "contact.wheel_profile"), geometry::ProfileKind::Wheel);
  });
  problems.check([&] {
    rail = read_profile(resolve_model_file(r, "contact.rail_profile"), geometry::ProfileKind::Rail);
  });
  if (wheel && rail) c.profiles = std::make_shared<const geometry::WheelRailPair>(*wheel, *rail);
  problems.check([&] { c.wheelset = {r.real("contact.lateral_displacement"), r.real("contact.yaw")}; });
  c.grid_options.nx = static_cast<int>(nx);
  // the grid is placed around the contact the profiles give (pipeline::placed_contact): a fixed
  // extent is not honoured there, so it is refused rather than silently ignored
  for (const char* key : {"grid.x_min", "grid.x_max", "grid.y_min", "grid.y_max"})
    problems.check([&] {
      if (r.has(key))
        r.fail(key, "is used only with contact.geometry = \"hertz\"; with \"profiles\" the grid is placed around "
                    "the contact the profiles give (set its size with grid.scale, grid.nx)");
    });
  for (const char* key : {"contact.wheel_radius", "contact.wheel_profile_radius", "contact.rail_radius"})
    problems.check([&] {
      if (r.has(key))
        r.fail(key, "is used only with contact.geometry = \"hertz\"; with \"profiles\" the profiles give the "
                    "curvatures at the contact point");
    });
  problems.check([&] { c.grid_options.scale = std::max(1.25, r.real("grid.scale")); });
}

// friction.law: "constant" (A, B must not be given) or "falling" (both required, checked).
contact::FallingFriction read_falling_friction(const CaseReader& r) {
  contact::FallingFriction f;
  if (r.string("friction.law") == "constant") {
    for (const char* key : {"friction.kinetic_ratio", "friction.decay"})
      if (r.has(key)) r.fail(key, "is used only with friction.law = \"falling\"");
    return f;
  }
  f.kinetic_ratio = r.real("friction.kinetic_ratio");
  f.decay = r.real("friction.decay");
  try {
    contact::check_falling_friction(f);
  } catch (const InputError& e) {
    r.fail(e.key(), e.what());
  }
  return f;
}

}  // namespace

pipeline::Limits read_limits(const CaseReader& r) {
  pipeline::Limits l;
  if (r.has("limits.memory")) l.memory = r.real("limits.memory");
  l.steps = r.integer("limits.steps");
  return l;
}

ContactCase read_contact_case(const CaseReader& r, InputProblems& problems) {
  ContactCase c;
  problems.check([&] { c.limits = read_limits(r); });
  problems.check([&] {
    // from soft polymers (~1 MPa) to the stiffest solids (diamond ~1.2e12 Pa): outside, a typo
    // (units, exponent) that the solvers would only report as a numerical failure
    c.material.E = r.real("material.E");
    if (!(c.material.E >= 1e6 && c.material.E <= 1e13)) r.fail("material.E", "must lie in [1e6, 1e13] Pa");
  });
  problems.check([&] {
    c.material.nu = r.real("material.nu");
    if (!(c.material.nu >= 0.0 && c.material.nu < 0.5)) r.fail("material.nu", "must lie in [0, 0.5)");
  });
  problems.check([&] { c.mu = r.real("friction.mu"); });
  problems.check([&] { c.falling = read_falling_friction(r); });
  problems.check([&] { c.speed = r.real("rolling.speed"); });
  problems.check([&] {
    const std::string s = r.string("rolling.creepage_sampling");
    c.sampling = s == "contact"   ? contact::CreepageSampling::contact
                 : s == "average" ? contact::CreepageSampling::average
                                  : contact::CreepageSampling::midstep;
  });
  problems.check([&] { c.normal_force = r.real("contact.normal_force"); });
  problems.check([&] {
    const auto cr = r.real3("creepage.mean");
    c.creepage = {cr[0], cr[1], cr[2]};
  });
  problems.check([&] { c.spin_offset = r.real("grid.spin_offset"); });
  problems.check([&] {
    c.geometry = r.string("contact.geometry");
    const long nx = r.integer("grid.nx"), ny = r.integer("grid.ny");
    // nx, ny >= 2 (schema); compared by division: nx * ny overflows a long for absurd inputs
    if (nx > 40000 / ny) r.fail("grid.nx", "nx*ny above 40000 elements is not supported");
    if (c.geometry == "hertz")
      read_hertz_grid(r, c, nx, ny);
    else
      read_profiles(r, c, nx, problems);
  });
  problems.check([&] {
    const std::string infl = r.string("solver.influence");
    c.backend = infl == "fft"     ? contact::Backend::Fft
                : infl == "dense" ? contact::Backend::Dense
                                  : contact::Backend::Auto;
  });
  problems.check([&] {
    const std::string lm = r.string("solver.linear_model");
    c.linear_solver = lm == "dense"         ? nss::LinearSolver::dense
                      : lm == "matrix_free" ? nss::LinearSolver::matrix_free
                                            : nss::LinearSolver::automatic;
  });
  problems.check([&] { c.threads = static_cast<int>(r.integer("solver.threads")); });
  problems.check([&] { c.normal.tolerance = r.real("solver.normal_tolerance"); });
  problems.check([&] { c.tangential.tolerance = r.real("solver.tangential_tolerance"); });
  problems.check([&] { c.tangential.max_iterations = static_cast<int>(r.integer("solver.max_iterations")); });
  return c;
}

ContactCase read_contact_case(const CaseReader& r) {
  InputProblems problems;
  ContactCase c = read_contact_case(r, problems);
  problems.throw_if_any();
  return c;
}

}  // namespace rollnoise::io
