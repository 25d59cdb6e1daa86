#include "io/wheel_modes_cache.hpp"

#include <cstdint>
#include <sstream>

#include "io/cache_files.hpp"

namespace rollnoise::io {

namespace {

constexpr const char* kMagic = "rollnoise wheel modes cache\n";
constexpr int kFormat = 1;

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

std::optional<dynamics::WheelFeModes> parse(const std::string& body) {
  Bytes b(body);
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

}  // namespace

std::optional<std::string> mode_cache_directory() {
  return cache_directory();
}

std::string mode_cache_key(const WheelFeCase& c) {
  const std::string build = build_identity();
  if (build.empty()) return {};
  const std::string section = file_bytes(c.section_file);
  if (section.empty()) return {};
  const auto& m = c.options.material;
  std::ostringstream key;
  key << "format " << kFormat << "\n"
      << build << "section " << section.size() << " bytes, fnv1a " << std::hex << fnv1a(section)
      << std::dec << "\n"
      << "E " << real_text(m.youngs_modulus) << " nu " << real_text(m.poisson_ratio) << " rho "
      << real_text(m.density) << " h " << real_text(c.options.mesh_size) << " n_max "
      << c.options.n_max << " f_max " << real_text(c.options.f_max) << "\n";
  return key.str();
}

std::string mode_cache_file(const std::string& directory, const std::string& key) {
  return cache_file(directory, "wheel-modes", key);
}

std::optional<dynamics::WheelFeModes> read_cached_modes(const std::string& directory,
                                                        const std::string& key) {
  const std::optional<std::string> body =
      read_cache_payload(mode_cache_file(directory, key), kMagic, key);
  return body ? parse(*body) : std::nullopt;
}

bool write_cached_modes(const std::string& directory, const std::string& key,
                        const dynamics::WheelFeModes& w) {
  return write_cache_payload(mode_cache_file(directory, key), kMagic, key, payload(w),
                             "wheel.mode_cache");
}

}  // namespace rollnoise::io
