// Transient (unsteady) rolling, paper Eq. 2 (Kalker 1990, Sec. 5.3; CONTACT's T = 2):
//
//   s_k = w(t_k) + (A p_k - A0 p_{k-1}) / dt,   dt = dx / V,
//
// on the grid that moves with the contact one element per step: A0 is A shifted by one column
// (the material now at x_I was at x_I + dx one step earlier). Each step is a full Coulomb-friction
// problem with the previous tractions known, S = A/dt, rhs = w - A0 p_{k-1}/dt, solved by the
// semismooth Newton method of coulomb_newton.hpp, started from the tractions extrapolated linearly
// from the last two steps (2 Newton iterations per step instead of 3 on the paper's case); its
// preconditioner, if any, carries over between steps. Element Gauss-Seidel (ConvexGS) also
// converges here (A/dt is symmetric positive definite) but needed ~90 sweeps per step to 1e-12 on
// the paper's grid (56 ms per step, against 2-3 ms now), so it was removed. The creepage of step k
// is taken at t_k = k dt, the end of the step (CONTACT's convention, DESIGN.md Sec. 3).
#pragma once

#include "contact/halfspace_operator.hpp"
#include "contact/coulomb_newton.hpp"
#include "contact/influence.hpp"
#include "contact/slip_operator.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

class TransientRolling {
 public:
  TransientRolling(const InfluenceTable& A, const GridField& pn, double mu, double speed,
                   double spin_offset, Backend backend = Backend::Auto,
                   const TangentialSolverSettings& settings = {});

  double time_step() const { return dt_; }
  /// Set the current tractions (e.g. the steady solution at the mean creepage, or zero).
  void set_tractions(const GridField& px, const GridField& py);
  /// Advance one step with the creepage of the new time; returns the new state.
  const TangentialSolution& step(const Creepage& c);
  const TangentialSolution& current() const { return current_; }

 private:
  const InfluenceTable& A_;
  GridField pn_;
  double mu_, speed_, spin_offset_, dt_;
  HalfSpaceOperator A0_;
  CoulombNewton newton_;
  TangentialSolverSettings settings_;
  TangentialSolution current_;
  std::vector<double> previous_;  // tractions (px, py) of the step before current_, for the start value
};

}  // namespace rollnoise::contact
