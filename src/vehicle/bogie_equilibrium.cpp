#include "vehicle/bogie_equilibrium.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "vehicle/cant.hpp"

namespace rollnoise::noise {
namespace {

// The lowering's fixed point settled to 1e-9 (VerticalLoadInput::settle) while solving: the forces
// are differenced over steps of 1e-7 m and balanced to 1e-6 Q.
constexpr double kSettle = 1e-9;
// On the way (AxleQuery::coarse): forces to about 1e-6 Q, differenced over 1e-6 m, balanced to
// 1e-2 Q.
constexpr double kSettleCoarse = 1e-6;
constexpr double kCoarseStep = 10.0;
// Newton iterations of a continuation step: one that has not led the way by then is halved.
constexpr int kStepIterations = 6;
// Newton iterations on the kept grids (the last digits): 2 to 7 where they serve.
constexpr int kKeptIterations = 10;
// Newton iterations from a guess at the curve (BogieEquilibriumInput::guess) before the
// continuation takes over.
constexpr int kGuessIterations = 12;

using Vector = Eigen::Matrix<double, 8, 1>;
using Matrix = Eigen::Matrix<double, 8, 8>;

// Indices in q and in (B2): axle i's y, psi, eps at 3i, 3i + 1, 3i + 2; the frame's at 6, 7.
constexpr int kFrame = 6;

// The bogie's constants of (B1), (B2) at the full curve (t = 1).
struct Bogie {
  double a = 0.0;         // half wheelbase (m)
  double kappa = 0.0;     // 1/R (1/m)
  double K_y = 0.0;       // lateral primary stiffness per wheelset (N/m)
  double K_psi = 0.0;     // primary yaw stiffness per wheelset (N m/rad)
  double K_s = 0.0;       // secondary yaw stiffness (N m/rad)
  double body_yaw = 0.0;  // s L kappa: the car body's yaw relative to the bogie's tangent (rad)
  double m_w = 0.0, m_frame = 0.0;  // wheelset mass, frame + half the car body (kg)
  double a_u = 0.0;                 // unbalanced lateral acceleration (m/s^2)
  double x(int i) const { return i == 0 ? a : -a; }
};

Bogie bogie_constants(const BogieEquilibriumInput& in) {
  const VehicleParameters& v = in.vehicle;
  Bogie b;
  b.a = 0.5 * in.curve.wheelbase;
  b.kappa = std::isinf(in.curve.radius) ? 0.0 : 1.0 / in.curve.radius;
  b.K_y = 2.0 * v.primary_lateral_stiffness;
  b.K_psi = v.primary_yaw_stiffness();
  b.K_s = v.secondary_yaw_stiffness;
  b.body_yaw = (v.rear_bogie ? -1.0 : 1.0) * 0.5 * v.bogie_centre_distance * b.kappa;
  b.m_w = v.wheelset_mass;
  const double body = v.carbody_mass > 0.0
                          ? v.carbody_mass
                          : std::max(0.0, 8.0 * in.curve.wheel_load / kGravity -
                                              2.0 * v.frame_mass - 4.0 * v.wheelset_mass);
  b.m_frame = v.frame_mass + 0.5 * body;
  // a_u = g h_d / s: the cant deficiency's unbalanced acceleration (EN 13803, vehicle/cant.hpp)
  b.a_u = kGravity * in.curve.cant_deficiency / kRailHeadDistance;
  return b;
}

// The suspension's and the masses' part of (B2) at continuation t (the contacts' added by the
// caller).
Vector suspension_residual(const Bogie& b, const Vector& q, double t) {
  const double kappa = t * b.kappa, a_u = t * b.a_u;
  Vector r = Vector::Zero();
  double frame_lat = b.m_frame * a_u, frame_yaw = -b.K_s * (q(kFrame + 1) - t * b.body_yaw);
  for (int i = 0; i < 2; ++i) {
    const double x = b.x(i);
    const double d = q(3 * i) - q(kFrame) - x * q(kFrame + 1) - 0.5 * x * x * kappa;  // (B1)
    const double e = q(3 * i + 1) - q(kFrame + 1) - x * kappa;
    r(3 * i) = -b.K_y * d + b.m_w * a_u;
    r(3 * i + 1) = -b.K_psi * e;
    frame_lat += b.K_y * d;
    frame_yaw += b.K_psi * e + x * b.K_y * d;
  }
  r(kFrame) = frame_lat;
  r(kFrame + 1) = frame_yaw;
  return r;
}

// d(suspension residual)/dq: constant.
Matrix suspension_jacobian(const Bogie& b) {
  Matrix J = Matrix::Zero();
  const int yb = kFrame, pb = kFrame + 1;
  for (int i = 0; i < 2; ++i) {
    const double x = b.x(i);
    const int y = 3 * i, p = 3 * i + 1;
    // d_i = y_i - yb - x psib (+ const); e_i = psi_i - psib (+ const)
    J(y, y) = -b.K_y, J(y, yb) = b.K_y, J(y, pb) = b.K_y * x;
    J(p, p) = -b.K_psi, J(p, pb) = b.K_psi;
    J(yb, y) += b.K_y, J(yb, yb) -= b.K_y, J(yb, pb) -= b.K_y * x;
    J(pb, y) += x * b.K_y, J(pb, yb) -= x * b.K_y, J(pb, pb) -= x * x * b.K_y;
    J(pb, p) += b.K_psi, J(pb, pb) -= b.K_psi;
  }
  J(pb, pb) -= b.K_s;
  return J;
}

// The iterate kept within the wheelset's physical range: |y| <= 10 mm (the flange is at 6 to 9
// mm for the usual profiles; beyond it the rigid contact would climb the flange and the forces
// of a wheel on its flange tip make spurious balances), |psi| <= 30 mrad, |eps| <= 1e-2, the
// frame within 50 mm and 50 mrad.
Vector inside(Vector q) {
  const double bound[3] = {10e-3, 30e-3, 1e-2};
  for (int k = 0; k < kFrame; ++k) q(k) = std::clamp(q(k), -bound[k % 3], bound[k % 3]);
  for (int k = kFrame; k < 8; ++k) q(k) = std::clamp(q(k), -0.05, 0.05);
  return q;
}

// One evaluation of (B2): the residual and the axles' contact forces there.
struct Evaluation {
  Vector r;
  std::array<AxleContactForces, 2> axles;
};

class Solver {
 public:
  Solver(const BogieEquilibriumInput& in, const AxleForceFunction& forces)
      : in_(in), forces_(forces), b_(bogie_constants(in)), Js_(suspension_jacobian(b_)) {}

