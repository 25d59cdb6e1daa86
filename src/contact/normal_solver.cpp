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

namespace {

// Start: uniform pressure over the whole potential contact area, or the given start scaled to the
// force. The method is globally convergent (convex problem), so the start only affects the
// iteration count.
std::vector<double> start_pressure(int n, double area, double normal_force, const GridField* start) {
  std::vector<double> p(n, normal_force / (area * n));
  if (start && static_cast<int>(start->size()) == n) {
    double total = 0.0;
    for (double v : *start) total += std::max(v, 0.0) * area;
    if (total > 0.0)
      for (int k = 0; k < n; ++k) p[k] = std::max((*start)[k], 0.0) * normal_force / total;
  }
  return p;
}

// The converged solution's gap, approach and force: e = h + A p - delta, delta = mean of h + A p
// over the contact.
void set_gap_and_force(const HalfSpaceOperator& op, const GridField& h, double area, NormalSolution& sol) {
  const std::vector<double>& p = sol.pn;
  const int n = static_cast<int>(p.size());
  std::vector<double> u(n);
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
}

}  // namespace

NormalSolution solve_normal(const Grid& grid, const HalfSpaceOperator& op, const GridField& h,
                            double normal_force, const NormalSolverSettings& settings,
                            const GridField* start) {
  const int n = grid.size();
  const double area = grid.element_area();
  NormalSolution sol;
  std::vector<double>& p = sol.pn;
  p = start_pressure(n, area, normal_force, start);

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
      set_gap_and_force(op, h, area, sol);
      return sol;
    }
  }
  std::ostringstream msg;
  msg << "normal solver (Polonsky-Keer CG) did not converge: relative change " << sol.residual
      << " after " << sol.iterations << " iterations (tolerance " << settings.tolerance << ")";
  throw NumericalError(msg.str());
}

FrozenAreaSolution frozen_area_solve(const Grid& grid, const HalfSpaceOperator& op,
                                     const NormalSolution& normal, const GridField& rhs,
                                     double tolerance) {
  // Conjugate gradients for A_CC x = b (A_zz is symmetric positive definite, so is its principal
  // submatrix on C); the products go through the full-grid operator with zeros outside C.
  const int n = grid.size();
  std::vector<char> in(n);
  for (int k = 0; k < n; ++k) in[k] = normal.pn[k] > 0.0;
  if (std::none_of(in.begin(), in.end(), [](char c) { return c != 0; }))
    throw NumericalError("frozen area solve: no element in contact");
  FrozenAreaSolution s;
  s.x.assign(n, 0.0);
  std::vector<double> r(n, 0.0), d(n, 0.0), q(n);
  for (int k = 0; k < n; ++k) r[k] = d[k] = in[k] ? rhs[k] : 0.0;
  double rr = 0.0;
  for (int k = 0; k < n; ++k) rr += r[k] * r[k];
  const double rr0 = rr;
  const int max_iterations = 10 * n + 100;
  while (rr > tolerance * tolerance * rr0) {
    if (++s.iterations > max_iterations) {
      std::ostringstream m;
      m << "frozen area solve: CG did not converge in " << max_iterations
        << " iterations (relative residual " << std::sqrt(rr / rr0) << ")";
      throw NumericalError(m.str());
    }
    op.apply(d.data(), q.data());
    double dq = 0.0;
    for (int k = 0; k < n; ++k)
      if (in[k]) dq += d[k] * q[k];
    const double alpha = rr / dq;
    double rr_new = 0.0;
    for (int k = 0; k < n; ++k) {
      if (!in[k]) continue;
      s.x[k] += alpha * d[k];
      r[k] -= alpha * q[k];
      rr_new += r[k] * r[k];
    }
    const double beta = rr_new / rr;
    for (int k = 0; k < n; ++k) d[k] = in[k] ? r[k] + beta * d[k] : 0.0;
    rr = rr_new;
  }
  return s;
}

NormalLoadSensitivity normal_load_sensitivity(const Grid& grid, const HalfSpaceOperator& op,
                                              const NormalSolution& normal, double tolerance) {
  // (N1): A_CC x = 1
  const FrozenAreaSolution x =
      frozen_area_solve(grid, op, normal, GridField(grid.size(), 1.0), tolerance);
  NormalLoadSensitivity s;
  s.iterations = x.iterations;
  double sum = 0.0;
  for (double v : x.x) sum += v;
  const double stiffness = grid.element_area() * sum;  // dN/d(delta)
  s.approach_per_load = 1.0 / stiffness;
  s.dpn_dN.resize(grid.size());
  for (int k = 0; k < grid.size(); ++k) s.dpn_dN[k] = x.x[k] / stiffness;
  return s;
}

}  // namespace rollnoise::contact
