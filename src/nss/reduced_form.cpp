// The step solvers of the reduced form (step_solver.hpp) built from the frozen patch: K0 assembled
// densely for the Cholesky step, the FFT operators and the preconditioner for the PCG step, and the
// recursion in time on either.
//
// Matrix-free path (solver.linear_model = "matrix_free", or "auto" above kDenseReducedUnknowns =
// 11000 reduced unknowns, where the dense factor passes ~1 GB). K0 x = D x + Pi' A (Pi x)/dt is one
// FFT convolution (contact::ElementOperator with the shift-0 kernel, like K1 with shift 1), and
// K0 solves are preconditioned CG (PcgStep) to a relative residual of 1e-12. Preconditioner:
// M^{-1} = W Pi' (C/dt + cbar I)^{-1} Pi W, C the zero-padded circulant of the compliance, inverted
// 2 x 2 per Fourier bin (HalfSpaceOperator::inverse_circulant; its eigenvalues floored at 0.1 of the
// self-compliance: the truncated kernel's circulant has a few slightly negative bins). W = 1 on
// adhesion unknowns and sqrt((kappa_e + cbar)/(kappa_e + c_e)) on slip unknowns (kappa_e =
// t_e' A_ee t_e/dt), so that the preconditioner's diagonal ~ 1/(kappa_e + cbar) becomes that of K0,
// 1/(kappa_e + c_e): where c_e dominates (deep slip, pn -> 0 at the edges) K0 is nearly diagonal and
// the full-space inverse would overweight those rows. cbar (preconditioner_shift) is the median c_e
// of the slip elements times the slip unknowns' share of r: 0 in full adhesion, where R C^{-1} R' >=
// (R C R')^{-1} (Schur complement) is the restricted hypersingular-like inverse with log-type growth
// only; the median in full sliding, where K0 has c_e ~30 kappa_e and C^{-1} alone (which grows like
// |k| in the Fourier bins) spreads a nearly diagonal spectrum instead of compressing it. The PCG
// iterations this gives, and the variants measured against it: docs/record/linear_model_sweep.md.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/element_operator.hpp"
#include "contact/halfspace_operator.hpp"
#include "core/assert.hpp"
#include "core/errors.hpp"
#include "nss/linear_model.hpp"
#include "nss/linear_model_parts.hpp"

