#include "contact/patch.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::contact {

GridField quadratic_distance(const Grid& g, double A, double B) {
  GridField h(g.size());
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix)
      h[g.index(ix, iy)] = A * g.x(ix) * g.x(ix) + B * g.y(iy) * g.y(iy);
  return h;
}

bool reaches_border(const Grid& g, const GridField& pn) {
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const bool border = ix == 0 || iy == 0 || ix == g.nx - 1 || iy == g.ny - 1;
      if (border && pn[g.index(ix, iy)] > 0.0) return true;
    }
  return false;
}

void check_inside_potential_area(const Grid& g, const GridField& pn, const std::string& context) {
  // A contact area touching the border of the potential contact area is cut off by it.
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const bool border = ix == 0 || iy == 0 || ix == g.nx - 1 || iy == g.ny - 1;
      if (border && pn[g.index(ix, iy)] > 0.0) {
        std::ostringstream msg;
        msg << "the contact area" << context
            << " reaches the border of the potential contact area (element ix=" << ix
            << ", iy=" << iy << "): enlarge the grid (grid.scale or its extent)";
        throw InputError("grid", msg.str());
      }
    }
}

ContactPatch solve_patch_unchecked(const Grid& g, const Material& m, GridField h, double normal_force,
                                   Backend backend, const NormalSolverSettings& s) {
  ContactPatch patch(g, m);
  const HalfSpaceOperator op(patch.influence, Problem::Normal, 0, backend);
  patch.undeformed_distance = std::move(h);
  patch.normal = solve_normal(g, op, patch.undeformed_distance, normal_force, s);
  return patch;
}

ContactPatch solve_patch(const Grid& g, const Material& m, GridField h, double normal_force,
                         Backend backend, const NormalSolverSettings& s) {
  ContactPatch patch = solve_patch_unchecked(g, m, std::move(h), normal_force, backend, s);
  check_inside_potential_area(g, patch.normal.pn, "");
  return patch;
}

}  // namespace rollnoise::contact
