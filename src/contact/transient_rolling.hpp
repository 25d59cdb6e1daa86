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
// the paper's grid (56 ms per step, against 2-3 ms now), so it was removed. step(c) takes the
// creepage of step k as given; when it is taken is the caller's choice (contact::roll,
// CreepageSampling): at t_k = k dt, the end of the step (CONTACT's convention, docs/conventions.md
// Sec. 3), at t_k - dt/2, where the displacement difference is centred (midstep), or its mean over
// [t_{k-1}, t_k] (average, the default).
//
// Varying normal load N(t) (step(c, N_k), after set_normal_problem). At each step whose load
// differs from the last one, the normal problem of the patch is solved for N_k (normal_solver.hpp,
// same undeformed distance h), then the tangential step above with the bound mu pn_k:
//   - Quasi-identical bodies: A_xz = A_yz = 0, so the normal problem does not see the tangential
//     tractions and pn_k depends on N_k alone (Kalker 1990, Sec. 1.6); the tangential problem sees
//     pn only through the traction bound mu pn_k (in slip p = -mu pn s/|s|: a load change changes
//     the slip tractions at once).
//   - The normal problem is quasi-static, without memory of the earlier steps: Eq. 2 is transient
//     only through the convective time derivative of the tangential displacement difference (the
//     slip is a velocity of material particles), whereas the normal contact condition is one on
//     the gap, a position, e = h + A_zz pn - delta >= 0, which has no time derivative. Elastic
//     inertia is neglected in both problems, as in Eq. 2: a Rayleigh wave (~2900 m/s in steel)
//     crosses the 14 mm patch in ~5 us, against periods >= 200 us up to 5 kHz. Without a
//     roughness h is fixed in the moving frame and the load history is force-controlled.
//   - Rail roughness (step(c, N, r), normal_approach(N, r)): a rail roughness r(X), X = x + V t
//     the rail coordinate under the element at x, passes through the patch. The caller gives the
//     roughness under each element at t_k, r_k(x, y) = r(x + V t_k) (roughness_rolling.hpp), and
//     the undeformed distance of the step is
//       h_k(x, y) = h(x, y) + r_k(x, y)                                                    (R1)
//     with r positive for a depression of the rail (docs/corrugation.md Sec. 4, noise/loop.hpp
//     L1: a dip opens the gap). The normal problem is solved at every such step (the same solver
//     as the load history, started from the last pressure), with the load prescribed; the approach
//     delta_k it returns lets a structure close the loop (roughness_rolling.hpp: the load whose
//     approach the wheel's displacement requires).
//   - Elements entering or leaving contact: an element entering at step k had p_{k-1} = 0 (it was
//     exterior), so it starts with zero traction, and A0 p_{k-1} is the displacement of the old
//     tractions wherever they were; an element leaving has bound 0 and drops its traction
//     (p_k = 0, output as exterior). The Newton unknowns are the elements that were in contact
//     at any step so far (bound 0 where not in contact now): the set only grows, so the LU
//     preconditioner, when there is one, survives load changes (a new factorisation on the
//     paper's coarse grid costs ~20 steps), and is dropped only when an element enters for the
//     first time.
//   - Cost: the normal solve (Polonsky-Keer CG) starts from the pressure of the last step (see
//     the .cpp for the start and the measured iterations). A constant load takes the old path
//     (no normal solve, bit-identical results).
#pragma once

#include <memory>

#include "contact/coulomb_newton.hpp"
#include "contact/halfspace_operator.hpp"
#include "contact/influence.hpp"
#include "contact/normal_solver.hpp"
#include "contact/slip_operator.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

class TransientRolling {
 public:
  TransientRolling(const InfluenceTable& A, const GridField& pn, double mu, double speed,
                   double spin_offset, Backend backend = Backend::Auto,
                   const TangentialSolverSettings& settings = {});

  double time_step() const { return dt_; }
  /// Falling friction mu(|s|) (friction_law.hpp; constant until called): mu of the constructor
  /// is mu_s. InputError (friction.kinetic_ratio, friction.decay) for bad values.
  void set_falling_friction(const FallingFriction& falling);
  /// Set the current tractions (e.g. the steady solution at the mean creepage, or zero).
  void set_tractions(const GridField& px, const GridField& py);
  /// Advance one step with the creepage of the new time; returns the new state.
  const TangentialSolution& step(const Creepage& c);
  const TangentialSolution& current() const { return current_; }

  /// Allow a varying normal load: `h` the undeformed distance of the patch (without the approach,
  /// ContactPatch::undeformed_distance) and `normal_force` the load the constructor's pn solves.
  void set_normal_problem(const GridField& h, double normal_force,
                          const NormalSolverSettings& settings = {});
  /// Advance one step with the creepage and the total normal load N (N > 0) of the new time. The
  /// same as step(c) if N is the load of the last step (after a step over a roughness too: the
  /// pressure then stays the roughness's). InputError (key "grid") if the contact area at N
  /// reaches the border of the grid.
  const TangentialSolution& step(const Creepage& c, double normal_force);
  /// Advance one step with the creepage and the normal load N of the new time on the undeformed
  /// distance h + r (R1): `roughness` r_k under each element at t_k (m, positive a depression, the
  /// grid's size). The normal problem is solved whatever N (the roughness moves).
  const TangentialSolution& step(const Creepage& c, double normal_force,
                                 const GridField& roughness);
  /// Solve the normal problem of the coming step for the load N on h + r (R1) without stepping
  /// the tangential problem; returns its approach delta (m). The next step(c) takes this pressure
  /// as its traction bound. Called repeatedly, the last call counts (roughness_rolling.hpp iterates
  /// on N until delta matches the structure's displacement).
  double normal_approach(double normal_force, const GridField& roughness);
  /// The approach delta (m) of the last normal solve (0 before any).
  double approach() const { return approach_; }
  /// The current pressure (Pa) and normal load (N).
  const GridField& pressure() const { return pn_; }
  double normal_force() const { return normal_force_; }
  /// Normal solves and their Polonsky-Keer iterations since construction (work counters).
  int normal_solves() const { return normal_solves_; }
  int normal_iterations() const { return normal_iterations_; }
  double normal_seconds() const { return normal_seconds_; }  ///< wall time in the normal solves

 private:
  void solve_normal_load(double normal_force, const GridField* roughness = nullptr);

  const InfluenceTable& A_;
  GridField pn_;
  double mu_, speed_, spin_offset_, dt_;
  Backend backend_;
  HalfSpaceOperator A0_;
  CoulombNewton newton_;
  TangentialSolverSettings settings_;
  TangentialSolution current_;
  std::vector<double> previous_;  // tractions (px, py) of the step before current_, for the start value
  // varying normal load
  std::unique_ptr<HalfSpaceOperator> normal_op_;
  GridField h_;
  GridField pn_previous_;  // pressure of the load before (start of the normal solve)
  double normal_force_previous_ = 0.0;
  NormalSolverSettings normal_settings_;
  double normal_force_ = 0.0;
  double approach_ = 0.0;
  GridField ever_in_contact_;  // 1 at the elements in contact at any step so far, else 0
  std::vector<int> elements_;  // those elements in sweep order: the Newton unknowns
  int normal_solves_ = 0, normal_iterations_ = 0;
  double normal_seconds_ = 0.0;
};

}  // namespace rollnoise::contact
