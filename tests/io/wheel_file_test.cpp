// The wheel model files (src/io/wheel_file.hpp): the wheelset parameters (TOML) and the mode table
// (CSV).
#include "io/wheel_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "core/errors.hpp"

namespace rd = rollnoise::dynamics;

namespace {

const std::string kWheelModels = std::string(ROLLNOISE_SOURCE_DIR) + "/models/wheel/";

// Writes `text` to a temporary mode file and returns its path.
std::string temp_file(const std::string& name, const std::string& text) {
  // per-process names: test programs of several build trees may run at once
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

const char* kHeader = "frequency_Hz,damping_ratio,modal_mass_kg,phi_z,phi_x,phi_y,phi_rz,label\n";

}  // namespace

TEST(WheelModes, DefaultFilesReadAndCoverTheRollingNoiseRange) {
  const rd::WheelModel w(rollnoise::io::read_wheelset(kWheelModels + "wheelset_920mm.toml"),
                         rollnoise::io::read_wheel_modes(kWheelModels + "wheel_920mm_modes.csv"));
  EXPECT_EQ(w.modes().size(), 36u);
  for (const auto& m : w.modes()) {
    EXPECT_GE(m.frequency, 300.0) << m.label;
    EXPECT_LE(m.frequency, 5000.0) << m.label;
  }
  EXPECT_EQ(w.wheelset().mass, 1500.0);
  EXPECT_EQ(w.wheelset().wheel_radius, 0.46);
}

TEST(WheelModeFile, BadInputNamesFileLineAndField) {
  using rollnoise::InputError;
  struct Case {
    const char* name;
    std::string text;
    const char* field;
    int line;
  };
  const Case cases[] = {
      {"missing_column.csv", std::string(kHeader) + "360,1e-4,110,0.2,0,1\n", "phi_rz", 2},
      {"nan.csv", std::string(kHeader) + "360,1e-4,nan,0.2,0,1,0,x\n", "modal_mass_kg", 2},
      {"negative.csv", std::string(kHeader) + "-360,1e-4,110,0.2,0,1,0,x\n", "frequency_Hz", 2},
      {"text.csv", std::string(kHeader) + "360,1e-4,110,0.2,zero,1,0,x\n", "phi_x", 2},
      {"damping.csv", std::string(kHeader) + "360,1.5,110,0.2,0,1,0,x\n", "damping_ratio", 2},
      {"zero_shape.csv", std::string(kHeader) + "360,1e-4,110,0,0,0,0,x\n", "phi_z", 2},
      {"header.csv", "frequency_Hz,damping,modal_mass_kg,phi_z,phi_x,phi_y,phi_rz\n",
       "damping_ratio", 1},
  };
  for (const Case& c : cases) {
    const std::string path = temp_file(c.name, c.text);
    try {
      rollnoise::io::read_wheel_modes(path);
      ADD_FAILURE() << c.name << ": no InputError";
    } catch (const InputError& e) {
      const std::string line = ":" + std::to_string(c.line);
      EXPECT_NE(e.key().find(path + line), std::string::npos) << c.name << ": key " << e.key();
      EXPECT_NE(e.key().find(c.field), std::string::npos) << c.name << ": key " << e.key();
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos)
          << c.name << ": " << e.what();
    }
    std::remove(path.c_str());
  }
  EXPECT_THROW(rollnoise::io::read_wheel_modes(::testing::TempDir() + "does_not_exist.csv"),
               InputError);
}

TEST(WheelsetFile, MissingOrBadParameterIsInputError) {
  using rollnoise::InputError;
  const std::string path = temp_file("ws.toml", "mass = 1500\nroll_inertia = -5\n");
  try {
    rollnoise::io::read_wheelset(path);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.key().find("roll_inertia"), std::string::npos) << e.key();
  }
  std::remove(path.c_str());
}
