// Steady rolling with Coulomb friction (paper Eq. 3):  s = w + V (A - A0) p / dx  at every contact
// element, |p| <= mu pn, adhesion s = 0, slip p = -mu pn s/|s| (with falling friction
// -mu(|s|) pn s/|s|, friction_law.hpp; mu = mu_s bounds the adhesion tractions).
//
// Solver: the semismooth Newton method of coulomb_newton.hpp with S = V (A - A0)/dx, rhs = w.
//
// Why not Gauss-Seidel: S = V (A - A0)/dx = V (I - T) A/dx (T the shift to the upstream neighbour) is
// a difference along x. Element Gauss-Seidel marching from the leading edge inverts (I - T), a
// summation, and amplifies the downstream influence: we measured divergence by a factor 3 per sweep
// on the paper's grid even at creepage 1e-9 (and a 2-cycle with slip). Marching the other way stalls.
// Newton steps are solved by GMRES with FFT products (coulomb_newton.hpp): on the paper's grids a
// steady solve takes 40-80 GMRES iterations per Newton step and no factorisation at all; see
// docs/accuracy.md ("Benchmarks") for sizes and timings.
#pragma once

#include <memory>

#include "contact/friction_law.hpp"
#include "contact/influence.hpp"
#include "contact/tangential_solver.hpp"

namespace rollnoise::contact {

struct SteadyRollingInput {
  // A constructor rather than an aggregate, so that {mu, speed, creepage, spin_offset} stays valid
  // (without -Wmissing-field-initializers) now that `falling` follows.
  SteadyRollingInput(double mu_ = 0.3, double speed_ = 0.0, Creepage creepage_ = {},
                     double spin_offset_ = 0.0, FallingFriction falling_ = {})
      : mu(mu_), speed(speed_), creepage(creepage_), spin_offset(spin_offset_), falling(falling_) {}
  double mu = 0.3;           ///< friction coefficient (-)
  double speed = 0.0;        ///< rolling speed V (m/s)
  Creepage creepage;         ///< mean creepages
  double spin_offset = 0.0;  ///< spin term at x + spin_offset dx (0: paper Eq. 21; 1/6: CONTACT)
  /// Falling friction mu(|s|) = mu [(1 - A) e^{-B |s|} + A] (friction_law.hpp; default constant).
  FallingFriction falling;
  /// Per-element creepages (-), grid layout: when not empty they replace the rigid slip of the
  /// mean creepages, w = V (local_creepage_x, local_creepage_y) (a contact on a curved reference
  /// surface, whose creepages vary across the patch: geometry/curved_contact.hpp).
  GridField local_creepage_x, local_creepage_y;
};

/// Steady rolling for the pressure pn on the grid of `A`. `start` (optional) warm-starts from a
/// solution on the same grid. The returned slip velocities satisfy Eq. 3 directly (recomputed).
TangentialSolution solve_steady_rolling(const InfluenceTable& A, const GridField& pn,
                                        const SteadyRollingInput& in,
                                        const TangentialSolverSettings& settings = {},
                                        const TangentialSolution* start = nullptr);

class CoulombNewton;
struct NewtonFactors;

/// Steady rolling solved again and again on one grid at one speed, with a pressure that changes
/// between the calls (a wheel lowered under its load: geometry/curved_contact.cpp). solve() is
/// solve_steady_rolling; the Newton solver is kept between the calls with its FFT products and
/// its LU factors (coulomb_newton.hpp: the preconditioner of its GMRES, renewed there when
/// GMRES needs more than 30 iterations with them), which serve while the contact elements stay
/// the same. The solution is that of solve_steady_rolling to the Newton solver's tolerance (the
/// factors precondition; they do not change the equations). `A` must outlive the solver.
class SteadyRollingSolver {
 public:
  explicit SteadyRollingSolver(const InfluenceTable& A);
  ~SteadyRollingSolver();
  SteadyRollingSolver(SteadyRollingSolver&&) noexcept;
  SteadyRollingSolver& operator=(SteadyRollingSolver&&) noexcept;

  TangentialSolution solve(const GridField& pn, const SteadyRollingInput& in,
                           const TangentialSolverSettings& settings = {},
                           const TangentialSolution* start = nullptr);
  /// LU factorisations made so far by the kept Newton solver(s).
  int factorisations() const;
  /// The factors of the Newton system held (NewtonFactors; null before the first).
  std::shared_ptr<const NewtonFactors> factors() const;
  /// Another solver's factors (of a nearby state on the same grid) as the first preconditioner
  /// (CoulombNewton::precondition_with: used if made for the same contact elements).
  void precondition_with(std::shared_ptr<const NewtonFactors> factors) {
    seed_ = std::move(factors);
  }

 private:
  const InfluenceTable* A_;
  double speed_ = 0.0;
  std::unique_ptr<CoulombNewton> newton_;
  int earlier_factorisations_ = 0;  // of solvers replaced (another speed)
  std::shared_ptr<const NewtonFactors> seed_;
};

}  // namespace rollnoise::contact
