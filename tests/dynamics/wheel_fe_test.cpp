// The default 920 mm wheel as an axisymmetric FE structure (dynamics/wheel_fe.hpp): its mass, the
// axial 0-nodal-circle family against published values for wheels of this size, mesh convergence,
// and the mode shapes on the tread.
#include "dynamics/wheel_fe.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iostream>
#include <set>
#include <string>

#include "core/errors.hpp"
#include "dynamics/wheel_mode_family.hpp"
#include "io/wheel_section_file.hpp"
#include "support/test_inputs.hpp"

using namespace rollnoise;
using namespace rollnoise::dynamics;

namespace {

using rollnoise::test_support::default_section;

// The lowest mode of order n in a family with the given nodal circles, or nullptr.
const WheelFeMode* find(const WheelFeModes& w, int n, ModeFamily f, int circles) {
  for (const auto& m : w.modes)
    if (m.n == n && m.family == f && m.nodal_circles == circles) return &m;
  return nullptr;
}

}  // namespace

// The consistent mass matrix carries the wheel's mass: 1^T M 1 / 3 equals rho 2 pi int r dA over
// the outline (Pappus; the polygon's first moment by the shoelace-type formula) to 1e-10.
TEST(WheelFe, MassEqualsDensityTimesVolumeOfRevolution) {
  const auto section = default_section();
  WheelFeOptions o;
  o.n_max = 0;
  o.f_max = 100.0;
  const auto w = wheel_fe_modes(section, o);
  // int r dA over a polygon = sum (x_i y_{i+1} - x_{i+1} y_i)(x_i + x_{i+1}) / 6.
  double first_moment = 0.0;
  const auto& p = section.outline;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    first_moment += (a.x() * b.y() - b.x() * a.y()) * (a.x() + b.x()) / 6.0;
  }
  const double expected = o.material.density * 2 * M_PI * std::abs(first_moment);
  EXPECT_NEAR(w.mass, expected, 1e-10 * expected);
  std::cout << "wheel mass " << w.mass << " kg\n";
}

// The axial 0-nodal-circle family n = 2..6 against the values taken as typically reported for 920 mm
// wheels (NOT re-read in a source: docs/record/fe_wheel.md Sec. 1 says what was searched),
// 360, 1000, 1760, 2600, 3430 Hz (Thompson, Railway Noise and Vibration (2009) Ch. 5; Thompson,
// J. Sound Vib. 161 (1993) 401-419): within 7 % (the section's rim, web and hub are approximate,
// models/wheel/wheel_920mm_section.csv; measured -5.6 % at n = 3 to +2.6 % at n = 6). Mesh
// convergence: every mode with n >= 2 up to 4 kHz at 12 mm moves by less than 0.5 % at 8 mm
// (docs/record/fe_wheel.md Sec. 2 for 5 mm).
TEST(WheelFe, AxialFamilyNearTheUnverifiedTypical920mmValuesAndConvergesInMesh) {
  const auto section = default_section();
  WheelFeOptions o;
  o.n_max = 6;
  o.f_max = 4000.0;
  o.mesh_size = 0.012;
  const auto coarse = wheel_fe_modes(section, o);
  o.mesh_size = 0.008;
  const auto fine = wheel_fe_modes(section, o);
  const double published[5] = {360, 1000, 1760, 2600, 3430};
  for (int n = 2; n <= 6; ++n) {
    const WheelFeMode* m = find(fine, n, ModeFamily::kAxial, 0);
    ASSERT_NE(m, nullptr) << "n = " << n;
    std::cout << "axial n = " << n << ", 0 circles: " << m->frequency << " Hz (published "
              << published[n - 2] << " Hz)\n";
    EXPECT_NEAR(m->frequency / published[n - 2], 1.0, 0.07) << "n = " << n;
  }
  ASSERT_EQ(coarse.modes.size(), fine.modes.size());
  for (std::size_t i = 0; i < fine.modes.size(); ++i) {
    if (fine.modes[i].n < 2) continue;
    EXPECT_EQ(coarse.modes[i].n, fine.modes[i].n);
    EXPECT_NEAR(coarse.modes[i].frequency / fine.modes[i].frequency, 1.0, 0.005)
        << "n = " << fine.modes[i].n << ", " << fine.modes[i].frequency << " Hz";
  }
}

