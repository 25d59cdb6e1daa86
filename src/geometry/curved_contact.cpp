#include "geometry/curved_contact.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "contact/halfspace_operator.hpp"
#include "core/errors.hpp"

namespace rollnoise::geometry {
namespace {

// The rail profile around the contact point parametrised by its arc length s (track frame of
// this side): s -> track y by linear interpolation of a table with 0.01 mm steps.
class RailArc {
 public:
  RailArc(const WheelRailPair& pair, double y0) {
    const double step = 1e-5, reach = 0.03;
    const double lo = std::max(y0 - reach, pair.rail().y_min() + pair.rail_offset());
    const double hi = std::min(y0 + reach, pair.rail().y_max() + pair.rail_offset());
    for (double y = y0; y >= lo; y -= step) y_.push_back(y);  // then reversed: ascending
    std::reverse(y_.begin(), y_.end());
    for (double y = y0 + step; y <= hi; y += step) y_.push_back(y);
    std::vector<double> z(y_.size());  // the rail at each sample, once (in order: a search hint)
    Profile::Cursor cursor;
    for (std::size_t i = 0; i < y_.size(); ++i) z[i] = pair.rail_z(y_[i], cursor);
    s_.assign(y_.size(), 0.0);
    const auto i0 = std::lower_bound(y_.begin(), y_.end(), y0 - 0.5 * step) - y_.begin();
    for (std::size_t i = i0 + 1; i < y_.size(); ++i)
      s_[i] = s_[i - 1] + std::hypot(y_[i] - y_[i - 1], z[i] - z[i - 1]);
    for (auto i = i0; i > 0; --i)
      s_[i - 1] = s_[i] - std::hypot(y_[i] - y_[i - 1], z[i] - z[i - 1]);
  }
  bool contains(double s) const { return s >= s_.front() && s <= s_.back(); }
  /// The arc length of the rail point at track y (within the table).
  double s(double y) const {
    const auto j = std::clamp<std::ptrdiff_t>(
        std::upper_bound(y_.begin(), y_.end(), y) - y_.begin(), 1, y_.size() - 1);
    const double t = (y - y_[j - 1]) / (y_[j] - y_[j - 1]);
    return s_[j - 1] + t * (s_[j] - s_[j - 1]);
  }
  double y(double s) const {
    const auto j = std::clamp<std::ptrdiff_t>(
        std::upper_bound(s_.begin(), s_.end(), s) - s_.begin(), 1, s_.size() - 1);
    const double t = (s - s_[j - 1]) / (s_[j] - s_[j - 1]);
    return y_[j - 1] + t * (y_[j] - y_[j - 1]);
  }

