// One wheel lowered vertically under its wheel load (src/geometry/loaded_contact.hpp) against
// CONTACT module 1 with a prescribed vertical force (tests/data/contact/C1_u3, README Sec. 4).
#include "geometry/loaded_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"
#include "support/test_inputs.hpp"

using namespace rollnoise;
using namespace rollnoise::geometry;

namespace {

using rollnoise::test_support::kProfiles;
const std::string kContactOut =
    std::string(ROLLNOISE_TEST_DATA) + "/contact/C1_u3/u3_vert_d2.out";

// The values printed below a header line of CONTACT's .out whose first word is `first`
// (the last such block in the file), by header name.
std::map<std::string, double> printed_block(const std::string& first) {
  std::ifstream f(kContactOut);
  EXPECT_TRUE(f.good()) << kContactOut;
  std::string line, header, values;
  while (std::getline(f, line)) {
    std::istringstream w(line);
    std::string word;
    if (w >> word && word == first) {
      header = line;
      std::getline(f, values);
    }
  }
  std::map<std::string, double> out;
  std::istringstream h(header), v(values);
  std::string name;
  double x;
  while (h >> name && v >> x) out[name] = x;
  return out;
}

}  // namespace

// CONTACT's u3_vert_d2 (u = 3 mm, psi = 2 mrad, R = 300 m, vertical force 98.1 kN prescribed,
// planar contact): with CONTACT's creepages, the wheel lowered vertically under the same load
// gives CONTACT's resultant on the rail in the track frame (FX, FY, FZ(TR)) within 2 % of its
// magnitude, and the normal force, the creep forces, the contact angle and the contact positions
// within 2 % (CONTACT's creepages moved from its reference point to ours). CONTACT: body 1 = rail, creepages (rail - wheel)/V, forces on the rail; rollnoise:
// body 1 = the wheel, so both the creepages and the forces change sign.
TEST(LoadedContact, TreadContactUnderVerticalLoadMatchesContactModule1) {
  const WheelRailPair pair(io::read_profile(kProfiles + "MBench_S1002_v3.prw"),
                           io::read_profile(kProfiles + "MBench_UIC60_v3.prr"));
  const ContactGeometry c = find_contact(pair, {3e-3, 2e-3});
  auto track = printed_block("FX(TR)");
  auto patch = printed_block("FN");
  auto kin = printed_block("CHI");
  auto place = printed_block("XCP(TR)");
  ASSERT_EQ(track.size(), 6u);
  ASSERT_EQ(kin.size(), 6u);

  VerticalLoadInput in;
  in.vertical_load = track["FZ(TR)"];
  in.material = contact::Material{210e9, 0.28};
  // CONTACT's creepages hold at its contact reference point (D = 2: the weighted centre of the
  // interpenetration area), XCP(TR), YCP(R); ours is the minimum-gap point, 0.17 mm away towards
  // the gauge side. The rigid slip w = (xi_x - phi y, xi_y + phi x) moved to our point.
  const double phi = -kin["CPHI"] * 1e3;
  const double ds = (c.rail_y - place["YCP(R)"] * 1e-3) / std::cos(c.contact_angle);
  const double dx = c.x - place["XCP(TR)"] * 1e-3;
  in.rolling = contact::SteadyRollingInput(
      0.3, kin["VELOC"] * 1e-3,
      contact::Creepage{-kin["CKSI"] - phi * ds, -kin["CETA"] + phi * dx, phi}, 1.0 / 6.0);
  const LoadedContact w = lower_under_vertical_load(pair, c, in);
  // On the rail, track frame with z down: minus the wheel's (longitudinal, lateral, up).
  const double fx = -w.force_track[0], fy = -w.force_track[1], fz = w.force_track[2];
  const double resultant = std::hypot(track["FX(TR)"], track["FY(TR)"], track["FZ(TR)"]);
  std::printf(
      "u3 vertical load: rollnoise FX, FY, FZ(TR) = %.0f %.0f %.0f N (CONTACT %.0f %.0f %.0f); N "
      "%.0f (%.0f), Fx %.0f (%.0f), Fs %.0f (%.0f); angle %.4f (%.4f); rail %.2f (%.2f), wheel "
      "%.2f (%.2f) mm; approach %.4f (%.4f) mm; %d iterations, grid %d x %d\n",
      fx, fy, fz, track["FX(TR)"], track["FY(TR)"], track["FZ(TR)"], w.normal_force, patch["FN"],
      -w.creep_force[0], patch["FX"], -w.creep_force[1], patch["FS"], c.contact_angle,
      -place["DELTCP(TR)"], c.rail_y * 1e3, place["YCP(R)"], c.wheel_s * 1e3,
      printed_block("XCP(W)")["YCP(W)"], w.patch->normal.approach * 1e3, printed_block("FN/G")["APPROACH"],
      w.iterations, w.patch->grid.nx, w.patch->grid.ny);
  const double tol = 0.02;
  EXPECT_NEAR(fz, track["FZ(TR)"], 1e-6 * resultant);  // (V1) holds
  EXPECT_LT(std::hypot(fx - track["FX(TR)"], fy - track["FY(TR)"], fz - track["FZ(TR)"]),
            tol * resultant);
  EXPECT_NEAR(fx, track["FX(TR)"], tol * std::abs(track["FX(TR)"]));
  EXPECT_NEAR(fy, track["FY(TR)"], tol * std::abs(track["FY(TR)"]));
  EXPECT_NEAR(w.normal_force, patch["FN"], tol * patch["FN"]);
  EXPECT_NEAR(-w.creep_force[0], patch["FX"], tol * std::abs(patch["FX"]));
  EXPECT_NEAR(-w.creep_force[1], patch["FS"], tol * std::abs(patch["FS"]));
  EXPECT_NEAR(c.contact_angle, -place["DELTCP(TR)"], tol * std::abs(place["DELTCP(TR)"]));
  EXPECT_NEAR(c.rail_y * 1e3, place["YCP(R)"], tol * std::abs(place["YCP(R)"]));
  EXPECT_NEAR(w.patch->normal.approach * 1e3, printed_block("FN/G")["APPROACH"],
              tol * printed_block("FN/G")["APPROACH"]);
  EXPECT_GE(w.iterations, 2);
}

