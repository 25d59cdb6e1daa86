// The bogie in equilibrium (src/vehicle/bogie_equilibrium.hpp): the balance (B2) on a model
// contact (the solver's limits: tangent track, rigid bogie, radial axles) and on the exact contacts
// of S1002/UIC60 (the residual, the tangent track).
#include "vehicle/bogie_equilibrium.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "curve_fixture.hpp"

using namespace noise_test;

namespace {

// A typical passenger bogie (models/vehicle/passenger_bogie.toml).
rn::VehicleParameters passenger_bogie() {
  rn::VehicleParameters v;
  v.carbody_mass = 32000.0;
  v.frame_mass = 2600.0;
  v.wheelset_mass = 1500.0;
  v.primary_longitudinal_stiffness = 12e6;
  v.primary_lateral_stiffness = 4.5e6;
  v.axlebox_semi_spacing = 1.0;
  v.secondary_yaw_stiffness = 3.0e5;
  v.bogie_centre_distance = 19.0;
  return v;
}

rn::CurveStateInput bogie_curve_input(double radius, double cant_deficiency) {
  return curve_input(radius, cant_deficiency);
}

// A model contact (no flange): a conical wheelset (conicity lambda, contact half distance l0,
// radius r0) with Kalker's linear creep law (f11, f22 per wheel, no saturation) and the
// gravitational stiffness k_g: F = -k_g y + 2 f22 psi, M = 2 l0 f11 (l0 kappa - lambda y / r0)
// (curving.hpp (K2), (K3)), T = 2 r0 f11 eps.
struct ModelContact {
  double lambda = 0.4, l0 = 0.75, r0 = 0.46, f11 = 8e6, f22 = 7e6, k_g = 1e6, radius = 300.0;
  rn::AxleContactForces operator()(const rn::AxleQuery& q) const {
    const double y = q.y, psi = q.psi, eps = q.eps, t = q.t;
    rn::AxleContactForces f;
    const double kappa = t / radius;
    f.lateral = -k_g * y + 2.0 * f22 * psi;
    f.yaw = 2.0 * l0 * f11 * (l0 * kappa - lambda * y / r0);
    f.torque = 2.0 * r0 * f11 * eps;  // both wheels' xi_x lowered by eps
    return f;
  }
};

// The model contact whose coarse lateral force (AxleQuery::coarse) jumps by 0.06 Q every few
// tenths of a nanometre of y (as a coarse grid's flange patch can, at a coarser scale); counts the
// coarse and the full evaluations.
rn::AxleForceFunction jumpy_when_coarse(const ModelContact& m, int& coarse, int& full) {
  return [&m, &coarse, &full](const rn::AxleQuery& q) {
    rn::AxleContactForces f = m(q);
    (q.coarse ? coarse : full) += 1;
    if (q.coarse) f.lateral += (std::sin(q.y * 1e10) > 0.0 ? 0.03 : -0.03) * kQ;
    return f;
  };
}

// `guessed` (Newton from a guess) balances to 1e-6 Q, took no continuation step and fewer contact
// evaluations than `way` (the continuation), and its axles sit where way's do within `tolerance`
// (m, rad).
void expect_the_same_state_sooner(const rn::BogieEquilibrium& guessed,
                                  const rn::BogieEquilibrium& way, double tolerance) {
  EXPECT_LE(guessed.max_residual(), 1e-6 * kQ);
  EXPECT_EQ(guessed.continuation_steps, 0);
  EXPECT_LT(guessed.contact_evaluations, way.contact_evaluations);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(guessed.lateral[i], way.lateral[i], tolerance) << i;
    EXPECT_NEAR(guessed.yaw[i], way.yaw[i], tolerance) << i;
  }
}

rn::BogieEquilibriumInput model_input(double radius, double cant_deficiency) {
  rn::BogieEquilibriumInput in;
  in.curve = bogie_curve_input(radius, cant_deficiency);
  in.vehicle = passenger_bogie();
  return in;
}

}  // namespace

// On the model contact (R = 1000 m: the model has no flange, its axles stay within the solver's
// 10 mm) every equation of (B2) holds to 1e-6 Q after the continuation.
TEST(BogieEquilibrium, ModelContactBalances) {
  ModelContact m;
  m.radius = 1000.0;
  const rn::BogieEquilibrium e = rn::solve_bogie_equilibrium(model_input(1000.0, 0.08), m);
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
  EXPECT_GT(e.iterations, 0);
  EXPECT_GT(e.yaw[0], 0.0);  // the leading axle turned towards the outer rail
}

