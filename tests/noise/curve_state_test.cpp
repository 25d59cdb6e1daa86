// The curve contact state from the profiles (src/vehicle/curve_state.hpp): limits, load transfer,
// the two-point share, the multibody input, friction and cant deficiency.
#include "vehicle/curve_state.hpp"
#include "pipeline/curve_input_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>

#include "core/errors.hpp"
#include "geometry/profile.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"
#include "curve_fixture.hpp"

using namespace noise_test;
namespace rg = rollnoise::geometry;

namespace {

rn::CurveStateInput input(double radius, double cant_deficiency, double mu = 0.3) {
  rn::CurveStateInput in = curve_input(radius, cant_deficiency, mu);
  in.table = table();
  return in;
}

template <class F>
void expect_input_error(F f, const std::string& key) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << key;
  } catch (const rollnoise::InputError& e) {
    EXPECT_EQ(e.key(), key);
  }
}

}  // namespace

// R -> infinity (uncanted track: h_d = s V^2 / (g R) -> 0) at the same speed and load gives the
// tangent state: contact angle, rolling radius, normal load, contact position and spin within
// 1 %, and the creepages that vanish on tangent track within 1 % of their 300 m values.
TEST(CurveState, LargeRadiusGivesTheTangentState) {
  const double inf = std::numeric_limits<double>::infinity();
  const rn::CurveContactState t = rn::curve_contact_state(input(inf, 0.0));
  const rn::CurveContactState c300 = rn::curve_contact_state(input(300.0, 0.08));
  // The S1002/UIC60 contact is very sensitive near the centred position (the contact point moves
  // 12 mm across the wheel for the first 0.5 mm of lateral displacement, docs/noise_loop.md), and
  // u ~ 1/R: at R = 1e5 m (u = 0.1 mm) the contact angle still differs by 5 %, at 1e6 m by 0.6 %
  // (the wheel position by 1.6 %), at 1e7 m (u = 1 um) everything is within 0.2 %.
  const double R = 1e7, hd = 1.5 * kV * kV / (9.81 * R);
  const rn::CurveContactState c = rn::curve_contact_state(input(R, hd));
  std::printf(
      "tangent: gamma %.5f r %.6f N %.1f s %.3f mm rail %.3f mm phi %.5f; R = 1e5 m: %.5f %.6f "
      "%.1f "
      "%.3f %.3f %.5f; xi (%.2e, %.2e) vs 300 m (%.2e, %.2e)\n",
      t.contact.contact_angle, t.contact.rolling_radius, t.normal_force, 1e3 * t.contact.wheel_s,
      1e3 * t.contact.rail_y, t.creepage(2), c.contact.contact_angle, c.contact.rolling_radius,
      c.normal_force, 1e3 * c.contact.wheel_s, 1e3 * c.contact.rail_y, c.creepage(2), c.creepage(0),
      c.creepage(1), c300.creepage(0), c300.creepage(1));
  EXPECT_FALSE(t.two_point);
  EXPECT_NEAR(t.lateral, 0.0, 1e-12);
  // The wheel lowered under Q: the vertical resultant is Q, and N is Q / cos gamma within 0.1 %
  // (the lateral creep force of the spin -sin(gamma)/r leans it; no creepage on tangent track).
  const double tg = t.contact.contact_angle;
  ASSERT_TRUE(t.loaded);
  EXPECT_NEAR(t.loaded->force_track[2], kQ, 1e-5 * kQ);
  EXPECT_NEAR(t.normal_force, kQ / std::cos(tg), 1e-3 * kQ);
  auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
  EXPECT_LT(rel(c.contact.contact_angle, t.contact.contact_angle), 0.01);
  EXPECT_LT(rel(c.contact.rolling_radius, t.contact.rolling_radius), 0.01);
  EXPECT_LT(rel(c.normal_force, t.normal_force), 0.01);
  EXPECT_LT(rel(c.contact.wheel_s, t.contact.wheel_s), 0.01);
  EXPECT_LT(rel(c.contact.rail_y, t.contact.rail_y), 0.01);
  EXPECT_LT(rel(c.creepage(2), t.creepage(2)), 0.01);
  EXPECT_LT(std::abs(c.creepage(0)), 0.01 * std::abs(c300.creepage(0)));
  EXPECT_LT(std::abs(c.creepage(1)), 0.01 * std::abs(c300.creepage(1)));
}

