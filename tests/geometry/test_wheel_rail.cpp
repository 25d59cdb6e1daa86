// Wheel-rail contact geometry: contact point, undeformed distance, and through contact::solve_patch
// the Hertzian (circle on circle) and the non-Hertzian (S1002 on UIC60) contact patch.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "core/errors.hpp"
#include "geometry/profile.hpp"
#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"
#include "support/test_inputs.hpp"

using namespace rollnoise;
using namespace rollnoise::geometry;

namespace {

using rollnoise::test_support::kProfiles;
constexpr double kWheelLoad = 98.1e3;  // 20 t per wheelset: 98.1 kN per wheel

WheelRailPair s1002_on_uic60() {
  return WheelRailPair(io::read_profile(kProfiles + "MBench_S1002_v3.prw"),
                       io::read_profile(kProfiles + "MBench_UIC60_v3.prr"));
}

// A circular arc z = sign (ρ - sqrt(ρ² - y²)) sampled every 0.2 mm on [-half, half].
Profile arc(double rho, double sign, double half, ProfileKind kind) {
  std::vector<double> y, z;
  const int n = static_cast<int>(std::round(2 * half / 0.2e-3));
  for (int i = 0; i <= n; ++i) {
    const double t = -half + 2 * half * i / n;
    y.push_back(t);
    z.push_back(sign * (rho - std::sqrt(rho * rho - t * t)));
  }
  return Profile(y, z, kind, "arc");
}

// Number of 4-connected groups of elements with pn > 0.
int contact_regions(const contact::ContactPatch& p) {
  const contact::Grid& g = p.grid;
  std::vector<int> mark(g.size(), 0);
  int regions = 0;
  for (int k = 0; k < g.size(); ++k) {
    if (!(p.normal.pn[k] > 0.0) || mark[k]) continue;
    ++regions;
    std::vector<int> stack{k};
    mark[k] = 1;
    while (!stack.empty()) {
      const int e = stack.back();
      stack.pop_back();
      const int ix = e % g.nx, iy = e / g.nx;
      const int nb[4][2] = {{ix - 1, iy}, {ix + 1, iy}, {ix, iy - 1}, {ix, iy + 1}};
      for (const auto& q : nb) {
        if (q[0] < 0 || q[1] < 0 || q[0] >= g.nx || q[1] >= g.ny) continue;
        const int f = g.index(q[0], q[1]);
        if (p.normal.pn[f] > 0.0 && !mark[f]) {
          mark[f] = 1;
          stack.push_back(f);
        }
      }
    }
  }
  return regions;
}

// Root of f on [a, b] by bisection (f(a) and f(b) of opposite signs).
double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

// Circle on circle: a wheel whose profile is a circular arc (crowned, lateral radius 0.5 m,
// rolling radius 0.46 m) on a rail head that is a circular arc (0.3 m) has constant curvatures:
// the geometry gives A = 1/(2 r0), B = (1/ρ_rail + 1/ρ_wheel)/2, and through contact::solve_patch
// the Hertzian patch of hertz_from_curvatures (semi-axes within one element, p0 within 3 %).
TEST(WheelRailGeometry, CircleOnCircleGivesHertzianPatch) {
  const double rho_r = 0.3, rho_w = 0.5;
  TrackParameters track;
  track.gauge_point_depth = 1e-3;  // the arc rail head is shallow
  track.rail_inclination = 0.0;
  const Profile wheel = arc(rho_w, -1.0, 40e-3, ProfileKind::Wheel);
  const Profile rail = arc(rho_r, 1.0, 35e-3, ProfileKind::Rail);
  // Choose the gauge so that the wheel's crown stands on the rail's crown when centred.
  const WheelRailPair probe(wheel, rail, track);
  track.gauge = 2.0 * (probe.wheel_offset() + probe.gauge_point());
  const WheelRailPair pair(wheel, rail, track);

  const ContactGeometry c = find_contact(pair, {0.0, 0.0});
  EXPECT_NEAR(c.pose.roll, 0.0, 1e-12);
  EXPECT_NEAR(c.wheel_s, 0.0, 1e-5);
  EXPECT_NEAR(c.rail_y, 0.0, 1e-5);
  EXPECT_NEAR(c.contact_angle, 0.0, 1e-4);
  EXPECT_NEAR(c.rolling_radius, 0.46, 1e-7);
  EXPECT_NEAR(c.rail_curvature, 1.0 / rho_r, 1e-3 / rho_r);
  EXPECT_NEAR(c.wheel_curvature, -1.0 / rho_w, 1e-3 / rho_w);
  EXPECT_NEAR(c.A, 1.0 / (2 * 0.46), 1e-6);
  EXPECT_NEAR(c.B, 0.5 * (1.0 / rho_r + 1.0 / rho_w), 1e-3 * c.B);

  const contact::Material m;
  const contact::HertzContact hz = contact::hertz_from_curvatures(c.A, c.B, kWheelLoad, m);
  const contact::ContactPatch patch = solve_wheel_rail_patch(pair, c, kWheelLoad, m);
  const PatchShape s = patch_shape(patch);
  const double dx = patch.grid.dx, dy = patch.grid.dy;
  std::cout << "circle on circle: Hertz a = " << hz.a * 1e3 << " mm, b = " << hz.b * 1e3
            << " mm, p0 = " << hz.p0 / 1e6 << " MPa; patch " << s.length() / 2 * 1e3 << " x "
            << s.width() / 2 * 1e3 << " mm (half), pmax " << s.peak_pressure / 1e6
            << " MPa, elements " << dx * 1e3 << " x " << dy * 1e3 << " mm, ellipse deviation "
            << patch_ellipse_deviation(patch) << "\n";
  EXPECT_NEAR(s.length() / 2, hz.a, dx);
  EXPECT_NEAR(s.width() / 2, hz.b, dy);
  EXPECT_NEAR(0.5 * (s.x_min + s.x_max), 0.0, dx);
  EXPECT_NEAR(0.5 * (s.y_min + s.y_max), 0.0, dy);
  EXPECT_NEAR(s.peak_pressure, hz.p0, 0.03 * hz.p0);
  EXPECT_NEAR(s.area, M_PI * hz.a * hz.b, 0.05 * M_PI * hz.a * hz.b);
  EXPECT_LT(patch_ellipse_deviation(patch), 0.15);
  EXPECT_EQ(contact_regions(patch), 1);
}

// The undeformed distance on the grid against an independent 3-D computation: along the contact
// normal through each grid point, the distance between the rail (a cylinder along x) and the
// wheel (a body of revolution about its rolled axle). Flange contact (δ ≈ 61°, roll -6 mrad),
// where the projection factor cos δ of the wheel's longitudinal curvature matters.
TEST(WheelRailGeometry, UndeformedDistanceMatchesExactSurfaceDistanceInFlangeContact) {
  const WheelRailPair pair = s1002_on_uic60();
  for (double u : {0.0, 7e-3}) {
    const ContactGeometry c = find_contact(pair, {u, 0.0});
    contact::Grid g;
    g.nx = 11;
    g.ny = 9;
    g.dx = 1e-3;
    g.dy = 0.5e-3;
    g.x_min = -5.5e-3;
    g.y_min = -2.25e-3;
    const contact::GridField h = undeformed_distance(pair, c, g);
    const double cd = std::cos(c.contact_angle), sd = std::sin(c.contact_angle);
    const WheelsetPose& p = c.local_pose;  // right wheel: no yaw here
    ASSERT_EQ(p.yaw, 0.0);
    const double cr = std::cos(p.roll), sr = std::sin(p.roll);
    double worst = 0.0;
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix) {
        // Point on the normal line: C + x e_x + y_c e_yc + t e_zc (track frame, z down).
        auto at = [&](double t, double& X, double& Y, double& Z) {
          X = c.x + g.x(ix);
          Y = c.y + g.y(iy) * cd + t * sd;
          Z = c.z - g.y(iy) * sd + t * cd;
        };
        auto rail = [&](double t) {  // > 0 inside the rail
          double X, Y, Z;
          at(t, X, Y, Z);
          return Z - pair.rail_z(Y);
        };
        auto wheel = [&](double t) {  // > 0 outside the wheel (further from the axle than r)
          double X, Y, Z;
          at(t, X, Y, Z);
          const double dy = Y - p.lateral, dz = Z - p.vertical;
          const double xi = cr * dy + sr * dz, zeta = -sr * dy + cr * dz;  // R_x(-φ)
          const double radius = std::hypot(X, zeta);
          return radius -
                 (pair.wheelset().nominal_radius + pair.wheel().z(xi - pair.wheel_offset()));
        };
        const double t_rail = bisect(rail, -3e-3, 3e-3);
        const double t_wheel = bisect(wheel, -3e-3, 3e-3);
        const double exact = t_rail - t_wheel;
        const double err = std::abs(h[g.index(ix, iy)] - exact);
        worst = std::max(worst, err / std::max(exact, 1e-6));
      }
    std::cout << "u = " << u * 1e3 << " mm, contact angle " << c.contact_angle
              << " rad: largest relative error of h " << worst << "\n";
    EXPECT_LT(worst, 0.003) << "u = " << u;  // measured 3e-5 (tread), 1e-3 (flange)
  }
}

