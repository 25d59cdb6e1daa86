// The wheel's FE modes kept between runs (wheel.mode_cache = "user"; docs/interface.md "The wheel's
// mode cache").
//
// The modes of an FE wheel depend only on its section, material, mesh and range (n <= n_max,
// f <= f_max), not on the case's contact; computing them (gmsh's meshing, one sparse eigen solve
// per order) costs more than a whole single-wheel noise run without them. The contact path needs
// only what the modes are along the tread (tread samples, frequencies, orders, families, tread
// shapes, the wheel's mass), so that is what is kept: one binary file per wheel and build of
// rollnoise in the user's cache directory,
//   $ROLLNOISE_CACHE_DIR (the value "off" switches the cache off for every case), else
//   $XDG_CACHE_HOME/rollnoise, else $HOME/.cache/rollnoise,
// named by a 64-bit FNV-1a hash of its key. The key (written into the file and compared in full on
// reading, so a hash collision reads nothing) holds: the format version; this build (its
// program_version and the executable's size and modification time: a rebuilt or updated rollnoise
// does not read another build's modes); the section file's bytes; E, nu, rho, the mesh size, n_max
// and f_max to all digits. The doubles are stored as their bytes: a run from the cache gives the
// same bits as the run that computed the modes.
//
// Best effort, never an error: a directory that cannot be made or written, a missing, truncated
// (checksum) or foreign file is the same as no cache (the modes are computed, and written when the
// directory takes them). Files are written to a temporary beside the final name and renamed
// (io/output_files.hpp), so a concurrent run reads either nothing or a whole file.
#pragma once

#include <optional>
#include <string>

#include "dynamics/wheel_fe.hpp"
#include "io/wheel_fe_case.hpp"

namespace rollnoise::io {

/// The cache directory (see the header comment); nullopt when switched off or when no directory
/// can be named (no HOME).
std::optional<std::string> mode_cache_directory();

/// The key of the case's wheel (see the header comment); empty when this build cannot be identified
/// (no /proc/self/exe) or the section file cannot be read: then nothing is cached.
std::string mode_cache_key(const WheelFeCase& c);

/// The file of `key` in `directory`.
std::string mode_cache_file(const std::string& directory, const std::string& key);

/// The modes along the tread stored under `key` (no mesh, no section shapes), or nullopt (no such
/// file, another key, a truncated or damaged file).
std::optional<dynamics::WheelFeModes> read_cached_modes(const std::string& directory,
                                                        const std::string& key);

/// Stores the modes along the tread under `key`; false when the directory cannot take them
/// (nothing is left behind then).
bool write_cached_modes(const std::string& directory, const std::string& key,
                        const dynamics::WheelFeModes& w);

}  // namespace rollnoise::io