// Coarse contacts that cannot lead the way give way to the full ones: a model contact whose coarse
// lateral force jumps by 0.06 Q every few tenths of a nanometre of y (as a coarse grid's flange
// patch can, at a coarser scale) never reaches the way's 1e-2 Q; the continuation goes on with the
// full contacts and every equation holds to 1e-6 Q, at the smooth contact's solution.
TEST(BogieEquilibrium, CoarseContactsThatCannotLeadTheWayGiveWayToTheFullOnes) {
  ModelContact m;
  m.radius = 1000.0;
  int coarse = 0, full = 0;
  const rn::BogieEquilibrium e =
      rn::solve_bogie_equilibrium(model_input(1000.0, 0.08), jumpy_when_coarse(m, coarse, full));
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
  EXPECT_GT(coarse, 0);
  EXPECT_GT(full, 20);  // more than the last digits alone
  const rn::BogieEquilibrium smooth = rn::solve_bogie_equilibrium(model_input(1000.0, 0.08), m);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(e.yaw[i], smooth.yaw[i], 1e-9) << i;
}

// A guess at the curve (BogieEquilibriumInput::guess) that Newton can start from: the state the
// continuation reaches (within 1e-9 m, 1e-9 rad), with no continuation step and fewer contact
// evaluations. The guess is 1 mm and 1 mrad off on every axle and 1 mm off on the frame.
TEST(BogieEquilibrium, AGuessAtTheCurveReachesTheContinuationsStateWithFewerEvaluations) {
  ModelContact m;
  m.radius = 1000.0;
  const rn::BogieEquilibrium way = rn::solve_bogie_equilibrium(model_input(1000.0, 0.08), m);
  rn::BogieEquilibriumInput in = model_input(1000.0, 0.08);
  rn::BogieGuess g;
  for (int i = 0; i < 2; ++i) g.lateral[i] = way.lateral[i] + 1e-3, g.yaw[i] = way.yaw[i] + 1e-3;
  g.bogie_lateral = way.bogie_lateral + 1e-3, g.bogie_yaw = way.bogie_yaw;
  in.guess = g;
  expect_the_same_state_sooner(rn::solve_bogie_equilibrium(in, m), way, 1e-9);
}

// A guess from which the coarse contacts cannot lead (the jumpy model contact above: its coarse
// force never settles within 1e-2 Q) gives way to the continuation, which ends at the smooth
// contact's solution.
TEST(BogieEquilibrium, AGuessThatCannotLeadGivesWayToTheContinuation) {
  ModelContact m;
  m.radius = 1000.0;
  int coarse = 0, full = 0;
  rn::BogieEquilibriumInput in = model_input(1000.0, 0.08);
  in.guess = rn::BogieGuess{};  // the centred bogie
  const rn::BogieEquilibrium e =
      rn::solve_bogie_equilibrium(in, jumpy_when_coarse(m, coarse, full));
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
  EXPECT_GT(e.continuation_steps, 0);
  const rn::BogieEquilibrium smooth = rn::solve_bogie_equilibrium(model_input(1000.0, 0.08), m);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(e.yaw[i], smooth.yaw[i], 1e-9) << i;
}

// Tangent track: the wheelsets and the frame centred and square, to round-off, and no iteration.
TEST(BogieEquilibrium, TangentTrackIsCentred) {
  const double inf = std::numeric_limits<double>::infinity();
  const rn::BogieEquilibrium e = rn::solve_bogie_equilibrium(model_input(inf, 0.0), ModelContact{});
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(e.lateral[i], 0.0);
    EXPECT_EQ(e.yaw[i], 0.0);
  }
  EXPECT_EQ(e.iterations, 0);
  EXPECT_EQ(e.max_residual(), 0.0);
}

// A very stiff primary yaw (K_psi x 1e4) gives the rigid bogie's kinematics (K1): psi1 - psi2 =
// 2a / R within 0.1 %, and the axles' yaw relative to the frame vanishes (|e_i| < 1e-3 a/R).
// R = 1000 m, as above.
TEST(BogieEquilibrium, StiffPrimaryYawGivesTheRigidBogie) {
  rn::BogieEquilibriumInput in = model_input(1000.0, 0.08);
  in.vehicle.primary_longitudinal_stiffness *= 1e4;
  ModelContact m;
  m.radius = 1000.0;
  const rn::BogieEquilibrium e = rn::solve_bogie_equilibrium(in, m);
  const double a_over_R = 1.25 / 1000.0;
  EXPECT_NEAR(e.yaw[0] - e.yaw[1], 2.0 * a_over_R, 1e-3 * 2.0 * a_over_R);
  EXPECT_NEAR(e.yaw[0] - e.bogie_yaw, a_over_R, 1e-3 * a_over_R);
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
}