 private:
  std::vector<double> y_, s_;
};

// One grid row of the curved surface.
struct Row {
  bool found = false;
  double y = 0.0, angle = 0.0;  // rail point (track y) and contact angle δ(s)
  GapStrip strip;               // g(s), r(s), x_w(s), k(s) in the frame of the row
};

// The row at arc length s: the rail point, its normal, and the wheel's cross-section met along
// the normal (root of the wheel point's offset along the row's tangent, then gap_strip at 0).
Row row_at(const WheelRailPair& pair, const ContactGeometry& c, const RailArc& arc, double s) {
  Row row;
  if (!arc.contains(s)) return row;
  row.y = arc.y(s);
  row.angle = std::atan(-pair.rail_slope(row.y));
  const double cd = std::cos(row.angle), sd = std::sin(row.angle), rz = pair.rail_z(row.y);
  auto offset = [&](double p) {
    const WheelPoint w = pair.wheel_point(p, c.local_pose);
    return (w.y - row.y) * cd - (w.z - rz) * sd;
  };
  const double p_lo = pair.wheel().y_min(), p_hi = pair.wheel().y_max();
  double pa = std::clamp(c.wheel_s + (row.y - c.y), p_lo, p_hi), fa = offset(pa);
  const double dir = fa > 0.0 ? -1.0 : 1.0, step = 1e-4;
  double pb = pa, fb = fa;
  for (int k = 0; k < 300 && (fb > 0.0) == (fa > 0.0); ++k) {
    pa = pb, fa = fb;
    pb = std::clamp(pa + dir * step, p_lo, p_hi);
    if (pb == pa) return row;
    fb = offset(pb);
  }
  if ((fb > 0.0) == (fa > 0.0)) return row;
  for (int it = 0; it < 60; ++it) {
    const double pm = 0.5 * (pa + pb), fm = offset(pm);
    if ((fm > 0.0) == (fa > 0.0))
      pa = pm, fa = fm;
    else
      pb = pm;
  }
  ContactGeometry cs = c;
  cs.y = row.y;
  cs.z = rz;
  cs.contact_angle = row.angle;
  cs.wheel_s = 0.5 * (pa + pb);
  row.strip = gap_strip(pair, cs, 0.0);
  row.found = row.strip.found;
  return row;
}

// The rows' range of arc length where the gap stays below `limit` (m), as choose_grid: the region
// around the contact point, or with `all_regions` every region within 30 mm of it (a second
// minimum of the gap across a hump: the two-point contact of a contact jump).
std::pair<double, double> small_gap_range(const WheelRailPair& pair, const ContactGeometry& c,
                                          const RailArc& arc, double half, double limit,
                                          double step, bool all_regions) {
  double lo = -half, hi = half;
  for (double dir : {-1.0, 1.0})
    for (double t = step; t < 0.03; t += step) {
      const Row r = row_at(pair, c, arc, dir * t);
      if (!r.found) break;
      if (!(r.strip.gap <= limit)) {
        if (all_regions) continue;
        break;
      }
      if (dir < 0)
        lo = std::min(lo, -t - step);
      else
        hi = std::max(hi, t + step);
    }
  return {lo, hi};
}

// The (x, s) grid: x as choose_grid, s over the small-gap range of the curved surface.
contact::Grid curved_grid(const WheelRailPair& pair, const ContactGeometry& c, const RailArc& arc,
                          double normal_force, const VerticalLoadInput& in,
                          const GridOptions& options) {
  contact::Grid g = choose_grid(pair, c, normal_force, in.material, options);
  const contact::HertzContact hz = hertz_estimate(c, normal_force, in.material, options);
  const auto [lo, hi] =
      small_gap_range(pair, c, arc, options.scale * hz.b, options.gap_factor * hz.approach,
                      std::min(hz.a, hz.b) / 20.0, in.gap_regions);
  cover_rows(g, lo, hi, std::min(g.dx, 2.0 * hz.b / std::max(1, options.min_elements_across)),
             options.max_elements);
  return g;
}

// The per-element creepages (C4).
void local_creepages(const ContactGeometry& c, const std::vector<Row>& rows,
                     const contact::Grid& g, const VerticalLoadInput& in,
                     contact::SteadyRollingInput& r) {
  const double w_v = in.rolling_rate > 0.0 ? in.rolling_rate : 1.0 / c.rolling_radius;
  const double inv_R = in.inverse_radius;
  const double sy = std::sin(in.yaw);
  auto lateral = [&](double radius, double angle, double x) {
    const double xa = x + c.x;
    const double vy = -w_v * radius * sy - xa * inv_R, vz = w_v * xa;
    return vy * std::cos(angle) - vz * std::sin(angle);
  };
  const double s0 = lateral(c.rolling_radius, c.contact_angle, 0.0);
  r.local_creepage_x.assign(g.size(), r.creepage.xi_x);
  r.local_creepage_y.assign(g.size(), r.creepage.xi_y);
  for (int iy = 0; iy < g.ny; ++iy) {
    const Row& row = rows[iy];
    if (!row.found) continue;
    const double xi_x = r.creepage.xi_x - w_v * (row.strip.radius - c.rolling_radius) +
                        (row.y - c.y) * inv_R;
    for (int ix = 0; ix < g.nx; ++ix) {
      const int k = g.index(ix, iy);
      r.local_creepage_x[k] = xi_x;
      r.local_creepage_y[k] =
          r.creepage.xi_y +
          lateral(row.strip.radius, row.angle, g.x(ix) + r.spin_offset * g.dx) - s0;
    }
  }
}

struct CurvedPatch {
  contact::Grid grid;
  std::vector<Row> rows;
  contact::GridField h;
};

// The rows of the grid `g` (x and s from the contact point) and their undeformed distance (C1).
CurvedPatch curved_patch_on(const WheelRailPair& pair, const ContactGeometry& c, const RailArc& arc,
                            const contact::Grid& g) {
  CurvedPatch p;
  p.grid = g;
  p.h.assign(p.grid.size(), far_distance);
  for (int iy = 0; iy < p.grid.ny; ++iy) {
    p.rows.push_back(row_at(pair, c, arc, p.grid.y(iy)));
    const Row& r = p.rows.back();
    if (!r.found) continue;
    for (int ix = 0; ix < p.grid.nx; ++ix) {
      const double dx = p.grid.x(ix) - r.strip.lead;
      p.h[p.grid.index(ix, iy)] = r.strip.gap + r.strip.k * dx * dx / (2.0 * r.strip.radius);  // (C1)
    }
  }
  return p;
}

CurvedPatch curved_patch(const WheelRailPair& pair, const ContactGeometry& c, const RailArc& arc,
                         double normal_force, const VerticalLoadInput& in,
                         const GridOptions& options) {
  return curved_patch_on(pair, c, arc, curved_grid(pair, c, arc, normal_force, in, options));
}

// The grid of a nearby solved state kept where it lies on the rail: its rows at the same rail
// points and its columns at the same distances along the track (x and s are counted from the
// contact point, which can move across a conformal patch quickly, or jump, when the wheel moves).
contact::Grid kept_grid(const LoadedContact& near, const ContactGeometry& c, const RailArc& arc) {
  contact::Grid g = near.patch->grid;
  g.x_min += near.geometry.x - c.x;
  g.y_min += arc.s(near.geometry.y);
  return g;
}

// N from (C3): secant steps on r(N) = up(N) - Q after a first step with d(up)/dN = mean cos d
// (and instead of a wild secant step).
double next_normal_force(double N, double r, double N_prev, double r_prev, double mean_cos,
                         bool first) {
  double next = N - r / mean_cos;
  if (!first && r != r_prev) next = N - r * (N - N_prev) / (r - r_prev);
  if (!(next > 0.5 * N && next < 2.0 * N)) next = N - r / mean_cos;
  return next;
}

// The undeformed distance after the vertical lowering dz, relative to the fixed point's c0:
// h0 - dz (cos delta_row - c0) (the lowering's part of the gap, see lower_on_curved_surface).
contact::GridField lowered_distance(const CurvedPatch& cp, const std::vector<double>& cosd,
                                    double dz, double c0) {
  const contact::Grid& g = cp.grid;
  contact::GridField h = cp.h;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) h[g.index(ix, iy)] -= dz * (cosd[iy] - c0);
  return h;
}

// cos and sin of each row's contact angle (the contact point's for a row not found).
std::pair<std::vector<double>, std::vector<double>> row_orientations(const CurvedPatch& cp,
                                                                     const ContactGeometry& c) {
  std::vector<double> cosd(cp.grid.ny), sind(cp.grid.ny);
  for (int iy = 0; iy < cp.grid.ny; ++iy) {
    const double d = cp.rows[iy].found ? cp.rows[iy].angle : c.contact_angle;
    cosd[iy] = std::cos(d), sind[iy] = std::sin(d);
  }
  return {cosd, sind};
}

// The sums over the patch of (C3) and the forces on the wheel, each row with its own orientation
// (cos and sin of its contact angle): up = sum pn cos + py sin, lat = sum py cos - pn sin,
// lon = sum px, pc = sum pn cos, psum = sum pn (per element area).
struct RowSums {
  double up = 0.0, lat = 0.0, lon = 0.0, pc = 0.0, psum = 0.0;
};
RowSums row_sums(const contact::Grid& g, const contact::GridField& pn_field, const contact::TangentialSolution& t,
                 const std::vector<double>& cosd, const std::vector<double>& sind) {
  RowSums r;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const int k = g.index(ix, iy);
      const double pn = pn_field[k], py = t.py[k];
      r.up += pn * cosd[iy] + py * sind[iy];
      r.lat += py * cosd[iy] - pn * sind[iy];
      r.lon += t.px[k];
      r.pc += pn * cosd[iy];
      r.psum += pn;
    }
  return r;
}

