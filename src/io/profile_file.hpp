// Reading wheel and rail profile files into geometry::Profile (the numerics take the points).
//
// Two formats: the SIMPACK point format of the Manchester contact benchmark (`.prw`, `.prr`,
// `.prf`, or any file with a `point.begin` block), with its processing flags applied, and plain
// CSV (two columns y, z in mm). The profile frame and what z means for a wheel and a rail:
// geometry/profile.hpp and docs/geometry.md.
#pragma once

#include <optional>
#include <string>

#include "geometry/profile.hpp"

namespace rollnoise::io {

/// Read a profile file: the SIMPACK point format (`.prw`, `.prr`, `.prf`, or any file containing a
/// `point.begin` block) or plain CSV (two columns y, z in mm, optional header line, '#' comments).
/// The kind comes from the SIMPACK header `type`, else from the extension (.prw wheel, .prr rail),
/// else from `kind`; a CSV file needs `kind`. Malformed files throw InputError naming the file,
/// the line and what is wrong (key: the path).
geometry::Profile read_profile(const std::string& path,
                               std::optional<geometry::ProfileKind> kind = std::nullopt);

/// The SIMPACK profile point format used by the Manchester contact benchmark. Applied processing
/// flags: shift.y/z, rotate, bound.y/z, mirror.y/z, inversion, units.len.f (lengths unit per
/// metre). A `comment` saying the rail is "already canted" sets Profile::canted().
geometry::Profile read_simpack_profile(const std::string& path,
                                       std::optional<geometry::ProfileKind> kind = std::nullopt);

/// Plain CSV: y, z in mm per line (separators ',', ';', tab or spaces), one optional header line.
geometry::Profile read_csv_profile(const std::string& path, geometry::ProfileKind kind);

}  // namespace rollnoise::io
