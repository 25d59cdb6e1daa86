// The waveguide rail's sampling cache (io/rail_sampling_cache.hpp): a kept sampling (the grid's
// samples, the checked intervals, the lines computed beside it) is read back to the bit; another
// key, a damaged or truncated file, or a folder that cannot take the file give nothing (the
// samplings are then computed); the identity changes with the track file, the section file and
// the contact position.
#include "io/rail_sampling_cache.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "io/cache_files.hpp"
#include "support/test_helpers.hpp"

namespace {

using namespace rollnoise;
namespace fs = std::filesystem;

fs::path rail_scratch(const std::string& name) {
  return test_support::scratch_folder("rollnoise_rail_cache", name);
}

// A sampling of two pairs on 5 frequencies with 2 lines beside it, random values (seeded).
dynamics::KeptSampling random_rail_sampling() {
  std::mt19937 rng(20261127);
  std::normal_distribution<double> n(0.0, 1e-9);
  auto r4 = [&] {
    dynamics::Receptance4 r;
    for (int i = 0; i < 16; ++i) r.data()[i] = {n(rng), n(rng)};
    return r;
  };
  dynamics::KeptSampling k;
  k.grid.at = {100.0, 150.0, 230.0, 400.0, 1000.0};
  k.grid.values.assign(2, {});
  for (auto& pair : k.grid.values)
    for (std::size_t i = 0; i < k.grid.at.size(); ++i) pair.push_back(r4());
  k.grid.checked = {1, 0, 1, 1};
  for (double f : {90.0, 175.5}) k.direct[f] = {r4(), r4()};
  return k;
}

bool same_sampling(const dynamics::KeptSampling& a, const dynamics::KeptSampling& b) {
  if (a.grid.at != b.grid.at || a.grid.checked != b.grid.checked ||
      a.direct.size() != b.direct.size())
    return false;
  for (std::size_t p = 0; p < a.grid.values.size(); ++p)
    for (std::size_t i = 0; i < a.grid.at.size(); ++i)
      if (a.grid.values[p][i] != b.grid.values[p][i]) return false;
  for (const auto& [f, v] : a.direct) {
    const auto it = b.direct.find(f);
    if (it == b.direct.end() || it->second.size() != v.size()) return false;
    for (std::size_t p = 0; p < v.size(); ++p)
      if (v[p] != it->second[p]) return false;
  }
  return true;
}

}  // namespace

TEST(RailSamplingCache, SamplingReadBackIsBitIdentical) {
  const io::RailSamplingCache cache(rail_scratch("roundtrip").string());
  const dynamics::KeptSampling k = random_rail_sampling();
  const std::string key = "identity\npoints, pairs, grid";
  EXPECT_FALSE(cache.read(key).has_value());
  cache.write(key, k);
  const auto back = cache.read(key);
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(same_sampling(*back, k));
}

TEST(RailSamplingCache, AnotherKeyADamagedOrTruncatedFileReadsNothing) {
  const fs::path dir = rail_scratch("damaged");
  const io::RailSamplingCache cache(dir.string());
  const std::string key = "identity\nthe key";
  cache.write(key, random_rail_sampling());
  ASSERT_TRUE(cache.read(key).has_value());
  EXPECT_FALSE(cache.read("identity\nanother key").has_value());
  const std::string file = cache.file(key), bytes = io::file_bytes(file);
  {  // one byte of a value changed: the checksum fails
    std::string changed = bytes;
    changed[bytes.size() / 2] ^= 0x01;
    std::ofstream(file, std::ios::binary | std::ios::trunc) << changed;
    EXPECT_FALSE(cache.read(key).has_value());
  }
  {  // truncated
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 100);
    EXPECT_FALSE(cache.read(key).has_value());
  }
  // a folder that cannot be made (a file is in the way): nothing written, nothing read, no error
  std::ofstream(dir / "blocked") << "x";
  const io::RailSamplingCache blocked((dir / "blocked" / "cache").string());
  blocked.write(key, random_rail_sampling());
  EXPECT_FALSE(blocked.read(key).has_value());
}

TEST(RailSamplingCache, IdentityChangesWithTrackSectionAndPosition) {
  const std::string src = ROLLNOISE_SOURCE_DIR;
  const std::string track = src + "/models/track/uic60_ballasted.toml";
  const std::string section = src + "/models/rail/uic60_outline.csv";
  const std::string id = io::rail_sampling_identity(track, "", 0.3);
  ASSERT_FALSE(id.empty());
  EXPECT_EQ(io::rail_sampling_identity(track, "", 0.3), id);
  EXPECT_NE(io::rail_sampling_identity(track, section, 0.3), id);
  EXPECT_NE(io::rail_sampling_identity(track, "", 0.0), id);
  const fs::path dir = rail_scratch("identity");
  const fs::path other = dir / "track.toml";
  std::ofstream(other) << io::file_bytes(track) << "\n# edited\n";
  EXPECT_NE(io::rail_sampling_identity(other.string(), "", 0.3), id);
  EXPECT_TRUE(io::rail_sampling_identity((dir / "missing.toml").string(), "", 0.3).empty());
}

// The values at complex s (squeal's continuation) read back to the bit, in their own file; a
// damaged one reads nothing.
TEST(RailSamplingCache, ValuesAtComplexFrequencyReadBackIsBitIdentical) {
  const io::RailSamplingCache cache(rail_scratch("laplace").string());
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, 1e-9);
  dynamics::KeptLaplace k;
  for (int i = 0; i < 5; ++i) {
    std::vector<dynamics::Receptance6> v(3);
    for (auto& r : v)
      for (int j = 0; j < 36; ++j) r.data()[j] = {n(rng), n(rng)};
    k.values[{-10.0 * i, 6000.0 + i}] = v;
  }
  const std::string key = "identity\nlaplace pairs";
  cache.write_laplace(key, k);
  EXPECT_FALSE(cache.read(key).has_value());  // not a sampling
  const auto back = cache.read_laplace(key);
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->values.size(), k.values.size());
  for (const auto& [s, v] : k.values) {
    const auto it = back->values.find(s);
    ASSERT_NE(it, back->values.end());
    for (std::size_t p = 0; p < v.size(); ++p) EXPECT_TRUE(it->second[p] == v[p]);
  }
  std::string bytes = io::file_bytes(cache.laplace_file(key));
  bytes[bytes.size() / 2] ^= 0x10;
  std::ofstream(cache.laplace_file(key), std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_FALSE(cache.read_laplace(key).has_value());
}
