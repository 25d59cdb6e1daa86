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
// accepted if it reduces |R|_2, else backtracking. Near the solution the convergence is quadratic,
// so R is driven to round-off and the adhesion/slip split is that of the exact discrete solution.
//
// Linear algebra: S is assembled densely on the contact elements (2 unknowns each, interleaved x, y).
// The Newton systems are solved by GMRES preconditioned with the LU factors of an earlier Jacobian,
// refactorised only when GMRES needs many iterations; the factors are kept between calls, so a
// sequence of related problems (time steps, sweep points) mostly costs O(n^2) per Newton step.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "contact/slip_operator.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

class CoulombNewton {
 public:
  /// `elements`: flat grid indices of the contact elements; `bound`: mu pn on the grid.
  CoulombNewton(const SlipOperator& S, std::vector<int> elements, const GridField& bound);

  /// Solve with the rigid-slip-like right-hand side (grid fields) from the start tractions
  /// (grid fields; projected onto the bounds). Throws NumericalError naming `solver`.
  TangentialSolution solve(const GridField& rhs_x, const GridField& rhs_y, const GridField& px,
                           const GridField& py, const TangentialSolverSettings& settings,
                           const std::string& solver);

  /// Number of LU factorisations so far (for benchmarks).
  int factorisations() const { return factorisations_; }

 private:
  Grid grid_;
  std::vector<int> elements_;
  std::vector<double> bound_;
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMatrix S_, J_;  // row-major: the Jacobian is assembled row block by row block
  double d1_ = 0.0, d2_ = 0.0;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // column-major copy inside
  bool have_lu_ = false;
  int factorisations_ = 0;
};

}  // namespace rollnoise::contact
