#include "io/rail_sampling_cache.hpp"

#include <complex>
#include <cstdint>
#include <sstream>
#include <vector>

#include "io/cache_files.hpp"

namespace rollnoise::io {

namespace {

constexpr const char* kSamplingMagic = "rollnoise rail sampling cache\n";
constexpr int kSamplingFormat = 1;
constexpr const char* kLaplaceMagic = "rollnoise rail laplace cache\n";
constexpr std::size_t kReceptanceBytes = 16 * sizeof(std::complex<double>);
constexpr std::size_t kReceptance6Bytes = 36 * sizeof(std::complex<double>);

void put_receptance(std::string& out, const dynamics::Receptance4& r) {
  out.append(reinterpret_cast<const char*>(r.data()), kReceptanceBytes);
}

bool get_receptance(Bytes& b, dynamics::Receptance4& r) {
  for (int i = 0; i < 16; ++i) {
    double re = 0.0, im = 0.0;
    if (!b.get(re) || !b.get(im)) return false;
    r.data()[i] = {re, im};
  }
  return true;
}

// pairs P, samples n, at[n], values[P][n], checked[n - 1], direct count D, D x (f, values[P])
std::string sampling_payload(const dynamics::KeptSampling& k) {
  std::string out;
  const dynamics::SampledGrid& g = k.grid;
  put<std::uint64_t>(out, g.values.size());
  put<std::uint64_t>(out, g.at.size());
  for (double f : g.at) put(out, f);
  for (const auto& pair : g.values)
    for (const auto& r : pair) put_receptance(out, r);
  for (char c : g.checked) put(out, c);
  put<std::uint64_t>(out, k.direct.size());
  for (const auto& [f, values] : k.direct) {
    put(out, f);
    for (const auto& r : values) put_receptance(out, r);
  }
  return out;
}

std::optional<dynamics::KeptSampling> parse_sampling(const std::string& body) {
  Bytes b(body);
  std::uint64_t pairs = 0, n = 0, direct = 0;
  dynamics::KeptSampling k;
  if (!b.get(pairs) || !b.get(n)) return std::nullopt;
  // sizes that the remaining bytes cannot hold are a damaged file, not an allocation
  if (pairs == 0 || n == 0 || n > b.left() / 8 || pairs > b.left() / (n * kReceptanceBytes))
    return std::nullopt;
  k.grid.at.resize(n);
  for (double& f : k.grid.at)
    if (!b.get(f)) return std::nullopt;
  k.grid.values.assign(pairs, std::vector<dynamics::Receptance4>(n));
  for (auto& pair : k.grid.values)
    for (auto& r : pair)
      if (!get_receptance(b, r)) return std::nullopt;
  k.grid.checked.resize(n - 1);
  for (char& c : k.grid.checked)
    if (!b.get(c)) return std::nullopt;
  if (!b.get(direct) || direct > b.left() / (8 + pairs * kReceptanceBytes)) return std::nullopt;
  for (std::uint64_t i = 0; i < direct; ++i) {
    double f = 0.0;
    std::vector<dynamics::Receptance4> values(pairs);
    if (!b.get(f)) return std::nullopt;
    for (auto& r : values)
      if (!get_receptance(b, r)) return std::nullopt;
    k.direct.emplace(f, std::move(values));
  }
  if (b.left() != 0) return std::nullopt;
  return k;
}

// pairs P, count N, N x (Re s, Im s, values[P])
std::string laplace_payload(const dynamics::KeptLaplace& k) {
  std::string out;
  const std::size_t pairs = k.values.empty() ? 0 : k.values.begin()->second.size();
  put<std::uint64_t>(out, pairs);
  put<std::uint64_t>(out, k.values.size());
  for (const auto& [s, values] : k.values) {
    put(out, s.first);
    put(out, s.second);
    for (const auto& r : values)
      out.append(reinterpret_cast<const char*>(r.data()), kReceptance6Bytes);
  }
  return out;
}

std::optional<dynamics::KeptLaplace> parse_laplace(const std::string& body) {
  Bytes b(body);
  std::uint64_t pairs = 0, n = 0;
  if (!b.get(pairs) || !b.get(n)) return std::nullopt;
  if (pairs == 0 || pairs > b.left() / kReceptance6Bytes ||
      n > b.left() / (16 + pairs * kReceptance6Bytes))
    return std::nullopt;
  dynamics::KeptLaplace k;
  for (std::uint64_t i = 0; i < n; ++i) {
    double re = 0.0, im = 0.0;
    if (!b.get(re) || !b.get(im)) return std::nullopt;
    std::vector<dynamics::Receptance6> values(pairs);
    for (auto& r : values)
      for (int j = 0; j < 36; ++j) {
        double x = 0.0, y = 0.0;
        if (!b.get(x) || !b.get(y)) return std::nullopt;
        r.data()[j] = {x, y};
      }
    k.values.emplace(std::make_pair(re, im), std::move(values));
  }
  if (b.left() != 0) return std::nullopt;
  return k;
}

}  // namespace

std::string RailSamplingCache::laplace_file(const std::string& key) const {
  return cache_file(directory_, "rail-laplace", key);
}

std::optional<dynamics::KeptLaplace> RailSamplingCache::read_laplace(const std::string& key) const {
  const std::optional<std::string> body = read_cache_payload(laplace_file(key), kLaplaceMagic, key);
  return body ? parse_laplace(*body) : std::nullopt;
}

void RailSamplingCache::write_laplace(const std::string& key,
                                      const dynamics::KeptLaplace& kept) const {
  if (kept.values.empty()) return;
  write_cache_payload(laplace_file(key), kLaplaceMagic, key, laplace_payload(kept),
                      "track.sampling_cache");
}

std::string RailSamplingCache::file(const std::string& key) const {
  return cache_file(directory_, "rail-sampling", key);
}

std::optional<dynamics::KeptSampling> RailSamplingCache::read(const std::string& key) const {
  const std::optional<std::string> body = read_cache_payload(file(key), kSamplingMagic, key);
  return body ? parse_sampling(*body) : std::nullopt;
}

void RailSamplingCache::write(const std::string& key, const dynamics::KeptSampling& kept) const {
  write_cache_payload(file(key), kSamplingMagic, key, sampling_payload(kept),
                      "track.sampling_cache");
}

std::string rail_sampling_identity(const std::string& track_file, const std::string& section_file,
                                   double position) {
  const std::string build = build_identity();
  const std::string track = file_bytes(track_file);
  const std::string section =
      section_file.empty() ? std::string("built-in UIC60") : file_bytes(section_file);
  if (build.empty() || track.empty() || section.empty()) return {};
  std::ostringstream id;
  id << "format " << kSamplingFormat << "\n"
     << build << "track " << track.size() << " bytes, fnv1a " << std::hex << fnv1a(track)
     << "\nsection " << section.size() << " bytes, fnv1a " << fnv1a(section) << std::dec
     << "\nposition " << real_text(position) << "\n";
  return id.str();
}

}  // namespace rollnoise::io
