// The discretised normal contact problem (Kalker 1990, Sec. 5.4; docs/conventions.md Secs. 1-2):
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
/// `start` (optional): a start pressure (e.g. the solution at a nearby load), rescaled to the
/// force; without it, a uniform pressure. Throws NumericalError when it does not converge.
NormalSolution solve_normal(const Grid& grid, const HalfSpaceOperator& op, const GridField& h,
                            double normal_force, const NormalSolverSettings& settings = {},
                            const GridField* start = nullptr);

}  // namespace rollnoise::contact

namespace rollnoise::contact {

/// Sensitivity of the normal solution to the normal load on the frozen contact area C (the
/// elements with pn > 0): with the area held, a load increment dN changes the approach by d(delta)
/// and the pressure by dpn, with
///
///   A_CC dpn = d(delta) 1,   dx dy 1' dpn = dN      =>   dpn/dN = x / (dx dy 1'x),
///   d(delta)/dN = 1 / (dx dy 1'x),   A_CC x = 1                                         (N1)
///
/// (x solved by conjugate gradients on C, FFT or dense products). For a smooth (Hertzian or
/// non-Hertzian) profile this is the exact derivative of the continuous solution: the pressure
/// vanishes at the edge of the area, so its growth does not contribute to first order, and dpn
/// is the flat-punch distribution of the current area; for Hertz it is p0 / (3 N sqrt(1 - rho^2)),
/// the N-derivative of p0 sqrt(1 - rho^2) with p0, a, b ~ N^(1/3) (Johnson 1985, Eq. 4.39-4.41).
/// On the grid it is the derivative of the discrete solution as long as no element enters or
/// leaves C. The normal contact stiffness is k_N = dN/d(delta) = dx dy 1'x.
struct NormalLoadSensitivity {
  GridField dpn_dN;            ///< 1/m^2 (Pa per N), 0 outside C
  double approach_per_load = 0.0;  ///< d(delta)/dN (m/N)
  double stiffness() const { return 1.0 / approach_per_load; }  ///< k_N (N/m)
  int iterations = 0;
};

/// x with A_CC x = b on the contact area C of `normal` (pn > 0), 0 outside: the pressure change on
/// the frozen area for the gap change b on it (e.g. (N1) with b = 1, or a roughness, R1 of
/// transient_rolling.hpp). Conjugate gradients, products by `op` (the Normal operator of the
/// grid). NumericalError when CG does not reach `tolerance` (relative residual).
struct FrozenAreaSolution {
  GridField x;
  int iterations = 0;
};
FrozenAreaSolution frozen_area_solve(const Grid& grid, const HalfSpaceOperator& op,
                                     const NormalSolution& normal, const GridField& b,
                                     double tolerance = 1e-13);

/// (N1) for a solved normal problem on `grid`; `op` the Normal operator of the grid.
/// Throws NumericalError when CG does not converge to `tolerance` (relative residual).
NormalLoadSensitivity normal_load_sensitivity(const Grid& grid, const HalfSpaceOperator& op,
                                              const NormalSolution& normal, double tolerance = 1e-13);

}  // namespace rollnoise::contact
