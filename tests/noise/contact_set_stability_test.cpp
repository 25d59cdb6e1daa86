// Squeal with several contacts (noise/stability.hpp, docs/squeal.md Sec. 8).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "dynamics/beam_rail_model.hpp"
#include "noise/contact_transfer.hpp"
#include "noise/stability.hpp"
#include "noise_fixture.hpp"

namespace {

using namespace noise_test;
using cd = std::complex<double>;

rn::ContactPoint wheelset_point(int side, double shift, double offset, double angle) {
  rn::ContactPoint c;
  c.side = side;
  c.position.wheel_shift_y = shift;
  c.position.rail_offset_y = offset;
  c.position.contact_angle = angle;
  c.rail_x = 0.3;
  return c;
}

// The loop of one contact assembled by hand from its parts (rigid wheelset, the rail at the one
// point, the contact), independently of laplace_loop's assembly of rail pairs and blocks; in the
// frame of side +1 (a wheel alone: the mirror image of side -1).
rn::LaplaceLoop single_loop(rn::ContactPoint c, const rd::RailModel& rail,
                            const rn::ContactTransfer& t) {
  c.side = 1;
  const std::vector<rn::ContactPoint> point{c};
  const Eigen::MatrixXd C = rn::rigid_flexibility(wheel().wheelset(), point);
  const double k = hertz().normal_stiffness();
  return rn::LaplaceLoop::one_contact(
      rn::loop_modes(wheel(), point).modes, [C, c, &rail, &t, k](cd s) {
        return Eigen::MatrixXcd(
            C.cast<cd>() / (s * s) + rn::rail_receptance_laplace(rail, s, c.position) +
            rn::contact_receptance_laplace(s, k, kSpeed, t.creep(s), Eigen::Vector3cd::Zero()));
      });
}

// A wheelset in a curve: the outer wheel (side +1) near the flange root, the inner (side -1) on its
// tread; Kalker's constant creep coefficients; band 300 Hz - 2.5 kHz.
struct Wheelset {
  rn::ConstantTransfer kalker =
      rn::ConstantTransfer::kalker(kA, kB, material().shear_modulus(), material().nu);
  std::vector<rn::ContactPoint> points{wheelset_point(1, -8e-3, -6e-3, 0.35),
                                       wheelset_point(-1, 2e-3, 3e-3, 0.03)};
  rd::BeamRailModel rail{rd::uic60_ballasted(), rd::TrackSupport::kContinuous, 0.3};
  std::vector<rn::SquealContact> contacts() const {
    std::vector<rn::SquealContact> c;
    for (const rn::ContactPoint& p : points) c.push_back({p, &kalker, hertz().normal_stiffness()});
    return c;
  }
  rn::StabilityOptions options() const {
    rn::StabilityOptions o;
    o.band_min = 300.0;
    o.band_max = 2500.0;
    return o;
  }
};

}  // namespace

// Without any cross term the wheelset's characteristic equation is the product of the two wheels'
// single-contact equations: every root of (S1) equals the roots of the loop of its own wheel's
// contact alone (1e-8 relative in s) and lies entirely on that wheel (share 1 to 1e-8).
TEST(ContactSetSqueal, UncoupledWheelsHaveTheSingleContactRoots) {
  const Wheelset w;
  const rn::LaplaceLoop loop =
      rn::laplace_loop(wheel(), w.rail, w.contacts(), kSpeed, false, rn::CrossCoupling::none());
  ASSERT_EQ(loop.wheels.size(), 2u);
  const std::vector<rn::ModeRoot> roots = rn::mode_roots(loop, w.options());
  const rd::BeamRailModel rail(rd::uic60_ballasted(), rd::TrackSupport::kContinuous, 0.3);
  int compared = 0;
  for (int side = 0; side < 2; ++side) {
    const std::vector<rn::ModeRoot> ref =
        rn::mode_roots(single_loop(w.points[side], rail, w.kalker), w.options());
    for (const rn::ModeRoot& r : ref) {
      ASSERT_TRUE(r.converged) << r.label;
      const rn::ModeRoot* match = nullptr;
      for (const rn::ModeRoot& c : roots)
        if (c.wheel == side && loop.modes[c.mode].index == r.mode) match = &c;
      ASSERT_NE(match, nullptr) << r.label;
      EXPECT_TRUE(match->converged) << r.label;
      EXPECT_LE(std::abs(match->s - r.s), 1e-8 * std::abs(r.s)) << r.label << " side " << side;
      EXPECT_NEAR(match->wheel_share[side], 1.0, 1e-8) << r.label;
      EXPECT_EQ(match->dominant_wheel, side);
      ++compared;
    }
  }
  EXPECT_EQ(static_cast<std::size_t>(compared), roots.size());
  EXPECT_GT(compared, 10);
}