// The tread shapes: an axial n = 2 mode moves the tread mostly axially, and tread_shape_at
// interpolates the samples (at a sample it returns the sample) and refuses points off the tread.
TEST(WheelFe, TreadShapeOfAxialModeIsAxialAndInterpolated) {
  WheelFeOptions o;
  o.n_max = 2;
  o.f_max = 800.0;
  o.mesh_size = 0.016;
  const auto w = wheel_fe_modes(default_section(), o);
  const WheelFeMode* m = find(w, 2, ModeFamily::kAxial, 0);
  ASSERT_NE(m, nullptr);
  const Eigen::Vector3d at0 = tread_shape_at(w, *m, 0.0);
  EXPECT_GT(std::abs(at0(2)), 2 * std::abs(at0(0)));
  const std::size_t i = w.tread_s.size() / 2;
  EXPECT_LT((tread_shape_at(w, *m, w.tread_s[i]) - m->tread_shape.row(i).transpose()).norm(),
            1e-12 * m->tread_shape.norm());
  EXPECT_THROW(tread_shape_at(w, *m, 0.2), InputError);
}

// The FE wheel at a contact (contact_mode_table): at s = -20 mm (towards the flange) the table
// carries the FE shape (phi_y = U_z, phi_z = -U_r of the cos partner), and the wheel model built
// from it is reciprocal (H = H^T to round-off) and passive ((H - H^H)/2i negative semidefinite:
// no power generated) at 200 Hz to 4 kHz.
TEST(WheelFe, ContactTableCarriesTreadShapeAndGivesReciprocalPassiveReceptance) {
  WheelFeOptions o;
  o.n_max = 6;
  o.f_max = 4000.0;
  o.mesh_size = 0.016;
  const auto w = wheel_fe_modes(default_section(), o);
  const auto table = contact_mode_table(w, -0.02);
  const WheelFeMode* m = find(w, 3, ModeFamily::kAxial, 0);
  ASSERT_NE(m, nullptr);
  const Eigen::Vector3d u = tread_shape_at(w, *m, -0.02);
  bool found = false;
  for (const auto& t : table)
    if (t.frequency == m->frequency && t.label.find("sin") == std::string::npos) {
      EXPECT_EQ(t.shape(2), u(2));
      EXPECT_EQ(t.shape(0), -u(0));
      found = true;
    }
  EXPECT_TRUE(found);
  RigidWheelset ws;
  ws.mass = 1500, ws.roll_inertia = 700, ws.spin_inertia = 110, ws.yaw_inertia = 700;
  ws.contact_offset_y = 0.75, ws.wheel_radius = 0.46;
  const WheelModel model(ws, table);
  for (double f : {200.0, 950.0, 2000.0, 4000.0}) {
    const Receptance4 h = model.receptance(f);
    EXPECT_LT((h - h.transpose()).norm(), 1e-12 * h.norm()) << f << " Hz";
    const Eigen::Matrix4cd dissipation = (h - h.adjoint()) / cdouble(0, 2);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4cd> eig(dissipation);
    EXPECT_LE(eig.eigenvalues().maxCoeff(), 1e-12 * h.norm()) << f << " Hz";
  }
}

namespace {

// The shipped wheel as the shipped cases mesh it (the section file, 8 mm, n <= 10, f <= 6 kHz:
// WheelFeOptions' defaults), computed once for the tests below.
const WheelFeModes& shipped_wheel() {
  static const WheelFeModes w = wheel_fe_modes(default_section(), WheelFeOptions{});
  return w;
}

}  // namespace

