#include "contact/steady_rolling.hpp"

#include "contact/coulomb_newton.hpp"
#include "core/errors.hpp"

namespace rollnoise::contact {

namespace {

// The rigid slip w = V (creepage) of Eq. 3 (or of the per-element creepages) and the bounds mu pn.
struct SteadyRightHandSide {
  GridField wx, wy, bound;
};
SteadyRightHandSide steady_right_hand_side(const Grid& g, const GridField& pn,
                                           const SteadyRollingInput& in) {
  check_rolling_input(in.mu, in.speed, in.creepage);
  check_falling_friction(in.falling);
  SteadyRightHandSide r;
  r.bound.resize(g.size());
  rigid_slip(g, in.speed, in.creepage, in.spin_offset, r.wx, r.wy);
  if (!in.local_creepage_x.empty()) {
    if (in.local_creepage_x.size() != r.wx.size() || in.local_creepage_y.size() != r.wy.size())
      throw NumericalError("steady rolling: the local creepages do not match the grid");
    for (int k = 0; k < g.size(); ++k) {
      r.wx[k] = in.speed * in.local_creepage_x[k];
      r.wy[k] = in.speed * in.local_creepage_y[k];
    }
  }
  for (int k = 0; k < g.size(); ++k) r.bound[k] = in.mu * pn[k];
  return r;
}

TangentialSolution solve_with(CoulombNewton& newton, const Grid& g, const SteadyRightHandSide& r,
                              const SteadyRollingInput& in,
                              const TangentialSolverSettings& settings,
                              const TangentialSolution* start) {
  newton.set_falling_friction(in.falling);
  const GridField zero(g.size(), 0.0);
  return newton.solve(r.wx, r.wy, start ? start->px : zero, start ? start->py : zero, settings,
                      "steady tangential solver");
}

}  // namespace

TangentialSolution solve_steady_rolling(const InfluenceTable& A, const GridField& pn,
                                        const SteadyRollingInput& in,
                                        const TangentialSolverSettings& settings,
                                        const TangentialSolution* start) {
  const Grid& g = A.grid();
  const SteadyRightHandSide r = steady_right_hand_side(g, pn, in);
  CoulombNewton newton(SlipOperator::steady(A, in.speed), sweep_order(g, pn), r.bound);
  return solve_with(newton, g, r, in, settings, start);
}

SteadyRollingSolver::SteadyRollingSolver(const InfluenceTable& A) : A_(&A) {}
SteadyRollingSolver::~SteadyRollingSolver() = default;
SteadyRollingSolver::SteadyRollingSolver(SteadyRollingSolver&&) noexcept = default;
SteadyRollingSolver& SteadyRollingSolver::operator=(SteadyRollingSolver&&) noexcept = default;

TangentialSolution SteadyRollingSolver::solve(const GridField& pn, const SteadyRollingInput& in,
                                              const TangentialSolverSettings& settings,
                                              const TangentialSolution* start) {
  const Grid& g = A_->grid();
  const SteadyRightHandSide r = steady_right_hand_side(g, pn, in);
  if (newton_ && in.speed == speed_) {
    newton_->set_bounds(sweep_order(g, pn), r.bound);
  } else {
    if (newton_) earlier_factorisations_ += newton_->factorisations();
    newton_ = std::make_unique<CoulombNewton>(SlipOperator::steady(*A_, in.speed),
                                              sweep_order(g, pn), r.bound);
    newton_->precondition_with(seed_);
    speed_ = in.speed;
  }
  return solve_with(*newton_, g, r, in, settings, start);
}

std::shared_ptr<const NewtonFactors> SteadyRollingSolver::factors() const {
  return newton_ ? newton_->factors() : nullptr;
}

int SteadyRollingSolver::factorisations() const {
  return earlier_factorisations_ + (newton_ ? newton_->factorisations() : 0);
}

}  // namespace rollnoise::contact
