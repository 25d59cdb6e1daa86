// Each wheel's Hertz state in a Hertzian curve case (vehicle/hertz_wheels.hpp,
// pipeline/squeal_hertz_wheels.hpp; docs/squeal.md Sec. 8.2), on cases/squeal_150m.toml: the
// leading outer wheel without load transfer is the case's own contact; the loads are Q +- dQ of
// (K4); the inner wheel's creepages (K2') mirror the outer's; the semi-axes follow Hertz at the
// case's curvatures. Geometry only (nothing solved): milliseconds.
#include "pipeline/squeal_hertz_wheels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/curve_setup.hpp"

namespace {

using namespace rollnoise;

io::NoiseInputs squeal_150m(const std::vector<std::string>& set = {}) {
  return io::read_noise_inputs(io::CaseReader::from_file(
      std::string(ROLLNOISE_SOURCE_DIR) + "/cases/squeal_150m.toml", set));
}

const noise::HertzWheel& find(const std::vector<noise::HertzWheel>& w, noise::WheelId id) {
  for (const auto& x : w)
    if (x.wheel == id) return x;
  throw std::runtime_error("wheel missing");
}

TEST(HertzWheels, LeadingOuterWheelWithoutLoadTransferIsTheCasesOwnContact) {
  const io::NoiseInputs in = squeal_150m({"curve.cg_height=0"});
  const pipeline::CurvePlacement p = pipeline::resolve_curve(in.contact, in.noise);
  ASSERT_TRUE(p.curve.estimated);
  const auto wheels = pipeline::hertz_curve_wheels(p.contact, in.noise);
  ASSERT_EQ(wheels.size(), 4u) << "curve.wheels defaults to all four in a curve";
  const noise::HertzWheel& lo = find(wheels, noise::WheelId::leading_outer);
  EXPECT_EQ(lo.load_ratio, 1.0);
  const pipeline::ContactCase c = pipeline::hertz_wheel_case(p.contact, lo);
  // the same estimate, the same formulas (K2): equal to rounding (1e-15 relative)
  EXPECT_NEAR(c.creepage.xi_x, p.contact.creepage.xi_x, 1e-15 * std::abs(p.contact.creepage.xi_x));
  EXPECT_NEAR(c.creepage.xi_y, p.contact.creepage.xi_y, 1e-15 * std::abs(p.contact.creepage.xi_y));
  EXPECT_NEAR(c.creepage.phi, p.contact.creepage.phi, 1e-15 * std::abs(p.contact.creepage.phi));
  EXPECT_EQ(c.normal_force, p.contact.normal_force);
  EXPECT_EQ(c.a, p.contact.a);
  EXPECT_EQ(c.grid.dx, p.contact.grid.dx);
  EXPECT_EQ(lo.position.wheel_shift_y, p.curve.position.wheel_shift_y);
  EXPECT_EQ(lo.position.contact_angle, p.curve.position.contact_angle);
}

TEST(HertzWheels, LoadsAreQPlusMinusTheCantDeficiencyTransferAndSemiAxesFollowHertz) {
  const io::NoiseInputs in = squeal_150m();
  const pipeline::CurvePlacement p = pipeline::resolve_curve(in.contact, in.noise);
  const auto wheels = pipeline::hertz_curve_wheels(p.contact, in.noise);
  // (K4): dQ = 2 Q h_d h_cg / s^2, s = 2 l0 = 1.5 m (the estimate's default l0 = 0.75 m)
  const double Q = p.contact.normal_force, dQ = 2.0 * Q * 0.08 * 1.5 / (1.5 * 1.5);
  for (const noise::HertzWheel& w : wheels) {
    // the conical tread has no flange share (K6): Q +- dQ exactly (1e-9 relative)
    EXPECT_NEAR(w.vertical_load, Q + (noise::is_outer(w.wheel) ? dQ : -dQ), 1e-9 * Q)
        << noise::wheel_name(w.wheel);
    // Hertz at the case's curvatures: A, B of the wheel's (a, b, N) equal the case's (1e-12)
    const pipeline::ContactCase c = pipeline::hertz_wheel_case(p.contact, w);
    std::printf("%-15s y %.3f mm psi %.3f mrad Q_w %.1f kN a %.3f mm xi (%.3e, %.3e, %.4f 1/m)\n",
                noise::wheel_name(w.wheel), 1e3 * w.lateral, 1e3 * w.yaw, 1e-3 * w.vertical_load,
                1e3 * c.a, w.creepage(0), w.creepage(1), w.creepage(2));
    const auto h0 = contact::hertz_from_semi_axes(p.contact.a, p.contact.b, Q, p.contact.material);
    const auto h = contact::hertz_from_semi_axes(c.a, c.b, c.normal_force, c.material);
    EXPECT_NEAR(h.A, h0.A, 1e-12 * h0.A);
    EXPECT_NEAR(h.B, h0.B, 1e-12 * h0.B);
    EXPECT_NEAR(c.grid.dx / c.a, p.contact.grid.dx / p.contact.a, 1e-12);  // elements per a
  }
}

TEST(HertzWheels, InnerWheelsCreepagesMirrorTheOuterWheelsInItsOwnFrame) {
  const io::NoiseInputs in = squeal_150m();
  const pipeline::CurvePlacement p = pipeline::resolve_curve(in.contact, in.noise);
  const auto wheels = pipeline::hertz_curve_wheels(p.contact, in.noise);
  const double inv_R = 1.0 / 150.0, r0 = in.noise.wheel_radius;
  for (bool lead : {true, false}) {
    const auto& o =
        find(wheels, lead ? noise::WheelId::leading_outer : noise::WheelId::trailing_outer);
    const auto& i =
        find(wheels, lead ? noise::WheelId::leading_inner : noise::WheelId::trailing_inner);
    const double g = o.position.contact_angle;
    EXPECT_EQ(i.position.contact_angle, g);
    EXPECT_EQ(i.lateral, o.lateral);
    EXPECT_EQ(i.position.wheel_shift_y, -o.position.wheel_shift_y);  // -y (outer), +y (inner)
    // (K2'): xi_x and xi_y change sign in the inner wheel's mirrored frame (1e-15 absolute)
    EXPECT_NEAR(i.creepage(0), -o.creepage(0), 1e-15);
    EXPECT_NEAR(i.creepage(1), -o.creepage(1), 1e-15);
    EXPECT_NEAR(i.creepage(1), o.yaw / std::cos(g), 1e-15);
    // rolling radii r0 +- lambda y on the cone (1e-12 m), spin with kappa = -+1/R
    EXPECT_NEAR(o.rolling_radius + i.rolling_radius, 2.0 * r0, 1e-12);
    EXPECT_NEAR(o.rolling_radius - i.rolling_radius, 2.0 * in.noise.conicity * o.lateral, 1e-12);
    EXPECT_NEAR(i.creepage(2), -std::sin(g) / i.rolling_radius + std::cos(g) * inv_R, 1e-12);
    EXPECT_NEAR(o.creepage(2), -std::sin(g) / o.rolling_radius - std::cos(g) * inv_R, 1e-12);
  }
}

}  // namespace

