// The track parameter files (src/io/track_file.hpp, TOML through io/parameter_table.hpp).
#include "io/track_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include "core/errors.hpp"

namespace rd = rollnoise::dynamics;

TEST(TrackParameters, Uic60FileEqualsBuiltInTrack) {
  const auto f = rollnoise::io::read_track_parameters(std::string(ROLLNOISE_SOURCE_DIR) +
                                                      "/models/track/uic60_ballasted.toml");
  const auto b = rd::uic60_ballasted();
  for (auto [p, q] : {std::pair{f.vertical, b.vertical}, std::pair{f.lateral, b.lateral}}) {
    EXPECT_EQ(p.youngs_modulus, q.youngs_modulus);
    EXPECT_EQ(p.shear_modulus, q.shear_modulus);
    EXPECT_EQ(p.area, q.area);
    EXPECT_EQ(p.second_moment, q.second_moment);
    EXPECT_EQ(p.mass_per_length, q.mass_per_length);
    EXPECT_EQ(p.shear_coefficient, q.shear_coefficient);
    EXPECT_EQ(p.loss_factor, q.loss_factor);
    EXPECT_EQ(p.timoshenko, q.timoshenko);
  }
  for (auto [p, q] : {std::pair{f.vertical_support, b.vertical_support},
                      std::pair{f.lateral_support, b.lateral_support},
                      std::pair{f.longitudinal_support, b.longitudinal_support}}) {
    EXPECT_EQ(p.pad_stiffness, q.pad_stiffness);
    EXPECT_EQ(p.pad_loss_factor, q.pad_loss_factor);
    EXPECT_EQ(p.sleeper_mass, q.sleeper_mass);
    EXPECT_EQ(p.ballast_stiffness, q.ballast_stiffness);
    EXPECT_EQ(p.ballast_loss_factor, q.ballast_loss_factor);
  }
  EXPECT_EQ(f.sleeper_spacing, b.sleeper_spacing);
  EXPECT_EQ(f.head_height, b.head_height);
  EXPECT_EQ(f.supports_each_side, b.supports_each_side);
}

TEST(TrackParameters, BadFileNamesFileLineAndKey) {
  using rollnoise::InputError;
  auto expect_error = [](const std::string& text, const std::string& key_part,
                         const std::string& what_part) {
    try {
      rollnoise::io::parse_track_parameters(text, "track.toml");
      ADD_FAILURE() << "no InputError for: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.key()).find(key_part), std::string::npos) << e.key();
      EXPECT_NE(std::string(e.what()).find(what_part), std::string::npos) << e.what();
    }
  };
  expect_error("sleeper_spacing = 0.6\n[rail]\narea 7e-3\n", "track.toml:3", "key = number");
  expect_error("sleeper_spacing = abc\n", "track.toml:1:sleeper_spacing", "finite number");
  expect_error("sleeper_spacing = 0.6\n", "rail.youngs_modulus", "missing parameter");
  // A complete file with one negative stiffness.
  std::ifstream in(std::string(ROLLNOISE_SOURCE_DIR) + "/models/track/uic60_ballasted.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto pos = text.find("pad_stiffness = 350e6");
  ASSERT_NE(pos, std::string::npos);
  text.replace(pos, 21, "pad_stiffness = -350e6");
  expect_error(text, "support.vertical.pad_stiffness", "positive");
}

// toml++ reads the files: TOML's own rules (a key given twice, a string value) and the reader's
// (an unknown key, a boolean flag) are errors or values as stated, each naming file, line and key.
TEST(TrackParameters, TomlRulesAndUnknownKeysNameFileLineAndKey) {
  using rollnoise::InputError;
  std::ifstream in(std::string(ROLLNOISE_SOURCE_DIR) + "/models/track/uic60_ballasted.toml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto expect_error = [&](const std::string& extra, const std::string& key_part,
                          const std::string& what_part) {
    try {
      rollnoise::io::parse_track_parameters(text + extra, "track.toml");
      ADD_FAILURE() << "no InputError for: " << extra;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.key()).find(key_part), std::string::npos) << e.key();
      EXPECT_NE(std::string(e.what()).find(what_part), std::string::npos) << e.what();
    }
  };
  const std::string last = std::to_string(std::count(text.begin(), text.end(), '\n') + 1);
  expect_error("pad_stifness = 1e6\n", "track.toml:" + last + ":support.longitudinal.pad_stifness",
               "unknown parameter");
  expect_error("sleeper_mass = 150\n", "track.toml:" + last, "sleeper_mass");
  expect_error("note = \"x\"\n", "track.toml:" + last + ":support.longitudinal.note",
               "finite number");
  const std::string next = std::to_string(std::stoi(last) + 1);
  expect_error("[extra]\nvalue = nan\n", "track.toml:" + next + ":extra.value", "finite number");
  // rail.timoshenko: 1 in the file; a TOML boolean is accepted as well.
  auto with_flag = [&](const std::string& v) {
    std::string t = text;
    const auto pos = t.find("timoshenko = 1");
    t.replace(pos, 14, "timoshenko = " + v);
    return rollnoise::io::parse_track_parameters(t, "track.toml");
  };
  EXPECT_TRUE(with_flag("true").vertical.timoshenko);
  EXPECT_FALSE(with_flag("false").lateral.timoshenko);
  EXPECT_FALSE(with_flag("0").vertical.timoshenko);
}