[[noreturn]] void no_fixed_point(double Q, int max_iterations, double vertical, double lowering_change,
                                 double cos_change) {
  std::ostringstream m;
  m << "wheel lowered under its vertical load " << Q << " N on the curved surface: no"
    << " fixed point in " << max_iterations << " iterations (vertical force " << vertical
    << " N, lowering change " << lowering_change << " m, mean cos change " << cos_change << ")";
  throw NumericalError(m.str());
}

// Each row's contact angle, and their range over the rows that carry pressure.
void set_row_angles(const CurvedPatch& cp, const ContactGeometry& c, const contact::GridField& pn,
                    LoadedContact& out) {
  const contact::Grid& g = cp.grid;
  out.angle_min = 10.0, out.angle_max = -10.0;
  for (int iy = 0; iy < g.ny; ++iy) {
    out.row_angle.push_back(cp.rows[iy].found ? cp.rows[iy].angle : c.contact_angle);
    for (int ix = 0; ix < g.nx; ++ix)
      if (pn[g.index(ix, iy)] > 0.0) {
        out.angle_min = std::min(out.angle_min, out.row_angle.back());
        out.angle_max = std::max(out.angle_max, out.row_angle.back());
      }
  }
}

}  // namespace

LoadedContact lower_on_curved_surface(const WheelRailPair& pair, const ContactGeometry& c,
                                      const VerticalLoadInput& in) {
  const RailArc arc(pair, c.y);
  const double Q = in.vertical_load;
  // A start from a nearby state (VerticalLoadInput::start): its grid and fixed point.
  const LoadedContact* near = in.start && in.start->curved ? in.start.get() : nullptr;
  double N = near ? near->normal_force : Q / std::cos(c.contact_angle);
  // The grid, enlarged while the area reaches its border (as solve_wheel_rail_patch).
  GridOptions options = in.grid;
  for (int attempt = 0;; ++attempt) {
    if (attempt > 0) near = nullptr;  // an enlarged grid: the near state's fields do not fit
    const CurvedPatch cp = near ? curved_patch_on(pair, c, arc, kept_grid(*near, c, arc))
                                : curved_patch(pair, c, arc, N, in, options);
    const contact::Grid& g = cp.grid;
    const auto [cosd, sind] = row_orientations(cp, c);
    auto patch = std::make_shared<contact::ContactPatch>(g, in.material);
    const contact::HalfSpaceOperator op(patch->influence, contact::Problem::Normal, 0,
                                        contact::Backend::Auto);
    contact::SteadyRollingInput rolling = in.rolling;
    local_creepages(c, cp.rows, g, in, rolling);
    LoadedContact out;
    // One Newton solver for the iterations: its LU factors serve again while the area stays.
    contact::SteadyRollingSolver steady(patch->influence);
    if (near) steady.precondition_with(near->tangential_factors);
    double dz = near ? near->vertical_approach : 0.0;
    double c0 = near ? near->mean_cos : std::cos(c.contact_angle), N_prev = 0.0, r_prev = 0.0;
    contact::GridField h;
    for (out.iterations = 1;; ++out.iterations) {
      h = lowered_distance(cp, cosd, dz, c0);
      const bool first = out.iterations == 1;
      const contact::GridField* start = !first ? &patch->normal.pn
                                        : near ? &near->patch->normal.pn
                                               : nullptr;
      patch->normal = contact::solve_normal(g, op, h, N, {}, start);
      const contact::TangentialSolution* tstart = !first ? &out.tangential
                                                  : near ? &near->tangential
                                                         : nullptr;
      out.tangential = steady.solve(patch->normal.pn, rolling, {}, tstart);
      // (C3) and the forces on the wheel, each row with its own orientation.
      const RowSums rs = row_sums(g, patch->normal.pn, out.tangential, cosd, sind);
      const double up = rs.up, lat = rs.lat, lon = rs.lon, pc = rs.pc, psum = rs.psum;
      const double a = g.element_area();
      out.force_track = {lon * a, lat * a, up * a};
      const double dz_next = patch->normal.approach / c0, mean_cos = pc / psum;
      const double shape = std::max(in.settle, 1e-7);  // the lowering's and c0's part (below)
      const bool settled = std::abs(up * a - Q) <= std::max(in.tolerance, in.settle) * Q &&
                           std::abs(dz_next - dz) <= 10.0 * shape * std::abs(dz_next) + 1e-13 &&
                           std::abs(mean_cos - c0) <= shape;
      if (settled) break;
      if (out.iterations >= in.max_iterations)
        no_fixed_point(Q, in.max_iterations, up * a, dz_next - dz, mean_cos - c0);
      // The vertical approach dz cos δ(s) at the fixed point; c0 the pressure-weighted mean. The
      // tolerances above leave an error in h~ of < 10 shape dz |cos δ - c0| (1e-4 of the
      // approach by default, at least 1e-6 of it: the fixed point on dz and c0 converges
      // linearly, slowly for a patch in two regions).
      dz = dz_next;
      c0 = mean_cos;
      const double r = up * a - Q,
                   next = next_normal_force(N, r, N_prev, r_prev, mean_cos, out.iterations == 1);
      N_prev = N, r_prev = r;
      N = next;
    }
    if (attempt < 3 && contact::reaches_border(g, patch->normal.pn)) {
      options.scale *= 1.5;
      options.gap_factor *= 1.5;
      continue;
    }
    contact::check_inside_potential_area(g, patch->normal.pn, " on the curved surface");
    patch->undeformed_distance = h;
    out.geometry = c;
    out.vertical_load = Q;
    out.normal_force = N;
    out.creep_force = integrate_creep_force(g, out.tangential);
    out.vertical_approach = dz;
    out.mean_cos = c0;
    out.curved = true;
    set_row_angles(cp, c, patch->normal.pn, out);
    if (in.keep_factors) out.tangential_factors = steady.factors();
    out.patch = std::move(patch);
    return out;
  }
}

}  // namespace rollnoise::geometry