// (K4): dQ/Q = 2 h_d h_cg / s^2 with s = 2 l0; its moment over the n axles balances the
// unbalanced force's moment about the rail plane; the outer wheel gains with a cant deficiency
// and loses with an excess of cant; without a flange contact the tread carries Q + dQ.
TEST(CurveState, LoadTransferFollowsTheCantDeficiency) {
  const double Q = kQ, hd = 0.1, hcg = 1.8, s = 1.5, g = 9.81;
  const double dQ = rn::cant_deficiency_load_transfer(Q, hd, hcg, s);
  // moment balance for n axles, m g = 2 n Q: n (2 dQ) s/2 = m (g h_d / s) h_cg
  const int n = 4;
  EXPECT_NEAR(n * 2.0 * dQ * s / 2.0, (2.0 * n * Q / g) * (g * hd / s) * hcg, 1e-9 * Q);
  const double l0 = rg::find_contact(*pair(), {0.0, 0.0}).y;
  EXPECT_NEAR(l0, 0.75, 0.01);
  for (double h : {0.15, -0.05}) {
    rn::CurveStateInput in = input(1000.0, h);
    const rn::CurveContactState st = rn::curve_contact_state(in);
    EXPECT_NEAR(st.load_transfer, 2.0 * Q * h * in.cg_height / (4.0 * l0 * l0), 1e-9 * Q);
    EXPECT_EQ(st.load_transfer > 0.0, h > 0.0);
    EXPECT_FALSE(st.two_point);
    EXPECT_NEAR(st.tread_load, Q + st.load_transfer, 1e-9 * Q);
  }
  rn::CurveStateInput in = input(1000.0, 0.15);
  in.cg_height = 0.0;
  EXPECT_EQ(rn::curve_contact_state(in).load_transfer, 0.0);
}

// The 300 m curve with mu = 0.4 (the leading axle at its flange in the estimate): the estimate's
// flange force (normal N_f at delta_f, friction mu N_f up the flange slope) has the lateral
// component |Y| and the vertical one Q_f, delta_f the profiles' flange (beyond 1 rad); they are
// reported, while the wheel is lowered under its whole load Q + dQ on the curved surface (the
// patch from the flange root onto the flank carries it, force_track up = Q + dQ); the patch of
// the loop carries that normal force.
TEST(CurveState, EstimatedFlangeShareIsReportedAndThePatchCarriesTheWheelLoad) {
  rn::CurveStateInput in = input(300.0, 0.08, 0.4);
  const rn::CurveContactState st = rn::curve_contact_state(in);
  ASSERT_TRUE(st.two_point);
  const double d = st.flange_angle, mu = in.friction, Nf = st.flange_normal_force;
  std::printf(
      "300 m, mu 0.4: |Y| %.1f kN, delta_f %.3f rad, N_f %.1f kN, Q_f %.1f kN, tread %.1f kN, N "
      "%.1f kN\n",
      1e-3 * st.flange_lateral_force, d, 1e-3 * Nf, 1e-3 * st.flange_vertical_load,
      1e-3 * st.tread_load, 1e-3 * st.normal_force);
  EXPECT_GT(d, 1.0);
  EXPECT_NEAR(d, table()->flange_angle, 0.0);
  // force on the wheel from the flange contact: normal (-sin d, cos d), friction mu (cos d, sin d)
  const double lateral = -Nf * std::sin(d) + mu * Nf * std::cos(d),
               vertical = Nf * std::cos(d) + mu * Nf * std::sin(d);
  EXPECT_NEAR(-lateral, st.flange_lateral_force, 1e-6 * kQ);
  EXPECT_NEAR(vertical, st.flange_vertical_load, 1e-6 * kQ);
  EXPECT_NEAR(st.flange_vertical_load, rn::flange_vertical_load(st.flange_lateral_force, d, mu),
              1e-6 * kQ);
  EXPECT_GT(st.flange_vertical_load, 0.05 * kQ);
  // The patch on the curved surface carries the whole vertical load (the flank's share too): the
  // estimate's flange share is reported, not added.
  EXPECT_NEAR(st.tread_load, kQ + st.load_transfer, 1e-9 * kQ);
  ASSERT_TRUE(st.loaded);
  EXPECT_NEAR(st.loaded->force_track[2], st.tread_load, 1e-5 * kQ);
  EXPECT_GT(st.lateral_creep_force, 0.0) << "the creep force pushes the leading axle outwards";
  const rollnoise::contact::ContactPatch patch = rn::solve_curve_patch(in, st);
  EXPECT_NEAR(patch.normal.force, st.normal_force, 1e-6 * st.normal_force);
}

