// The sound keys of a noise case (noise.sound, [sound]; docs/sound.md, docs/interface.md) read
// into pipeline::SoundCase, with the radiation tables' providers (io/radiation_cache.hpp).
#pragma once

#include <optional>

#include "io/case_reader.hpp"
#include "io/input_problems.hpp"
#include "io/wheel_fe_case.hpp"
#include "pipeline/sound_power.hpp"

namespace rollnoise::io {

/// `fe`: the case's FE wheel (nullopt: wheel.model = "table"); `rail_section`: the waveguide's
/// section (empty: the built-in UIC60 outline).
pipeline::SoundCase read_sound_case(const CaseReader& r, InputProblems& problems,
                                    const std::optional<WheelFeCase>& fe,
                                    const std::vector<Eigen::Vector2d>& rail_section);

}  // namespace rollnoise::io
