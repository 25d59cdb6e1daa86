// The FE wheel's case keys ([wheel] model = "fe", io/wheel_fe_case.hpp): defaults, bad values
// reported with the key in the message, and the FE wheel model with its modes on their own thread.
#include "io/wheel_fe_case.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/wheel_file.hpp"

namespace {

using namespace rollnoise;

// The message of reading the [wheel] keys of a minimal case with `overrides`, or "" if it reads.
std::string read_error(const std::vector<std::string>& overrides) {
  const io::CaseReader r = io::CaseReader::from_string("[wheel]\n", "wheel.toml", overrides);
  try {
    io::InputProblems problems;
    io::read_wheel_fe_case(r, problems);
    problems.throw_if_any();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The defaults: the table wheel; with model = "fe" the shipped 920 mm section, steel, 8 mm, n <=
// 10, 6 kHz, Thompson's damping (1e-3, 1e-2, 1e-4) and the rotation split on.
TEST(WheelFeCase, DefaultsAreTableAndSteelSolidWheelValues) {
  io::InputProblems problems;
  EXPECT_FALSE(io::read_wheel_fe_case(io::CaseReader::from_string("", "w.toml"), problems));
  const auto c = io::read_wheel_fe_case(
      io::CaseReader::from_string("[wheel]\nmodel = \"fe\"\n",
                                  std::string(ROLLNOISE_SOURCE_DIR) + "/cases/w.toml"),
      problems);
  ASSERT_TRUE(problems.empty());
  ASSERT_TRUE(c);
  EXPECT_NE(c->section_file.find("wheel_920mm_section.csv"), std::string::npos);
  EXPECT_EQ(c->options.material.youngs_modulus, 2.1e11);
  EXPECT_EQ(c->options.material.density, 7850.0);
  EXPECT_EQ(c->options.mesh_size, 0.008);
  EXPECT_EQ(c->options.n_max, 10);
  EXPECT_EQ(c->options.f_max, 6000.0);
  EXPECT_EQ(c->contact.damping.n0, 1e-3);
  EXPECT_EQ(c->contact.damping.n1, 1e-2);
  EXPECT_EQ(c->contact.damping.axial, 1e-4);
  EXPECT_TRUE(c->rotation_split);
}

// Each bad value names its key.
TEST(WheelFeCase, BadValuesNameTheirKey) {
  const std::string fe = "wheel.model=\"fe\"";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"wheel.poisson_ratio=0.6", "wheel.poisson_ratio"},
      {"wheel.youngs_modulus=-1.0", "wheel.youngs_modulus"},
      {"wheel.density=0.0", "wheel.density"},
      {"wheel.mesh_size=0.5", "wheel.mesh_size"},
      {"wheel.n_max=-1", "wheel.n_max"},
      {"wheel.n_max=51", "wheel.n_max"},
      {"wheel.f_max=0.0", "wheel.f_max"},
      {"wheel.damping_axial=1.5", "wheel.damping_axial"},
      {"wheel.damping_n1=-0.1", "wheel.damping_n1"},
      {"wheel.bore=\"free\"", "wheel.bore"},
      {"wheel.rotation=\"spin\"", "wheel.rotation"},
      {"wheel.section=\"no_such_section.csv\"", "wheel.section"},
  };
  // model = "shapes" needs its file; its keys are refused with another model.
  EXPECT_NE(read_error({"wheel.model=\"shapes\""}).find("wheel.shapes"), std::string::npos);
  EXPECT_NE(read_error({fe, "wheel.shapes=\"s.csv\""}).find("wheel.shapes"), std::string::npos);
  EXPECT_NE(read_error({"wheel.model=\"shapes\"", "wheel.shapes=\"s.csv\"", "wheel.mesh_size=0.01"})
                .find("wheel.mesh_size"),
            std::string::npos);
  for (const auto& [override_kv, key] : cases) {
    const std::string message = read_error({fe, override_kv});
    EXPECT_NE(message.find(key), std::string::npos) << override_kv << ": " << message;
  }
  // An FE key with the table wheel is a mistake, named.
  EXPECT_NE(read_error({"wheel.mesh_size=0.01"}).find("wheel.mesh_size"), std::string::npos);
  EXPECT_EQ(read_error({"wheel.model=\"table\""}), "");
}

namespace {

// The FE wheel of a case on a coarse mesh (20 mm, modes to 2999 Hz, n <= 5: an id no other test
// computes, so that its modes are computed here and not taken from the process's cache), `threads`
// for its orders and its thread.
io::WheelFeCase coarse_fe_case(int threads, double rolling_speed) {
  io::InputProblems problems;
  auto c = io::read_wheel_fe_case(
      io::CaseReader::from_string(
          "[wheel]\nmodel = \"fe\"\nmesh_size = 0.02\nf_max = 2999.0\nn_max = 5\n",
          std::string(ROLLNOISE_SOURCE_DIR) + "/cases/w.toml"),
      problems);
  problems.throw_if_any();
  c->options.threads = threads;
  c->rolling_speed = rolling_speed;
  return *c;
}

dynamics::RigidWheelset test_wheelset() {
  return io::read_wheelset(std::string(ROLLNOISE_SOURCE_DIR) + "/models/wheel/wheelset_920mm.toml");
}

void expect_same_table(const std::vector<dynamics::WheelMode>& a,
                       const std::vector<dynamics::WheelMode>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].frequency, b[k].frequency) << k;
    EXPECT_EQ(a[k].damping_ratio, b[k].damping_ratio) << k;
    EXPECT_EQ(a[k].modal_mass, b[k].modal_mass) << k;
    EXPECT_EQ(a[k].shape, b[k].shape) << k;
    EXPECT_EQ(a[k].label, b[k].label) << k;
  }
}

}  // namespace