namespace rollnoise::nss {

using contact::Component;

namespace {
// Matrix-free path (top of the file): PCG tolerance, floor of the circulant symbol's eigenvalues
// (relative to the largest), and the shift of the rolled start (elements in x).
constexpr double kPcgTolerance = 1e-12;
constexpr double kSymbolFloor = 0.1;
constexpr int kRollShift = 1;
}  // namespace

const StepSolver& LinearContactModel::step() const {
  std::call_once(built_->step_once, [this] {
    if (route_ == Route::reduced_matrix_free)
      built_->step = make_pcg_step();
    else
      built_->step = make_dense_step(threads_);
  });
  return *built_->step;
}

Eigen::MatrixXd LinearContactModel::solve_step(const StepSolver& step, const Eigen::MatrixXd& B,
                                               const Eigen::MatrixXd& previous) const {
  if (!step.uses_initial_guess()) return step.solve(B);
  const Eigen::MatrixXd guess = rolled(previous);  // N X is nearly X rolled on by one element
  return step.solve(B, &guess);
}

OperatorFactory LinearContactModel::operator_factory(bool matrix_free, double cbar) const {
  // The first set's K1 uses the model's A0 operator; every further set (another thread) builds its
  // own FFT operators (the kernel spectra again: a few FFTs of the padded grid, ~1 MB on 100 x 100).
  auto first = std::make_shared<bool>(true);
  return [this, matrix_free, cbar, first] {
    OperatorSet set;
    set.K1 = *first ? std::make_unique<contact::ElementOperator>(A0_op_, table_.grid(), el_, slip_, t_, dt_)
                    : reduced_operator(ReducedOperator::rolling_step);
    *first = false;
    if (matrix_free) {
      set.A = reduced_operator(ReducedOperator::compliance);
      set.G = reduced_operator(ReducedOperator::preconditioner, cbar);
    }
    return set;
  };
}

Eigen::MatrixXd LinearContactModel::assemble_K0() const {
  if (falling_)
    throw std::logic_error(
        "linear contact model: the reduced form K0 (Cholesky) does not hold falling friction (linear_model.hpp)");
  const contact::Grid& g = table_.grid();
  const int m = static_cast<int>(el_.size());
  Eigen::MatrixXd K0;
  // K0 = D + Pi' A Pi / dt: only the lower triangle (element a >= b) is written and read. The
  // block of elements (a, b) is Pi_a' A_ab Pi_b / dt with A_ab = [xx xy; xy yy](di, dj).
  K0.resize(r_, r_);
  for (int b = 0; b < m; ++b) {
    const int ixb = el_[b] % g.nx, iyb = el_[b] / g.nx, ob = offset_[b];
    const int nb = slip_[b] ? 1 : 2;
    for (int cb = 0; cb < nb; ++cb) {
      // column (ob + cb) of K0 = Pi' A (Pi e_{ob+cb}) / dt; traction direction of that column
      const Eigen::Vector2d pb = slip_[b] ? t_[b] : Eigen::Vector2d(cb == 0 ? 1.0 : 0.0, cb == 1 ? 1.0 : 0.0);
      double* col = K0.col(ob + cb).data();
      for (int a = b; a < m; ++a) {
        const int di = el_[a] % g.nx - ixb, dj = el_[a] / g.nx - iyb;
        const double xx = table_(Component::xx, di, dj), xy = table_(Component::xy, di, dj),
                     yy = table_(Component::yy, di, dj);
        const double ux = (xx * pb(0) + xy * pb(1)) / dt_, uy = (xy * pb(0) + yy * pb(1)) / dt_;
        const int oa = offset_[a];
        if (slip_[a]) {
          col[oa] = t_[a](0) * ux + t_[a](1) * uy;
        } else {
          col[oa] = ux;
          col[oa + 1] = uy;
        }
      }
    }
    if (slip_[b]) K0(ob, ob) += c_[b];
  }
  return K0;
}

std::unique_ptr<DenseCholeskyStep> LinearContactModel::make_dense_step(int threads) const {
  Eigen::MatrixXd K0 = assemble_K0();
  return std::make_unique<DenseCholeskyStep>(std::move(K0), operator_factory(false, 0.0), threads);
}

std::unique_ptr<PcgStep> LinearContactModel::make_pcg_step() const {
  // Preconditioner (top of the file): M^{-1} = W Pi' (C/dt + cbar I)^{-1} Pi W, cbar = 0 with
  // adhesion elements, else the median c_e.
  const double cbar = preconditioner_shift();
  Eigen::VectorXd w = Eigen::VectorXd::Ones(r_);
  const Eigen::Matrix2d self = (Eigen::Matrix2d() << table_(Component::xx, 0, 0), table_(Component::xy, 0, 0),
                                table_(Component::xy, 0, 0), table_(Component::yy, 0, 0))
                                   .finished() /
                               dt_;
  for (size_t a = 0; a < el_.size(); ++a)
    if (slip_[a]) {
      const double kappa = t_[a].dot(self * t_[a]);
      w(offset_[a]) = std::sqrt((kappa + cbar) / (kappa + c_[a]));
    }
  return std::make_unique<PcgStep>(step_matrix_slip_diagonal(), std::move(w), kPcgTolerance,
                                   operator_factory(true, cbar), threads_);
}

double LinearContactModel::preconditioner_shift() const {
  // The median c_e of the slip elements weighted by the slip unknowns' share of r ("Matrix-free
  // path" at the top of the file): 0 in full adhesion, the median in full sliding.
  if (n_slip_ == 0) return 0.0;
  std::vector<double> c;
  for (size_t a = 0; a < el_.size(); ++a)
    if (slip_[a]) c.push_back(c_[a]);
  std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
  return double(n_slip_) / double(r_) * c[c.size() / 2];
}

std::unique_ptr<contact::ElementOperator> LinearContactModel::reduced_operator(ReducedOperator which,
                                                                              double cbar) const {
  const contact::Grid& g = table_.grid();
  auto on_elements = [&](contact::HalfSpaceOperator op, double divisor) {
    return std::make_unique<contact::ElementOperator>(std::make_shared<const contact::HalfSpaceOperator>(std::move(op)),
                                                      g, el_, slip_, t_, divisor);
  };
  switch (which) {
    case ReducedOperator::rolling_step:
      return on_elements(contact::HalfSpaceOperator(table_, contact::Problem::Tangential, 1), dt_);
    case ReducedOperator::compliance:
      return on_elements(contact::HalfSpaceOperator(table_, contact::Problem::Tangential, 0), dt_);
    case ReducedOperator::preconditioner:
      return on_elements(contact::HalfSpaceOperator::inverse_circulant(table_, kSymbolFloor, cbar * dt_), 1.0 / dt_);
  }
  ROLLNOISE_ASSERT(false, "reduced_operator: unknown operator");
  return nullptr;
}

Eigen::MatrixXd LinearContactModel::rolled(const Eigen::MatrixXd& X) const {
  // Element a takes the traction of the element kRollShift columns upstream (zero if that is not
  // a contact element), projected on its own unknowns: Pi_a' Pi_b x_b.
  const contact::Grid& g = table_.grid();
  std::vector<int> position(g.size(), -1);
  for (size_t a = 0; a < el_.size(); ++a) position[el_[a]] = static_cast<int>(a);
  Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(X.rows(), X.cols());
  for (size_t a = 0; a < el_.size(); ++a) {
    const int ix = el_[a] % g.nx - kRollShift;
    if (ix < 0 || ix >= g.nx) continue;
    const int b = position[el_[a] + (ix - el_[a] % g.nx)];
    if (b < 0) continue;
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
      const Eigen::Vector2d p = slip_[b] ? Eigen::Vector2d(t_[b] * X(offset_[b], j))
                                         : Eigen::Vector2d(X.block<2, 1>(offset_[b], j));
      if (slip_[a])
        Y(offset_[a], j) = t_[a].dot(p);
      else
        Y.block<2, 1>(offset_[a], j) = p;
    }
  }
  return Y;
}

