#include "contact/steady_rolling.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/coulomb.hpp"
#include "contact/slip_operator.hpp"
#include "core/errors.hpp"
#include "linalg/gmres.hpp"

namespace rollnoise::contact {
namespace {

// R(p) = p - Pi(p) and the per-element derivatives dPi/db, for the contact elements.
struct FixedPointResidual {
  Eigen::VectorXd R, s;
  std::vector<ElementTraction> local;
  double norm = 0.0;  // max_I |R_I|
};

}  // namespace

TangentialSolution solve_steady_rolling(const InfluenceTable& A, const GridField& pn,
                                        const SteadyRollingInput& in,
                                        const TangentialSolverSettings& settings,
                                        const TangentialSolution* start) {
  const Grid& g = A.grid();
  const std::vector<int> elems = sweep_order(g, pn);
  const int m = static_cast<int>(elems.size());
  const int n = 2 * m;  // unknowns, interleaved (px, py) per element

  // Dense slip operator on the contact elements.
  const SlipOperator S = SlipOperator::steady(A, in.speed);
  Eigen::MatrixXd Sd(n, n);
  for (int b = 0; b < m; ++b) {
    const int ixb = elems[b] % g.nx, iyb = elems[b] / g.nx;
    for (int a = 0; a < m; ++a) {
      const int k = S.offset_index(elems[a] % g.nx - ixb, elems[a] / g.nx - iyb);
      Sd(2 * a, 2 * b) = S.xx(k);
      Sd(2 * a, 2 * b + 1) = S.xy(k);
      Sd(2 * a + 1, 2 * b) = S.xy(k);
      Sd(2 * a + 1, 2 * b + 1) = S.yy(k);
    }
  }
  const int k0 = S.offset_index(0, 0);
  const double d1 = S.xx(k0), d2 = S.yy(k0);

  GridField wxg, wyg;
  rigid_slip(g, in.speed, in.creepage, in.spin_offset, wxg, wyg);
  Eigen::VectorXd w(n), p = Eigen::VectorXd::Zero(n);
  std::vector<double> bound(m);
  for (int a = 0; a < m; ++a) {
    const int k = elems[a];
    w(2 * a) = wxg[k], w(2 * a + 1) = wyg[k];
    bound[a] = in.mu * pn[k];
    if (start) p(2 * a) = start->px[k], p(2 * a + 1) = start->py[k];
  }

  auto residual = [&](const Eigen::VectorXd& q) {
    FixedPointResidual r;
    r.s = w + Sd * q;
    r.R.resize(n);
    r.local.resize(m);
    for (int a = 0; a < m; ++a) {
      const double bx = r.s(2 * a) - d1 * q(2 * a), by = r.s(2 * a + 1) - d2 * q(2 * a + 1);
      r.local[a] = solve_coulomb_element(bx, by, d1, d2, bound[a]);
      r.R(2 * a) = q(2 * a) - r.local[a].px;
      r.R(2 * a + 1) = q(2 * a + 1) - r.local[a].py;
      r.norm = std::max(r.norm, std::hypot(r.R(2 * a), r.R(2 * a + 1)));
    }
    return r;
  };
  double scale = 0.0;  // traction scale for the relative residual
  for (int a = 0; a < m; ++a) scale = std::max(scale, bound[a]);

  TangentialSolution sol;
  FixedPointResidual r = residual(p);
  Eigen::MatrixXd J(n, n);
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  bool have_lu = false;
  sol.residual = 1.0;
  bool converged = false;
  for (int it = 1; it <= settings.max_iterations; ++it) {
    // Jacobian I - dPi/db (S - D), row block by row block
    for (int a = 0; a < m; ++a) {
      const double* G = r.local[a].dp_db;
      J.row(2 * a) = -G[0] * Sd.row(2 * a) - G[1] * Sd.row(2 * a + 1);
      J.row(2 * a + 1) = -G[2] * Sd.row(2 * a) - G[3] * Sd.row(2 * a + 1);
      J(2 * a, 2 * a) += 1.0 + G[0] * d1;
      J(2 * a, 2 * a + 1) += G[1] * d2;
      J(2 * a + 1, 2 * a) += G[2] * d1;
      J(2 * a + 1, 2 * a + 1) += 1.0 + G[3] * d2;
    }
    // Newton step J dp = -R. The LU factors of an earlier Jacobian precondition GMRES; they are
    // renewed when GMRES needs many iterations (the Jacobian changed much since).
    Eigen::VectorXd dp = Eigen::VectorXd::Zero(n);
    bool solved = false;
    if (have_lu) {
      const double forcing = std::min(1e-2, std::max(1e-13, sol.residual * 1e-2));
      const auto g = linalg::gmres([&](const Eigen::VectorXd& v) { return Eigen::VectorXd(J * v); },
                                   [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(lu.solve(v)); },
                                   -r.R, dp, forcing, 60);
      solved = g.converged;
    }
    if (!solved) {
      lu.compute(J);
      have_lu = true;
      dp = -lu.solve(r.R);
    }
    // Step: the Newton point projected onto the traction bounds |p_I| <= mu pn_I (an
    // admissible traction field), accepted if it reduces |R|_2; else backtracking on |R|_2.
    auto project = [&](Eigen::VectorXd q) {
      for (int a = 0; a < m; ++a) {
        const double len = std::hypot(q(2 * a), q(2 * a + 1));
        if (len > bound[a]) q.segment<2>(2 * a) *= bound[a] / len;
      }
      return q;
    };
    const double r2 = r.R.norm();
    Eigen::VectorXd next = project(p + dp);
    FixedPointResidual trial = residual(next);
    double t = 1.0;
    for (int k = 0; k < 30 && !(trial.R.norm() <= (1.0 - 1e-4 * t) * r2); ++k) {
      t *= 0.5;
      next = project(p + t * dp);
      trial = residual(next);
    }
    p = std::move(next);
    r = std::move(trial);
    sol.iterations = it;
    // relative to the tractions present (creepage 1e-8 gives tractions ~1e-5 mu pn)
    double p_max = 0.0;
    for (int a = 0; a < m; ++a) p_max = std::max(p_max, std::hypot(p(2 * a), p(2 * a + 1)));
    sol.residual = r.norm / std::max(p_max, 1e-300 * scale);
    if (!std::isfinite(sol.residual)) break;
    if (r.norm == 0.0 || sol.residual <= settings.tolerance) {
      converged = true;
      break;
    }
  }
  if (!converged) {
    std::ostringstream msg;
    msg << "steady tangential solver (semismooth Newton) did not converge: relative residual "
        << sol.residual << " after " << sol.iterations << " iterations (tolerance "
        << settings.tolerance << ")";
    throw NumericalError(msg.str());
  }

  // Output on the grid: tractions Pi(p) (exactly on the Coulomb bound in slip), slip from Eq. 3.
  sol.px.assign(g.size(), 0.0);
  sol.py.assign(g.size(), 0.0);
  sol.sx.assign(g.size(), 0.0);
  sol.sy.assign(g.size(), 0.0);
  sol.state.assign(g.size(), static_cast<std::int8_t>(ElementState::exterior));
  for (int a = 0; a < m; ++a) {
    const int k = elems[a];
    const ElementTraction& e = r.local[a];
    sol.px[k] = e.px, sol.py[k] = e.py;
    if (e.slip) sol.sx[k] = e.sx, sol.sy[k] = e.sy;
    sol.state[k] = static_cast<std::int8_t>(e.slip ? ElementState::slip : ElementState::adhesion);
  }
  return sol;
}

}  // namespace rollnoise::contact
