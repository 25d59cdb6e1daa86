// Reading the wheel model files: the rigid-wheelset parameters (TOML, e.g.
// models/wheel/wheelset_920mm.toml; format and errors in io/parameter_table.hpp) and the table of
// flexible modes (CSV, e.g. models/wheel/wheel_920mm_modes.csv) into the structs of
// dynamics/wheel.hpp.
#pragma once

#include <string>
#include <vector>

#include "dynamics/wheel.hpp"

namespace rollnoise::io {

/// Reads the wheelset parameters (keys: mass, roll_inertia, spin_inertia, yaw_inertia,
/// contact_offset_y, wheel_radius; all required, no others allowed).
dynamics::RigidWheelset read_wheelset(const std::string& path);

/// The same from text in memory; `origin` names it in messages.
dynamics::RigidWheelset parse_wheelset(const std::string& text, const std::string& origin);

/// Reads a mode table. CSV with the header
///   frequency_Hz,damping_ratio,modal_mass_kg,phi_z,phi_x,phi_y,phi_rz[,label]
/// ('#' starts a comment line). Any bad line is an InputError whose key is "<path>:<line>:<field>"
/// and whose message names the field.
std::vector<dynamics::WheelMode> read_wheel_modes(const std::string& path);

}  // namespace rollnoise::io
