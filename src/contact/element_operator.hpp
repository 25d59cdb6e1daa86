// A grid operator restricted to the contact elements: y = Pi' G (Pi x) / divisor.
//
// G is a HalfSpaceOperator on the whole grid (tangential structure: (u_x, u_y) from (p_x, p_y),
// component-major grid fields). Pi expands the unknowns of the contact elements to tractions on
// the grid (zero outside the elements) and Pi' projects the grid result back. Per element either
//   free:      two unknowns, the traction (p_x, p_y) itself (Pi_e = I);
//   directed:  one unknown, the amplitude pi_e of a traction along the unit vector t_e (Pi_e = t_e).
// Uses:
//   - the slip operator S of the Newton solver on the contact elements (coulomb_newton.hpp: every
//     element free, divisor 1; s = S q, paper Eqs. 2-3);
//   - the rolling step K1 = Pi' A0 Pi / dt of the linear model (nss/linear_model.hpp: adhesion
//     elements free, slip elements directed along t_e, divisor dt; paper Eq. 11 reduced).
// The unknowns are ordered element by element, in the order of `elements`; a free element's two
// unknowns are adjacent (x, then y).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "contact/halfspace_operator.hpp"

namespace rollnoise::contact {

class ElementOperator {
 public:
  /// Every element free (two unknowns each), y = Pi' G Pi x / divisor.
  ElementOperator(std::shared_ptr<const HalfSpaceOperator> grid_operator, const Grid& grid,
                  std::vector<int> elements, double divisor = 1.0);
  /// Elements with directed[a] != 0 carry one unknown along direction[a] (a unit vector); the
  /// others are free. `direction` may be empty when no element is directed.
  ElementOperator(std::shared_ptr<const HalfSpaceOperator> grid_operator, const Grid& grid,
                  std::vector<int> elements, std::vector<char> directed,
                  std::vector<Eigen::Vector2d> direction, double divisor);

  /// Number of unknowns (of x and y).
  int size() const { return size_; }
  const std::vector<int>& elements() const { return elements_; }
  /// y = Pi' G Pi x / divisor; x and y hold size() values and may not alias.
  void apply(const double* x, double* y) const;
  /// The same, column by column (X and Y: size() rows, as many columns).
  void apply(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::MatrixXd> Y) const;
  Eigen::MatrixXd operator*(const Eigen::Ref<const Eigen::MatrixXd>& X) const;

 private:
  std::shared_ptr<const HalfSpaceOperator> op_;
  int grid_size_ = 0;
  std::vector<int> elements_;
  std::vector<char> directed_;
  std::vector<Eigen::Vector2d> t_;
  std::vector<int> offset_;  // first unknown of each element
  double divisor_ = 1.0;
  int size_ = 0;
  // Grid work arrays (component-major): zero outside the elements, which are always the same.
  mutable std::vector<double> p_, u_;
};

}  // namespace rollnoise::contact
