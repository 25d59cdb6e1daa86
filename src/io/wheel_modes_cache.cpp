#include "io/wheel_modes_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/output_files.hpp"

namespace rollnoise::io {

namespace {

namespace fs = std::filesystem;

constexpr const char* kMagic = "rollnoise wheel modes cache\n";
constexpr int kFormat = 1;

// FNV-1a, 64 bits (Fowler, Noll, Vo): the file name of a key and the payload's checksum.
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

// Raw values appended to and taken from a byte string (the same machine writes and reads: the
// key names the executable).
template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

class Bytes {
 public:
  explicit Bytes(const std::string& s, std::size_t at) : s_(s), at_(at) {}
  template <class T>
  bool get(T& value) {
    if (s_.size() - at_ < sizeof value) return false;
    std::memcpy(&value, s_.data() + at_, sizeof value);
    at_ += sizeof value;
    return true;
  }
  std::size_t at() const { return at_; }

 private:
  const std::string& s_;
  std::size_t at_;
};

std::string payload(const dynamics::WheelFeModes& w) {
  std::string out;
  const std::size_t samples = w.tread_s.size();
  put<std::uint64_t>(out, samples);
  put<std::uint64_t>(out, w.modes.size());
  put(out, w.mass);
  for (double s : w.tread_s) put(out, s);
  for (double r : w.tread_r) put(out, r);
  for (const dynamics::WheelFeMode& m : w.modes) {
    put(out, m.frequency);
    put<std::int64_t>(out, m.n);
    put<std::int64_t>(out, static_cast<std::int64_t>(m.family));
    put<std::int64_t>(out, m.nodal_circles);
    put(out, m.damping_ratio);
    for (std::size_t i = 0; i < samples; ++i)
      for (int c = 0; c < 3; ++c) put(out, m.tread_shape(static_cast<Eigen::Index>(i), c));
  }
  return out;
}

std::optional<dynamics::WheelFeModes> parse(const std::string& s, std::size_t at, std::size_t end) {
  const std::string body = s.substr(at, end - at);
  Bytes b(body, 0);
  std::uint64_t samples = 0, count = 0;
  dynamics::WheelFeModes w;
  if (!b.get(samples) || !b.get(count) || !b.get(w.mass)) return std::nullopt;
  // sizes that the remaining bytes cannot hold are a damaged file, not an allocation
  const std::uint64_t per_mode = 5 * 8 + samples * 3 * 8;
  if (samples > body.size() / 16 || count > body.size() / per_mode) return std::nullopt;
  w.tread_s.resize(samples);
  w.tread_r.resize(samples);
  for (double& v : w.tread_s)
    if (!b.get(v)) return std::nullopt;
  for (double& v : w.tread_r)
    if (!b.get(v)) return std::nullopt;
  w.modes.resize(count);
  for (dynamics::WheelFeMode& m : w.modes) {
    std::int64_t n = 0, family = 0, circles = 0;
    if (!b.get(m.frequency) || !b.get(n) || !b.get(family) || !b.get(circles) ||
        !b.get(m.damping_ratio))
      return std::nullopt;
    if (family < 0 || family > 2) return std::nullopt;
    m.n = static_cast<int>(n);
    m.family = static_cast<dynamics::ModeFamily>(family);
    m.nodal_circles = static_cast<int>(circles);
    m.tread_shape.resize(static_cast<Eigen::Index>(samples), 3);
    for (std::uint64_t i = 0; i < samples; ++i)
      for (int c = 0; c < 3; ++c)
        if (!b.get(m.tread_shape(static_cast<Eigen::Index>(i), c))) return std::nullopt;
  }
  if (b.at() != body.size()) return std::nullopt;
  return w;
}

std::string real_text(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

}  // namespace

std::optional<std::string> mode_cache_directory() {
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

std::string mode_cache_key(const WheelFeCase& c) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto size = fs::file_size(exe, ec);
  if (ec) return {};
  const auto time = fs::last_write_time(exe, ec);
  if (ec) return {};
  const std::string section = file_bytes(c.section_file);
  if (section.empty()) return {};
  const auto& m = c.options.material;
  std::ostringstream key;
  key << "format " << kFormat << "\n"
      << "build " << provenance().program_version << " " << exe.string() << " " << size << " "
      << time.time_since_epoch().count() << "\n"
      << "section " << section.size() << " bytes, fnv1a " << std::hex << fnv1a(section) << std::dec
      << "\n"
      << "E " << real_text(m.youngs_modulus) << " nu " << real_text(m.poisson_ratio) << " rho "
      << real_text(m.density) << " h " << real_text(c.options.mesh_size) << " n_max "
      << c.options.n_max << " f_max " << real_text(c.options.f_max) << "\n";
  return key.str();
}

std::string mode_cache_file(const std::string& directory, const std::string& key) {
  char name[64];
  std::snprintf(name, sizeof name, "wheel-modes-%016llx.bin",
                static_cast<unsigned long long>(fnv1a(key)));
  return (fs::path(directory) / name).string();
}

std::optional<dynamics::WheelFeModes> read_cached_modes(const std::string& directory,
                                                        const std::string& key) {
  if (key.empty()) return std::nullopt;
  const std::string s = file_bytes(mode_cache_file(directory, key));
  // magic, the key's length and the key, the payload, its checksum
  const std::string head = std::string(kMagic) + std::to_string(key.size()) + "\n" + key;
  if (s.size() < head.size() + sizeof(std::uint64_t) || s.compare(0, head.size(), head) != 0)
    return std::nullopt;
  const std::size_t end = s.size() - sizeof(std::uint64_t);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, s.data() + end, sizeof checksum);
  if (checksum != fnv1a(s.substr(head.size(), end - head.size()))) return std::nullopt;
  return parse(s, head.size(), end);
}

bool write_cached_modes(const std::string& directory, const std::string& key,
                        const dynamics::WheelFeModes& w) {
  if (key.empty()) return false;
  try {
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec) return false;
    const std::string body = payload(w);
    std::string bytes = std::string(kMagic) + std::to_string(key.size()) + "\n" + key + body;
    put(bytes, fnv1a(body));
    TemporaryFile t(mode_cache_file(directory, key), "wheel.mode_cache");
    write_bytes(t, bytes);
    t.commit();
    return true;
  } catch (const std::exception&) {
    return false;  // best effort: the run goes on with the modes it computed
  }
}

}  // namespace rollnoise::io
