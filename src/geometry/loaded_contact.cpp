#include "geometry/loaded_contact.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/curved_contact.hpp"

namespace rollnoise::geometry {

std::array<double, 3> integrate_creep_force(const contact::Grid& g,
                                            const contact::TangentialSolution& t) {
  double fx = 0.0, fy = 0.0, mz = 0.0;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const int k = g.index(ix, iy);
      fx += t.px[k];
      fy += t.py[k];
      mz += g.x(ix) * t.py[k] - g.y(iy) * t.px[k];
    }
  const double a = g.element_area();
  return {fx * a, fy * a, mz * a};
}

std::array<double, 3> wheel_force_in_track_frame(double contact_angle, double fx, double fy,
                                                 double normal_force) {
  const double c = std::cos(contact_angle), s = std::sin(contact_angle);
  // The wheel feels N along -z_c = (0, -sin δ, -cos δ) (z down) and F_y along
  // y_c = (0, cos δ, -sin δ); "up" is -z.
  return {fx, fy * c - normal_force * s, normal_force * c + fy * s};
}

LoadedContact lower_under_vertical_load(const WheelRailPair& pair, const ContactGeometry& c,
                                        const VerticalLoadInput& in) {
  if (in.curved) return lower_on_curved_surface(pair, c, in);
  const double cd = std::cos(c.contact_angle), sd = std::sin(c.contact_angle);
  const double Q = in.vertical_load;
  LoadedContact out;
  out.geometry = c;
  out.vertical_load = Q;
  double N = Q / cd;  // start: no tangential share in (V1)
  // The grid is chosen (and enlarged until the area fits) once, at the first N; N changes by a
  // few per cent over the iteration, inside the grid's margin (solve_patch checks the border).
  auto patch = std::make_shared<contact::ContactPatch>(
      solve_wheel_rail_patch(pair, c, N, in.material, in.grid));
  const contact::GridField h = patch->undeformed_distance;
  double N_prev = 0.0, r_prev = 0.0;
  for (out.iterations = 1;; ++out.iterations) {
    if (out.iterations > 1)
      patch = std::make_shared<contact::ContactPatch>(
          contact::solve_patch(patch->grid, in.material, h, N));
    const contact::TangentialSolution* start = out.iterations > 1 ? &out.tangential : nullptr;
    out.tangential =
        contact::solve_steady_rolling(patch->influence, patch->normal.pn, in.rolling, {}, start);
    out.creep_force = integrate_creep_force(patch->grid, out.tangential);
    // (V1) as a root of r(N) = N cos d + F_y(N) sin d - Q: secant steps after a first fixed-point
    // step (the fixed point alone contracts by mu tan d only, slowly on a flank).
    const double r = N * cd + out.creep_force[1] * sd - Q;
    double next = (Q - out.creep_force[1] * sd) / cd;
    if (out.iterations > 1 && r != r_prev) next = N - r * (N - N_prev) / (r - r_prev);
    if (!(next > 0.5 * N && next < 2.0 * N)) next = (Q - out.creep_force[1] * sd) / cd;
    N_prev = N, r_prev = r;
    const double change = std::abs(next - N);
    if (change <= in.tolerance * N) break;
    if (out.iterations >= in.max_iterations) {
      std::ostringstream m;
      m << "wheel lowered under its vertical load " << Q << " N: the normal force did not settle"
        << " in " << in.max_iterations << " iterations (last change " << change << " N)";
      throw NumericalError(m.str());
    }
    N = next;
  }
  out.normal_force = N;
  out.force_track =
      wheel_force_in_track_frame(c.contact_angle, out.creep_force[0], out.creep_force[1], N);
  out.vertical_approach = patch->normal.approach / cd;
  out.row_angle.assign(patch->grid.ny, c.contact_angle);
  out.angle_min = out.angle_max = c.contact_angle;
  out.patch = std::move(patch);
  return out;
}

}  // namespace rollnoise::geometry
