// Every wheel's contact state (src/noise/wheel_contact.hpp, bogie_wheel_contacts of
// src/vehicle/curve_state.hpp): the inner wheel's mirrored frame, its sign conventions, the loads
// and creepages of the four wheels, and the multibody input of both wheelsets.
#include "noise/wheel_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "core/errors.hpp"
#include "curve_fixture.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"
#include "vehicle/curve_state.hpp"
#include "pipeline/curve_input_checks.hpp"

using namespace noise_test;
namespace rg = rollnoise::geometry;
using rn::WheelId;

namespace {

rn::WheelContactInput wheel_input(WheelId id, double u, double psi, double inv_R) {
  rn::WheelContactInput in;
  in.pair = pair();
  in.material = material();
  in.grid.nx = 16;
  in.lowering_nx = 16;
  in.inverse_radius = inv_R;
  in.speed = kV;
  in.wheel = id;
  in.lateral = u;
  in.yaw = psi;
  in.vertical_load = kQ;
  return in;
}

// the fixture's curve input with the curving table, the wheel lowered on 16 elements too
rn::CurveStateInput table_curve_input(double radius, double cant_deficiency) {
  rn::CurveStateInput in = curve_input(radius, cant_deficiency);
  in.table = table();
  in.lowering_nx = 16;
  return in;
}

const std::vector<WheelId> kFour(rn::kAllWheels.begin(), rn::kAllWheels.end());

}  // namespace

// Tangent track without cant deficiency: the leading inner (left) wheel of the wheelset at
// (u, psi) is the mirror image of the leading outer (right) wheel of the wheelset at (-u, -psi):
// in its own mirrored frame its contact, creepages (K2'), normal force and contact-frame forces
// are the outer's within 1e-6 relative, and in the track frame (lateral towards the outer rail)
// its lateral force has the opposite sign.
TEST(WheelContact, TangentTrackInnerWheelMirrorsTheOuterWheel) {
  const double u = 2e-3, psi = 1e-3;
  const rn::WheelContact in = rn::wheel_contact(wheel_input(WheelId::leading_inner, u, psi, 0.0));
  const rn::WheelContact out =
      rn::wheel_contact(wheel_input(WheelId::leading_outer, -u, -psi, 0.0));
  EXPECT_EQ(in.contact.side, rg::Side::Left);
  auto near = [](double a, double b, double scale) { EXPECT_NEAR(a, b, 1e-6 * scale); };
  near(in.contact.contact_angle, out.contact.contact_angle, out.contact.contact_angle);
  near(in.contact.wheel_s, out.contact.wheel_s, std::abs(out.contact.wheel_s));
  near(in.contact.rail_y, out.contact.rail_y, std::abs(out.contact.rail_y));
  near(in.contact.rolling_radius, out.contact.rolling_radius, out.contact.rolling_radius);
  for (int i = 0; i < 3; ++i) near(in.creepage(i), out.creepage(i), out.creepage.norm());
  near(in.normal_force(), out.normal_force(), out.normal_force());
  const auto fi = in.force_track(), fo = out.force_track();
  const double scale = std::hypot(fo[0], fo[1], fo[2]);
  near(fi[0], fo[0], scale);
  near(fi[1], -fo[1], scale);
  near(fi[2], fo[2], scale);
  near(in.loaded->creep_force[1], out.loaded->creep_force[1], scale);
  std::printf("mirror: inner N %.3f N, outer N %.3f N; xi (%.4e, %.4e, %.5f)\n", in.normal_force(),
              out.normal_force(), in.creepage(0), in.creepage(1), in.creepage(2));
}

