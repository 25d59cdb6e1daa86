// The linear model on the frozen patch: the element data of the scaled formulation (linear_model.hpp),
// its inputs W and outputs L, the normal-load input (G1-G2), and the route the model solves by.
// The other parts: paper_form.cpp (M0 - z M1: direct solves, the Hessenberg form), reduced_form.cpp
// (the step solvers of K0 - z K1), markov_sweep.cpp (the block Krylov and exact Markov parameters),
// transfer.cpp (f and g at real and complex frequency).

#include "nss/linear_model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "contact/element_operator.hpp"
#include "contact/halfspace_operator.hpp"
#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "nss/linear_model_parts.hpp"

namespace rollnoise::nss {

using contact::Component;
using contact::ElementState;


LinearContactModel::LinearContactModel(const contact::ContactPatch& patch,
                                       const contact::TangentialSolution& mean,
                                       const LinearModelInput& in)
    : dt_(patch.grid.dx / in.speed), speed_(in.speed), mu_(in.mu), solver_(in.solver), sampling_(in.sampling),
      table_(patch.influence), built_(std::make_unique<Built>()) {
  contact::check_rolling_input(in.mu, in.speed, contact::Creepage{});
  if (in.threads < 0 || in.threads > kMaxThreads)
    throw InputError("solver.threads", "must be 0 (one per hardware thread) to " + std::to_string(kMaxThreads) +
                                           ", not " + std::to_string(in.threads));
  threads_ = resolved_threads(in.threads, kMaxThreads);
  const contact::Grid& g = patch.grid;
  el_ = contact::sweep_order(g, patch.normal.pn);
  const std::vector<double> mu_bar = freeze_elements(patch, mean, in);
  set_inputs_and_outputs(g, in);
  // A0 by FFT (shift 1): the rolling step of the sweeps (K1) and the delayed load input below.
  A0_op_ = std::make_shared<const contact::HalfSpaceOperator>(table_, contact::Problem::Tangential, 1);
  set_normal_load_input(patch, mean, mu_bar);

  // steps per contact length: the extent of the contact area in x, in elements
  int ix_min = g.nx, ix_max = -1;
  for (int k : el_) ix_min = std::min(ix_min, k % g.nx), ix_max = std::max(ix_max, k % g.nx);
  steps_per_contact_length_ = std::max(1, ix_max - ix_min + 1);

  // The route, once: falling friction needs the paper form (header); else K0 is factored densely
  // up to kDenseReducedUnknowns reduced unknowns (automatic) or solved by PCG.
  if (falling_)
    route_ = Route::paper_form;
  else
    route_ = uses_matrix_free(solver_, r_) ? Route::reduced_matrix_free : Route::reduced_dense;
}

std::vector<double> LinearContactModel::freeze_elements(const contact::ContactPatch& patch,
                                                        const contact::TangentialSolution& mean,
                                                        const LinearModelInput& in) {
  const contact::InfluenceTable& A = patch.influence;
  const int m = static_cast<int>(el_.size());
  // Element data (scaled formulation, see the header): t_e and c_e for slip elements; c_e is
  // floored at 1e-12 times the self-compliance A_ee/dt so that the pencil stays regular.
  const double self = std::max(A(Component::xx, 0, 0), A(Component::yy, 0, 0)) / dt_;
  offset_.resize(m);
  t_.assign(m, Eigen::Vector2d::Zero());
  c_.assign(m, 0.0);
  kappa_.assign(m, 0.0);
  contact::check_falling_friction(in.falling);
  const contact::FrictionLaw law{in.mu, in.falling};
  std::vector<double> mu_bar(m, in.mu);  // mu(|s_bar|) at the slip elements
  slip_.assign(m, 0);
  for (int a = 0; a < m; ++a) {
    const int k = el_[a];
    offset_[a] = r_;
    if (mean.state[k] == static_cast<std::int8_t>(ElementState::slip)) {
      const double s1 = mean.sx[k], s2 = mean.sy[k], s = std::hypot(s1, s2);
      t_[a] = Eigen::Vector2d(s2 / s, -s1 / s);
      mu_bar[a] = law.mu(s);  // in.mu itself for constant friction
      c_[a] = std::max(s / (mu_bar[a] * patch.normal.pn[k]), 1e-12 * self);
      // radial term of K_e (header): kappa = mu'(|s|) |s| / mu(|s|)
      if (in.falling.active()) kappa_[a] = law.slope(s) * s / mu_bar[a];
      if (kappa_[a] != 0.0) falling_ = true;
      slip_[a] = 1;
      ++n_slip_;
      r_ += 1;
    } else {
      ++n_adhesion_;
      r_ += 2;
    }
  }
  return mu_bar;
}

void LinearContactModel::set_inputs_and_outputs(const contact::Grid& g, const LinearModelInput& in) {
  const int m = static_cast<int>(el_.size()), n = 2 * m;
  // Inputs W (per unit creepage) and outputs L in the paper's form; -Pi' W and dx dy Pi' U reduced.
  W_.setZero(n, 3);
  L_.setZero(n, 3);
  Wr_.setZero(r_, 3);
  Lr_.setZero(r_, 3);
  const double area = g.element_area();
  for (int a = 0; a < m; ++a) {
    const double x = g.x(el_[a] % g.nx), y = g.y(el_[a] / g.nx);
    W_(2 * a, 0) = in.speed;
    W_(2 * a + 1, 1) = in.speed;
    W_(2 * a, 2) = -in.speed * y;
    W_(2 * a + 1, 2) = in.speed * (x + in.spin_offset * g.dx);
    Eigen::Matrix<double, 2, 3> U;  // U1, U2, Usp0 at this element
    U << 1, 0, -y, 0, 1, x;
    if (slip_[a]) {
      const Eigen::Matrix2d B = slip_traction_matrix(a);
      L_.block<2, 3>(2 * a, 0) = area * B.transpose() * U;
      Wr_.row(offset_[a]) = -t_[a].transpose() * W_.block<2, 3>(2 * a, 0);
      Lr_.row(offset_[a]) = area * t_[a].transpose() * U;
    } else {
      L_.block<2, 3>(2 * a, 0) = area * U;
      Wr_.block<2, 3>(offset_[a], 0) = -W_.block<2, 3>(2 * a, 0);
      Lr_.block<2, 3>(offset_[a], 0) = area * U;
    }
  }
}

void LinearContactModel::set_normal_load_input(const contact::ContactPatch& patch,
                                               const contact::TangentialSolution& mean,
                                               const std::vector<double>& mu_bar) {
  const contact::Grid& g = patch.grid;
  const contact::InfluenceTable& A = patch.influence;
  const int m = static_cast<int>(el_.size()), n = 2 * m;
  const double area = g.element_area();
  // Normal-load input (G1): bN on the slip elements from the frozen-area sensitivity dpn/dN, then
  // A bN/dt and A0 bN/dt on the grid (two FFT products) and their reduced forms.
  if (n_slip_ > 0) {
    const contact::HalfSpaceOperator normal_op(A, contact::Problem::Normal);
    const contact::NormalLoadSensitivity sens =
        contact::normal_load_sensitivity(g, normal_op, patch.normal);
    const int N = g.size();
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * N, 1);
    for (int a = 0; a < m; ++a) {
      if (!slip_[a]) continue;
      const int k = el_[a];
      const double s = std::hypot(mean.sx[k], mean.sy[k]);
      B(k, 0) = -mu_bar[a] * sens.dpn_dN[k] * mean.sx[k] / s;
      B(N + k, 0) = -mu_bar[a] * sens.dpn_dN[k] * mean.sy[k] / s;
      const double x = g.x(k % g.nx), y = g.y(k / g.nx);
      dN_ += area * Eigen::Vector3d(B(k, 0), B(N + k, 0), x * B(N + k, 0) - y * B(k, 0));
    }
    const TractionInput in = traction_input(B);
    bN_ = in.b.col(0);
    wN0_ = in.w0.col(0);
    wN1_ = in.w1.col(0);
    rN0_ = in.r0.col(0);
    rN1_ = in.r1.col(0);
    block_ = 4;
  } else {
    bN_.setZero(n);
    wN0_.setZero(n);
    wN1_.setZero(n);
    rN0_.setZero(r_);
    rN1_.setZero(r_);
  }
}

