// The FE wheel in the loop (dynamics::WheelModel with ModesAlongTread): at a contact shifted across
// the tread the loop's wheel receptance (noise::wheel_receptance6, moved by the lever arm, then
// rotated into the contact frame) and its modes in the contact frame (loop_modes, the squeal
// loop's) carry the FE shapes at the contact itself, i.e. equal dynamics::fe_cross_receptance
// there.
#include <gtest/gtest.h>

#include <string>

#include "dynamics/wheel_fe.hpp"
#include "io/wheel_section_file.hpp"
#include "noise/loop.hpp"
#include "noise/stability.hpp"

using namespace rollnoise;
using dynamics::cdouble;
using dynamics::Receptance4;

// Shift -32.6 mm (the flange root of curve_300m), contact angle 0.524 rad, 300 Hz .. 3 kHz: the
// loop's wheel minus the rigid wheelset equals the FE point receptance at s = -32.6 mm to 1e-10,
// and the sum of the contact-frame modes' rank-one terms equals it too (squeal's route 2 sees the
// same wheel).
TEST(FeWheelLoop, LoopWheelAtShiftedContactIsTheFeReceptanceThere) {
  dynamics::WheelFeOptions o;
  o.n_max = 5;
  o.f_max = 3000.0;
  o.mesh_size = 0.02;
  const auto w = std::make_shared<const dynamics::WheelFeModes>(
      dynamics::wheel_fe_modes(io::read_wheel_section(std::string(ROLLNOISE_SOURCE_DIR) +
                                                      "/models/wheel/wheel_920mm_section.csv"),
                               o));
  dynamics::RigidWheelset ws;
  ws.mass = 1500, ws.roll_inertia = 700, ws.spin_inertia = 110, ws.yaw_inertia = 700;
  ws.contact_offset_y = 0.75, ws.wheel_radius = 0.46;
  dynamics::WheelFeContactOptions co;
  co.spin_speed = 42.0;
  const dynamics::WheelModel fe(
      ws, dynamics::contact_mode_table(*w, 0.0, co),
      [w, co](double shift) { return dynamics::contact_mode_table(*w, shift, co); });
  const dynamics::WheelModel rigid(ws, {});
  noise::ContactPosition p;
  p.wheel_shift_y = -0.0326, p.contact_angle = 0.524;
  noise::ContactPoint point;
  point.position = p;
  const auto modes = noise::loop_modes(fe, {point}).modes;
  for (double f : {300.0, 950.0, 3000.0}) {
    const Receptance4 loop =
        noise::to_contact_frame(noise::wheel_receptance6(fe, f, p.wheel_shift_y), p.contact_angle) -
        noise::to_contact_frame(noise::wheel_receptance6(rigid, f, p.wheel_shift_y),
                                p.contact_angle);
    const Receptance4 expected = dynamics::fe_cross_receptance(
        *w, co, {p.wheel_shift_y, p.contact_angle}, {p.wheel_shift_y, p.contact_angle}, f);
    EXPECT_LT((loop - expected).norm(), 1e-10 * expected.norm()) << f << " Hz";
    Receptance4 sum = Receptance4::Zero();
    const double omega = 2 * M_PI * f;
    for (const auto& m : modes) {
      const double wk = 2 * M_PI * m.frequency;
      sum += (m.shape * m.shape.transpose()).cast<cdouble>() /
             (m.modal_mass * cdouble(wk * wk - omega * omega, 2 * m.damping_ratio * wk * omega));
    }
    EXPECT_LT((sum - expected).norm(), 1e-10 * expected.norm()) << f << " Hz";
  }
}
