// Reading a wheel cross-section outline (CSV, e.g. models/wheel/wheel_920mm_section.csv) into
// dynamics::WheelSection (docs/models.md Sec. 3.4).
#pragma once

#include <string>

#include "dynamics/wheel_fe.hpp"

namespace rollnoise::io {

/// Reads the outline: header `r_mm,z_mm,segment`, one point per line ('#' comments), segment one of
/// bore, tread, free for the boundary from this point to the next (the last closes to the first).
/// Coordinates in mm, returned in m. Errors: InputError with key "<path>:<line>" naming the field;
/// fewer than 3 points, no bore or no tread segment.
dynamics::WheelSection read_wheel_section(const std::string& path);

}  // namespace rollnoise::io