  Evaluation evaluate(const Vector& q, double t) {
    Evaluation e;
    e.r = suspension_residual(b_, q, t);
    for (int i = 0; i < 2; ++i) {
      e.axles[i] = axle(i, q.segment<3>(3 * i), t, near_ ? &near_->axles[i] : nullptr);
      e.r(3 * i) += e.axles[i].lateral;
      e.r(3 * i + 1) += e.axles[i].yaw;
      e.r(3 * i + 2) += e.axles[i].torque;
    }
    return e;
  }

  // The Jacobian at q: the suspension's, and the contacts' 3 x 3 blocks by forward differences.
  Matrix jacobian(const Vector& q, double t, const Evaluation& at) {
    Matrix J = Js_;
    // on the way (coarse contacts, settled to 1e-6) over steps ten times as long
    const double f = coarse_ ? kCoarseStep : 1.0;
    const double h[3] = {f * in_.lateral_step, f * in_.yaw_step, f * in_.spin_step};
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d p = q.segment<3>(3 * i);
        p(k) += h[k];
        const AxleContactForces f = axle(i, p, t, keep_grids_ ? &at.axles[i] : nullptr);
        const AxleContactForces& f0 = at.axles[i];
        J(3 * i, 3 * i + k) += (f.lateral - f0.lateral) / h[k];
        J(3 * i + 1, 3 * i + k) += (f.yaw - f0.yaw) / h[k];
        J(3 * i + 2, 3 * i + k) += (f.torque - f0.torque) / h[k];
      }
    return J;
  }

