// The FE wheel's case keys ([wheel] model = "fe", io/wheel_fe_case.hpp): defaults, and bad values
// reported with the key in the message.
#include "io/wheel_fe_case.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/errors.hpp"

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
