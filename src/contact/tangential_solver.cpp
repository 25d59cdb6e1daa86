#include "contact/tangential_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/coulomb.hpp"
#include "core/errors.hpp"

namespace rollnoise::contact {

int TangentialSolution::count(ElementState s) const {
  return static_cast<int>(std::count(state.begin(), state.end(), static_cast<std::int8_t>(s)));
}

void rigid_slip(const Grid& g, double speed, const Creepage& c, double spin_offset, GridField& wx,
                GridField& wy) {
  wx.assign(g.size(), 0.0);
  wy.assign(g.size(), 0.0);
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = g.nx - 1; ix >= 0; --ix) {
      const int k = g.index(ix, iy);
      wx[k] = speed * (c.xi_x - c.phi * g.y(iy));
      wy[k] = speed * (c.xi_y + c.phi * (g.x(ix) + spin_offset * g.dx));
    }
}

std::vector<int> sweep_order(const Grid& g, const GridField& pn) {
  std::vector<int> order;
  for (int ix = g.nx - 1; ix >= 0; --ix)
    for (int iy = 0; iy < g.ny; ++iy)
      if (pn[g.index(ix, iy)] > 0.0) order.push_back(g.index(ix, iy));
  return order;
}

TangentialSolution solve_coulomb(const SlipOperator& S, const GridField& rhs_x,
                                 const GridField& rhs_y, const GridField& bound,
                                 const std::vector<int>& order, GridField px, GridField py,
                                 const TangentialSolverSettings& settings,
                                 const std::string& solver) {
  const Grid& g = S.grid();
  const int m = static_cast<int>(order.size());
  std::vector<int> ix(m), iy(m);
  for (int q = 0; q < m; ++q) ix[q] = order[q] % g.nx, iy[q] = order[q] / g.nx;

  // Zero tractions outside the contact, then s = rhs + S p on the contact elements.
  std::vector<std::int8_t> in(g.size(), 0);
  for (int k : order) in[k] = 1;
  for (int k = 0; k < g.size(); ++k)
    if (!in[k]) px[k] = py[k] = 0.0;
  std::vector<double> sx(m), sy(m), qx(m), qy(m);
  for (int q = 0; q < m; ++q) qx[q] = px[order[q]], qy[q] = py[order[q]];
  for (int a = 0; a < m; ++a) {
    double vx = rhs_x[order[a]], vy = rhs_y[order[a]];
    for (int b = 0; b < m; ++b) {
      if (qx[b] == 0.0 && qy[b] == 0.0) continue;
      const int k = S.offset_index(ix[a] - ix[b], iy[a] - iy[b]);
      vx += S.xx(k) * qx[b] + S.xy(k) * qy[b];
      vy += S.xy(k) * qx[b] + S.yy(k) * qy[b];
    }
    sx[a] = vx, sy[a] = vy;
  }
  const int k0 = S.offset_index(0, 0);
  const double d1 = S.xx(k0), d2 = S.yy(k0);

  TangentialSolution sol;
  sol.state.assign(g.size(), static_cast<std::int8_t>(ElementState::exterior));
  std::vector<std::int8_t> slip(m, 0);
  for (int it = 1; it <= settings.max_iterations; ++it) {
    double max_change = 0.0, max_p = 0.0;
    for (int a = 0; a < m; ++a) {
      // slip with this element's own traction removed: b = s - D p
      const double bx = sx[a] - d1 * qx[a], by = sy[a] - d2 * qy[a];
      const ElementTraction e = solve_coulomb_element(bx, by, d1, d2, bound[order[a]]);
      slip[a] = e.slip;
      const double dpx = e.px - qx[a], dpy = e.py - qy[a];
      if (dpx == 0.0 && dpy == 0.0) continue;
      qx[a] = e.px, qy[a] = e.py;
      max_change = std::max(max_change, std::hypot(dpx, dpy));
      // update the slip of every contact element for the change of this traction
      for (int c = 0; c < m; ++c) {
        const int k = S.offset_index(ix[c] - ix[a], iy[c] - iy[a]);
        sx[c] += S.xx(k) * dpx + S.xy(k) * dpy;
        sy[c] += S.xy(k) * dpx + S.yy(k) * dpy;
      }
    }
    for (int a = 0; a < m; ++a) max_p = std::max(max_p, std::hypot(qx[a], qy[a]));
    sol.iterations = it;
    sol.residual = max_p > 0.0 ? max_change / max_p : max_change;
    if (!std::isfinite(sol.residual)) break;
    if (sol.residual <= settings.tolerance) {
      sol.px.assign(g.size(), 0.0);
      sol.py.assign(g.size(), 0.0);
      sol.sx.assign(g.size(), 0.0);
      sol.sy.assign(g.size(), 0.0);
      for (int a = 0; a < m; ++a) {
        const int k = order[a];
        sol.px[k] = qx[a], sol.py[k] = qy[a];
        if (slip[a]) sol.sx[k] = sx[a], sol.sy[k] = sy[a];
        sol.state[k] =
            static_cast<std::int8_t>(slip[a] ? ElementState::slip : ElementState::adhesion);
      }
      return sol;
    }
  }
  std::ostringstream msg;
  msg << solver << " (Gauss-Seidel) did not converge: relative traction change " << sol.residual
      << " after " << sol.iterations << " sweeps (tolerance " << settings.tolerance << ")";
  throw NumericalError(msg.str());
}

}  // namespace rollnoise::contact