// S1002 on UIC60 (1:40, gauge 1435, back-to-back 1360), wheelset centred, 20 t per wheelset.
// The contact point is on the rail crown near the taping line; the lateral gap is nearly
// conformal and has a second near-contact 10-13 mm towards the gauge side, so the single patch is
// clearly not the Hertz ellipse of the curvatures at the contact point: it is shorter, spans the
// plateau with two pressure maxima, and its peak pressure is far above Hertz's p0.
TEST(WheelRailGeometry, S1002OnUIC60CentredGivesSingleNonEllipticPatch) {
  const WheelRailPair pair = s1002_on_uic60();
  const ContactGeometry c = find_contact(pair, {0.0, 0.0});
  EXPECT_NEAR(c.pose.roll, 0.0, 1e-12);
  EXPECT_NEAR(c.rolling_radius, 0.46, 0.5e-3);
  EXPECT_GT(c.contact_angle, 0.0);
  EXPECT_LT(c.contact_angle, 0.05);
  EXPECT_GT(c.wheel_s, 0.0);  // on the tread, a few mm on the field side of the taping line
  EXPECT_LT(c.wheel_s, 6e-3);
  EXPECT_NEAR(c.rail_curvature, 1.0 / 0.3, 0.01 / 0.3);  // the UIC60 crown radius R300

  const contact::Material m;
  const contact::HertzContact hz = hertz_estimate(c, kWheelLoad, m);
  const contact::ContactPatch patch = solve_wheel_rail_patch(pair, c, kWheelLoad, m);
  const PatchShape s = patch_shape(patch);
  const double deviation = patch_ellipse_deviation(patch);
  std::cout << "S1002/UIC60 centred: contact on the rail at y = " << c.rail_y * 1e3
            << " mm, on the wheel at s = " << c.wheel_s * 1e3 << " mm, contact angle "
            << c.contact_angle << " rad, rolling radius " << c.rolling_radius * 1e3
            << " mm, A = " << c.A << " 1/m, B = " << c.B << " 1/m\n"
            << "  Hertz: a = " << hz.a * 1e3 << " mm, b = " << hz.b * 1e3
            << " mm, p0 = " << hz.p0 / 1e6 << " MPa, area " << M_PI * hz.a * hz.b * 1e6
            << " mm2\n  patch: " << s.length() * 1e3 << " x " << s.width() * 1e3 << " mm (y from "
            << s.y_min * 1e3 << " to " << s.y_max * 1e3 << " mm), area " << s.area * 1e6
            << " mm2, peak " << s.peak_pressure / 1e6 << " MPa, ellipse deviation " << deviation
            << ", grid " << patch.grid.nx << " x " << patch.grid.ny << "\n";
  EXPECT_NEAR(s.force, kWheelLoad, 1e-6 * kWheelLoad);
  EXPECT_EQ(contact_regions(patch), 1);
  // Non-elliptic: the row lengths differ from the ellipse of the same extents by a large part of
  // the length (a Hertzian patch: < 0.15, see CircleOnCircleGivesHertzianPatch) ...
  EXPECT_GT(deviation, 0.3);
  // ... and the peak pressure is more than 15 % above Hertz's for the same curvatures.
  EXPECT_GT(s.peak_pressure, 1.15 * hz.p0);
  // The patch reaches into the second near-contact region (rail y ≈ -19 mm, y_c ≈ -12 mm).
  EXPECT_LT(s.y_min, -12e-3);
  EXPECT_GT(patch_length_at(patch, -11.5e-3), 0.8 * s.length());
}

