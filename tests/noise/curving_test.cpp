// The quasi-static curving estimate (src/vehicle/curving.hpp).
#include "vehicle/curving.hpp"
#include "pipeline/curve_input_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "geometry/profile.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"
#include "noise_fixture.hpp"

using namespace noise_test;

namespace {

rn::BogieCurvingInput bogie(double radius, double cant_deficiency = 0.0) {
  rn::BogieCurvingInput in;
  in.radius = radius;
  in.speed = kSpeed;
  in.cant_deficiency = cant_deficiency;
  in.wheel_load =
      kN / 2;  // the paper's normal force is 10 t; here a 5 t wheel (same patch: approx.)
  const Eigen::Matrix3d f = kalker();
  in.f11 = f(0, 0);
  in.f22 = f(1, 1);
  return in;
}

}  // namespace

// Free curving (no flange contact, no cant deficiency, linear creep): Boocock's rigid bogie.
// The yaw of the bogie vanishes, psi_1 = -psi_2 = a/R, and the axles run outside the pure-rolling
// line so that xi_x = -f22 a^2 / (f11 l0 R) on both: everything scales exactly like 1/R.
TEST(Curving, FreeCurvingYawAndCreepagesScaleAsOneOverRadius) {
  double first = 0;
  for (double R : {3000.0, 6000.0, 12000.0}) {
    rn::BogieCurvingInput in = bogie(R);
    in.saturation = false;
    const rn::CurvingEstimate e = rn::estimate_bogie_curving(in);
    const double a = 1.25, l0 = in.half_distance();
    EXPECT_EQ(e.leading.flange, 0);
    EXPECT_NEAR(e.leading.attack_angle * R, a, 1e-9);
    EXPECT_NEAR(e.trailing.attack_angle * R, -a, 1e-9);
    EXPECT_NEAR(e.leading.xi_x_outer * R, -in.f22 * a * a / (in.f11 * l0), 1e-9);
    EXPECT_NEAR(e.xi_y * R, -a / std::cos(e.contact_angle), 1e-9);
    if (R == 3000.0) first = e.leading.lateral * R;
    EXPECT_NEAR(e.leading.lateral * R, first, 1e-9 * std::abs(first));
  }
  // With saturation the scaling holds to within 2 % at these radii (small creepages).
  const rn::CurvingEstimate e1 = rn::estimate_bogie_curving(bogie(3000.0));
  const rn::CurvingEstimate e2 = rn::estimate_bogie_curving(bogie(6000.0));
  EXPECT_NEAR(e2.xi_y * 6000.0 / (e1.xi_y * 3000.0), 1.0, 0.02);
  EXPECT_NEAR(e2.leading.lateral * 6000.0 / (e1.leading.lateral * 3000.0), 1.0, 0.02);
}

// Signs in the frame of curving.hpp (y towards the outer rail): the leading axle points outwards
// (psi > 0, xi_y < 0), the trailing one inwards; the spin of the outer wheel is negative for a
// positive contact angle; in a sharp curve the leading axle runs against the outer rail (flange
// force inwards), more so with more cant deficiency.
TEST(Curving, SignConventionsAndFlangeContactInSharpCurves) {
  std::printf(
      "   R (m)  h_d (m)  flange  y1 (mm)  psi1 (mrad)  psi2 (mrad)  Y1 (kN)   xi_x      xi_y      "
      "phi (1/m)\n");
  double previous_flange_force = 0.0;
  for (double hd : {0.0, 0.05, 0.1}) {
    for (double R : {300.0, 500.0, 1000.0}) {
      const rn::CurvingEstimate e = rn::estimate_bogie_curving(bogie(R, hd));
      std::printf("  %6.0f  %6.2f  %6d  %7.2f  %10.3f  %10.3f  %8.2f  %+.2e %+.2e %+.4f\n", R, hd,
                  e.leading.flange, 1e3 * e.leading.lateral, 1e3 * e.leading.attack_angle,
                  1e3 * e.trailing.attack_angle, 1e-3 * e.leading.flange_force, e.xi_x, e.xi_y,
                  e.phi);
      EXPECT_GT(e.leading.attack_angle, 0.0);
      EXPECT_LT(e.xi_y, 0.0);
      EXPECT_LT(e.trailing.attack_angle, e.leading.attack_angle);
      EXPECT_LT(e.phi, 0.0);
      EXPECT_GT(e.contact_angle, 0.0);
      EXPECT_NEAR(e.contact_shift_on_wheel, -e.leading.lateral, 0.0);
      EXPECT_EQ(e.position().wheel_shift_y, e.contact_shift_on_wheel);
      if (R == 300.0) {
        EXPECT_EQ(e.leading.flange, 1) << "h_d " << hd;
        EXPECT_LE(e.leading.flange_force, 0.0);
        EXPECT_LE(e.leading.flange_force, previous_flange_force + 1e-6);  // grows inwards with h_d
        previous_flange_force = e.leading.flange_force;
      }
    }
  }
}

// Tangent track: no yaw, no longitudinal or lateral creepage, and the spin of the coned tread
// alone, -sin(gamma)/r0.
TEST(Curving, TangentTrackLeavesOnlyTheConicalSpin) {
  const rn::CurvingEstimate e =
      rn::estimate_bogie_curving(bogie(std::numeric_limits<double>::infinity()));
  EXPECT_NEAR(e.leading.attack_angle, 0.0, 1e-12);  // root finding of the free state (K7)
  EXPECT_NEAR(e.xi_x, 0.0, 1e-15);
  EXPECT_NEAR(e.xi_y, 0.0, 1e-15);
  EXPECT_NEAR(e.phi, -std::sin(std::atan(0.15)) / 0.46, 1e-12);
}

