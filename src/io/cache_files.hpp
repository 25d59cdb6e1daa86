// Files in the user's cache directory, kept between runs: the wheel's FE modes
// (io/wheel_modes_cache.hpp) and the waveguide rail's frequency samplings
// (io/rail_sampling_cache.hpp); docs/interface.md, "The wheel's mode cache" and "The rail's
// sampling cache".
//
// Each file holds a magic line, its key (the length, a newline, the bytes), a payload and the
// payload's FNV-1a checksum, and is named by the key's FNV-1a hash (64 bits; Fowler, Noll, Vo). The
// key is compared in full on reading, so a hash collision reads nothing; it always begins with
// build_identity(): a rebuilt or updated rollnoise does not read another build's values, which is
// what lets the payload hold doubles as raw bytes (the same machine writes and reads) and a run
// from the cache give the bits of the run that computed them.
//
// Best effort, never an error: a directory that cannot be made or written, a missing, truncated
// (checksum) or foreign file is the same as no file. Files are written to a temporary beside the
// final name and renamed (io/output_files.hpp), so a concurrent run reads either nothing or a
// whole file.
#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

namespace rollnoise::io {

/// The cache directory: $ROLLNOISE_CACHE_DIR (the value "off", or empty, switches every cache
/// off: nullopt), else $XDG_CACHE_HOME/rollnoise, else $HOME/.cache/rollnoise; nullopt when none
/// can be named (no HOME).
std::optional<std::string> cache_directory();

/// "build <version> <executable> <size> <modification time>\n", or empty when this build cannot
/// be identified (no /proc/self/exe): then nothing is cached.
std::string build_identity();

/// FNV-1a, 64 bits, of `bytes`.
std::uint64_t fnv1a(const std::string& bytes);

/// The bytes of the file at `path` (empty when it cannot be read).
std::string file_bytes(const std::string& path);

/// `value`'s digits, all 17 ("%.17g"), for keys.
std::string real_text(double value);

/// `directory`/<prefix>-<16 hex digits of fnv1a(key)>.bin
std::string cache_file(const std::string& directory, const std::string& prefix,
                       const std::string& key);

/// The payload of the cache file `path` when it begins with `magic` and `key` and its checksum
/// holds; nullopt otherwise (no file, another key, a truncated or damaged file).
std::optional<std::string> read_cache_payload(const std::string& path, const std::string& magic,
                                              const std::string& key);

/// Writes `payload` under `magic` and `key` to `path` (its directory made where missing); false
/// when it cannot (nothing is left behind then). `what` names the cache in a temporary's messages.
bool write_cache_payload(const std::string& path, const std::string& magic, const std::string& key,
                         const std::string& payload, const std::string& what);

/// Raw values appended to a byte string.
template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// Raw values read back from a byte string, in order; get() is false past its end.
class Bytes {
 public:
  explicit Bytes(const std::string& s) : s_(s) {}
  template <class T>
  bool get(T& value) {
    if (s_.size() - at_ < sizeof value) return false;
    std::memcpy(&value, s_.data() + at_, sizeof value);
    at_ += sizeof value;
    return true;
  }
  std::size_t at() const { return at_; }
  std::size_t left() const { return s_.size() - at_; }

 private:
  const std::string& s_;
  std::size_t at_ = 0;
};

}  // namespace rollnoise::io
