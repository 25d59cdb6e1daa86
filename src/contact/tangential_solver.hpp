// The tangential problem of rolling contact with Coulomb friction on the grid (paper Eqs. 2-3,
// DESIGN.md Sec. 2), solved by block Gauss-Seidel with the exact element solution of coulomb.hpp.
//
// Why Gauss-Seidel. Every element step solves Coulomb's law exactly, so the iteration needs no
// regularisation and no slip-set guesses, and it works unchanged from creepage 0 (all adhesion) to
// full sliding. For the transient step the operator A/dt is symmetric positive definite and the
// iteration is the exact minimisation of a convex functional, element by element (Vollebregt's
// ConvexGS), hence globally convergent. Steady rolling needs a transformed system: see
// steady_rolling.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "contact/grid.hpp"
#include "contact/slip_operator.hpp"

namespace rollnoise::contact {

/// Creepages: longitudinal xi_x (-), lateral xi_y (-), spin phi (rad/m).
struct Creepage {
  double xi_x = 0.0, xi_y = 0.0, phi = 0.0;
};

/// Element state as written to the output: 0 exterior, 1 adhesion, 2 slip (CONTACT's igs).
enum class ElementState : std::int8_t { exterior = 0, adhesion = 1, slip = 2 };

struct TangentialSolverSettings {
  double tolerance = 1e-11;   ///< on max |change of p| / max |p| over one sweep
  int max_iterations = 20000;  ///< sweeps
};

struct TangentialSolution {
  GridField px, py;  ///< tractions on body 1 (Pa)
  GridField sx, sy;  ///< slip velocities (m/s), zero in adhesion
  std::vector<std::int8_t> state;  ///< ElementState per element
  int iterations = 0;
  double residual = 0.0;
  int count(ElementState s) const;
};

/// Rigid slip velocity w = V (xi_x - phi y, xi_y + phi (x + spin_offset dx)) (paper Eq. 21; with
/// spin_offset = 1/6 CONTACT's default discretisation of the spin term).
void rigid_slip(const Grid& g, double speed, const Creepage& c, double spin_offset, GridField& wx,
                GridField& wy);

/// The contact elements (pn > 0) in the sweep order: from the leading edge (largest x) backwards.
std::vector<int> sweep_order(const Grid& g, const GridField& pn);

/// Solve s = rhs + S p with Coulomb's law |p| <= bound at the elements `order` (tractions elsewhere
/// are zero). `p` holds the start values on entry (warm start). Throws NumericalError (naming
/// `solver`) when the iteration does not converge.
TangentialSolution solve_coulomb(const SlipOperator& S, const GridField& rhs_x,
                                 const GridField& rhs_y, const GridField& bound,
                                 const std::vector<int>& order, GridField px, GridField py,
                                 const TangentialSolverSettings& settings,
                                 const std::string& solver);

}  // namespace rollnoise::contact