  // Damped Newton from q at t: true when max |r| <= tol; q and e hold the last iterate. The
  // Jacobian is differenced when none is held or the last one served badly (a step it gave had
  // to be cut below a half, or lowered the residual by less than half); in between it follows
  // Broyden's rank-one update (Broyden, Math. Comp. 19 (1965) 577-593; Dennis & Schnabel,
  // Numerical Methods for Unconstrained Optimization and Nonlinear Equations, 1983, Sec. 8.1), and
  // it is carried over from one continuation step to the next. A step along a Jacobian that is
  // not fresh is cut down to 1/4 at most before a fresh one is differenced; a fresh one's down to
  // 1/64 (line_search). At most `max_iterations`.
  bool newton(Vector& q, double t, double tol, int max_iterations, Evaluation& e, int* iterations) {
    e = evaluate(q, t);
    if (keep_grids_) near_ = e;
    bool fresh = false;
    for (int it = 0; it < max_iterations; ++it) {
      if (e.r.cwiseAbs().maxCoeff() <= tol) return true;
      if (!have_jacobian_) {
        J_ = jacobian(q, t, e);
        have_jacobian_ = fresh = true;
      }
      Vector dq = J_.fullPivLu().solve(-e.r);
      if (!dq.allFinite()) return false;
      // at most 2 mm, 4 mrad and 1e-3 per step
      const double limit[3] = {2e-3, 4e-3, 1e-3};
      double scale = 1.0;
      for (int k = 0; k < 8; ++k)
        scale = std::min(
            scale, limit[k < kFrame ? k % 3 : k - kFrame] / std::max(std::abs(dq(k)), 1e-300));
      dq *= scale;
      ++*iterations;
      const Vector r_old = e.r;
      const double alpha = line_search(q, dq, t, fresh ? 1.0 / 64.0 : 0.25, e);
      if (keep_grids_ && alpha > 0.0) near_ = e;
      if (alpha == 0.0) {  // no descent along this step: a fresh Jacobian, or give up
        if (fresh) return false;
        have_jacobian_ = false;
        continue;
      }
      const Vector step = alpha * dq, change = e.r - r_old;
      J_ += (change - J_ * step) * step.transpose() / step.squaredNorm();
      // a limited step's slow descent is the limit's, not the Jacobian's
      if (!keep_grids_ && (alpha < 0.5 || (scale == 1.0 && e.r.norm() > 0.5 * r_old.norm())))
        have_jacobian_ = false;
      // on the kept grids: a Jacobian carried over (the coarse contacts') that lowers the residual
      // by less than 4 in a step is differenced afresh (a fresh one there keeps its updates)
      if (keep_grids_ && !fresh && e.r.norm() > 0.25 * r_old.norm()) have_jacobian_ = false;
      fresh = false;
    }
    return e.r.cwiseAbs().maxCoeff() <= tol;
  }

  /// The last digits: the full contacts from now on, each started from the last iterate's with
  /// its grid kept (VerticalLoadInput::start) when `keep`, so that the residual varies smoothly
  /// with q (no grid row comes or goes between the iterates and their differences); else each on
  /// the grid chosen for its state. With kept grids the Jacobian held (the coarse contacts') leads
  /// on until a step along it lowers the residual by less than 4 (newton); else it is differenced
  /// afresh.
  void last_digits(bool keep) {
    coarse_ = false;
    keep_grids_ = keep;
    near_.reset();
    if (!keep) have_jacobian_ = false;
  }

  /// Back to the coarse contacts and no Jacobian held (the continuation after a failed guess).
  void restart() {
    coarse_ = true;
    have_jacobian_ = false;
  }

  /// The way on the full contacts from now on (where the coarse ones cannot lead it).
  void refine_the_way() {
    coarse_ = false;
    have_jacobian_ = false;
  }
  bool coarse() const { return coarse_; }

  int evaluations() const { return evaluations_; }
  const Bogie& bogie() const { return b_; }

