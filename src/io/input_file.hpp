// Input files read once, whole, into memory, and bounded in size before they are read
// (docs/stability.md, "Hostile environments").
//
// Every file the program parses (the case, the study file, profiles, track and wheel tables, wheel
// modes, roughness spectra, excitation histories) is read through read_input(): the first call
// reads the file into memory and keeps its bytes for the rest of the process, so a file that can be
// read only once (a pipe, a FIFO, bash's process substitution `<(...)`) gives the same bytes to
// the check of the run's files and to the run itself, and the digest that stamps a study case
// (input_digest) is of the bytes actually used. A file above kMaxInputBytes is refused before it is
// read (its size, for a regular file) or as soon as the bound is passed (pipes, devices such as
// /dev/zero), with InputError naming the key (or the file) and the limit.
#pragma once

#include <cstdint>
#include <string>

namespace rollnoise::io {

/// The largest input file read (bytes): 256 MiB, far above any model file (kilobytes) or case.
constexpr std::uint64_t kMaxInputBytes = 256ull << 20;

/// The bytes of `path`, read once per process and then kept (read again only if a regular file has
/// changed since). InputError(key, "PATH: ...") naming `what` (e.g. "the case file") if it is
/// missing, a folder, unreadable or larger than `limit` bytes.
const std::string& read_input(const std::string& path, const std::string& key,
                              const std::string& what, std::uint64_t limit = kMaxInputBytes);

/// A 64-bit FNV-1a digest of `bytes` as 16 hexadecimal digits (detects changed inputs; not a
/// cryptographic hash).
std::string digest(const std::string& bytes);

}  // namespace rollnoise::io