// The multibody input: the given position, load and (optionally) creepages; contact, patch and
// the rest from the profiles; the estimate's own position given as multibody input reproduces
// its contact and creepages.
TEST(CurveState, MultibodyInputPlacesTheContactAndKeepsGivenCreepages) {
  rn::CurveStateInput in = input(500.0, 0.0);
  in.multibody = true;
  in.lateral = 3e-3;
  in.yaw = 2e-3;
  in.wheel_load = 80e3;
  const rn::CurveContactState a = rn::curve_contact_state(in);
  const rg::ContactGeometry c = rg::find_contact(*pair(), {3e-3, 2e-3});
  EXPECT_FALSE(a.estimated);
  EXPECT_EQ(a.contact.wheel_s, c.wheel_s);
  EXPECT_EQ(a.contact.contact_angle, c.contact_angle);
  EXPECT_EQ(a.tread_load, 80e3);
  EXPECT_FALSE(a.two_point);
  EXPECT_NEAR(a.creepage(1), -2e-3 / std::cos(c.contact_angle), 1e-15);
  EXPECT_NEAR(a.creepage(2),
              -std::sin(c.contact_angle) / c.rolling_radius - std::cos(c.contact_angle) / 500.0,
              1e-12);
  in.creepage = Eigen::Vector3d(1e-3, -2e-3, -0.1);
  const rn::CurveContactState b = rn::curve_contact_state(in);
  EXPECT_EQ(b.creepage, *in.creepage);
  EXPECT_EQ(b.contact.wheel_s, a.contact.wheel_s);

  const rn::CurveContactState e = rn::curve_contact_state(input(500.0, 0.08));
  rn::CurveStateInput m = input(500.0, 0.08);
  m.multibody = true;
  m.lateral = e.lateral;
  m.yaw = e.yaw;
  m.wheel_load = e.tread_load;
  const rn::CurveContactState f = rn::curve_contact_state(m);
  EXPECT_EQ(f.contact.wheel_s, e.contact.wheel_s);
  EXPECT_NEAR((f.creepage - e.creepage).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.normal_force, e.normal_force, 1e-9 * kQ);
}

// The pipeline's checks of the state's inputs (pipeline/curve_input_checks.hpp) name the case key;
// curve_contact_state itself takes them as a contract.
TEST(CurveState, BadInputNamesTheKey) {
  rn::CurveStateInput in = input(300.0, 0.0);
  in.cg_height = -1.0;
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "curve.cg_height");
  in = input(300.0, 0.0);
  in.wheel_load = 0.0;
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "contact.normal_force");
  in = input(300.0, 0.0);
  in.multibody = true;
  in.lateral = 0.1;
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "wheelset.lateral_displacement");
  in.lateral = 0.0;
  in.yaw = std::nan("");
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "wheelset.yaw");
  in.yaw = 0.0;
  in.creepage = Eigen::Vector3d(0.0, INFINITY, 0.0);
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "wheelset.creepage");
  in = input(300.0, 0.0);
  in.cg_height = 100.0;  // dQ = 2 Q h_d h_cg / s^2 above Q: the estimate's load transfer
  in.cant_deficiency = 0.15;
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "curve.cg_height");
  in = input(300.0, 0.0);
  in.wheelbase = 0.0;
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "curve.wheelbase");
  in = input(300.0, 0.0);
  EXPECT_NO_THROW(rollnoise::pipeline::check_curve_state_input(in));
  in.pair.reset();
  expect_input_error([&] { rollnoise::pipeline::check_curve_state_input(in); }, "contact.geometry");
}