 private:
  // Backtracking on the residual norm (Armijo's condition with 1e-4): the step's fraction taken,
  // 0 when no step down to `smallest` of dq lowers it.
  double line_search(Vector& q, const Vector& dq, double t, double smallest, Evaluation& e) {
    const double norm = e.r.norm();
    for (double alpha = 1.0; alpha >= smallest; alpha *= 0.5) {
      const Vector trial = inside(q + alpha * dq);
      Evaluation et = evaluate(trial, t);
      if (et.r.allFinite() && et.r.norm() < (1.0 - 1e-4 * alpha) * norm) {
        q = trial;
        e = std::move(et);
        return alpha;
      }
    }
    return 0.0;
  }

  AxleContactForces axle(int i, const Eigen::Vector3d& p, double t, const AxleContactForces* near) {
    ++evaluations_;
    return forces_({i, p(0), p(1), p(2), t, coarse_, near});
  }

  const BogieEquilibriumInput& in_;
  const AxleForceFunction& forces_;
  Bogie b_;
  Matrix Js_;
  Matrix J_;  // the Jacobian held (differenced, then Broyden's updates)
  bool have_jacobian_ = false;
  bool keep_grids_ = false;
  bool coarse_ = true;              // the contacts on the way (AxleQuery::coarse)
  std::optional<Evaluation> near_;  // the last iterate, when the grids are kept
  int evaluations_ = 0;
};

// The continuation in t from tangent track (q = 0) to the curve (t = 1): steps of 1/4, halved on
// failure (down to 1/64, then NumericalError), grown by 1.5 after a step that came easily; a
// secant predictor from the last two solutions; every step to a loose tolerance (1e-2 Q on the
// way, 1e-3 Q at the curve: they only lead the way, each contact on the coarse grid chosen for its
// state). The last digits are the caller's.
struct Continued {
  Vector q = Vector::Zero();
  Evaluation e;
  int steps = 0;  // accepted steps in t
};

Continued continue_to_curve(Solver& solver, double Q, double tol, int* iterations) {
  Continued c;
  double t = 0.0, dt = 0.25, t_prev = 0.0;
  Vector q_prev = c.q;
  while (t < 1.0) {
    const double t_next = std::min(1.0, t + dt);
    Vector trial = c.q;
    if (t > 0.0) trial = inside(c.q + (c.q - q_prev) * ((t_next - t) / (t - t_prev)));
    const double step_tol = std::max(tol, (t_next < 1.0 ? 1e-2 : 1e-3) * Q);
    const int before = *iterations;
    if (solver.newton(trial, t_next, step_tol, kStepIterations, c.e, iterations)) {
      q_prev = c.q, t_prev = t;
      c.q = trial, t = t_next;
      ++c.steps;
      if (*iterations - before <= 3) dt *= 1.5;  // a step that came easily: a longer one
      continue;
    }
    dt *= 0.5;
    // Coarse contacts that cannot lead the way (at the flange their few elements across the
    // narrow patch can make the forces jump by more than the way's tolerance): the full ones,
    // from steps of 1/16 again.
    if (dt < 1.0 / 64.0 && solver.coarse()) {
      solver.refine_the_way();
      dt = 1.0 / 16.0;
    }
    if (dt < 1.0 / 64.0) {
      std::ostringstream m;
      m << "bogie equilibrium: no solution along the continuation at t = " << t_next
        << " of the curve (continuation step below 1/64; last residual "
        << c.e.r.cwiseAbs().maxCoeff() << " N against " << step_tol << " N)";
      throw NumericalError(m.str());
    }
  }
  return c;
}

// The loose solution at the curve (t = 1), on the coarse contacts: Newton from the guess where
// one is given and it leads there within kGuessIterations to 1e-2 Q (the coarse contacts' forces
// differ from the full ones' by up to ~1.5 kN at a flange: a tighter loose solution buys
// nothing), else the continuation from tangent track.
Continued reach_the_curve(Solver& solver, const std::optional<BogieGuess>& guess, double Q,
                          double tol, int* iterations) {
  if (guess) {
    const BogieGuess& g = *guess;
    Continued c;
    c.q << g.lateral[0], g.yaw[0], 0.0, g.lateral[1], g.yaw[1], 0.0, g.bogie_lateral, g.bogie_yaw;
    c.q = inside(c.q);
    if (solver.newton(c.q, 1.0, std::max(tol, 1e-2 * Q), kGuessIterations, c.e, iterations))
      return c;
    solver.restart();
  }
  return continue_to_curve(solver, Q, tol, iterations);
}

// The solution's fields from the last iterate.
BogieEquilibrium result(const Vector& q, Evaluation& e) {
  BogieEquilibrium out;
  for (int i = 0; i < 2; ++i) {
    out.lateral[i] = q(3 * i);
    out.yaw[i] = q(3 * i + 1);
    out.spin[i] = q(3 * i + 2);
  }
  out.bogie_lateral = q(kFrame);
  out.bogie_yaw = q(kFrame + 1);
  for (int k = 0; k < 8; ++k) out.residual[k] = e.r(k);
  for (int i = 0; i < 2; ++i)
    for (WheelContact& w : e.axles[i].wheels)
      if (w.loaded) {
        if (w.loaded->tangential_factors) {  // the solver's alone: not kept with the state
          auto state = std::make_shared<geometry::LoadedContact>(*w.loaded);
          state->tangential_factors.reset();
          w.loaded = std::move(state);
        }
        out.wheels.push_back(std::move(w));
      }
  return out;
}

}  // namespace