// The tangential share of (V1): with zero creepage the normal force is exactly Q / cos(delta),
// and a lateral creep force F_y on the wheel changes it by -F_y tan(delta).
TEST(LoadedContact, NormalForceCarriesTheVerticalLoadWithTheCreepForce) {
  const WheelRailPair pair(io::read_profile(kProfiles + "MBench_S1002_v3.prw"),
                           io::read_profile(kProfiles + "MBench_UIC60_v3.prr"));
  const ContactGeometry c = find_contact(pair, {3e-3, 2e-3});
  VerticalLoadInput in;
  in.vertical_load = 98.1e3;
  in.material = contact::Material{210e9, 0.28};
  in.grid.nx = 16;
  in.rolling = contact::SteadyRollingInput(0.3, 20.0, {0.0, 0.0, 0.0});
  const LoadedContact free = lower_under_vertical_load(pair, c, in);
  EXPECT_NEAR(free.normal_force, in.vertical_load / std::cos(c.contact_angle), 1e-9 * 98.1e3);
  EXPECT_EQ(free.iterations, 1);
  in.rolling.creepage = {0.0, -2e-3, 0.0};
  const LoadedContact w = lower_under_vertical_load(pair, c, in);
  const double fy = w.creep_force[1];
  EXPECT_GT(fy, 0.0);  // the creep force opposes the creepage
  EXPECT_NEAR(w.normal_force,
              (in.vertical_load - fy * std::sin(c.contact_angle)) / std::cos(c.contact_angle),
              1e-8 * in.vertical_load);
  EXPECT_NEAR(w.force_track[2], in.vertical_load, 1e-8 * in.vertical_load);
}

