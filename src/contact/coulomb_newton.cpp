#include "contact/coulomb_newton.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/coulomb.hpp"
#include "contact/friction_law.hpp"
#include "core/errors.hpp"
#include "linalg/gmres.hpp"

namespace rollnoise::contact {
namespace {

// q with each element's traction brought back onto its Coulomb bound |q_a| <= bound_a.
Eigen::VectorXd project_on_bounds(Eigen::VectorXd q, const std::vector<double>& bound) {
  for (int a = 0; a < static_cast<int>(bound.size()); ++a) {
    const double len = std::hypot(q(2 * a), q(2 * a + 1));
    if (len > bound[a]) q.segment<2>(2 * a) *= bound[a] / len;
  }
  return q;
}

// max_I |R_I| relative to the tractions present (creepage 1e-8 gives tractions ~1e-5 mu pn).
double relative_residual(const std::vector<ElementTraction>& local, double norm) {
  double p_max = 0.0;
  for (const ElementTraction& e : local) p_max = std::max(p_max, std::hypot(e.px, e.py));
  return p_max > 0.0 ? norm / p_max : norm;
}

// GMRES iterations allowed without a preconditioner (restarted every 150) before J is factorised.
// An iteration costs one FFT product, O(N log N), plus the orthogonalisation; the factorisation
// costs O(n^3) and each preconditioned iteration adds two triangular solves, O(n^2), cheap while
// the factors stay in cache. Measured (rollnoise_bench --benchmark_filter='Steady|Transient',
// paper case): on 34x25 (1076 unknowns) a transient step costs 2.1 ms with factors and ~3.5 ms
// without, so small systems are factorised early; on 68x50 (4192 unknowns) 28 ms without against
// 67 ms with, and the steady solve 0.35 s without against 2.7 s with. A budget proportional to n
// keeps the unpreconditioned work below the factorisation (136x100, 16720 unknowns: one float LU
// took 100 s against ~2 ms per GMRES iteration).
int unpreconditioned_budget(int unknowns) { return unknowns <= 2000 ? 8 : unknowns / 4; }

// Tiny tractions. The problem is positively homogeneous: if p solves it for the
// right-hand side w and the bounds g, then sigma p solves it for sigma w and sigma g (sigma > 0; the
// element law of coulomb.hpp and R are homogeneous of degree 1). The solver, though, is not scale
// free in floating point: squared norms (|R|_2 in GMRES and the line search) underflow below
// ~1e-154, and the float LU factors see residuals below ~1e-38 as zero; creepages below ~1e-46 then
// stalled Newton. So when the traction scale of the problem, max(|w|/d, |p_start|) (d the smaller
// diagonal of S: the adhesion traction of an element alone), is below 2^-40 Pa (tractions from
// creepages below ~1e-23), the problem is solved for sigma = 2^k that brings it to ~1 Pa (bounds
// at most 2^1000, no overflow), and the tractions divided by sigma. A power of two is exact, so the
// iterates are those of the scaled problem to the bit; above the floor nothing changes (sigma = 1).
// The convergence test needs no change: it is relative to the tractions present.
int traction_scale_exponent(const Eigen::VectorXd& w, const Eigen::VectorXd& p, double d,
                            const std::vector<double>& bound) {
  const double c = std::max(w.cwiseAbs().maxCoeff() / d, p.cwiseAbs().maxCoeff());
  if (!(c > 0.0 && c < 0x1p-40)) return 0;  // zero or normal scale (or NaN: reported as before)
  const double g = bound.empty() ? 0.0 : *std::max_element(bound.begin(), bound.end());
  const int k = g > 0.0 ? std::min(-std::ilogb(c), 1000 - std::ilogb(g)) : -std::ilogb(c);
  return std::max(k, 0);
}

}  // namespace

CoulombNewton::CoulombNewton(const SlipOperator& S, std::vector<int> elements,
                             const GridField& bound)
    : grid_(S.grid()),
      S_(S),
      product_(std::make_shared<const HalfSpaceOperator>(
          S.grid(), Problem::Tangential, [&S](Component c, int di, int dj) { return S(c, di, dj); })),
      elements_(std::move(elements)),
      S_elements_(element_operator()) {
  const int k0 = S.offset_index(0, 0);
  d1_ = S.xx(k0);
  d2_ = S.yy(k0);
  const int m = static_cast<int>(elements_.size());
  bound_.resize(m);
  for (int a = 0; a < m; ++a) bound_[a] = bound[elements_[a]];
}

ElementOperator CoulombNewton::element_operator() const {
  return ElementOperator(product_, grid_, elements_);
}

void CoulombNewton::set_bounds(std::vector<int> elements, const GridField& bound) {
  if (elements != elements_) {
    elements_ = std::move(elements);
    S_elements_ = element_operator();
    factors_.reset();  // factors of another system
  }
  const int m = static_cast<int>(elements_.size());
  bound_.resize(m);
  for (int a = 0; a < m; ++a) bound_[a] = bound[elements_[a]];
}

void CoulombNewton::check_falling_uniqueness() const {
  // Element-level uniqueness of the slip speed (coulomb.hpp): d_max g_max (1 - A) B < 1 with
  // g = mu_s pn, i.e.  B < B_max = 1 / (d_max mu_s pn_max (1 - A)).
  const double g_max = bound_.empty() ? 0.0 : *std::max_element(bound_.begin(), bound_.end());
  const double d_max = std::max(d1_, d2_);
  if (!(d_max * g_max * falling_.steepest_ratio_slope() < 1.0)) {
    std::ostringstream msg;
    msg << "the falling friction law is steeper than the contact's elastic slip compliance allows: "
           "the slip of an element is not unique when mu_s pn (1 - A) B d >= 1 (d = "
        << d_max << " (m/s)/Pa the element's self slip compliance, mu_s pn_max = " << g_max
        << " Pa, 1 - A = " << 1.0 - falling_.kinetic_ratio << "); friction.decay must be below "
        << 1.0 / (d_max * g_max * (1.0 - falling_.kinetic_ratio)) << " s/m, got " << falling_.decay;
    throw InputError("friction.decay", msg.str());
  }
}

void CoulombNewton::apply_S(const Eigen::VectorXd& q, Eigen::VectorXd& s) const {
  s.resize(S_elements_.size());
  S_elements_.apply(q.data(), s.data());
}

void CoulombNewton::factorise(const std::vector<ElementTraction>& local) {
  // J = I - dPi/db (S - D): row block a is -G_a S_(a,:), plus I + G_a D on the diagonal block.
  const Grid& g = grid_;
  const int m = static_cast<int>(elements_.size()), n = 2 * m;
  auto assemble = [&](auto& J) {
    J.resize(n, n);
    for (int b = 0; b < m; ++b) {  // column-major storage: fill column pairs
      const int ixb = elements_[b] % g.nx, iyb = elements_[b] / g.nx;
      for (int a = 0; a < m; ++a) {
        const int k = S_.offset_index(elements_[a] % g.nx - ixb, elements_[a] / g.nx - iyb);
        const double sxx = S_.xx(k), sxy = S_.xy(k), syy = S_.yy(k);
        const double* G = local[a].dp_db;
        J(2 * a, 2 * b) = -(G[0] * sxx + G[1] * sxy);
        J(2 * a + 1, 2 * b) = -(G[2] * sxx + G[3] * sxy);
        J(2 * a, 2 * b + 1) = -(G[0] * sxy + G[1] * syy);
        J(2 * a + 1, 2 * b + 1) = -(G[2] * sxy + G[3] * syy);
      }
    }
    for (int a = 0; a < m; ++a) {
      const double* G = local[a].dp_db;
      J(2 * a, 2 * a) += 1.0 + G[0] * d1_;
      J(2 * a, 2 * a + 1) += G[1] * d2_;
      J(2 * a + 1, 2 * a) += G[2] * d1_;
      J(2 * a + 1, 2 * a + 1) += 1.0 + G[3] * d2_;
    }
  };
  auto f = std::make_shared<NewtonFactors>();
  f->elements = elements_;
  f->double_precision = double_factors_;
  if (double_factors_) {
    Eigen::MatrixXd J;
    assemble(J);
    f->lu_double.compute(J);
  } else {
    Eigen::MatrixXf J;
    assemble(J);
    f->lu_float.compute(J);
  }
  factors_ = std::move(f);
  ++factorisations_;
}

Eigen::VectorXd NewtonFactors::solve(const Eigen::VectorXd& v) const {
  if (double_precision) return lu_double.solve(v);
  return lu_float.solve(v.cast<float>()).cast<double>();
}

void CoulombNewton::precondition_with(std::shared_ptr<const NewtonFactors> factors) {
  if (factors && factors->elements == elements_) factors_ = std::move(factors);
}

Eigen::VectorXd CoulombNewton::precondition(const Eigen::VectorXd& v) const {
  return factors_ ? factors_->solve(v) : v;
}

// R(p) = p - Pi(p) and the per-element Coulomb solutions (with dPi/db).
struct CoulombNewton::FixedPointResidual {
  Eigen::VectorXd R;
  std::vector<ElementTraction> local;
  double norm = 0.0;  // max_I |R_I|
};

CoulombNewton::FixedPointResidual CoulombNewton::residual(const Eigen::VectorXd& q, const Eigen::VectorXd& w,
                                                          const std::vector<double>& bound) const {
  const int m = static_cast<int>(elements_.size()), n = 2 * m;
  FixedPointResidual r;
  Eigen::VectorXd s;
  apply_S(q, s);
  s += w;
  r.R.resize(n);
  r.local.resize(m);
  for (int a = 0; a < m; ++a) {
    const double bx = s(2 * a) - d1_ * q(2 * a), by = s(2 * a + 1) - d2_ * q(2 * a + 1);
    r.local[a] = falling_.active() ? solve_coulomb_element(bx, by, d1_, d2_, bound[a], falling_)
                                   : solve_coulomb_element(bx, by, d1_, d2_, bound[a]);
    r.R(2 * a) = q(2 * a) - r.local[a].px;
    r.R(2 * a + 1) = q(2 * a + 1) - r.local[a].py;
    const double len = std::hypot(r.R(2 * a), r.R(2 * a + 1));
    if (!(len <= r.norm)) r.norm = len;  // keeps a NaN (std::max would drop it)
  }
  return r;
}

Eigen::VectorXd CoulombNewton::newton_direction(const FixedPointResidual& r, double relative_residual,
                                                const std::string& solver) {
  const int m = static_cast<int>(elements_.size()), n = 2 * m;
  Eigen::VectorXd Sv;
  // Jacobian action J v = v - dPi/db (S v - D v), element by element
  auto jacobian = [&](const Eigen::VectorXd& v) {
    apply_S(v, Sv);
    Eigen::VectorXd Jv(n);
    for (int a = 0; a < m; ++a) {
      const double* G = r.local[a].dp_db;
      const double bx = Sv(2 * a) - d1_ * v(2 * a), by = Sv(2 * a + 1) - d2_ * v(2 * a + 1);
      Jv(2 * a) = v(2 * a) - (G[0] * bx + G[1] * by);
      Jv(2 * a + 1) = v(2 * a + 1) - (G[2] * bx + G[3] * by);
    }
    return Jv;
  };
  // Newton step J dp = -R: GMRES with the current preconditioner (none before the first
  // factorisation); on failure new factors (double precision once float factors have failed).
  // Forcing term of the inexact Newton method (Dembo, Eisenstat & Steihaug 1982): the linear
  // residual relative to |R|. With factors GMRES is cheap and 1e-2 |R| keeps Newton quadratic;
  // without, reaching 1e-13 costs more GMRES iterations than the extra Newton steps that the
  // floor 1e-3 (linear convergence by 1e-3 per step once the slip set is fixed) costs.
  const double forcing =
      std::min(1e-2, std::max(factors_ ? 1e-13 : 1e-3, relative_residual * 1e-2));
  // GMRES(restart) from dp = 0 until converged or `budget` iterations are spent.
  auto gmres = [&](Eigen::VectorXd& dp, int restart, int budget) {
    dp.setZero(n);
    for (int spent = 0; spent < budget;) {
      const auto res = linalg::gmres(
          jacobian, [&](const Eigen::VectorXd& v) { return precondition(v); }, -r.R, dp, forcing,
          std::min(restart, budget - spent));
      linear_iterations_ += res.iterations;
      spent += std::max(res.iterations, 1);
      if (res.converged) return true;
    }
    return false;
  };
  Eigen::VectorXd dp;
  bool solved = factors_ ? gmres(dp, 30, 30) : gmres(dp, 150, unpreconditioned_budget(n));
  if (!solved) {  // new factors of the current J; double precision if float ones fail
    factorise(r.local);
    solved = gmres(dp, 30, 30);
    if (!solved && !double_factors_) {
      double_factors_ = true;
      factorise(r.local);
      solved = gmres(dp, 60, 60);
    }
    if (!solved) {
      std::ostringstream msg;
      msg << solver << ": the Newton system is too ill-conditioned for GMRES with LU factors";
      throw NumericalError(msg.str());
    }
  }
  return dp;
}

TangentialSolution CoulombNewton::on_grid(const std::vector<ElementTraction>& local, int scale_exponent) const {
  // Output on the grid: tractions Pi(p) (exactly on the Coulomb bound in slip) and slip velocities.
  const Grid& g = grid_;
  TangentialSolution sol;
  sol.px.assign(g.size(), 0.0);
  sol.py.assign(g.size(), 0.0);
  sol.sx.assign(g.size(), 0.0);
  sol.sy.assign(g.size(), 0.0);
  sol.state.assign(g.size(), static_cast<std::int8_t>(ElementState::exterior));
  for (int a = 0; a < static_cast<int>(elements_.size()); ++a) {
    if (bound_[a] == 0.0) continue;  // out of contact at this load (set_bounds): p = 0
    const int k = elements_[a];
    const ElementTraction& e = local[a];
    sol.px[k] = std::ldexp(e.px, -scale_exponent), sol.py[k] = std::ldexp(e.py, -scale_exponent);
    if (e.slip) sol.sx[k] = std::ldexp(e.sx, -scale_exponent), sol.sy[k] = std::ldexp(e.sy, -scale_exponent);
    sol.state[k] = static_cast<std::int8_t>(e.slip ? ElementState::slip : ElementState::adhesion);
  }
  return sol;
}

TangentialSolution CoulombNewton::solve(const GridField& rhs_x, const GridField& rhs_y,
                                        const GridField& px, const GridField& py,
                                        const TangentialSolverSettings& settings,
                                        const std::string& solver) {
  const int m = static_cast<int>(elements_.size()), n = 2 * m;
  Eigen::VectorXd w(n), p(n);
  for (int a = 0; a < m; ++a) {
    const int k = elements_[a];
    w(2 * a) = rhs_x[k], w(2 * a + 1) = rhs_y[k];
    p(2 * a) = px[k], p(2 * a + 1) = py[k];
  }
  if (falling_.active()) check_falling_uniqueness();
  // tiny tractions: solve sigma times the problem (see traction_scale_exponent); not with falling
  // friction, whose element law is not homogeneous (mu depends on |s|)
  const int scale_exponent =
      m > 0 && !falling_.active() ? traction_scale_exponent(w, p, std::min(d1_, d2_), bound_) : 0;
  std::vector<double> scaled_bound;
  if (scale_exponent != 0) {
    const double sigma = std::ldexp(1.0, scale_exponent);
    w *= sigma;
    p *= sigma;
    scaled_bound = bound_;
    for (double& b : scaled_bound) b *= sigma;
  }
  const std::vector<double>& bound = scale_exponent != 0 ? scaled_bound : bound_;
  p = project_on_bounds(p, bound);

  const int factorisations_before = factorisations_, linear_before = linear_iterations_;
  FixedPointResidual r = residual(p, w, bound);
  int iterations = 0;
  double rel = relative_residual(r.local, r.norm);
  bool converged = r.norm == 0.0 || rel <= settings.tolerance;
  for (int it = 1; it <= settings.max_iterations && !converged && std::isfinite(rel); ++it) {
    const Eigen::VectorXd dp = newton_direction(r, rel, solver);
    // projected Newton point, accepted if it reduces |R|_2, else backtracking
    const double r2 = r.R.norm();
    Eigen::VectorXd next = project_on_bounds(p + dp, bound);
    FixedPointResidual trial = residual(next, w, bound);
    double t = 1.0;
    for (int k = 0; k < 30 && !(trial.R.norm() <= (1.0 - 1e-4 * t) * r2); ++k) {
      t *= 0.5;
      next = project_on_bounds(p + t * dp, bound);
      trial = residual(next, w, bound);
    }
    if (falling_.active() && !(trial.R.norm() <= (1.0 - 1e-4 * t) * r2)) {
      // No descent along the Newton direction: with falling friction the solution need not be
      // unique or exist (docs/falling_friction.md, Sec. 3); report instead of iterating on.
      std::ostringstream msg;
      msg << solver << " (semismooth Newton): the line search stalled at relative residual " << rel << " after "
          << it
          << " iterations with falling friction; the falling branch may be too steep for a unique"
             " solution: lower friction.decay or raise friction.kinetic_ratio";
      throw NumericalError(msg.str());
    }
    p = std::move(next);
    r = std::move(trial);
    iterations = it;
    rel = relative_residual(r.local, r.norm);
    if (!std::isfinite(rel)) break;
    converged = r.norm == 0.0 || rel <= settings.tolerance;
  }
  if (!converged) {
    std::ostringstream msg;
    msg << solver << " (semismooth Newton) did not converge: relative residual " << rel << " after " << iterations
        << " iterations (tolerance " << settings.tolerance << ")";
    throw NumericalError(msg.str());
  }
  TangentialSolution sol = on_grid(r.local, scale_exponent);
  sol.iterations = iterations;
  sol.residual = rel;
  sol.factorisations = factorisations_ - factorisations_before;
  sol.linear_iterations = linear_iterations_ - linear_before;
  return sol;
}

}  // namespace rollnoise::contact