bool VehicleParameters::valid() const {
  const auto non_negative = [](double v) { return v >= 0.0 && std::isfinite(v); };
  return non_negative(carbody_mass) && non_negative(frame_mass) && non_negative(wheelset_mass) &&
         non_negative(primary_longitudinal_stiffness) && primary_lateral_stiffness > 0.0 &&
         std::isfinite(primary_lateral_stiffness) && axlebox_semi_spacing > 0.0 &&
         std::isfinite(axlebox_semi_spacing) && non_negative(secondary_yaw_stiffness) &&
         non_negative(bogie_centre_distance);
}

double BogieEquilibrium::max_residual() const {
  double m = 0.0;
  for (double r : residual) m = std::max(m, std::abs(r));
  return m;
}

AxleContactForces contact_forces(const CurveStateInput& in, double load_transfer,
                                 const AxleQuery& query) {
  const auto [axle, y, psi, eps, t, coarse, near] = query;
  AxleContactForces f;
  const WheelId ids[2] = {axle == 0 ? WheelId::leading_outer : WheelId::trailing_outer,
                          axle == 0 ? WheelId::leading_inner : WheelId::trailing_inner};
  for (int w = 0; w < 2; ++w) {
    WheelContactInput wi = wheel_input(in, ids[w], y, psi);
    wi.inverse_radius *= t;
    wi.lowering_settle = coarse ? kSettleCoarse : kSettle;
    if (coarse) {  // a third of the elements each way
      wi.lowering_nx = std::max(8, wi.lowering_nx / 3);
      wi.grid.min_elements_across = std::max(4, wi.grid.min_elements_across / 3);
    }
    wi.gap_regions = true;  // a contact jump is a two-point contact: the forces stay continuous
    wi.axle_spin = eps;     // the axle's own rolling speed (WheelContactInput::axle_spin)
    wi.vertical_load = in.wheel_load + (w == 0 ? 1.0 : -1.0) * t * load_transfer;
    if (near) wi.start = near->wheels[w].loaded;
    wi.keep_factors = !coarse;  // the full contacts' factors precondition the next ones
    f.wheels[w] = wheel_contact(wi);
    const WheelContact& c = f.wheels[w];
    const std::array<double, 3> ft = c.force_track();  // towards the outer rail
    const double y_w = w == 0 ? c.contact.y : -c.contact.y;
    const double mz =
        (w == 0 ? 1.0 : -1.0) * c.loaded->creep_force[2] * std::cos(c.contact.contact_angle);
    // (B3)
    f.lateral += ft[1];
    f.yaw += c.contact.x * ft[1] - y_w * ft[0] + mz;
    f.torque += c.contact.rolling_radius * ft[0];
  }
  return f;
}