// The pipeline's checks of the estimate's inputs (pipeline/curve_input_checks.hpp) name the case
// key; estimate_bogie_curving itself takes them as a contract.
TEST(Curving, BadInputNamesTheKey) {
  rn::BogieCurvingInput in = bogie(-300.0);
  try {
    rollnoise::pipeline::check_bogie_curving_input(in);
    FAIL();
  } catch (const rollnoise::InputError& e) {
    EXPECT_EQ(e.key(), "curve.radius");
  }
  in = bogie(300.0);
  EXPECT_NO_THROW(rollnoise::pipeline::check_bogie_curving_input(in));
  in.f22 = 0.0;
  try {
    rollnoise::pipeline::check_bogie_curving_input(in);
    FAIL();
  } catch (const rollnoise::InputError& e) {
    EXPECT_EQ(e.key(), "curving.f22");
  }
}

// Nadal's limit (K6): with a flange angle delta_f = 1.2 rad, tan(delta_f) = 2.572; a flange
// friction of 2.6 reaches it, 2.5 stays below. The estimate states it as a std::domain_error (a
// model range, no key); the pipeline's check names the key that set the flange friction:
// friction.mu unless curving.flange_friction is given apart.
TEST(Curving, NadalLimitIsADomainErrorOfTheEstimateAndAnInputErrorNamingItsKey) {
  rn::BogieCurvingInput in = bogie(300.0, 0.1);
  in.flange_angle = 1.2;
  in.flange_friction = 2.5;
  EXPECT_TRUE(rn::flange_friction(in).below_nadal_limit());
  EXPECT_NO_THROW(rollnoise::pipeline::check_bogie_curving_input(in));
  in.flange_friction = 2.6;
  EXPECT_FALSE(rn::flange_friction(in).below_nadal_limit());
  EXPECT_THROW(rn::estimate_bogie_curving(in), std::domain_error);
  try {
    rollnoise::pipeline::check_bogie_curving_input(in);
    FAIL();
  } catch (const rollnoise::InputError& e) {
    EXPECT_EQ(e.key(), "curving.flange_friction");
  }
  in.flange_friction = std::numeric_limits<double>::quiet_NaN();  // mu_f = friction.mu
  in.friction = 2.6;
  try {
    rollnoise::pipeline::check_bogie_curving_input(in);
    FAIL();
  } catch (const rollnoise::InputError& e) {
    EXPECT_EQ(e.key(), "friction.mu");
    EXPECT_NE(std::string(e.what()).find("Nadal"), std::string::npos) << e.what();
  }
  in.flange_angle = 0.0;  // no flange share: no limit
  EXPECT_TRUE(rn::flange_friction(in).below_nadal_limit());
}

// The S1002 wheel on the UIC60 rail (1:40, 1435 mm) as the profile table: the centred wheelset has
// no rolling-radius difference and a tread contact; the contact jumps to the flange within
// 5-8 mm; in a 300 m curve the leading axle runs at that clearance and the loop's contact position
// is the table's there.
TEST(Curving, ProfileTableFromS1002OnUic60) {
  namespace rg = rollnoise::geometry;
  const rg::WheelRailPair pair(rollnoise::io::read_profile(model_path("profiles/MBench_S1002_v3.prw")),
                               rollnoise::io::read_profile(model_path("profiles/MBench_UIC60_v3.prr")));
  auto table =
      std::make_shared<rn::ProfileCurvingTable>(rn::profile_curving_table(pair, 0.01, 0.5e-3));
  const std::size_t centre = table->lateral.size() / 2;
  EXPECT_EQ(table->lateral[centre], 0.0);
  EXPECT_NEAR(table->rolling_radius_difference[centre], 0.0, 1e-9);
  EXPECT_LT(table->contact_angle[centre], 0.1);
  EXPECT_GT(table->flange_clearance, 5e-3);
  EXPECT_LT(table->flange_clearance, 8e-3);
  rn::BogieCurvingInput in = bogie(300.0, 0.05);
  in.profiles = table;
  const rn::CurvingEstimate e = rn::estimate_bogie_curving(in);
  std::printf(
      "S1002/UIC60: flange clearance %.2f mm; R = 300 m, h_d = 50 mm: y1 %.2f mm, psi1 "
      "%.2f mrad, xi = (%.2e, %.2e, %.3f 1/m), contact angle %.3f rad, on the wheel at "
      "s = %.1f mm, on the rail at %.1f mm\n",
      1e3 * table->flange_clearance, 1e3 * e.leading.lateral, 1e3 * e.leading.attack_angle, e.xi_x,
      e.xi_y, e.phi, e.contact_angle, 1e3 * e.contact_shift_on_wheel, 1e3 * e.rail_contact_offset);
  EXPECT_EQ(e.leading.flange, 1);
  EXPECT_NEAR(e.leading.lateral, table->flange_clearance, 1e-12);
  EXPECT_NEAR(e.contact_angle, table->at(table->contact_angle, table->flange_clearance), 1e-12);
  EXPECT_NEAR(e.position().wheel_shift_y, table->at(table->wheel_position, e.leading.lateral),
              1e-12);
  EXPECT_NEAR(e.position().rail_offset_y, table->at(table->rail_position, e.leading.lateral),
              1e-12);
  EXPECT_LT(e.xi_y, 0.0);
  EXPECT_LT(e.phi, 0.0);
}