// The sign conventions of the four wheels in the 300 m curve (the bogie estimate): each wheel in
// its own contact frame (the inner ones mirrored, curvature -1/R, yaw -psi), so
//   xi_x(outer) + xi_x(inner) = (y_c,outer - y_c,inner)/R  (the rolling-radius terms cancel),
//   xi_y = -psi_side / cos(gamma): negative on the outer, positive on the inner wheel,
//   phi + sin(gamma)/r_c = -cos(gamma)/R on the outer, +cos(gamma)/R on the inner wheel
// (exact to rounding); the vertical loads are Q +- dQ and each patch carries its load (1e-5); the
// leading wheels' lateral creep forces push the axle towards the outer rail (its angle of attack
// points outwards) and the leading outer wheel's resultant is towards the track centre (the flank
// carries the guidance).
TEST(WheelContact, FourWheelsSignConventionsAndLoadsIn300mCurve) {
  const rn::CurveStateInput in = table_curve_input(300.0, 0.08);
  const rn::CurveContactState s = rn::curve_contact_state(in);
  const std::vector<rn::WheelContact> w = rn::bogie_wheel_contacts(in, s, kFour);
  ASSERT_EQ(w.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(w[k].wheel, kFour[k]);
  EXPECT_EQ(w[0].loaded, s.loaded) << "the leading outer wheel is the state's";
  const double R = 300.0;
  for (int axle : {0, 2}) {
    const rn::WheelContact &o = w[axle], &i = w[axle + 1];
    EXPECT_EQ(o.lateral, i.lateral);
    EXPECT_EQ(o.yaw, i.yaw);
    EXPECT_NEAR(o.creepage(0) + i.creepage(0), (o.contact.y - i.contact.y) / R, 1e-12);
    EXPECT_NEAR(o.creepage(1), -o.yaw / std::cos(o.contact.contact_angle), 1e-14);
    EXPECT_NEAR(i.creepage(1), o.yaw / std::cos(i.contact.contact_angle), 1e-14);
    EXPECT_NEAR(o.creepage(2) + std::sin(o.contact.contact_angle) / o.contact.rolling_radius,
                -std::cos(o.contact.contact_angle) / R, 1e-12);
    EXPECT_NEAR(i.creepage(2) + std::sin(i.contact.contact_angle) / i.contact.rolling_radius,
                std::cos(i.contact.contact_angle) / R, 1e-12);
    EXPECT_NEAR(o.vertical_load, kQ + s.load_transfer, 1e-9 * kQ);
    EXPECT_NEAR(i.vertical_load, kQ - s.load_transfer, 1e-9 * kQ);
    EXPECT_EQ(o.other_rolling_radius, i.contact.rolling_radius);
    for (const rn::WheelContact* x : {&o, &i})
      EXPECT_NEAR(x->force_track()[2], x->vertical_load, 1e-5 * kQ);
  }
  EXPECT_EQ(w[2].lateral, s.estimate.trailing.lateral);
  EXPECT_EQ(w[2].yaw, s.estimate.trailing.attack_angle);
  EXPECT_GT(w[1].creepage(1), 0.0);
  EXPECT_GT(w[1].force_track()[1], 0.0) << "leading inner: creep force towards the outer rail";
  EXPECT_LT(w[0].force_track()[1], 0.0) << "leading outer: the flank pushes towards the centre";
  for (const rn::WheelContact& x : w) {
    const auto f = x.force_track();
    std::printf(
        "%-14s u %5.2f mm psi %5.2f mrad s %6.1f mm rail %6.1f mm angle %.3f..%.3f xi "
        "(%+.2e, %+.2e, %+.3f) Q %.1f N %.1f F (%+.1f, %+.1f, %.1f) kN\n",
        rn::wheel_name(x.wheel), 1e3 * x.lateral, 1e3 * x.yaw, 1e3 * x.contact.wheel_s,
        1e3 * x.contact.rail_y, x.loaded->angle_min, x.loaded->angle_max, x.creepage(0),
        x.creepage(1), x.creepage(2), 1e-3 * x.vertical_load, 1e-3 * x.normal_force(), 1e-3 * f[0],
        1e-3 * f[1], 1e-3 * f[2]);
  }
}

// The multibody input of both wheelsets: the trailing wheelset's position, each wheel's load and
// creepages as given (each patch carries its given load); the others default to the static load
// and (K2'); bad values name their key.
TEST(WheelContact, MultibodyInputForBothWheelsets) {
  rn::CurveStateInput in = table_curve_input(500.0, 0.0);
  in.multibody = true;
  in.lateral = 3e-3;
  in.yaw = 2e-3;
  in.trailing_lateral = 1e-3;
  in.trailing_yaw = -0.5e-3;
  in.wheel_load = 90e3;
  in.static_wheel_load = kQ;
  in.wheel_loads[static_cast<int>(WheelId::trailing_inner)] = 70e3;
  const Eigen::Vector3d xi(-1e-3, 1e-3, 0.05);
  in.wheel_creepages[static_cast<int>(WheelId::leading_inner)] = xi;
  const rn::CurveContactState s = rn::curve_contact_state(in);
  const std::vector<rn::WheelContact> w = rn::bogie_wheel_contacts(in, s, kFour);
  EXPECT_EQ(w[0].vertical_load, 90e3);
  EXPECT_EQ(w[1].vertical_load, kQ);
  EXPECT_EQ(w[2].vertical_load, kQ);
  EXPECT_EQ(w[3].vertical_load, 70e3);
  EXPECT_TRUE(w[1].creepage_given);
  EXPECT_EQ(w[1].creepage, xi);
  EXPECT_FALSE(w[2].creepage_given);
  EXPECT_EQ(w[2].lateral, 1e-3);
  EXPECT_EQ(w[3].yaw, -0.5e-3);
  const rg::ContactGeometry c = rg::find_contact(*pair(), {1e-3, -0.5e-3}, rg::Side::Left);
  EXPECT_EQ(w[3].contact.wheel_s, c.wheel_s);
  for (const rn::WheelContact& x : w) EXPECT_NEAR(x.force_track()[2], x.vertical_load, 1e-5 * kQ);

  // the pipeline's input checks name the key (curve_contact_state takes them as a contract)
  auto expect_key = [&](rn::CurveStateInput bad, const std::string& key) {
    try {
      rollnoise::pipeline::check_curve_state_input(bad);
      ADD_FAILURE() << "no InputError for " << key;
    } catch (const rollnoise::InputError& e) {
      EXPECT_EQ(e.key(), key);
    }
  };
  rn::CurveStateInput bad = in;
  bad.trailing_yaw = 0.1;
  expect_key(bad, "trailing_wheelset.yaw");
  bad = in;
  bad.trailing_lateral = std::nan("");
  expect_key(bad, "trailing_wheelset.lateral_displacement");
  bad = in;
  bad.wheel_loads[static_cast<int>(WheelId::trailing_outer)] = -1.0;
  expect_key(bad, "trailing_wheelset.wheel_load");
  bad = in;
  bad.wheel_creepages[static_cast<int>(WheelId::leading_inner)] = Eigen::Vector3d(0, NAN, 0);
  expect_key(bad, "wheelset.inner_creepage");
}

// A wheel lowered from a nearby solved state (WheelContactInput::start) keeps that state's grid
// where it lies on the rail, so that its forces vary smoothly with the wheelset's position, as
// the bogie's equilibrium needs for its last digits (vehicle/bogie_equilibrium.hpp). The 300 m
// curve's leading outer wheel at the flange root (u = 6.2 mm, psi = 6 mrad, the axle's own rolling
// speed, settled to 1e-9), u stepped by 1 um twelve times: the lateral force's second differences
// sum to less than 5 % of its first differences (measured 2.5 %; elements entering the area),
// where each state on its own grid gives 22 % (a grid row more or less between two states);
// started from itself the state is reproduced in one fixed-point iteration within 1e-9 of the load.
TEST(WheelContact, StartFromANearbyStateKeepsTheGridAndTheForcesSmooth) {
  rn::WheelContactInput in = wheel_input(WheelId::leading_outer, 6.2e-3, 6e-3, 1.0 / 300.0);
  in.vertical_load = kQ + 10.4e3;
  in.lowering_settle = 1e-9;
  in.gap_regions = true;
  in.axle_spin = -5.8e-3;
  const rn::WheelContact base = rn::wheel_contact(in);
  rn::WheelContactInput again = in;
  again.start = base.loaded;
  const rn::WheelContact same = rn::wheel_contact(again);
  EXPECT_EQ(same.loaded->iterations, 1);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(same.loaded->force_track[k], base.loaded->force_track[k], 1e-9 * kQ) << k;
  // sum |second differences| / sum |first differences| of the lateral force along u
  auto roughness = [](const std::vector<double>& f) {
    double first = 0.0, second = 0.0;
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      first += std::abs(f[k + 1] - f[k]);
      second += std::abs(f[k + 1] - 2.0 * f[k] + f[k - 1]);
    }
    return second / first;
  };
  std::vector<double> kept, fresh;
  for (int k = 0; k <= 12; ++k) {
    rn::WheelContactInput step = in;
    step.lateral += k * 1e-6;
    fresh.push_back(rn::wheel_contact(step).force_track()[1]);
    step.start = base.loaded;
    const rn::WheelContact w = rn::wheel_contact(step);
    EXPECT_EQ(w.loaded->patch->grid.ny, base.loaded->patch->grid.ny);
    kept.push_back(w.force_track()[1]);
  }
  std::printf("lateral force roughness: kept grid %.3f, own grids %.3f\n", roughness(kept),
              roughness(fresh));
  EXPECT_LT(roughness(kept), 0.05);
  EXPECT_LT(roughness(kept), roughness(fresh));
}