namespace {

// K2 (docs/noise_loop.md Sec. 7) at the outer (right) wheel's contact, wheel convention.
contact::Creepage k2_creepage(const WheelRailPair& pair, const ContactGeometry& c, double R) {
  const double l0 = find_contact(pair, {0.0, 0.0}).y, r0 = pair.wheelset().nominal_radius;
  const double ri = find_contact(pair, {c.pose.lateral, c.pose.yaw}, Side::Left).rolling_radius;
  const double g = c.contact_angle;
  return {l0 / R - (c.rolling_radius - ri) / (2.0 * r0), -c.pose.yaw / std::cos(g),
          -std::sin(g) / c.rolling_radius - std::cos(g) / R};
}

VerticalLoadInput curve_input(const WheelRailPair& pair, const ContactGeometry& c, double Q,
                              double R, int nx, bool curved) {
  VerticalLoadInput in;
  in.vertical_load = Q;
  in.material = contact::Material{210e9, 0.28};
  in.grid.nx = nx;
  in.rolling = contact::SteadyRollingInput(0.3, 70 / 3.6, k2_creepage(pair, c, R), 1.0 / 6.0);
  in.curved = curved;
  in.yaw = c.pose.yaw;
  in.inverse_radius = 1.0 / R;
  return in;
}

}  // namespace

// The limit where the patch is flat: at the tread contact of u = 3 mm (the contact angle varies
// by 0.02 rad across the patch) the curved reference surface gives the planar patch's resultant
// within 1 %, and at a tenth of the load (a patch half as wide) within 0.3 %.
TEST(LoadedContact, CurvedSurfaceReducesToThePlaneForAFlatPatch) {
  const WheelRailPair pair(io::read_profile(kProfiles + "MBench_S1002_v3.prw"),
                           io::read_profile(kProfiles + "MBench_UIC60_v3.prr"));
  const ContactGeometry c = find_contact(pair, {3e-3, 2e-3});
  for (double Q : {98.1e3, 9.81e3}) {
    const LoadedContact p = lower_under_vertical_load(pair, c, curve_input(pair, c, Q, 300, 24, false));
    const LoadedContact w = lower_under_vertical_load(pair, c, curve_input(pair, c, Q, 300, 24, true));
    const double d = std::hypot(p.force_track[0] - w.force_track[0],
                                p.force_track[1] - w.force_track[1],
                                p.force_track[2] - w.force_track[2]) /
                     std::hypot(p.force_track[0], p.force_track[1], p.force_track[2]);
    std::printf("flat limit Q = %.0f N: planar (%.0f, %.0f, %.0f), curved (%.0f, %.0f, %.0f) N, "
                "angles %.4f..%.4f rad, difference %.2e, %d iterations\n",
                Q, p.force_track[0], p.force_track[1], p.force_track[2], w.force_track[0],
                w.force_track[1], w.force_track[2], w.angle_min, w.angle_max, d, w.iterations);
    EXPECT_LT(d, Q > 5e4 ? 0.01 : 0.003);
    EXPECT_NEAR(w.force_track[2], Q, 1e-5 * Q);  // the curved iteration stops at 1e-5 Q
  }
}