// The rolling-radius difference of the new S1002/UIC60 1:40 pair grows with the lateral
// displacement; at u = 3 mm the equivalent conicity (r_right - r_left)/(2u) is about 0.2
// (new S1002 on 1:40 UIC60 at 1435 mm: between 0.1 and 0.3). The left wheel is the mirror image:
// the left contact at -u equals the right contact at +u, and the roll lifts the wheel with the
// larger radius.
TEST(WheelRailGeometry, LateralDisplacementGivesConicityAndMirrorSymmetry) {
  const WheelRailPair pair = s1002_on_uic60();
  const double u = 3e-3;
  const ContactGeometry right = find_contact(pair, {u, 0.0}, Side::Right);
  const ContactGeometry left = find_contact(pair, {u, 0.0}, Side::Left);
  const double conicity = (right.rolling_radius - left.rolling_radius) / (2 * u);
  std::cout << "u = 3 mm: r_right = " << right.rolling_radius * 1e3
            << " mm, r_left = " << left.rolling_radius * 1e3 << " mm, conicity " << conicity
            << ", roll " << right.pose.roll << " rad\n";
  EXPECT_GT(conicity, 0.1);
  EXPECT_LT(conicity, 0.3);
  EXPECT_LT(right.pose.roll, 0.0);  // the right wheel (larger radius) is lifted
  const ContactGeometry mirrored = find_contact(pair, {-u, 0.0}, Side::Left);
  EXPECT_NEAR(mirrored.rolling_radius, right.rolling_radius, 1e-12);
  EXPECT_NEAR(mirrored.contact_angle, right.contact_angle, 1e-12);
  EXPECT_NEAR(mirrored.rail_y, right.rail_y, 1e-12);
  EXPECT_NEAR(mirrored.pose.roll, -right.pose.roll, 1e-12);
}

