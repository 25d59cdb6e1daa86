#include "io/cache_files.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/output_files.hpp"

namespace rollnoise::io {

namespace fs = std::filesystem;

std::optional<std::string> cache_directory() {
  if (const char* dir = std::getenv("ROLLNOISE_CACHE_DIR")) {
    if (std::string(dir) == "off" || std::string(dir).empty()) return std::nullopt;
    return std::string(dir);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::string(xdg) + "/rollnoise";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.cache/rollnoise";
  return std::nullopt;
}

std::string build_identity() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto size = fs::file_size(exe, ec);
  if (ec) return {};
  const auto time = fs::last_write_time(exe, ec);
  if (ec) return {};
  std::ostringstream s;
  s << "build " << provenance().program_version << " " << exe.string() << " " << size << " "
    << time.time_since_epoch().count() << "\n";
  return s.str();
}

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return in.bad() ? std::string{} : s.str();
}

std::string real_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string cache_file(const std::string& directory, const std::string& prefix,
                       const std::string& key) {
  char name[32];
  std::snprintf(name, sizeof name, "-%016llx.bin", static_cast<unsigned long long>(fnv1a(key)));
  return (fs::path(directory) / (prefix + name)).string();
}

std::optional<std::string> read_cache_payload(const std::string& path, const std::string& magic,
                                              const std::string& key) {
  if (key.empty()) return std::nullopt;
  const std::string s = file_bytes(path);
  // magic, the key's length and the key, the payload, its checksum
  const std::string head = magic + std::to_string(key.size()) + "\n" + key;
  if (s.size() < head.size() + sizeof(std::uint64_t) || s.compare(0, head.size(), head) != 0)
    return std::nullopt;
  const std::size_t end = s.size() - sizeof(std::uint64_t);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, s.data() + end, sizeof checksum);
  std::string payload = s.substr(head.size(), end - head.size());
  if (checksum != fnv1a(payload)) return std::nullopt;
  return payload;
}

bool write_cache_payload(const std::string& path, const std::string& magic, const std::string& key,
                         const std::string& payload, const std::string& what) {
  if (key.empty()) return false;
  try {
    std::error_code ec;
    fs::create_directories(fs::path(path).parent_path(), ec);
    if (ec) return false;
    std::string bytes = magic + std::to_string(key.size()) + "\n" + key + payload;
    put(bytes, fnv1a(payload));
    TemporaryFile t(path, what);
    write_bytes(t, bytes);
    t.commit();
    return true;
  } catch (const std::exception&) {
    return false;  // best effort: the run goes on with what it computed
  }
}

}  // namespace rollnoise::io
