// Checks of the modal wheel model (src/dynamics/wheel.hpp); its files: tests/io/wheel_file_test.cpp.
#include "dynamics/wheel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "io/wheel_file.hpp"

namespace rd = rollnoise::dynamics;

namespace {

std::string model_path(const std::string& rel) {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/models/wheel/" + rel;
}

rd::WheelModel default_wheel() {
  return rd::WheelModel(rollnoise::io::read_wheelset(model_path("wheelset_920mm.toml")),
                        rollnoise::io::read_wheel_modes(model_path("wheel_920mm_modes.csv")));
}

}  // namespace

TEST(WheelReceptance, IsReciprocal) {
  const rd::WheelModel w = default_wheel();
  for (double f : {30.0, 360.0, 1234.5, 2600.0, 4800.0}) {
    const rd::Receptance4 H = w.receptance(f);
    EXPECT_LT((H - H.transpose()).norm(), 1e-14 * H.norm()) << "f = " << f;
    // the rigid wheelset couples z with y (roll) and x with rot z (yaw): non-trivial symmetry
    EXPECT_GT(std::abs(H(rd::kZ, rd::kY)), 0.0);
    EXPECT_GT(std::abs(H(rd::kX, rd::kRotZ)), 0.0);
  }
}

TEST(WheelReceptance, FollowsRigidWheelsetMassLineAtLowFrequency) {
  const rd::WheelModel w = default_wheel();
  const rd::RigidWheelset& ws = w.wheelset();
  // Independent rigid-body algebra, contact at r = (0, y_c, -R):
  //   z: bounce + roll (y_c), y: sway + roll (R), x: surge + spin (R) + yaw (y_c), rot z: yaw.
  const double yc = ws.contact_offset_y, R = ws.wheel_radius;
  const double cz = 1.0 / ws.mass + yc * yc / ws.roll_inertia;
  const double cy = 1.0 / ws.mass + R * R / ws.roll_inertia;
  const double cx = 1.0 / ws.mass + R * R / ws.spin_inertia + yc * yc / ws.yaw_inertia;
  const double cr = 1.0 / ws.yaw_inertia;
  const double expect[4] = {cz, cx, cy, cr};
  {  // the rigid part exactly, at any frequency
    const double omega = 2.0 * M_PI * 700.0;
    const rd::Receptance4 Hr = ws.receptance(700.0);
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(Hr(j, j).real() * (-omega * omega) / expect[j], 1.0, 1e-12) << "dof " << j;
    // Roll couples z and y: F_y at depth R below the axle gives the moment R F_y about x, which
    // lifts the contact at +y_c: theta_x = -R F_y / (I_xx omega^2), u_z = y_c theta_x.
    EXPECT_NEAR(Hr(rd::kZ, rd::kY).real() * omega * omega * ws.roll_inertia / (yc * R), -1.0,
                1e-12);
  }
  // The whole wheel tends to the rigid mass line well below the first mode (300 Hz): within 1 %
  // at 1 Hz in all four directions (the flexible modes add their static compliance).
  const double omega = 2.0 * M_PI * 1.0;
  const rd::Receptance4 H = w.receptance(1.0);
  for (int j = 0; j < 4; ++j)
    EXPECT_NEAR(H(j, j).real() / (-expect[j] / (omega * omega)), 1.0, 0.01) << "dof " << j;
  // The vertical effective mass is roughly half the wheelset (bounce + roll).
  EXPECT_NEAR(1.0 / cz / ws.mass, 0.45, 0.1);
}

TEST(WheelReceptance, PeaksAtModalFrequencies) {
  const rd::WheelModel w = default_wheel();
  int checked = 0;
  for (const auto& m : w.modes()) {
    if (m.label.find("sin") != std::string::npos) continue;  // partners: same frequency
    // The dominant direction of this mode at the contact.
    int dof = 0;
    m.shape.cwiseAbs().maxCoeff(&dof);
    // Scan bins of width zeta f_n (a tenth of the half-power bandwidth 2 zeta f_n, at least
    // 0.01 Hz) over +-10 bins, or less so that no other natural frequency is in the window: the
    // largest |H| must be the bin at f_n or its neighbour.
    const double bin = std::max(m.damping_ratio * m.frequency, 0.01);
    double gap = 1e9;
    for (const auto& o : w.modes())
      if (o.frequency != m.frequency) gap = std::min(gap, std::abs(o.frequency - m.frequency));
    const int half = std::min(10, static_cast<int>(0.5 * gap / bin));
    ASSERT_GE(half, 2) << m.label;
    double best = 0.0;
    int best_i = 0;
    for (int i = -half; i <= half; ++i) {
      const double a = std::abs(w.receptance(m.frequency + i * bin)(dof, dof));
      if (a > best) best = a, best_i = i;
    }
    EXPECT_LE(std::abs(best_i), 1) << m.label << " at " << m.frequency << " Hz";
    // ... and it is a resonance: well above the level half an octave away.
    const double off = std::abs(w.receptance(m.frequency * 0.7)(dof, dof));
    EXPECT_GT(best, 3.0 * off) << m.label;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

TEST(WheelReceptance, SingleModeMatchesModalFormula) {
  rd::WheelMode m;
  m.frequency = 1000.0;
  m.damping_ratio = 1e-3;
  m.modal_mass = 80.0;
  m.shape << 0.3, 0.0, 1.0, 2.0;
  const rd::WheelModel w(rollnoise::io::read_wheelset(model_path("wheelset_920mm.toml")), {m});
  const double f = 990.0, wn = 2.0 * M_PI * 1000.0, om = 2.0 * M_PI * f;
  const std::complex<double> q =
      1.0 / (80.0 * std::complex<double>(wn * wn - om * om, 2e-3 * wn * om));
  const rd::Receptance4 H = w.modal_receptance(f);
  EXPECT_NEAR(std::abs(H(rd::kY, rd::kRotZ) - 2.0 * q), 0.0, 1e-12 * std::abs(q));
  EXPECT_NEAR(std::abs(H(rd::kZ, rd::kZ) - 0.09 * q), 0.0, 1e-12 * std::abs(q));
  EXPECT_EQ(std::abs(H(rd::kX, rd::kX)), 0.0);
  // At resonance the response is -i / (2 zeta m omega_n^2): phase -90 degrees.
  const auto res = w.modal_receptance(1000.0)(rd::kY, rd::kY);
  EXPECT_NEAR(std::arg(res), -M_PI / 2, 1e-12);
  EXPECT_NEAR(std::abs(res), 1.0 / (2e-3 * 80.0 * wn * wn), 1e-9 * std::abs(res));
}