// A very soft primary yaw (K_psi x 1e-6) gives radial axles: without cant deficiency and
// gravitational stiffness each axle's angle of attack stays below 10 % of a/R (what is left is
// the lateral creep force that carries the secondary yaw moment's lateral reaction, K_s L/(4 a
// f22 R) = 6.5 % of a/R here; the rigid bogie's leading axle has about a/R), and each axle sits
// at the conical tread's pure-rolling position y = l0 r0 / (lambda R) within 0.1 %.
TEST(BogieEquilibrium, SoftPrimaryYawGivesRadialAxles) {
  rn::BogieEquilibriumInput in = model_input(300.0, 0.0);
  in.vehicle.primary_longitudinal_stiffness *= 1e-6;
  ModelContact m;
  m.k_g = 0.0;
  const rn::BogieEquilibrium e = rn::solve_bogie_equilibrium(in, m);
  const double a_over_R = 1.25 / 300.0, y0 = m.l0 * m.r0 / (m.lambda * 300.0);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT(std::abs(e.yaw[i]), 0.1 * a_over_R) << i;
    EXPECT_NEAR(e.lateral[i], y0, 1e-3 * y0) << i;
  }
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
}

// The exact contacts of S1002/UIC60 at 300 m (cases/curve_300m.toml's curve, 16 elements): every
// equation of (B2) within 1e-6 Q; the leading axle towards the outer rail and turned outwards;
// the continuation from tangent track and Newton from the estimate end at the same state.
TEST(BogieEquilibrium, ExactContactsBalanceAt300m) {
  rn::BogieEquilibriumInput in;
  in.curve = bogie_curve_input(300.0, 0.08);
  in.vehicle = passenger_bogie();
  const auto t0 = std::chrono::steady_clock::now();
  const rn::BogieEquilibrium e = rn::solve_bogie_equilibrium(in);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "300 m: y %.3f %.3f mm, psi %.3f %.3f mrad, frame %.3f mm %.3f mrad, residual %.2e N, "
      "%d iterations, %d steps, %d axle evaluations, %.1f s\n",
      e.lateral[0] * 1e3, e.lateral[1] * 1e3, e.yaw[0] * 1e3, e.yaw[1] * 1e3, e.bogie_lateral * 1e3,
      e.bogie_yaw * 1e3, e.max_residual(), e.iterations, e.continuation_steps,
      e.contact_evaluations, s);
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
  EXPECT_GT(e.lateral[0], 0.0);
  EXPECT_GT(e.yaw[0], 0.0);
  // From the quasi-static estimate's state (the pipeline's start): the same state within 0.01 mm
  // and 0.01 mrad, no continuation step and fewer evaluations. Not within 1e-6 Q over the
  // stiffnesses: each path's last digits keep the grids of its own loose solution, and a grid
  // placed a fraction of an element elsewhere moves the flange contact's forces by some 10 N
  // (WheelContact.StartFromANearbyStateKeepsTheGridAndTheForcesSmooth), the state by ~4e-6 rad.
  in.guess = rn::estimated_guess(in.curve);
  ASSERT_TRUE(in.guess.has_value());
  const rn::BogieEquilibrium g = rn::solve_bogie_equilibrium(in);
  std::printf(
      "from the estimate: y %.4f %.4f mm, psi %.4f %.4f mrad, %d iterations, %d axle "
      "evaluations\n",
      g.lateral[0] * 1e3, g.lateral[1] * 1e3, g.yaw[0] * 1e3, g.yaw[1] * 1e3, g.iterations,
      g.contact_evaluations);
  expect_the_same_state_sooner(g, e, 1e-5);
  ASSERT_EQ(e.wheels.size(), 4u);
  for (const rn::WheelContact& w : e.wheels) {
    const auto f = w.force_track();
    std::printf(
        "  %-14s u %.2f mm psi %.2f mrad angle %.3f xi (%.2e %.2e %.3f) Q %.1f kN F (%.1f %.1f "
        "%.1f) kN\n",
        rn::wheel_name(w.wheel), w.lateral * 1e3, w.yaw * 1e3, w.contact.contact_angle,
        w.creepage(0), w.creepage(1), w.creepage(2), w.vertical_load * 1e-3, f[0] * 1e-3,
        f[1] * 1e-3, f[2] * 1e-3);
  }
}

// Tangent track on the exact contacts: the wheelsets and the frame centred and square exactly
// (the mirror), and the axles' spin equations solved too (the S1002/UIC60 patch is not symmetric
// about its centre line: at the nominal rolling speed the spin creepage leaves a torque on each
// axle), every equation within 1e-6 Q.
TEST(BogieEquilibrium, ExactContactsOnTangentTrackAreCentredAndFreeRolling) {
  rn::BogieEquilibriumInput in;
  in.curve = bogie_curve_input(std::numeric_limits<double>::infinity(), 0.0);
  in.vehicle = passenger_bogie();
  const rn::BogieEquilibrium e = rn::solve_bogie_equilibrium(in);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(e.lateral[i], 0.0) << i;
    EXPECT_EQ(e.yaw[i], 0.0) << i;
    EXPECT_NE(e.spin[i], 0.0) << i;
  }
  EXPECT_EQ(e.bogie_lateral, 0.0);
  EXPECT_EQ(e.bogie_yaw, 0.0);
  EXPECT_LE(e.max_residual(), 1e-6 * kQ);
  EXPECT_EQ(e.continuation_steps, 0);
}