namespace {

// With per-wheel Hertz states (noise.squeal_wheelsets = "on") the top-level squeal contact is the
// leading outer wheel's state from the estimate with the load transfer, the same case the
// per-wheel run solves for that wheel (bit for bit: one function builds both); without them the
// case's own state (static load Q, the estimate without load transfer).
TEST(HertzWheels, TopLevelSquealContactIsTheLeadingOuterWheelsStateWithTheLoadTransfer) {
  const io::NoiseInputs in = squeal_150m();
  const pipeline::CurvePlacement p = pipeline::resolve_curve(in.contact, in.noise);
  ASSERT_TRUE(pipeline::has_hertz_wheel_states(p, in.noise)) << "squeal_150m ships them on";
  const pipeline::CurvePlacement q = pipeline::leading_outer_placement(p, in.noise);
  const auto wheels = pipeline::hertz_curve_wheels(p.contact, in.noise);
  const noise::HertzWheel& lo = find(wheels, noise::WheelId::leading_outer);
  const pipeline::ContactCase c = pipeline::hertz_wheel_case(p.contact, lo);
  EXPECT_EQ(q.contact.normal_force, c.normal_force);
  EXPECT_EQ(q.contact.a, c.a);
  EXPECT_EQ(q.contact.b, c.b);
  EXPECT_EQ(q.contact.grid.dx, c.grid.dx);
  EXPECT_EQ(q.contact.grid.dy, c.grid.dy);
  EXPECT_EQ(q.contact.creepage.xi_x, c.creepage.xi_x);
  EXPECT_EQ(q.contact.creepage.xi_y, c.creepage.xi_y);
  EXPECT_EQ(q.contact.creepage.phi, c.creepage.phi);
  EXPECT_EQ(q.curve.position.wheel_shift_y, lo.position.wheel_shift_y);
  EXPECT_EQ(q.curve.position.contact_angle, lo.position.contact_angle);
  // the curve setup's estimate is the one with the load transfer: its contact point is the wheel's
  EXPECT_EQ(q.curve.curving.position().wheel_shift_y, lo.position.wheel_shift_y);
  EXPECT_EQ(q.curve.curving.leading.lateral, lo.lateral);
  // the load transfer is in it: N_w = N (Q + dQ) / Q, dQ = 2 Q h_d h_cg / s^2 (K4), 1e-12 relative
  const double Q = p.contact.normal_force, dQ = 2.0 * Q * 0.08 * 1.5 / (1.5 * 1.5);
  EXPECT_NEAR(q.contact.normal_force, Q + dQ, 1e-12 * Q);
  // without the per-wheel run the top level keeps the case's state
  const io::NoiseInputs off = squeal_150m({"noise.squeal_wheelsets=\"off\""});
  EXPECT_FALSE(pipeline::has_hertz_wheel_states(pipeline::resolve_curve(off.contact, off.noise),
                                                off.noise));
}

}  // namespace