// Families from the whole section (wheel_mode_family.hpp). Each n = 2..6 has two modes between
// 1.8 and 4.7 kHz whose tread moves mostly radially. A 3D finite-element model of the same
// section made in another program (issue 51) shows the lower one's web bending out of plane with
// one nodal circle (the one-nodal-circle axial family, the rim rocking) at 1883, 2318, 2874, 3553,
// 4337 Hz, and the upper one in-plane (the radial family) at 2132, 2704, 3315, 3964, 4667 Hz: ours
// must be "axial, 1 circle" below "radial, 0 circles", at those frequencies within 1 % (the issue
// measured 0.53 % at 8 mm), and the tread alone (tread_family) would call both radial.
TEST(WheelModes, TheLowerModeOfEachPairIsTheOneNodalCircleAxialFamily) {
  const WheelFeModes& w = shipped_wheel();
  const double axial_3d[5] = {1883, 2318, 2874, 3553, 4337};
  const double radial_3d[5] = {2132, 2704, 3315, 3964, 4667};
  for (int n = 2; n <= 6; ++n) {
    const WheelFeMode* axial = find(w, n, ModeFamily::kAxial, 1);
    const WheelFeMode* radial = find(w, n, ModeFamily::kRadial, 0);
    ASSERT_NE(axial, nullptr) << "n = " << n;
    ASSERT_NE(radial, nullptr) << "n = " << n;
    std::cout << "n = " << n << ": axial 1 circle " << axial->frequency << " Hz (3D "
              << axial_3d[n - 2] << "), radial 0 circles " << radial->frequency << " Hz (3D "
              << radial_3d[n - 2] << ")\n";
    EXPECT_LT(axial->frequency, radial->frequency) << "n = " << n;
    EXPECT_NEAR(axial->frequency / axial_3d[n - 2], 1.0, 0.01) << "n = " << n;
    EXPECT_NEAR(radial->frequency / radial_3d[n - 2], 1.0, 0.01) << "n = " << n;
    EXPECT_EQ(tread_family(axial->tread_shape), ModeFamily::kRadial) << "n = " << n;
    EXPECT_EQ(tread_family(radial->tread_shape), ModeFamily::kRadial) << "n = " << n;
  }
}

// One label per mode: on the shipped wheel every mode's label (family, n, circles) is its own,
// without the " #k" of mode_labels' tie-break, and so is every entry of its contact table (sin
// partners and the travelling waves of the split).
TEST(WheelModes, TheShippedWheelsLabelsAreUnique) {
  const WheelFeModes& w = shipped_wheel();
  const std::vector<std::string> labels = mode_labels(w.modes);
  ASSERT_EQ(labels.size(), w.modes.size());
  EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), labels.size());
  for (std::size_t k = 0; k < labels.size(); ++k)
    EXPECT_EQ(labels[k], mode_label(w.modes[k])) << labels[k] << " needed the tie-break";
  WheelFeContactOptions o;
  o.spin_speed = 42.0;
  std::set<std::string> entries;
  for (const auto& t : contact_mode_table(w, 0.0, o))
    EXPECT_TRUE(entries.insert(t.label).second) << t.label;
}

// Modes that share family, n and circles (e.g. imported ones, circles unknown) are numbered in
// ascending frequency, whatever their order; a label of its own stays as it is.
TEST(WheelModes, ModesSharingALabelAreNumberedByFrequency) {
  std::vector<WheelFeMode> modes(3);
  modes[0].n = 2, modes[0].family = ModeFamily::kRadial, modes[0].nodal_circles = -1;
  modes[0].frequency = 2135.0;
  modes[1] = modes[0], modes[1].frequency = 1887.0;
  modes[2] = modes[0], modes[2].family = ModeFamily::kAxial, modes[2].frequency = 352.0;
  const std::vector<std::string> labels = mode_labels(modes);
  EXPECT_EQ(labels[0], "radial n=2 -1 circles #2");
  EXPECT_EQ(labels[1], "radial n=2 -1 circles #1");
  EXPECT_EQ(labels[2], "axial n=2 -1 circles");
}