// Passivity extended to a wheelset: constant (Kalker) friction, normal coupling off, both wheels
// and a flange patch coupled through the rigid wheelset, the flexible wheel and each rail: every
// root decays (Re s < 0; no tolerance) and converged; each root's wheel shares add to 1.
TEST(ContactSetSqueal, WheelsetWithConstantFrictionAndNoNormalCouplingIsPassive) {
  Wheelset w;
  w.points.push_back(wheelset_point(1, -30e-3, -25e-3, 1.2));  // the flange patch of the outer wheel
  const rn::LaplaceLoop loop = rn::laplace_loop(wheel(), w.rail, w.contacts(), kSpeed, false);
  const std::vector<rn::ModeRoot> roots = rn::mode_roots(loop, w.options());
  ASSERT_GT(roots.size(), 10u);
  for (const rn::ModeRoot& r : roots) {
    EXPECT_TRUE(r.converged) << r.label;
    EXPECT_LT(r.s.real(), 0.0) << r.label << " wheel " << r.wheel;
    EXPECT_LT(r.singular_ratio, 1e-8) << r.label;
    EXPECT_NEAR(r.wheel_share[0] + r.wheel_share[1], 1.0, 1e-12);
    std::printf("wheel %d %-14s %8.2f Hz  zeta %.3e  share outer %.3f\n", r.wheel, r.label.c_str(),
                r.frequency, r.damping_ratio, r.wheel_share[0]);
  }
}

// Which wheel squeals: the inner wheel's (side -1) contact given a falling-friction-like lateral
// creep coefficient (f22 < 0: a negative creep damping f22/V, as mu'(v) N V of a saturated contact
// on a falling friction branch; f11, f33 small and positive), the outer wheel Kalker's. Roots go
// unstable, and every unstable root lies on the inner wheel (its share > 0.9); the outer wheel's
// own roots stay stable (the rigid wheelset couples the two wheels only weakly above 300 Hz).
// The clusters of the n = 1 modes (the same mode of both wheels with its sin partner, four
// branches from one uncoupled root, two of them a near-double root ~1e-4 1/s apart) converge: they
// stopped at the first continuation step while the homotopy's tangent took H_s of the undeflated
// H by a central difference wider than the two roots' distance (docs/squeal.md Sec. 8.1); every
// one of the 32 roots converges now.
TEST(ContactSetSqueal, NegativeCreepDampingAtTheInnerWheelDestabilisesTheInnerWheelsModes) {
  Wheelset w;
  Eigen::Matrix3d falling = Eigen::Matrix3d::Zero();
  falling(0, 0) = 1e4;
  falling(1, 1) = -2e5;
  falling(2, 2) = 1.0;
  const rn::ConstantTransfer inner(falling);
  std::vector<rn::SquealContact> contacts = w.contacts();
  contacts[1].transfer = &inner;
  const rn::LaplaceLoop loop = rn::laplace_loop(wheel(), w.rail, contacts, kSpeed, false);
  const std::vector<rn::ModeRoot> roots = rn::mode_roots(loop, w.options());
  int unstable = 0, unconverged = 0;
  for (const rn::ModeRoot& r : roots) {
    if (!r.converged) ++unconverged;
    if (!r.converged)
      std::printf("unconverged: wheel %d %-14s s0 %g%+gi  s %g%+gi steps %d it %d\n", r.wheel,
                  r.label.c_str(), r.s0.real(), r.s0.imag(), r.s.real(), r.s.imag(), r.steps,
                  r.iterations);
    if (!r.unstable || !r.converged) continue;
    ++unstable;
    std::printf("unstable: wheel %d %-14s %8.2f Hz  zeta %.3e  share inner %.3f\n", r.wheel,
                r.label.c_str(), r.frequency, r.damping_ratio, r.wheel_share[1]);
    EXPECT_EQ(r.dominant_wheel, 1) << r.label;
    EXPECT_GT(r.wheel_share[1], 0.9) << r.label;
    EXPECT_LT(r.singular_ratio, 1e-8) << r.label;
  }
  EXPECT_GT(unstable, 0);
  EXPECT_EQ(unconverged, 0);
  EXPECT_EQ(roots.size(), 32u);
}
