// Reading track parameter files (TOML, keys as in models/track/uic60_ballasted.toml) into
// dynamics::TrackParameters. The file format and its errors: io/parameter_table.hpp.
#pragma once

#include <string>

#include "dynamics/track.hpp"

namespace rollnoise::io {

/// Reads a track parameter file. Every key but rail.timoshenko (default 1: Timoshenko beam) and
/// supports_each_side (default 60) is required; an unknown key is an error.
dynamics::TrackParameters read_track_parameters(const std::string& path);

/// The same from text in memory; `origin` names it in messages.
dynamics::TrackParameters parse_track_parameters(const std::string& text,
                                                 const std::string& origin);

}  // namespace rollnoise::io