// The 300 m case's leading outer wheel (u = 6.20 mm, psi = 7.786 mrad): the patch wraps from the
// flange root onto the flank. CONTACT module 1 with its curved-surface option (the run's
// input is not in the repository) gives on the wheel lateral -28.5 kN, longitudinal 9.9 kN, at
// the vertical force of rollnoise's tread load Q_t = 98.9 kN (the same convention as its u3 runs,
// tests/data/contact/C1_u3; our planar patch at 98.9 kN reproduces the rollnoise numbers
// -26.6 kN, 12.7 kN). The curved reference surface: within 5 % laterally, 10 % longitudinally.
// Our own check: the resultant changes by < 0.5 % from the 16- to the 24-element grid (x and s
// refined together), and the patch spans the contact angles from the flange root (< 0.4 rad) to
// the flank (> 0.9 rad). ROLLNOISE_FLANGE_STUDY=<Q in N> prints a study (u = 6.20, 6.25 mm; 16,
// 24, 32 elements; planar and curved).
TEST(LoadedContact, FlangeRootPatchWrapsOntoTheFlank) {
  const WheelRailPair pair(io::read_profile(kProfiles + "MBench_S1002_v3.prw"),
                           io::read_profile(kProfiles + "MBench_UIC60_v3.prr"));
  const char* env = std::getenv("ROLLNOISE_FLANGE_STUDY");
  const double Q = env && std::atof(env) > 0 ? std::atof(env) : 98.9e3;
  auto solve = [&](double u, int n, bool curved) {
    const ContactGeometry c = find_contact(pair, {u, 7.786e-3});
    VerticalLoadInput in = curve_input(pair, c, Q, 300, n, curved);
    in.grid.min_elements_across = n;
    const LoadedContact w = lower_under_vertical_load(pair, c, in);
    std::printf("u %.2f mm n %d %s: force on wheel (%.0f, %.0f, %.0f) N, N %.0f, angles "
                "%.3f..%.3f (contact point %.3f), grid %d x %d, %d iterations\n",
                u * 1e3, n, curved ? "curved" : "planar", w.force_track[0], w.force_track[1],
                w.force_track[2], w.normal_force, w.angle_min, w.angle_max, c.contact_angle,
                w.patch->grid.nx, w.patch->grid.ny, w.iterations);
    return w;
  };
  if (env) {
    for (double u : {6.20e-3, 6.25e-3})
      for (int n : {16, 24, 32})
        for (bool curved : {false, true}) solve(u, n, curved);
    return;
  }
  const LoadedContact w = solve(6.20e-3, 24, true);
  const LoadedContact coarse = solve(6.20e-3, 16, true);
  EXPECT_NEAR(w.force_track[1], -28.5e3, 0.05 * 28.5e3);
  EXPECT_NEAR(w.force_track[0], 9.9e3, 0.10 * 9.9e3);
  EXPECT_NEAR(w.force_track[2], Q, 1e-5 * Q);  // the curved iteration stops at 1e-5 Q
  EXPECT_LT(w.angle_min, 0.4);
  EXPECT_GT(w.angle_max, 0.9);
  for (int i : {0, 1})
    EXPECT_LT(std::abs(w.force_track[i] - coarse.force_track[i]), 0.005 * std::abs(w.force_track[i]));
}

// Tangent track without cant deficiency: the left wheel of the wheelset at (-u, -psi) is the
// mirror image of the right wheel at (u, psi); lowered under the same load on the curved surface
// with the mirrored creepages, the two contacts agree within 1e-6 relative (the left one is
// computed in the mirrored frame, so its numbers read like the right's).
TEST(LoadedContact, TangentTrackSidesMirror) {
  const WheelRailPair pair(io::read_profile(kProfiles + "MBench_S1002_v3.prw"),
                           io::read_profile(kProfiles + "MBench_UIC60_v3.prr"));
  const ContactGeometry right = find_contact(pair, {2e-3, 1e-3}, Side::Right);
  const ContactGeometry left = find_contact(pair, {-2e-3, -1e-3}, Side::Left);
  auto lower = [&](const ContactGeometry& c) {
    VerticalLoadInput in;
    in.vertical_load = 98.1e3;
    in.material = contact::Material{210e9, 0.28};
    in.grid.nx = 16;
    in.rolling = contact::SteadyRollingInput(
        0.3, 20.0, {1e-3, -c.local_pose.yaw, -std::sin(c.contact_angle) / c.rolling_radius});
    in.curved = true;
    in.yaw = c.local_pose.yaw;
    return lower_under_vertical_load(pair, c, in);
  };
  const LoadedContact r = lower(right), l = lower(left);
  const double scale = std::hypot(r.force_track[0], r.force_track[1], r.force_track[2]);
  EXPECT_NEAR(l.geometry.contact_angle, r.geometry.contact_angle, 1e-6 * r.geometry.contact_angle);
  EXPECT_NEAR(l.geometry.wheel_s, r.geometry.wheel_s, 1e-6 * std::abs(r.geometry.wheel_s));
  EXPECT_NEAR(l.normal_force, r.normal_force, 1e-6 * r.normal_force);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(l.force_track[i], r.force_track[i], 1e-6 * scale) << i;
}
