// The discretised normal contact problem (Kalker 1990, Sec. 5.4; DESIGN.md Sec. 2):
//
//   find pn >= 0 and the approach delta with  e = h + A_zz pn - delta >= 0,  pn e = 0,
//   sum(pn) dx dy = N,
//
// for any undeformed distance h on the grid (quadratic for Hertz, from profiles otherwise).
// Solved with the bound-constrained conjugate-gradient method of Polonsky & Keer (Wear 231, 1999,
// 206-219, their Sec. 3): CG on the active set, projection onto pn >= 0, re-activation of elements
// with pn = 0 and negative gap, and rescaling to the prescribed force; products by HalfSpaceOperator
// (FFT for large grids). It minimises the complementary energy 1/2 pn'A pn + pn'h, which is convex,
// so the method converges from any start.
#pragma once

#include <vector>

#include "contact/grid.hpp"
#include "contact/halfspace_operator.hpp"

namespace rollnoise::contact {

struct NormalSolverSettings {
  double tolerance = 1e-12;  ///< on the relative change of the pressure field per iteration
  int max_iterations = 2000;
};

struct NormalSolution {
  GridField pn;            ///< pressure per element (Pa), 0 outside the contact area
  GridField gap;           ///< deformed distance e (m), 0 in contact
  double approach = 0.0;   ///< rigid approach delta (m)
  double force = 0.0;      ///< sum pn dx dy (N)
  int iterations = 0;
  double residual = 0.0;   ///< final relative change of pn
  int contact_elements() const;
  double max_pressure() const;
};

/// Solve the normal problem for the undeformed distance `h` (m, without the approach; larger is
/// further apart) and the total normal force (N). `op` must be the Normal operator of the grid.
/// Throws NumericalError when it does not converge.
NormalSolution solve_normal(const Grid& grid, const HalfSpaceOperator& op, const GridField& h,
                            double normal_force, const NormalSolverSettings& settings = {});

}  // namespace rollnoise::contact