// With two threads the case's FE modes are computed on a thread of their own while the caller goes
// on; the model then holds exactly (bit for bit, tolerance 0) the tables of the modes computed
// directly on the caller's thread: at the reference point, 5 mm across the tread, and the
// receptance at 1 kHz.
TEST(WheelFeCase, ModesOnTheirOwnThreadEqualThoseOfTheCallersThread) {
  const io::WheelFeCase c = coarse_fe_case(2, 20.0);
  const dynamics::WheelModel later = io::fe_wheel_model(c, test_wheelset());
  EXPECT_NE(c.id.find("f_max 2999"), std::string::npos);

  dynamics::WheelFeOptions serial = c.options;
  serial.threads = 1;
  const dynamics::WheelFeModes modes = dynamics::wheel_fe_modes(c.section, serial);
  const dynamics::WheelFeContactOptions o = io::contact_options(c, modes);
  EXPECT_GT(o.spin_speed, 0.0);
  const dynamics::WheelModel now(
      test_wheelset(), dynamics::contact_mode_table(modes, 0.0, o),
      [&](double shift_y) { return dynamics::contact_mode_table(modes, shift_y, o); });
  ASSERT_FALSE(now.modes().empty());
  expect_same_table(later.modes(), now.modes());
  expect_same_table(later.modes_at(0.005), now.modes_at(0.005));
  EXPECT_EQ(later.receptance(1000.0), now.receptance(1000.0));
}

// An error of the modes' own thread is thrown at their first use, with its type and key; on one
// thread it is thrown where the model is made (both: n Omega above a natural frequency at 5 km/s).
TEST(WheelFeCase, ErrorOfTheModesThreadIsThrownAtTheirFirstUse) {
  const io::WheelFeCase c2 = coarse_fe_case(2, 5000.0);
  const dynamics::WheelModel later = io::fe_wheel_model(c2, test_wheelset());
  try {
    later.modes();
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "wheel.rotation");
  }
  EXPECT_THROW(later.receptance(1000.0), InputError);  // again at every use
  EXPECT_THROW(io::fe_wheel_model(coarse_fe_case(1, 5000.0), test_wheelset()), InputError);
}