LinearContactModel::TractionInput LinearContactModel::traction_input(
    const Eigen::MatrixXd& B) const {
  // A b/dt and A0 b/dt on the grid (two FFT products per column) and their reduced forms (G2)
  const int m = static_cast<int>(el_.size()), n = 2 * m, N = table_.grid().size();
  const int c = static_cast<int>(B.cols());
  const contact::HalfSpaceOperator A_op(table_, contact::Problem::Tangential, 0);
  TractionInput in{Eigen::MatrixXd(n, c), Eigen::MatrixXd(n, c), Eigen::MatrixXd(n, c),
                   Eigen::MatrixXd::Zero(r_, c), Eigen::MatrixXd::Zero(r_, c)};
  std::vector<double> b(2 * N), u0(2 * N), u1(2 * N);
  for (int j = 0; j < c; ++j) {
    Eigen::Map<Eigen::VectorXd>(b.data(), 2 * N) = B.col(j);
    A_op.apply(b.data(), u0.data());
    A0_op_->apply(b.data(), u1.data());
    for (int a = 0; a < m; ++a) {
      const int k = el_[a];
      const Eigen::Vector2d v0(u0[k] / dt_, u0[N + k] / dt_), v1(u1[k] / dt_, u1[N + k] / dt_);
      in.b.block<2, 1>(2 * a, j) << b[k], b[N + k];
      in.w0.block<2, 1>(2 * a, j) = v0;
      in.w1.block<2, 1>(2 * a, j) = v1;
      if (slip_[a]) {
        in.r0(offset_[a], j) = -t_[a].dot(v0);
        in.r1(offset_[a], j) = t_[a].dot(v1);
      } else {
        in.r0.block<2, 1>(offset_[a], j) = -v0;
        in.r1.block<2, 1>(offset_[a], j) = v1;
      }
    }
  }
  return in;
}

