// The element fields of the linear model (LinearContactModel::element_impulse_response): the
// traction and slip variations of every contact element, step by step, for a unit impulse of each
// input. What the wear transfer (wear_transfer.hpp) integrates; the forces of the other parts are
// dx dy U' of the same tractions (F~_k = L' pi_k + dx dy U' bN N~_k, reduced_form.cpp).

#include <algorithm>
#include <stdexcept>

#include "contact/halfspace_operator.hpp"
#include "nss/linear_model.hpp"
#include "nss/linear_model_parts.hpp"

namespace rollnoise::nss {

namespace {

// u = op(P) on the contact elements `el` (grid indices), column by column: P and u are 2 m x c
// (x and y of element a in rows 2a, 2a + 1); the rest of the grid carries no traction.
Eigen::MatrixXd apply_on_elements(const contact::HalfSpaceOperator& op, const std::vector<int>& el,
                                  int grid_size, const Eigen::MatrixXd& P) {
  const int N = grid_size;
  Eigen::MatrixXd u(P.rows(), P.cols());
  std::vector<double> b(2 * N), v(2 * N);
  for (Eigen::Index j = 0; j < P.cols(); ++j) {
    std::fill(b.begin(), b.end(), 0.0);
    for (std::size_t a = 0; a < el.size(); ++a)
      b[el[a]] = P(2 * a, j), b[N + el[a]] = P(2 * a + 1, j);
    op.apply(b.data(), v.data());
    for (std::size_t a = 0; a < el.size(); ++a)
      u(2 * a, j) = v[el[a]], u(2 * a + 1, j) = v[N + el[a]];
  }
  return u;
}

}  // namespace

int LinearContactModel::element_impulse_response(const FieldVisitor& visit, double tolerance,
                                                 int max_contact_lengths) const {
  if (route_ == Route::paper_form)
    throw std::domain_error(
        "element fields: the reduced form only (constant friction), not with falling friction");
  const StepSolver& red = step();
  const int m = static_cast<int>(el_.size()), n = 2 * m, N = table_.grid().size();
  const contact::HalfSpaceOperator A_op(table_, contact::Problem::Tangential, 0);
  // P~ = Pi pi: adhesion elements carry their two amplitudes, slip elements t_e pi_e
  // (linear_model.hpp).
  auto expand = [&](const Eigen::MatrixXd& pi) {
    Eigen::MatrixXd P(n, pi.cols());
    for (int a = 0; a < m; ++a)
      if (slip_[a])
        P.block(2 * a, 0, 2, pi.cols()) = t_[a] * pi.row(offset_[a]);
      else
        P.block(2 * a, 0, 2, pi.cols()) = pi.block(offset_[a], 0, 2, pi.cols());
    return P;
  };
  const int Lc = steps_per_contact_length_, max_steps = std::max(2, max_contact_lengths * Lc);
  Eigen::MatrixXd pi = Eigen::MatrixXd::Zero(r_, 4), P_prev = Eigen::MatrixXd::Zero(n, 4);
  double peak = 0.0;
  int quiet = 0;
  for (int k = 0; k < max_steps; ++k) {
    Eigen::MatrixXd rhs = red.apply_K1(pi);
    if (k == 0) {
      rhs.leftCols(3) += Wr_;
      if (block_ == 4) rhs.col(3) += rN0_;
    } else if (k == 1 && block_ == 4) {
      rhs.col(3) += rN1_;
    }
    pi = solve_step(red, rhs, pi);
    Eigen::MatrixXd P = expand(pi);
    if (k == 0 && block_ == 4) P.col(3) += bN_;
    Eigen::MatrixXd S =
        (apply_on_elements(A_op, el_, N, P) - apply_on_elements(*A0_op_, el_, N, P_prev)) / dt_;
    if (k == 0) S.leftCols(3) += W_;
    visit(k, P, S);
    const double size = P.norm();
    peak = std::max(peak, size);
    quiet = size <= tolerance * peak ? quiet + 1 : 0;
    if (k > 1 && quiet >= Lc) return k + 1;
    P_prev = std::move(P);
  }
  return max_steps;
}

}  // namespace rollnoise::nss
