// The tangential problem  s = rhs + S p  with Coulomb's law at the contact elements, solved by a
// semismooth Newton method on the element-wise Coulomb fixed point (used for steady rolling, paper
// Eq. 3, and for each step of transient rolling, paper Eq. 2).
//
// Let Pi_I(p) be the exact solution of Coulomb's law at element I with all other tractions fixed
// (coulomb.hpp: the Gauss-Seidel element step). The solution is the root of R(p) = p - Pi(p). R is
// piecewise smooth; its Jacobian is  I - dPi/db (S - D)  with dPi/db = -D^{-1} in adhesion and the
// tangential projection of coulomb.hpp in slip, so every Newton step re-decides adhesion and slip
// for every element (Kalker's TANG with Newton on the slip set, without separate set updates).
// Globalisation: the Newton point is projected onto the traction bounds |p_I| <= mu pn_I and
// accepted if it reduces |R|_2, else backtracking. Once the adhesion/slip split is settled R is
// affine, so R is driven to round-off and the split is that of the exact discrete solution.
//
// Linear algebra (profiled on the paper's 68x50 grid, 2096 contact elements, n = 4192 unknowns:
// before, dense products with S and J and double LU factors took 26 %, 30 % and 25 % of the time).
//   - Products with S are block-Toeplitz convolutions on the grid (HalfSpaceOperator, FFT), so the
//     residual and the Jacobian action  J v = v - dPi/db ((S v) - D v)  cost O(N log N); only the
//     O(N) table of S is kept, and J is assembled only to be factorised.
//   - Newton steps are solved by GMRES (right-preconditioned), inexactly: the linear residual is
//     at most 1e-2 |R|, and not below 1e-3 |R| without a preconditioner (then Newton converges by
//     ~1e-3 per step instead of quadratically, which costs fewer GMRES iterations in all).
//   - Without a preconditioner GMRES is restarted every 150 iterations within a budget of n/4
//     (8 for n <= 2000, whose factors stay in cache; see unpreconditioned_budget in the .cpp for
//     the measurements). Only when that fails is J assembled in single precision and LU-factorised
//     (mixed precision: the float factors precondition, GMRES in double restores full accuracy);
//     if float factors fail (cond(J) near 1/eps_float), double ones are used from then on. The
//     factors are kept between Newton steps and between calls (time steps), and renewed when
//     preconditioned GMRES needs more than 30 iterations.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "contact/coulomb.hpp"
#include "contact/element_operator.hpp"
#include "contact/halfspace_operator.hpp"
#include "contact/slip_operator.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

/// LU factors of the Newton system J (float, or double where float ones failed to precondition),
/// made for the contact elements `elements`: GMRES's preconditioner between the solves of one
/// solver, and the first one of another solver of the same elements (a nearby state on the same
/// grid: CoulombNewton::precondition_with). The solution does not depend on them, only GMRES's
/// iterations do.
struct NewtonFactors {
  std::vector<int> elements;
  Eigen::PartialPivLU<Eigen::MatrixXf> lu_float;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_double;
  bool double_precision = false;
  Eigen::VectorXd solve(const Eigen::VectorXd& v) const;
};

class CoulombNewton {
 public:
  /// `elements`: flat grid indices of the contact elements; `bound`: mu pn on the grid.
  CoulombNewton(const SlipOperator& S, std::vector<int> elements, const GridField& bound);
  CoulombNewton(const CoulombNewton&) = delete;  // the grid operator's work arrays are not shared
  CoulombNewton& operator=(const CoulombNewton&) = delete;
  CoulombNewton(CoulombNewton&&) = default;
  CoulombNewton& operator=(CoulombNewton&&) = default;

  /// New traction bounds (a varying normal load, transient_rolling.hpp): `elements` as in the
  /// constructor, `bound` mu pn on the grid, which may be 0 at some of the elements (these carry no
  /// traction and are output as exterior). The factors are kept (as a preconditioner) if the
  /// elements are the same, else dropped.
  void set_bounds(std::vector<int> elements, const GridField& bound);

  /// Falling friction (friction_law.hpp): `bound` stays mu_s pn (the adhesion limit) and the slip
  /// traction is bound * ratio(|s|). solve() throws InputError naming friction.decay when the
  /// element law is not unique (d_max bound_max (1 - A) B >= 1, coulomb.hpp), and NumericalError
  /// naming it when the line search stalls (a non-unique or non-existent global solution).
  void set_falling_friction(const FallingFriction& falling) { falling_ = falling; }

  /// Solve with the rigid-slip-like right-hand side (grid fields) from the start tractions
  /// (grid fields; projected onto the bounds). Throws NumericalError naming `solver`.
  TangentialSolution solve(const GridField& rhs_x, const GridField& rhs_y, const GridField& px,
                           const GridField& py, const TangentialSolverSettings& settings,
                           const std::string& solver);

  /// The factors held (null before the first factorisation).
  std::shared_ptr<const NewtonFactors> factors() const { return factors_; }
  /// Another solver's factors as the preconditioner, if they were made for these elements.
  void precondition_with(std::shared_ptr<const NewtonFactors> factors);

  /// Work counters since construction (for benchmarks and tests).
  int factorisations() const { return factorisations_; }
  int linear_iterations() const { return linear_iterations_; }
  bool double_precision_factors() const { return double_factors_; }

 private:
  /// s = S q on the contact elements (q, s interleaved x, y per element), by FFT on the grid.
  void check_falling_uniqueness() const;
  void apply_S(const Eigen::VectorXd& q, Eigen::VectorXd& s) const;
  /// The contact-element operator of S on elements_.
  ElementOperator element_operator() const;
  /// Assemble J = I - dPi/db (S - D) densely and factorise it (float, or double if needed).
  void factorise(const std::vector<ElementTraction>& local);
  Eigen::VectorXd precondition(const Eigen::VectorXd& v) const;
  /// The steps of solve: R(q) = q - Pi(q) with the element solutions, for the right-hand side w and
  /// the bounds (both as scaled for the solve); the Newton direction J dp = -R (GMRES, factors
  /// renewed on failure); the tractions and slip on the grid, unscaled by 2^-scale_exponent.
  struct FixedPointResidual;
  FixedPointResidual residual(const Eigen::VectorXd& q, const Eigen::VectorXd& w,
                              const std::vector<double>& bound) const;
  Eigen::VectorXd newton_direction(const FixedPointResidual& r, double relative_residual, const std::string& solver);
  TangentialSolution on_grid(const std::vector<ElementTraction>& local, int scale_exponent) const;

  Grid grid_;
  SlipOperator S_;
  std::shared_ptr<const HalfSpaceOperator> product_;  // S on the grid
  std::vector<int> elements_;
  ElementOperator S_elements_;  // S on the contact elements (every element free)
  std::vector<double> bound_;
  FallingFriction falling_;
  double d1_ = 0.0, d2_ = 0.0;
  std::shared_ptr<const NewtonFactors> factors_;
  bool double_factors_ = false;  // factorise in double precision from now on
  int factorisations_ = 0, linear_iterations_ = 0;
};

}  // namespace rollnoise::contact
