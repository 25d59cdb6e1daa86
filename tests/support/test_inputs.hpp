// The model and case files that several tests read, named once (see test_helpers.hpp on
// why test files share such helpers). ROLLNOISE_SOURCE_DIR is defined for every test program.
#pragma once

#include <string>

#include "dynamics/wheel_fe.hpp"
#include "io/wheel_section_file.hpp"

namespace rollnoise::test_support {

/// The folder of the shipped wheel and rail profiles, with its trailing slash.
inline const std::string kProfiles = std::string(ROLLNOISE_SOURCE_DIR) + "/models/profiles/";

/// The default 920 mm wheel's cross-section (models/wheel/wheel_920mm_section.csv).
inline dynamics::WheelSection default_section() {
  return io::read_wheel_section(std::string(ROLLNOISE_SOURCE_DIR) +
                                "/models/wheel/wheel_920mm_section.csv");
}

/// The small curve case of the study tests (tests/data/study/curve_small.toml).
inline std::string study_base_case() {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/tests/data/study/curve_small.toml";
}

}  // namespace rollnoise::test_support
