// Steady rolling with Coulomb friction (paper Eq. 3):  s = w + V (A - A0) p / dx  at every contact
// element, |p| <= mu pn, adhesion s = 0, slip p = -mu pn s/|s|.
//
// Solver: a semismooth Newton method on the element-wise Coulomb fixed point. Let Pi_I(p) be the
// exact solution of Coulomb's law at element I with all other tractions fixed (coulomb.hpp, the
// Gauss-Seidel element step). The solution is the root of R(p) = p - Pi(p). R is piecewise smooth:
// its Jacobian is  I - dPi/db (S - D)  with dPi/db = -D^{-1} in adhesion and the tangential
// projection of coulomb.hpp in slip, so each Newton step re-decides adhesion and slip for every
// element (Kalker's TANG with Newton on the slip set, in a form that needs no separate set
// updates). Steps are damped by backtracking on |R| for global robustness; near the solution the
// convergence is quadratic, so the residual is driven to round-off and the adhesion/slip split is
// that of the exact discrete solution.
//
// Why not Gauss-Seidel: S = V (A - A0)/dx = V (I - T) A/dx (T the shift to the upstream neighbour) is
// a difference along x. Element Gauss-Seidel marching from the leading edge inverts (I - T), a
// summation, and amplifies the downstream influence: we measured divergence by a factor 3 per sweep
// on the paper's grid even at creepage 1e-9 (and a 2-cycle with slip). Marching the other way stalls.
// The dense Jacobian costs O(n^3) per step; see README "Performance" for sizes and timings.
#pragma once

#include "contact/influence.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

struct SteadyRollingInput {
  double mu = 0.3;           ///< friction coefficient (-)
  double speed = 0.0;        ///< rolling speed V (m/s)
  Creepage creepage;         ///< mean creepages
  double spin_offset = 0.0;  ///< spin term at x + spin_offset dx (0: paper Eq. 21; 1/6: CONTACT)
};

/// Steady rolling for the pressure pn on the grid of `A`. `start` (optional) warm-starts from a
/// solution on the same grid. The returned slip velocities satisfy Eq. 3 directly (recomputed).
TangentialSolution solve_steady_rolling(const InfluenceTable& A, const GridField& pn,
                                        const SteadyRollingInput& in,
                                        const TangentialSolverSettings& settings = {},
                                        const TangentialSolution* start = nullptr);

}  // namespace rollnoise::contact
