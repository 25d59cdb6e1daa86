#include "geometry/wheel_rail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/errors.hpp"
#include "geometry/parabola_fit.hpp"
#include "linalg/nearest_root.hpp"

namespace rollnoise::geometry {
namespace {

constexpr double kSampleStep = 0.1e-3;  // sampling of the profiles when searching (m)
constexpr double kGolden = 0.3819660112501051;

// Golden-section search for the minimum of f on [a, b].
template <class F>
double golden_minimum(F&& f, double a, double b, int iterations = 80) {
  double x1 = a + kGolden * (b - a), x2 = b - kGolden * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < iterations && b - a > 1e-13; ++it) {
    if (f1 <= f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = a + kGolden * (b - a);
      f1 = f(x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = b - kGolden * (b - a);
      f2 = f(x2);
    }
  }
  return f1 <= f2 ? x1 : x2;
}

// A cross-section curve (rail or wheel) seen in the contact frame of contact point (yc0, zc0)
// with contact angle δ: parameter p -> track (y, z) -> contact (y_c, z_c):
//   y_c = (y - y0) cos δ - (z - z0) sin δ,   z_c = (y - y0) sin δ + (z - z0) cos δ.
// at(t) finds the parameter where y_c = t on the branch through the contact point (walking out
// from p0 while y_c keeps increasing in the walking direction, then bisection), or nothing when
// the curve ends or folds back (a flank turned away from the contact normal) before reaching t.
template <class Point>
struct ContactFrameCurve {
  Point point;  // p -> std::pair<double, double> (track y, z)
  double p0, p_lo, p_hi;
  double y0, z0, c, s;

  std::pair<double, double> local(double p) const {
    const auto [y, z] = point(p);
    return {(y - y0) * c - (z - z0) * s, (y - y0) * s + (z - z0) * c};
  }

  std::optional<double> at(double t) const {
    const double dir = t >= 0.0 ? 1.0 : -1.0;
    double pa = p0, ya = local(p0).first;
    if (ya * dir >= t * dir) return bisect(p0, p0, t);
    for (int k = 1;; ++k) {
      double pb = p0 + dir * k * kSampleStep;
      const bool last = pb < p_lo || pb > p_hi;
      pb = std::clamp(pb, p_lo, p_hi);
      if (pb == pa) return std::nullopt;
      const double yb = local(pb).first;
      if (yb * dir <= ya * dir) return std::nullopt;  // folds back
      if (yb * dir >= t * dir) return bisect(pa, pb, t);
      if (last) return std::nullopt;
      pa = pb;
      ya = yb;
    }
  }

  double bisect(double pa, double pb, double t) const {
    // local(pa).first - t and local(pb).first - t have opposite signs (or pa == pb).
    const double fa = local(pa).first - t;
    for (int it = 0; it < 100 && std::abs(pb - pa) > 1e-15; ++it) {
      const double pm = 0.5 * (pa + pb);
      const double fm = local(pm).first - t;
      if ((fm < 0.0) == (fa < 0.0))
        pa = pm;
      else
        pb = pm;
    }
    return 0.5 * (pa + pb);
  }
};

// The wheelset axes of one pose in the track frame, R = Rz(ψ) Rx(φ): axle a = R e_y, down
// d1 = R e_z, forward d2 = R e_x (d2z = 0), and the direction α = atan2(d2x, d1x) of the wheel's
// silhouette, as cos α, sin α. Computed once per pose: point() then needs no trigonometry.
struct PoseFrame {
  double lateral, vertical;
  double ax, ay, az, d1x, d1y, d1z, d2x, d2y;
  double rho, cos_alpha = 1.0, sin_alpha = 0.0;

  explicit PoseFrame(const WheelsetPose& pose) : lateral(pose.lateral), vertical(pose.vertical) {
    const double cp = std::cos(pose.roll), sp = std::sin(pose.roll);
    const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
    ax = -sy * cp, ay = cy * cp, az = sp;
    d1x = sy * sp, d1y = -cy * sp, d1z = cp;
    d2x = cy, d2y = sy;
    rho = std::hypot(d1x, d2x);
    if (rho > 0.0) cos_alpha = d1x / rho, sin_alpha = d2x / rho;
  }

