#include "contact/tangential_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

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

void check_rolling_input(double mu, double speed, const Creepage& c) {
  auto text = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  if (!(std::isfinite(mu) && mu > 0.0))
    throw InputError("friction.mu", "must be a positive finite number, got " + text(mu));
  if (!(std::isfinite(speed) && speed > 0.0))
    throw InputError("rolling.speed", "must be a positive finite speed (m/s), got " + text(speed));
  if (!(std::isfinite(c.xi_x) && std::isfinite(c.xi_y) && std::isfinite(c.phi)))
    throw InputError("creepage.mean", "creepages must be finite, got (" + text(c.xi_x) + ", " +
                                          text(c.xi_y) + ", " + text(c.phi) + ")");
}

std::vector<int> sweep_order(const Grid& g, const GridField& pn) {
  std::vector<int> order;
  for (int ix = g.nx - 1; ix >= 0; --ix)
    for (int iy = 0; iy < g.ny; ++iy)
      if (pn[g.index(ix, iy)] > 0.0) order.push_back(g.index(ix, iy));
  return order;
}

}  // namespace rollnoise::contact
