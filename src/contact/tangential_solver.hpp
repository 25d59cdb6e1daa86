// The tangential problem of rolling contact with Coulomb friction on the grid (paper Eqs. 2-3,
// docs/conventions.md Secs. 1-2): creepages, element states, solutions, rigid slip and the element order.
//
// The solvers live in coulomb_newton.hpp (both problems), steady_rolling.hpp and
// transient_rolling.hpp; this header holds what they share.
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
  int iterations = 0;         ///< Newton iterations
  double residual = 0.0;      ///< final relative residual
  int linear_iterations = 0;  ///< GMRES iterations over all Newton steps (work counter)
  int factorisations = 0;     ///< LU factorisations of the Jacobian made by this solve
  int count(ElementState s) const;
};

/// Rigid slip velocity w = V (xi_x - phi y, xi_y + phi (x + spin_offset dx)) (paper Eq. 21; with
/// spin_offset = 1/6 CONTACT's default discretisation of the spin term).
void rigid_slip(const Grid& g, double speed, const Creepage& c, double spin_offset, GridField& wx,
                GridField& wy);

/// Throw InputError unless mu > 0, speed > 0 and the creepages are finite (keys friction.mu,
/// rolling.speed, creepage.mean: the case keys these come from). Non-finite input would otherwise
/// travel through the solvers as NaN tractions.
void check_rolling_input(double mu, double speed, const Creepage& c);

/// The contact elements (pn > 0) in the sweep order: from the leading edge (largest x) backwards.
std::vector<int> sweep_order(const Grid& g, const GridField& pn);

}  // namespace rollnoise::contact
