#include "contact/steady_rolling.hpp"

#include "contact/coulomb_newton.hpp"
#include "core/errors.hpp"

namespace rollnoise::contact {

TangentialSolution solve_steady_rolling(const InfluenceTable& A, const GridField& pn,
                                        const SteadyRollingInput& in,
                                        const TangentialSolverSettings& settings,
                                        const TangentialSolution* start) {
  check_rolling_input(in.mu, in.speed, in.creepage);
  check_falling_friction(in.falling);
  const Grid& g = A.grid();
  GridField wx, wy, bound(g.size());
  rigid_slip(g, in.speed, in.creepage, in.spin_offset, wx, wy);
  if (!in.local_creepage_x.empty()) {
    if (in.local_creepage_x.size() != wx.size() || in.local_creepage_y.size() != wy.size())
      throw NumericalError("steady rolling: the local creepages do not match the grid");
    for (int k = 0; k < g.size(); ++k) {
      wx[k] = in.speed * in.local_creepage_x[k];
      wy[k] = in.speed * in.local_creepage_y[k];
    }
  }
  for (int k = 0; k < g.size(); ++k) bound[k] = in.mu * pn[k];
  CoulombNewton newton(SlipOperator::steady(A, in.speed), sweep_order(g, pn), bound);
  newton.set_falling_friction(in.falling);
  const GridField zero(g.size(), 0.0);
  return newton.solve(wx, wy, start ? start->px : zero, start ? start->py : zero, settings,
                      "steady tangential solver");
}

}  // namespace rollnoise::contact