long LinearContactModel::inner_solves() const {
  return route_ == Route::reduced_matrix_free ? step().solves() : 0L;
}
long LinearContactModel::inner_iterations() const {
  return route_ == Route::reduced_matrix_free ? step().iterations() : 0L;
}

Eigen::MatrixXd LinearContactModel::step_matrix_cholesky_factor() const {
  if (route_ == Route::reduced_dense) return static_cast<const DenseCholeskyStep&>(step()).factor();
  return make_dense_step(1)->factor();
}

double LinearContactModel::step_matrix_rcond() const {
  if (route_ == Route::reduced_dense) return static_cast<const DenseCholeskyStep&>(step()).rcond();
  return make_dense_step(1)->rcond();
}

Eigen::VectorXd LinearContactModel::step_matrix_slip_diagonal() const {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(r_);
  for (size_t a = 0; a < el_.size(); ++a)
    if (slip_[a]) d(offset_[a]) = c_[a];
  return d;
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response(const std::vector<Eigen::Vector3d>& xi) const {
  return time_response(xi, std::vector<double>(xi.size(), 0.0));
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response(const std::vector<Eigen::Vector3d>& xi,
                                                               const std::vector<double>& dN) const {
  // K0 pi_k = K1 pi_{k-1} - Pi' W xi_k + rN0 N~_k + rN1 N~_{k-1} (the reduced form of M0 Q_k =
  // M1 Q_{k-1} + W xi_k + (A bN N~_k - A0 bN N~_{k-1})/dt, G2), F_k = dx dy U' (Pi pi_k + bN N~_k).
  ROLLNOISE_ASSERT(dN.size() == xi.size(), "time_response: the normal-load and creepage histories differ in length");
  if (falling_) return time_response_dense(xi, dN);
  const StepSolver& red = step();
  std::vector<Eigen::Vector3d> F;
  F.reserve(xi.size());
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(r_, 1);
  double previous = 0.0;
  for (size_t k = 0; k < xi.size(); ++k) {
    Eigen::MatrixXd rhs = red.apply_K1(p) + Wr_ * xi[k];
    if (block_ == 4) rhs += rN0_ * dN[k] + rN1_ * previous;
    p = solve_step(red, rhs, p);
    F.push_back(Lr_.transpose() * p + dN_ * dN[k]);
    previous = dN[k];
  }
  return F;
}

}  // namespace rollnoise::nss