  // The point of the circle of radius r (slope dr/ds = rp) at axle coordinate xi. Circle s:
  // c + r (cos θ d1 + sin θ d2). The surface normal of a body of revolution is ∝ e_r - r' a; seen
  // along x the outline is where its x component vanishes:
  //   cos θ d1x + sin θ d2x = r' ax,   i.e. ρ cos(θ - α) = r' ax,   θ = α ∓ q, cos q = r' ax / ρ.
  // Of the two solutions the lower one (largest cos θ, as d1z > 0) is the wheel's bottom; as
  // cos(α - q) - cos(α + q) = 2 sin α sin q with sin q >= 0, it is α - q when sin α >= 0. cos θ and
  // sin θ follow from the angle-difference formulas (equal to cos, sin of the angles to round-off).
  WheelPoint point(double xi, double r, double rp) const {
    double ct = 1.0, st = 0.0;
    if (rho > 0.0) {
      const double cq = std::clamp(rp * ax / rho, -1.0, 1.0);
      const double sq = std::sqrt(std::max(0.0, 1.0 - cq * cq));
      if (sin_alpha >= 0.0)
        ct = cos_alpha * cq + sin_alpha * sq, st = sin_alpha * cq - cos_alpha * sq;
      else
        ct = cos_alpha * cq - sin_alpha * sq, st = sin_alpha * cq + cos_alpha * sq;
    }
    WheelPoint p;
    p.x = xi * ax + r * (ct * d1x + st * d2x);
    p.y = lateral + xi * ay + r * (ct * d1y + st * d2y);
    p.z = vertical + xi * az + r * (ct * d1z);
    p.radius = r;
    p.radial_y = ct * d1y + st * d2y;
    p.radial_z = ct * d1z;
    return p;
  }
};

GapStrip strip_at(const WheelRailPair& pair, const ContactGeometry& cg, double t) {
  const double c = std::cos(cg.contact_angle), s = std::sin(cg.contact_angle);
  const WheelsetPose& pose = cg.local_pose;
  Profile::Cursor cursor;  // the strip's walk moves along the rail: a search hint
  auto rail_point = [&](double y) { return std::make_pair(y, pair.rail_z(y, cursor)); };
  const PoseFrame frame(pose);
  auto wheel_at = [&](double sw) {
    return frame.point(pair.wheel_offset() + sw,
                       pair.wheelset().nominal_radius + pair.wheel().z(sw), pair.wheel().slope(sw));
  };
  auto wheel_point = [&](double sw) {
    const WheelPoint p = wheel_at(sw);
    return std::make_pair(p.y, p.z);
  };
  const double ry_lo = pair.rail().y_min() + pair.rail_offset();
  const double ry_hi = pair.rail().y_max() + pair.rail_offset();
  ContactFrameCurve<decltype(rail_point)> rail{rail_point, cg.y, ry_lo, ry_hi, cg.y, cg.z, c, s};
  ContactFrameCurve<decltype(wheel_point)> wheel{
      wheel_point, cg.wheel_s, pair.wheel().y_min(), pair.wheel().y_max(), cg.y, cg.z, c, s};
  GapStrip st;
  const auto pr = rail.at(t);
  const auto pw = wheel.at(t);
  if (!pr || !pw) return st;
  st.found = true;
  st.gap = rail.local(*pr).second - wheel.local(*pw).second;
  const WheelPoint wp = wheel_at(*pw);
  st.radius = wp.radius;
  st.lead = wp.x - cg.x;
  // dz_c/dy_c of the wheel at the strip, by central differences along the profile.
  const double e = 1e-5;
  const auto a = wheel.local(std::max(*pw - e, pair.wheel().y_min()));
  const auto b = wheel.local(std::min(*pw + e, pair.wheel().y_max()));
  const double slope_w = (b.second - a.second) / (b.first - a.first);
  // The wheel's rise along -e_r, seen in the contact frame: k = e_z - e_y dz_w/dy_c.
  const double ey = wp.radial_y * c - wp.radial_z * s, ez = wp.radial_y * s + wp.radial_z * c;
  st.k = ez - ey * slope_w;
  return st;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
WheelRailPair::WheelRailPair(Profile wheel, Profile rail, const TrackParameters& track,
                             const WheelsetParameters& wheelset)
    : wheel_(std::move(wheel)), rail_(std::move(rail)), track_(track), wheelset_(wheelset) {
  if (wheel_.kind() != ProfileKind::Wheel)
    throw InputError(wheel_.source(),
                     wheel_.source() + ": is a rail profile, a wheel profile was expected");
  if (rail_.kind() != ProfileKind::Rail)
    throw InputError(rail_.source(),
                     rail_.source() + ": is a wheel profile, a rail profile was expected");
  // contracts: no case key sets the gauge or the nominal radius (the defaults of the structs)
  if (!(track_.gauge > 0.5 && track_.gauge < 3.0))
    throw std::invalid_argument("the track gauge must be between 0.5 and 3 m");
  if (!(wheelset_.nominal_radius > 0.05))
    throw std::invalid_argument("the nominal rolling radius must exceed 0.05 m");
  // Cant an upright rail towards the track centre: its top turns towards -y (the gauge side), a
  // rotation by -atan(inclination) from +y towards +z.
  if (!rail_.canted() && track_.rail_inclination != 0.0)
    rail_ = rail_.rotated(-std::atan(track_.rail_inclination));

  // Gauge point: the gauge-side point (smallest y) of the rail head at gauge_point_depth below the
  // top of the rail (the lowest z), found by walking from the top towards -y.
  const auto& y = rail_.y_points();
  const auto& z = rail_.z_points();
  const auto top = std::min_element(z.begin(), z.end()) - z.begin();
  const double z_gauge = z[top] + track_.gauge_point_depth;
  std::optional<double> yg;
  for (auto i = top; i > 0; --i) {
    if (z[i - 1] >= z_gauge && z[i] < z_gauge) {
      double lo = y[i - 1], hi = y[i];  // z(lo) >= z_gauge > z(hi): bisection on the spline
      for (int it = 0; it < 100; ++it) {
        const double m = 0.5 * (lo + hi);
        (rail_.z(m) >= z_gauge ? lo : hi) = m;
      }
      yg = 0.5 * (lo + hi);
      break;
    }
  }
  if (!yg) {
    std::ostringstream m;
    m << rail_.source() << ": the rail profile does not reach " << track_.gauge_point_depth * 1e3
      << " mm below its top on the gauge side (y < " << y[top] * 1e3
      << " mm): the gauge point is undefined";
    throw InputError(rail_.source(), m.str());
  }
  gauge_point_ = *yg;
  rail_offset_ = track_.gauge / 2 - gauge_point_;

  // The wheel's search table: n + 1 samples s_k = s_lo + (s_hi - s_lo) k / n, n = width / step.
  auto table = std::make_shared<WheelTable>();
  const double s_lo = wheel_.y_min(), s_hi = wheel_.y_max();
  const int n = static_cast<int>((s_hi - s_lo) / kSampleStep);
  for (int k = 0; k <= n; ++k) {
    const double s = s_lo + (s_hi - s_lo) * k / n;
    table->s.push_back(s);
    table->radius.push_back(wheelset_.nominal_radius + wheel_.z(s));
    table->slope.push_back(wheel_.slope(s));
  }
  wheel_table_ = std::move(table);
}

WheelPoint WheelRailPair::wheel_point(double s, const WheelsetPose& pose) const {
  return PoseFrame(pose).point(wheel_offset() + s, wheelset_.nominal_radius + wheel_.z(s),
                               wheel_.slope(s));
}

double WheelRailPair::minimum_gap(const WheelsetPose& pose, double* s_at_minimum) const {
  const PoseFrame frame(pose);
  const double offset = wheel_offset();
  Profile::Cursor cursor;  // the scan's samples move along the rail: a search hint
  auto gap_of = [&](const WheelPoint& p) {
    if (!rail_contains(p.y)) return std::numeric_limits<double>::infinity();
    return rail_z(p.y, cursor) - p.z;
  };
  auto gap = [&](double s) {
    return gap_of(frame.point(offset + s, wheelset_.nominal_radius + wheel_.z(s), wheel_.slope(s)));
  };
  // The scan over the tabulated wheel (no spline, no trigonometry per sample), then a golden
  // section search between the neighbours of the best sample.
  const WheelTable& table = *wheel_table_;
  const double s_lo = wheel_.y_min(), s_hi = wheel_.y_max();
  double best = std::numeric_limits<double>::infinity(), s_best = 0.0;
  const int n = static_cast<int>(table.s.size()) - 1;
  for (int k = 0; k <= n; ++k) {
    const double g = gap_of(frame.point(offset + table.s[k], table.radius[k], table.slope[k]));
    if (g < best) {
      best = g;
      s_best = table.s[k];
    }
  }
  if (!std::isfinite(best))
    throw InputError("geometry",
                     "the wheel and the rail profile do not overlap laterally "
                     "(lateral displacement too large?)");
  const double h = (s_hi - s_lo) / n;
  const double s_min = golden_minimum(gap, std::max(s_lo, s_best - h), std::min(s_hi, s_best + h));
  const double g_min = gap(s_min);
  if (g_min < best) {
    best = g_min;
    s_best = s_min;
  }
  if (s_at_minimum) *s_at_minimum = s_best;
  return best;
}

WheelsetPose WheelRailPair::equilibrium(const WheelsetPosition& position) const {
  // For a roll angle φ, the vertical position at which the right (left) wheel touches its rail is
  // w = w0 + min gap(w0) (the gap falls one to one with w). The roll makes both equal.
  const double w0 = -wheelset_.nominal_radius;
  auto touch = [&](double roll, bool left) {
    WheelsetPose p{position.lateral, w0, roll, position.yaw};
    if (left) p = p.mirrored();
    return w0 + minimum_gap(p);
  };
  auto mismatch = [&](double roll) { return touch(roll, false) - touch(roll, true); };
  // Secant iteration from φ = 0; d(mismatch)/dφ ≈ -2 (wheel offset) ≈ -1.5 m.
  double p0 = 0.0, f0 = mismatch(p0);
  double p1 = f0 / (2.0 * wheel_offset()), f1 = mismatch(p1);
  int it = 0;
  for (; it < 50 && std::abs(f1) > 1e-13 && p1 != p0; ++it) {
    const double p2 = p1 - f1 * (p1 - p0) / (f1 - f0);
    p0 = p1;
    f0 = f1;
    p1 = p2;
    f1 = mismatch(p1);
  }
  if (!(std::abs(f1) <= 1e-10) || !std::isfinite(p1)) {
    // The secant can cycle where a wheel's contact point jumps across its profile (the mismatch's
    // slope jumps there). The mismatch falls monotonically with the roll: bracket the root from
    // the secant's first step on, then Brent's method (linalg::brent_root).
    double a = 0.0, fa = mismatch(a);
    const double step = fa / (2.0 * wheel_offset());
    double b = step, fb = mismatch(b);
    for (int k = 0; k < 40 && fa != 0.0 && (fa > 0.0) == (fb > 0.0); ++k) {
      a = b, fa = fb;
      b = a + std::ldexp(step, k + 1);
      fb = mismatch(b);
    }
    p1 = fa == 0.0 ? a : fb == 0.0 ? b : linalg::brent_root(mismatch, a, b);
    f1 = mismatch(p1);
  }
  if (!(std::abs(f1) <= 1e-10) || !std::isfinite(p1)) {
    std::ostringstream m;
    m << "geometry: wheelset roll iteration (secant) did not converge: residual " << f1
      << " m after " << it << " iterations";
    throw NumericalError(m.str());
  }
  return {position.lateral, touch(p1, false), p1, position.yaw};
}

// ---------------------------------------------------------------------------------------------
ContactGeometry find_contact(const WheelRailPair& pair, const WheelsetPosition& position, Side side,
                             const ContactOptions& options) {
  return find_contact_at_pose(pair, pair.equilibrium(position), side, options);
}

ContactGeometry find_contact_at_pose(const WheelRailPair& pair, const WheelsetPose& pose, Side side,
                                     const ContactOptions& options) {
  ContactGeometry c;
  c.side = side;
  c.pose = pose;
  c.local_pose = side == Side::Right ? c.pose : c.pose.mirrored();
  double s = 0.0;
  pair.minimum_gap(c.local_pose, &s);
  const WheelPoint p = pair.wheel_point(s, c.local_pose);
  c.x = p.x;
  c.y = p.y;
  c.z = pair.rail_z(p.y);
  c.rail_y = p.y - pair.rail_offset();
  c.wheel_s = s;
  c.contact_angle = std::atan(-pair.rail_slope(p.y));
  c.rolling_radius = p.radius;
  if (!options.curvatures) return c;
  c.rail_curvature = pair.rail().curvature(c.rail_y, options.curvature_window);
  c.wheel_curvature = pair.wheel().curvature(s, options.curvature_window);
  c.A = strip_at(pair, c, 0.0).k / (2.0 * c.rolling_radius);
  c.B = quadratic_coefficient([&](double t) { return lateral_gap(pair, c, t); },
                              options.curvature_window);
  return c;
}

GapStrip gap_strip(const WheelRailPair& pair, const ContactGeometry& c, double y_c) {
  return strip_at(pair, c, y_c);
}

double lateral_gap(const WheelRailPair& pair, const ContactGeometry& c, double y_c) {
  return strip_at(pair, c, y_c).gap;
}

contact::GridField undeformed_distance(const WheelRailPair& pair, const ContactGeometry& c,
                                       const contact::Grid& grid) {
  contact::GridField h(grid.size());
  for (int iy = 0; iy < grid.ny; ++iy) {
    const GapStrip st = strip_at(pair, c, grid.y(iy));
    for (int ix = 0; ix < grid.nx; ++ix) {
      double v = far_distance;
      if (st.found) {
        const double dx = grid.x(ix) - st.lead;
        v = st.gap + st.k * dx * dx / (2.0 * st.radius);
      }
      h[grid.index(ix, iy)] = v;
    }
  }
  return h;
}

contact::HertzContact hertz_estimate(const ContactGeometry& c, double normal_force,
                                     const contact::Material& material,
                                     const GridOptions& options) {
  const double B = std::max(c.B, options.min_curvature_ratio * c.A);
  return contact::hertz_from_curvatures(c.A, B, normal_force, material);
}

contact::Grid choose_grid(const WheelRailPair& pair, const ContactGeometry& c, double normal_force,
                          const contact::Material& material, const GridOptions& options) {
  if (!(options.nx >= 4)) throw InputError("grid.nx", "at least 4 elements in x are needed");
  const contact::HertzContact hz = hertz_estimate(c, normal_force, material, options);
  const double ex = options.scale * hz.a;
  // The y-range around the contact point where the lateral gap stays below gap_factor x approach.
  const double limit = options.gap_factor * hz.approach;
  const double step = std::min(hz.a, hz.b) / 20.0;
  double y_lo = -options.scale * hz.b, y_hi = options.scale * hz.b;
  for (double dir : {-1.0, 1.0}) {
    for (double t = step; t < 0.06; t += step) {
      if (!(lateral_gap(pair, c, dir * t) <= limit)) break;
      if (dir < 0)
        y_lo = std::min(y_lo, -t - step);
      else
        y_hi = std::max(y_hi, t + step);
    }
  }
  contact::Grid g;
  g.nx = options.nx;
  g.dx = 2.0 * ex / g.nx;
  g.x_min = -ex;
  cover_rows(g, y_lo, y_hi, std::min(g.dx, 2.0 * hz.b / std::max(1, options.min_elements_across)),
             options.max_elements);
  return g;
}

void cover_rows(contact::Grid& g, double y_lo, double y_hi, double dy, int max_elements) {
  g.dy = dy;
  g.ny = static_cast<int>(std::ceil((y_hi - y_lo) / g.dy));
  if (g.nx * g.ny > max_elements) {
    g.ny = std::max(4, max_elements / g.nx);
    g.dy = (y_hi - y_lo) / g.ny;
  }
  // Centre the rows on the y-range.
  g.y_min = 0.5 * (y_lo + y_hi) - 0.5 * g.ny * g.dy;
}

contact::ContactPatch solve_wheel_rail_patch(const WheelRailPair& pair, const ContactGeometry& c,
                                             double normal_force, const contact::Material& material,
                                             GridOptions options) {
  // Enlarge the grid (up to 3 times) while the contact area reaches its border.
  for (int attempt = 0;; ++attempt) {
    const contact::Grid g = choose_grid(pair, c, normal_force, material, options);
    contact::ContactPatch patch =
        contact::solve_patch_unchecked(g, material, undeformed_distance(pair, c, g), normal_force);
    if (attempt == 3) contact::check_inside_potential_area(g, patch.normal.pn, "");
    if (attempt == 3 || !contact::reaches_border(g, patch.normal.pn)) return patch;
    options.scale *= 1.5;
    options.gap_factor *= 1.5;
  }
}

PatchShape patch_shape(const contact::ContactPatch& patch) {
  const contact::Grid& g = patch.grid;
  PatchShape s;
  s.x_min = s.y_min = std::numeric_limits<double>::infinity();
  s.x_max = s.y_max = -std::numeric_limits<double>::infinity();
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const double p = patch.normal.pn[g.index(ix, iy)];
      if (!(p > 0.0)) continue;
      ++s.elements;
      s.force += p * g.element_area();
      s.peak_pressure = std::max(s.peak_pressure, p);
      s.x_min = std::min(s.x_min, g.x(ix) - 0.5 * g.dx);
      s.x_max = std::max(s.x_max, g.x(ix) + 0.5 * g.dx);
      s.y_min = std::min(s.y_min, g.y(iy) - 0.5 * g.dy);
      s.y_max = std::max(s.y_max, g.y(iy) + 0.5 * g.dy);
    }
  s.area = s.elements * g.element_area();
  if (s.elements == 0) s.x_min = s.x_max = s.y_min = s.y_max = 0.0;
  return s;
}

double patch_length_at(const contact::ContactPatch& patch, double y) {
  const contact::Grid& g = patch.grid;
  const int iy = std::clamp(static_cast<int>(std::floor((y - g.y_min) / g.dy)), 0, g.ny - 1);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int ix = 0; ix < g.nx; ++ix)
    if (patch.normal.pn[g.index(ix, iy)] > 0.0) {
      lo = std::min(lo, g.x(ix) - 0.5 * g.dx);
      hi = std::max(hi, g.x(ix) + 0.5 * g.dx);
    }
  return hi > lo ? hi - lo : 0.0;
}

double patch_ellipse_deviation(const contact::ContactPatch& patch) {
  const PatchShape s = patch_shape(patch);
  if (s.elements == 0) return 0.0;
  const contact::Grid& g = patch.grid;
  const double y_mid = 0.5 * (s.y_min + s.y_max), half = 0.5 * s.width();
  double worst = 0.0;
  for (int iy = 0; iy < g.ny; ++iy) {
    const double y = g.y(iy);
    if (y < s.y_min || y > s.y_max) continue;
    const double q = (y - y_mid) / half;
    const double ellipse = s.length() * std::sqrt(std::max(0.0, 1.0 - q * q));
    worst = std::max(worst, std::abs(patch_length_at(patch, y) - ellipse));
  }
  return worst / s.length();
}

}  // namespace rollnoise::geometry
