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
  // the creepage columns [-Pi' W, 0, 0, W] and the load's [rN0, rN1, bN, 0] (header)
  const int n = static_cast<int>(W_.rows());
  TractionInput in{Eigen::MatrixXd::Zero(n, 4), Eigen::MatrixXd(), Eigen::MatrixXd(),
                   Eigen::MatrixXd::Zero(r_, 4), Eigen::MatrixXd::Zero(r_, 4)};
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, 4);
  in.r0.leftCols(3) = Wr_;
  w.leftCols(3) = W_;
  if (block_ == 4) in.r0.col(3) = rN0_, in.r1.col(3) = rN1_, in.b.col(3) = bN_;
  return impulse_response(in, w, visit, tolerance, max_contact_lengths);
}

int LinearContactModel::element_pressure_response(const std::vector<contact::GridField>& patterns,
                                                  const FieldVisitor& visit, double tolerance,
                                                  int max_contact_lengths) const {
  if (route_ == Route::paper_form)
    throw std::domain_error(
        "element fields: the reduced form only (constant friction), not with falling friction");
  // (G1) with dpn in place of (dpn/dN) N~: b_e = -mu dpn_e s_e/|s_e| on the slip elements, where
  // s/|s| = (-t_2, t_1) (t = (s_2, -s_1)/|s|, linear_model.hpp)
  const int N = table_.grid().size(), c = static_cast<int>(patterns.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * N, c);
  for (int j = 0; j < c; ++j)
    for (std::size_t a = 0; a < el_.size(); ++a) {
      if (!slip_[a]) continue;
      const int k = el_[a];
      B(k, j) = mu_ * patterns[j][k] * t_[a](1);
      B(N + k, j) = -mu_ * patterns[j][k] * t_[a](0);
    }
  const TractionInput in = traction_input(B);
  return impulse_response(in, Eigen::MatrixXd::Zero(in.b.rows(), c), visit, tolerance,
                          max_contact_lengths);
}

int LinearContactModel::impulse_response(const TractionInput& in, const Eigen::MatrixXd& w,
                                         const FieldVisitor& visit, double tolerance,
                                         int max_contact_lengths) const {
  const StepSolver& red = step();
  const int m = static_cast<int>(el_.size()), n = 2 * m, N = table_.grid().size();
  const int c = static_cast<int>(w.cols());
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
  Eigen::MatrixXd pi = Eigen::MatrixXd::Zero(r_, c), P_prev = Eigen::MatrixXd::Zero(n, c);
  double peak = 0.0;
  int quiet = 0;
  for (int k = 0; k < max_steps; ++k) {
    Eigen::MatrixXd rhs = red.apply_K1(pi);
    if (k == 0) rhs += in.r0;
    if (k == 1) rhs += in.r1;
    pi = solve_step(red, rhs, pi);
    Eigen::MatrixXd P = expand(pi);
    if (k == 0 && in.b.size() > 0) P += in.b;
    Eigen::MatrixXd S =
        (apply_on_elements(A_op, el_, N, P) - apply_on_elements(*A0_op_, el_, N, P_prev)) / dt_;
    if (k == 0) S += w;
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
