// Reading a rail cross-section outline (CSV, e.g. models/rail/uic60_outline.csv) for the waveguide
// rail (track.rail_section; docs/models.md Sec. 2.6).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dynamics/waveguide_rail_model.hpp"
#include "io/case_reader.hpp"

namespace rollnoise::io {

/// Reads the closed polygon of a rail section: header `y_mm,z_mm`, one vertex per line ('#'
/// comments), y lateral (0 on the centre line), z up; either orientation, the last point not
/// repeated (a repeated first point is dropped). Coordinates in mm, returned in m, shifted so that
/// the foot's bottom is at z = 0 (the lowest z). Errors: InputError with key "<path>:<line>" naming
/// the field, or "<path>" for fewer than 3 points, a zero area, or a foot without a flat bottom
/// (the support acts on the boundary edges along the lowest z, so two consecutive vertices must lie
/// there). Self-intersection is found by the mesher (fem::mesh_polygon).
std::vector<Eigen::Vector2d> read_rail_section(const std::string& path);

/// The waveguide rail's options from the case: the section of track.rail_section (absent: the
/// built-in UIC60 outline), the head's underside at rail_head_bottom() of it. `id` gets ", section
/// <file>" when a file is read (for the structures' cache key).
dynamics::WaveguideRailOptions waveguide_rail_options(const CaseReader& r, std::string& id);

}  // namespace rollnoise::io
