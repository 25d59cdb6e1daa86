#include "contact/normal_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::contact {

int NormalSolution::contact_elements() const {
  return static_cast<int>(std::count_if(pn.begin(), pn.end(), [](double p) { return p > 0.0; }));
}

double NormalSolution::max_pressure() const { return *std::max_element(pn.begin(), pn.end()); }

NormalSolution solve_normal(const Grid& grid, const HalfSpaceOperator& op, const GridField& h,
                            double normal_force, const NormalSolverSettings& settings) {
  const int n = grid.size();
  const double area = grid.element_area();
  NormalSolution sol;
  std::vector<double>& p = sol.pn;
  // Start: uniform pressure over the whole potential contact area. The method is globally
  // convergent (convex problem), so the start only affects the iteration count.
  p.assign(n, normal_force / (area * n));

  std::vector<double> u(n), g(n), t(n, 0.0), r(n), p_old(n);
  double G_old = 1.0, g_mean = 0.0;
  bool conjugate = false;  // delta of Polonsky & Keer: 1 continues the CG direction, 0 restarts
  for (int it = 1; it <= settings.max_iterations; ++it) {
    // gradient of the complementary energy: g = A p + h, mean-free over the active set
    op.apply(p.data(), u.data());
    double sum = 0.0;
    int active = 0;
    for (int k = 0; k < n; ++k) {
      g[k] = u[k] + h[k];
      if (p[k] > 0.0) sum += g[k], ++active;
    }
    g_mean = active ? sum / active : 0.0;
    double G = 0.0;
    for (int k = 0; k < n; ++k) {
      g[k] -= g_mean;
      if (p[k] > 0.0) G += g[k] * g[k];
    }
    // search direction
    for (int k = 0; k < n; ++k)
      t[k] = p[k] > 0.0 ? g[k] + (conjugate ? G / G_old * t[k] : 0.0) : 0.0;
    G_old = G;
    op.apply(t.data(), r.data());
    double r_sum = 0.0;
    for (int k = 0; k < n; ++k)
      if (p[k] > 0.0) r_sum += r[k];
    const double r_mean = active ? r_sum / active : 0.0;
    double gt = 0.0, rt = 0.0;
    for (int k = 0; k < n; ++k)
      if (p[k] > 0.0) gt += g[k] * t[k], rt += (r[k] - r_mean) * t[k];
    const double tau = rt > 0.0 ? gt / rt : 0.0;
    // step, projection onto p >= 0, re-activation of overlapping elements
    p_old = p;
    bool overlap = false;
    for (int k = 0; k < n; ++k) {
      if (p[k] > 0.0) p[k] = std::max(0.0, p[k] - tau * t[k]);
    }
    for (int k = 0; k < n; ++k) {
      if (p[k] == 0.0 && g[k] < 0.0) {
        p[k] = -tau * g[k];
        overlap = true;
      }
    }
    conjugate = !overlap;
    // prescribed total force
    double total = 0.0;
    for (double v : p) total += v;
    total *= area;
    if (!(total > 0.0)) {  // everything projected away: restart from a uniform field
      std::fill(p.begin(), p.end(), normal_force / (area * n));
      conjugate = false;
      continue;
    }
    const double scale = normal_force / total;
    double change = 0.0;
    for (int k = 0; k < n; ++k) {
      p[k] *= scale;
      change += std::abs(p[k] - p_old[k]);
    }
    sol.residual = change * area / normal_force;
    sol.iterations = it;
    if (!std::isfinite(sol.residual)) break;
    if (sol.residual < settings.tolerance) {
      // final gap and approach: e = h + A p - delta, delta = mean of h + A p over the contact
      op.apply(p.data(), u.data());
      double s = 0.0;
      int m = 0;
      for (int k = 0; k < n; ++k)
        if (p[k] > 0.0) s += u[k] + h[k], ++m;
      sol.approach = s / m;
      sol.gap.resize(n);
      for (int k = 0; k < n; ++k) sol.gap[k] = p[k] > 0.0 ? 0.0 : u[k] + h[k] - sol.approach;
      sol.force = 0.0;
      for (double v : p) sol.force += v * area;
      return sol;
    }
  }
  std::ostringstream msg;
  msg << "normal solver (Polonsky-Keer CG) did not converge: relative change " << sol.residual
      << " after " << sol.iterations << " iterations (tolerance " << settings.tolerance << ")";
  throw NumericalError(msg.str());
}

}  // namespace rollnoise::contact