// Both wheels of one wheelset position share its equilibrium pose: the search from the pose
// (find_contact_at_pose, what the profile table and the wheel contacts use to solve the roll
// iteration once per position) finds the same contact as the search from the position, to the
// bit; without curvatures the point, angle and radius are the same and the curvatures are left 0.
TEST(WheelRailGeometry, ContactFromTheSharedPoseEqualsTheSearchFromThePosition) {
  const WheelRailPair pair = s1002_on_uic60();
  ContactOptions point_only;
  point_only.curvatures = false;
  for (const double u : {-4e-3, 0.0, 2.5e-3, 7e-3})  // 7 mm: on the flange
    for (const Side side : {Side::Right, Side::Left}) {
      const ContactGeometry full = find_contact(pair, {u, 2e-3}, side);
      const WheelsetPose pose = pair.equilibrium({u, 2e-3});
      const ContactGeometry shared = find_contact_at_pose(pair, pose, side);
      EXPECT_EQ(shared.rolling_radius, full.rolling_radius);
      EXPECT_EQ(shared.contact_angle, full.contact_angle);
      EXPECT_EQ(shared.wheel_s, full.wheel_s);
      EXPECT_EQ(shared.rail_y, full.rail_y);
      EXPECT_EQ(shared.A, full.A);
      EXPECT_EQ(shared.B, full.B);
      EXPECT_EQ(shared.pose.roll, full.pose.roll);
      const ContactGeometry point = find_contact_at_pose(pair, pose, side, point_only);
      EXPECT_EQ(point.rolling_radius, full.rolling_radius);
      EXPECT_EQ(point.contact_angle, full.contact_angle);
      EXPECT_EQ(point.wheel_s, full.wheel_s);
      EXPECT_EQ(point.rail_y, full.rail_y);
      EXPECT_NE(full.A, 0.0);
      EXPECT_EQ(point.A, 0.0);
      EXPECT_EQ(point.B, 0.0);
      EXPECT_EQ(point.rail_curvature, 0.0);
    }
}

