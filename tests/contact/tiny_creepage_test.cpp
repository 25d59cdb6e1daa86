// Tiny creepages: in full adhesion the steady problem is linear in the creepage
// (s = w + S p = 0 with |p| far below mu pn), so the forces at creepage 1e-50 (or 1e-200, where
// squared norms underflow) are exactly 1e-50/1e-9 times those at 1e-9, up to the solver's
// tolerance. Before, the Newton solver stalled below ~1e-46 (float LU factors saw the residual as
// zero).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/forces.hpp"
#include "contact/steady_rolling.hpp"
#include "paper_case.hpp"

using namespace rollnoise::contact;
using namespace rollnoise::testing;

namespace {

struct Solved {
  TangentialForces f;
  int adhesion, contact;
};

Solved solve(const Creepage& c) {
  const ContactPatch& patch = paper_patch();
  SteadyRollingInput in;
  in.mu = kMu;
  in.speed = kSpeed;
  in.creepage = c;
  const TangentialSolution s = solve_steady_rolling(patch.influence, patch.normal.pn, in);
  return {total_forces(patch.grid, s.px, s.py), s.count(ElementState::adhesion), patch.normal.contact_elements()};
}

Creepage along(int direction, double value) {
  Creepage c;
  (direction == 0 ? c.xi_x : direction == 1 ? c.xi_y : c.phi) = value;
  return c;
}

}  // namespace

class TinyCreepage : public ::testing::TestWithParam<int> {};

TEST_P(TinyCreepage, ForcesScaleLinearlyWithTheCreepageInFullAdhesion) {
  const double reference = 1e-9;  // rad/m for spin; full adhesion on the paper's grid
  const Solved ref = solve(along(GetParam(), reference));
  ASSERT_EQ(ref.adhesion, ref.contact) << "the reference must be in full adhesion (linear regime)";
  const double force_scale = std::hypot(ref.f.Fx, ref.f.Fy);
  ASSERT_GT(force_scale, 0.0);
  for (const double tiny : {1e-50, 1e-200}) {
    const Solved s = solve(along(GetParam(), tiny));
    const double k = tiny / reference;
    EXPECT_EQ(s.adhesion, s.contact) << tiny;
    // each component to 1e-9 of the force scale (the solver's relative tolerance is 1e-11); Mz with
    // the contact half-length 7.18 mm as lever arm for the components that vanish by symmetry
    EXPECT_NEAR(s.f.Fx / k, ref.f.Fx, 1e-9 * force_scale) << tiny;
    EXPECT_NEAR(s.f.Fy / k, ref.f.Fy, 1e-9 * force_scale) << tiny;
    EXPECT_NEAR(s.f.Mz / k, ref.f.Mz, 1e-9 * (std::abs(ref.f.Mz) + force_scale * 7.18e-3)) << tiny;
  }
}

INSTANTIATE_TEST_SUITE_P(XiXXiYSpin, TinyCreepage, ::testing::Values(0, 1, 2));
