#include "contact/coulomb_newton.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/coulomb.hpp"
#include "core/errors.hpp"
#include "linalg/gmres.hpp"

namespace rollnoise::contact {
namespace {

// R(p) = p - Pi(p) and the per-element Coulomb solutions (with dPi/db).
struct FixedPointResidual {
  Eigen::VectorXd R;
  std::vector<ElementTraction> local;
  double norm = 0.0;  // max_I |R_I|
};

}  // namespace

CoulombNewton::CoulombNewton(const SlipOperator& S, std::vector<int> elements,
                             const GridField& bound)
    : grid_(S.grid()), elements_(std::move(elements)) {
  const Grid& g = grid_;
  const int m = static_cast<int>(elements_.size()), n = 2 * m;
  S_.resize(n, n);
  for (int b = 0; b < m; ++b) {
    const int ixb = elements_[b] % g.nx, iyb = elements_[b] / g.nx;
    for (int a = 0; a < m; ++a) {
      const int k = S.offset_index(elements_[a] % g.nx - ixb, elements_[a] / g.nx - iyb);
      S_(2 * a, 2 * b) = S.xx(k);
      S_(2 * a, 2 * b + 1) = S.xy(k);
      S_(2 * a + 1, 2 * b) = S.xy(k);
      S_(2 * a + 1, 2 * b + 1) = S.yy(k);
    }
  }
  const int k0 = S.offset_index(0, 0);
  d1_ = S.xx(k0);
  d2_ = S.yy(k0);
  bound_.resize(m);
  for (int a = 0; a < m; ++a) bound_[a] = bound[elements_[a]];
  J_.resize(n, n);
}

TangentialSolution CoulombNewton::solve(const GridField& rhs_x, const GridField& rhs_y,
                                        const GridField& px, const GridField& py,
                                        const TangentialSolverSettings& settings,
                                        const std::string& solver) {
  const Grid& g = grid_;
  const int m = static_cast<int>(elements_.size()), n = 2 * m;
  Eigen::VectorXd w(n), p(n);
  for (int a = 0; a < m; ++a) {
    const int k = elements_[a];
    w(2 * a) = rhs_x[k], w(2 * a + 1) = rhs_y[k];
    p(2 * a) = px[k], p(2 * a + 1) = py[k];
  }
  auto project = [&](Eigen::VectorXd q) {
    for (int a = 0; a < m; ++a) {
      const double len = std::hypot(q(2 * a), q(2 * a + 1));
      if (len > bound_[a]) q.segment<2>(2 * a) *= bound_[a] / len;
    }
    return q;
  };
  p = project(p);
  auto residual = [&](const Eigen::VectorXd& q) {
    FixedPointResidual r;
    const Eigen::VectorXd s = w + S_ * q;
    r.R.resize(n);
    r.local.resize(m);
    for (int a = 0; a < m; ++a) {
      const double bx = s(2 * a) - d1_ * q(2 * a), by = s(2 * a + 1) - d2_ * q(2 * a + 1);
      r.local[a] = solve_coulomb_element(bx, by, d1_, d2_, bound_[a]);
      r.R(2 * a) = q(2 * a) - r.local[a].px;
      r.R(2 * a + 1) = q(2 * a + 1) - r.local[a].py;
      r.norm = std::max(r.norm, std::hypot(r.R(2 * a), r.R(2 * a + 1)));
    }
    return r;
  };
  auto relative = [&](const FixedPointResidual& r) {
    // relative to the tractions present (creepage 1e-8 gives tractions ~1e-5 mu pn)
    double p_max = 0.0;
    for (int a = 0; a < m; ++a)
      p_max = std::max(p_max, std::hypot(r.local[a].px, r.local[a].py));
    return p_max > 0.0 ? r.norm / p_max : r.norm;
  };

  TangentialSolution sol;
  FixedPointResidual r = residual(p);
  sol.residual = relative(r);
  bool converged = r.norm == 0.0 || sol.residual <= settings.tolerance;
  for (int it = 1; it <= settings.max_iterations && !converged; ++it) {
    // Jacobian I - dPi/db (S - D), row block by row block
    for (int a = 0; a < m; ++a) {
      const double* G = r.local[a].dp_db;
      J_.row(2 * a) = -G[0] * S_.row(2 * a) - G[1] * S_.row(2 * a + 1);
      J_.row(2 * a + 1) = -G[2] * S_.row(2 * a) - G[3] * S_.row(2 * a + 1);
      J_(2 * a, 2 * a) += 1.0 + G[0] * d1_;
      J_(2 * a, 2 * a + 1) += G[1] * d2_;
      J_(2 * a + 1, 2 * a) += G[2] * d1_;
      J_(2 * a + 1, 2 * a + 1) += 1.0 + G[3] * d2_;
    }
    // Newton step J dp = -R: GMRES with the LU factors of an earlier Jacobian, or a new LU.
    Eigen::VectorXd dp = Eigen::VectorXd::Zero(n);
    bool solved = false;
    if (have_lu_) {
      const double forcing = std::min(1e-2, std::max(1e-13, sol.residual * 1e-2));
      const auto res = linalg::gmres(
          [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(J_ * v); },
          [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(lu_.solve(v)); }, -r.R, dp,
          forcing, 60);
      solved = res.converged;
    }
    if (!solved) {
      lu_.compute(J_);
      have_lu_ = true;
      ++factorisations_;
      dp = -lu_.solve(r.R);
    }
    // projected Newton point, accepted if it reduces |R|_2, else backtracking
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
    sol.residual = relative(r);
    if (!std::isfinite(sol.residual)) break;
    converged = r.norm == 0.0 || sol.residual <= settings.tolerance;
  }
  if (!converged) {
    std::ostringstream msg;
    msg << solver << " (semismooth Newton) did not converge: relative residual " << sol.residual
        << " after " << sol.iterations << " iterations (tolerance " << settings.tolerance << ")";
    throw NumericalError(msg.str());
  }

  // Output on the grid: tractions Pi(p) (exactly on the Coulomb bound in slip) and slip velocities.
  sol.px.assign(g.size(), 0.0);
  sol.py.assign(g.size(), 0.0);
  sol.sx.assign(g.size(), 0.0);
  sol.sy.assign(g.size(), 0.0);
  sol.state.assign(g.size(), static_cast<std::int8_t>(ElementState::exterior));
  for (int a = 0; a < m; ++a) {
    const int k = elements_[a];
    const ElementTraction& e = r.local[a];
    sol.px[k] = e.px, sol.py[k] = e.py;
    if (e.slip) sol.sx[k] = e.sx, sol.sy[k] = e.sy;
    sol.state[k] = static_cast<std::int8_t>(e.slip ? ElementState::slip : ElementState::adhesion);
  }
  return sol;
}

}  // namespace rollnoise::contact