// Friction and cant deficiency move the state where physics says (docs/noise_loop.md Sec. 7.1
// prints this table): more friction gives larger creep forces against the same gravitational
// stiffness (K7), so the leading axle is pushed further out with a larger attack angle and a
// larger flange force; more cant deficiency moves the trailing axle outwards (smaller attack
// angle of the leading one) and loads the outer wheel. Without (K7) the balance is homogeneous in
// the saturated creep forces and, without cant deficiency, the creepages could not depend on mu
// (the reported defect).
TEST(CurveState, FrictionAndCantDeficiencyMoveTheState) {
  auto print = [](double R, double mu, double hd, const rn::CurveContactState& s) {
    std::printf(
        "| %.0f | %.1f | %.2f | %.2f | %.2f | %.2f | %+.2e | %+.2e | %.3f | %.3f | %.1f | %.1f |\n",
        R, mu, hd, 1e3 * s.lateral, 1e3 * s.estimate.trailing.lateral, 1e3 * s.yaw, s.creepage(0),
        s.creepage(1), s.creepage(2), s.contact.contact_angle, 1e-3 * s.tread_load,
        1e-3 * s.flange_vertical_load);
  };
  std::printf(
      "| R (m) | mu | h_d (m) | u1 (mm) | u2 (mm) | psi1 (mrad) | xi_x | xi_y | phi (1/m) | gamma "
      "(rad) | Q_t (kN) | Q_f (kN) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  if (std::getenv("ROLLNOISE_CURVE_TABLE"))  // the whole table of docs/noise_loop.md Sec. 7.1
    for (double R : {300.0, 500.0, 1000.0})
      for (double mu : {0.2, 0.3, 0.4})
        for (double hd : {0.0, 0.08, 0.15})
          print(R, mu, hd, rn::curve_contact_state(input(R, hd, mu)));
  for (double R : {300.0, 1000.0}) {
    // friction at h_d = 0.08 m: the leading axle further out, more flange force, less tread load
    rn::CurveContactState prev;
    for (double mu : {0.2, 0.3, 0.4}) {
      const rn::CurveContactState s = rn::curve_contact_state(input(R, 0.08, mu));
      print(R, mu, 0.08, s);
      if (mu > 0.2) {
        EXPECT_GE(s.lateral, prev.lateral - 1e-9) << R << " " << mu;
        EXPECT_GE(s.flange_lateral_force, prev.flange_lateral_force) << R << " " << mu;
        EXPECT_LE(s.tread_load, prev.tread_load) << R << " " << mu;
        EXPECT_NE(s.creepage(1), prev.creepage(1)) << R << " " << mu;
      }
      prev = s;
    }
    if (R == 300.0) {
      EXPECT_TRUE(prev.two_point);
    }
    // cant deficiency at mu = 0.3: the trailing axle moves outwards, the attack angle drops, the
    // outer wheel gains load
    for (double hd : {0.0, 0.15}) {
      const rn::CurveContactState s = rn::curve_contact_state(input(R, hd, 0.3));
      const rn::CurveContactState m = rn::curve_contact_state(input(R, 0.08, 0.3));
      print(R, 0.3, hd, s);
      const double sign = hd > 0.08 ? 1.0 : -1.0;
      EXPECT_GT(sign * (s.estimate.trailing.lateral - m.estimate.trailing.lateral), 0.0)
          << R << " " << hd;
      EXPECT_LT(sign * (s.yaw - m.yaw), 0.0) << R << " " << hd;
      EXPECT_GT(sign * (s.tread_load - m.tread_load), 0.0) << R << " " << hd;
    }
  }
  // The reported defect: at 300 m without cant deficiency the creepages respond to mu only with
  // the gravitational stiffness (K7).
  rn::BogieCurvingInput b;
  b.radius = 300.0;
  b.wheel_load = kQ;
  b.profiles = table();
  const Eigen::Matrix3d f = kalker();
  b.f11 = f(0, 0);
  b.f22 = f(1, 1);
  auto xi_y = [&](double mu, bool k7) {
    b.friction = mu;
    b.gravitational_stiffness = k7;
    return rn::estimate_bogie_curving(b).xi_y;
  };
  EXPECT_NEAR(xi_y(0.2, false), xi_y(0.4, false), 1e-12);
  EXPECT_GT(std::abs(xi_y(0.4, true) - xi_y(0.2, true)), 0.03 * std::abs(xi_y(0.3, true)));
}