std::optional<BogieGuess> estimated_guess(const CurveStateInput& in) {
  CurveStateInput e = in;
  e.equilibrium = false;
  CurvingEstimate est;
  try {
    est = estimated_curve_position(e).estimate;
  } catch (const std::domain_error&) {
    return std::nullopt;
  } catch (const NumericalError&) {
    return std::nullopt;
  }
  BogieGuess g;
  g.lateral = {est.leading.lateral, est.trailing.lateral};
  g.yaw = {est.leading.attack_angle, est.trailing.attack_angle};
  // (B1) with no deflection: psib = psi_i - x_i kappa = theta, yb = mean(y_i) - a^2 kappa / 2
  const double a = 0.5 * in.wheelbase, kappa = std::isinf(in.radius) ? 0.0 : 1.0 / in.radius;
  g.bogie_yaw = est.bogie_yaw;
  g.bogie_lateral = 0.5 * (g.lateral[0] + g.lateral[1]) - 0.5 * a * a * kappa;
  return g;
}

BogieEquilibrium solve_bogie_equilibrium(const BogieEquilibriumInput& in,
                                         const AxleForceFunction& forces) {
  ROLLNOISE_ASSERT(in.vehicle.valid(),
                   "vehicle parameters outside the model (pipeline checks [vehicle])");
  const double Q = in.curve.wheel_load;
  const double dQ = std::isinf(in.curve.radius)
                        ? 0.0
                        : cant_deficiency_load_transfer(
                              Q, in.curve.cant_deficiency, in.curve.cg_height,
                              2.0 * geometry::find_contact(*in.curve.pair, {0.0, 0.0}).y);
  const bool tangent = std::isinf(in.curve.radius) && in.curve.cant_deficiency == 0.0;
  const AxleForceFunction contacts =
      forces ? forces : AxleForceFunction([&in, dQ](const AxleQuery& query) {
        return contact_forces(in.curve, dQ, query);
      });
  Solver solver(in, contacts);
  const Bogie& b = solver.bogie();
  Vector q = Vector::Zero();
  Evaluation e;
  BogieEquilibrium out;
  if (tangent) {
    // y, psi and the frame's q = 0 by symmetry; the axles' rolling speed is not: the patch of a
    // profile pair is not symmetric about its centre line, so the spin creepage gives both wheels
    // of an axle a longitudinal force of the same sign and a torque T_i at eps = 0. Newton from
    // q = 0 on the full grid at t = 0 (the lateral and yaw equations stay balanced to round-off).
    solver.last_digits(true);
    int iterations = 0;
    const bool converged = solver.newton(q, 0.0, in.tolerance * Q, in.max_newton, e, &iterations);
    out = result(q, e);
    out.converged = converged;
    out.iterations = iterations;
  } else {
    const double tol = in.tolerance * Q;
    int iterations = 0;
    Continued c = reach_the_curve(solver, in.guess, Q, tol, &iterations);
    q = c.q, e = std::move(c.e);
    // The last digits: each wheel's grid kept from the loose solution (Solver::last_digits), so
    // that no grid row comes or goes between the iterates. Where that stalls (the forces of a
    // wheel at the onset of a two-point contact have a kink: the load shared between the two
    // regions turns with the contact stiffness, 1e9 N/m laterally against 1e7 N/m on one
    // region), Newton goes on from its best iterate with each contact on the grid chosen for its
    // state. A Newton iteration that stalls there too keeps its best iterate, reported by its
    // residual (out.converged false, the summary says so).
    solver.last_digits(true);
    bool converged = solver.newton(q, 1.0, tol, kKeptIterations, e, &iterations);
    if (!converged) {
      solver.last_digits(false);
      converged = solver.newton(q, 1.0, tol, in.max_newton, e, &iterations);
    }
    out = result(q, e);
    out.converged = converged;
    out.iterations = iterations;
    out.continuation_steps = c.steps;
  }
  out.contact_evaluations = solver.evaluations();
  out.unbalanced_acceleration = b.a_u;
  out.load_transfer = dQ;
  return out;
}

}  // namespace rollnoise::noise