LinearContactModel::~LinearContactModel() = default;
LinearContactModel::LinearContactModel(LinearContactModel&&) noexcept = default;
LinearContactModel& LinearContactModel::operator=(LinearContactModel&&) noexcept = default;

Eigen::Matrix2d LinearContactModel::slip_traction_matrix(int a) const {
  // B_e = -t t' - kappa s^ s^' (header, "Falling friction"); s^ = (-t2, t1) as t = (s2, -s1)/|s|
  Eigen::Matrix2d B = -t_[a] * t_[a].transpose();
  if (kappa_[a] != 0.0) {
    const Eigen::Vector2d sh(-t_[a](1), t_[a](0));
    B -= kappa_[a] * sh * sh.transpose();
  }
  return B;
}

double linear_model_bytes(LinearSolver solver, int r, int grid_elements, int Lc) {
  const double p = 4.0, d = 1.5 * p * std::min(10 * Lc, 2 * Lc + 2);  // the largest Krylov basis
  const double basis = 8.0 * r * d, projection = 3 * 8.0 * d * d;     // V; H and its copies
  // FFT operators (A, A0, C^{-1}, the normal one): zero-padded grid of ~4 N values, a few real and
  // complex arrays each (kernel spectra 4 per tangential operator).
  const double fft = 4 * 12 * 16.0 * 4.0 * grid_elements;
  if (!uses_matrix_free(solver, r)) return 8.0 * r * r + 2 * basis + projection + fft;
  return (lean_krylov_basis(r, int(d / 1.5)) ? basis : 2 * basis) + projection + fft + 64.0 * r;
}

bool uses_matrix_free(LinearSolver solver, int reduced_unknowns) {
  if (solver == LinearSolver::automatic) return reduced_unknowns > kDenseReducedUnknowns;
  return solver == LinearSolver::matrix_free;
}

void LinearContactModel::check_frequency(double f) const {
  if (!std::isfinite(f) || f < 0.0) {
    std::ostringstream msg;
    msg << "frequency " << f << " Hz: must be finite and non-negative";
    throw InputError("frequency", msg.str());
  }
  if (f > nyquist_frequency() * (1 + 1e-12)) {
    std::ostringstream msg;
    msg << "frequency " << f << " Hz is above the grid's Nyquist limit V/(2 dx) = "
        << nyquist_frequency() << " Hz: refine the grid in x (grid.nx) or lower the frequency";
    throw InputError("frequency", msg.str());
  }
}

}  // namespace rollnoise::nss