// Beyond the flange clearance (about 6 mm for this pair) the contact jumps to the flange: a
// contact angle above 60° (S1002's flange flank is at 70°), a rolling radius over 475 mm.
TEST(WheelRailGeometry, LargeLateralDisplacementGivesFlangeContact) {
  const WheelRailPair pair = s1002_on_uic60();
  const ContactGeometry tread = find_contact(pair, {5.5e-3, 0.0});
  const ContactGeometry flange = find_contact(pair, {7e-3, 0.0});
  std::cout << "flange contact at u = 7 mm: s = " << flange.wheel_s * 1e3
            << " mm, rail y = " << flange.rail_y * 1e3 << " mm, contact angle "
            << flange.contact_angle << " rad, rolling radius " << flange.rolling_radius * 1e3
            << " mm\n";
  EXPECT_LT(tread.contact_angle, 0.5);
  EXPECT_GT(flange.contact_angle, 60.0 * M_PI / 180.0);
  EXPECT_LT(flange.contact_angle, 71.0 * M_PI / 180.0);
  EXPECT_GT(flange.rolling_radius, 0.475);
  EXPECT_LT(flange.wheel_s, -35e-3);  // on the flange
  // The grid for the long, narrow flange patch (Hertz b/a ≈ 1/20) resolves its width with
  // narrower elements, and covers it (the patch does not touch the border).
  const contact::Material m;
  const contact::HertzContact hz = hertz_estimate(flange, kWheelLoad, m);
  const contact::ContactPatch patch = solve_wheel_rail_patch(pair, flange, kWheelLoad, m);
  const PatchShape s = patch_shape(patch);
  std::cout << "  Hertz a = " << hz.a * 1e3 << " mm, b = " << hz.b * 1e3
            << " mm, p0 = " << hz.p0 / 1e6 << " MPa; patch " << s.length() * 1e3 << " x "
            << s.width() * 1e3 << " mm, area " << s.area * 1e6 << " mm2 (Hertz "
            << M_PI * hz.a * hz.b * 1e6 << "), peak " << s.peak_pressure / 1e6 << " MPa, grid "
            << patch.grid.nx << " x " << patch.grid.ny << "\n";
  EXPECT_NEAR(s.force, kWheelLoad, 1e-6 * kWheelLoad);
  EXPECT_LT(patch.grid.dy, patch.grid.dx);
  EXPECT_GE(s.width() / patch.grid.dy, 12.0);
  EXPECT_GT(s.length(), 10.0 * s.width());
}

// A yawed wheelset (angle of attack ψ) in flange contact: the contact point leads the wheel's
// axle line by about r tan δ sin ψ (the classic flange lead), and without yaw there is no lead.
TEST(WheelRailGeometry, YawedWheelsetFlangeContactLeadsByRTanDeltaSinPsi) {
  const WheelRailPair pair = s1002_on_uic60();
  EXPECT_EQ(find_contact(pair, {7e-3, 0.0}).x, 0.0);
  for (double psi : {5e-3, -5e-3}) {
    const ContactGeometry c = find_contact(pair, {7e-3, psi});
    // The wheel's own axle line passes x = -ξ sin ψ cos φ at the axle coordinate ξ of the contact.
    const double xi = pair.wheel_offset() + c.wheel_s;
    const double lead = c.x + xi * std::sin(psi) * std::cos(c.pose.roll);
    const double expected = c.rolling_radius * std::tan(c.contact_angle) * std::sin(psi);
    EXPECT_NEAR(lead, expected, 0.05 * std::abs(expected)) << "yaw " << psi;
  }
}

// The grid chosen from the Hertz estimate is centred on the contact point, has square elements
// and covers the lateral range where the gap is small.
TEST(WheelRailGeometry, ChosenGridCoversSmallGapRegion) {
  const WheelRailPair pair = s1002_on_uic60();
  const ContactGeometry c = find_contact(pair, {0.0, 0.0});
  const contact::Material m;
  const contact::HertzContact hz = hertz_estimate(c, kWheelLoad, m);
  const contact::Grid g = choose_grid(pair, c, kWheelLoad, m);
  EXPECT_EQ(g.nx, 40);
  EXPECT_DOUBLE_EQ(g.dx, g.dy);
  EXPECT_NEAR(g.x_min, -1.25 * hz.a, 1e-12);
  const double y_lo = g.y_min, y_hi = g.y_min + g.ny * g.dy;
  EXPECT_LE(y_lo, -1.25 * hz.b);
  EXPECT_GE(y_hi, 1.25 * hz.b);
  // at the ends of the y-range the gap exceeds the Hertz approach
  EXPECT_GT(lateral_gap(pair, c, y_lo), hz.approach);
  EXPECT_GT(lateral_gap(pair, c, y_hi), hz.approach);
}
