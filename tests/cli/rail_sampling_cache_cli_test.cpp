// The waveguide rail's sampling cache through the program (track.sampling_cache,
// ROLLNOISE_CACHE_DIR; docs/interface.md "The rail's sampling cache"): the first run of a waveguide
// case stores its samplings at the contacts, the second reads them and writes the same numbers;
// "off" (key or environment) stores nothing; the key belongs to the waveguide rail; an edited rail
// never reads another rail's samplings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "io/cache_files.hpp"
#include "io/hdf5_reader.hpp"

namespace {

using namespace rollnoise::cli_test;

// The shipped waveguide curve case (continuous support), its leading outer wheel alone, lines to
// 500 Hz, one refinement level (lines beside the sampling).
// (The sound stage off: these tests are about the samplings; the sound's own tables have theirs,
// tests/cli/mode_cache_cli_test.cpp.)
std::string waveguide_curve(const std::string& out, const std::string& more = "") {
  return source_file("cases/curve_300m_waveguide.toml") + " -o " + out +
         " -q --set 'curve.wheels=[\"leading_outer\"]' --set noise.band_max=500 "
         "--set noise.points_per_band=8 --set noise.band_refinement=1 --set noise.sound=\\\"off\\\" " +
         more;
}

std::vector<double> numbers_of(const std::filesystem::path& file, const std::string& name) {
  const rollnoise::io::Hdf5Reader h(file.string());
  EXPECT_TRUE(h.ok()) << file;
  return h.numbers(name).value_or(std::vector<double>{});
}

}  // namespace

TEST(RailSamplingCache, SecondRunReadsTheSamplingsAndWritesTheSameNumbers) {
  const auto dir = fresh_dir("rail_cache");
  const auto cache = dir / "cache";
  const CacheFolder folder(cache.string());
  const auto first = dir / "first.h5", second = dir / "second.h5";
  const Invocation a = run("noise " + waveguide_curve(first.string()));
  ASSERT_EQ(a.status, 0) << a.output;
  const std::vector<std::string> files = listing(cache);  // the sound's tables left out (sound off)
  ASSERT_GE(files.size(), 1u);
  for (const auto& f : files)
    EXPECT_EQ(f.rfind("rail-sampling-", 0), 0u) << f;  // no temporary left
  std::vector<std::filesystem::file_time_type> stored;
  for (const auto& f : files) stored.push_back(std::filesystem::last_write_time(cache / f));
  const Invocation b = run("noise " + waveguide_curve(second.string()));
  ASSERT_EQ(b.status, 0) << b.output;
  ASSERT_EQ(listing(cache), files);
  for (std::size_t i = 0; i < files.size(); ++i)
    EXPECT_EQ(std::filesystem::last_write_time(cache / files[i]), stored[i])
        << files[i];  // read, not rewritten
  // the band levels (the refinement's band means), also of the quasi-steady baseline
  for (const char* name : {"/noise/bands/force_level", "/noise/bands/velocity_level",
                           "/noise/quasi_steady/bands/velocity_level"}) {
    const std::vector<double> x = numbers_of(first, name), y = numbers_of(second, name);
    ASSERT_FALSE(x.empty()) << name;
    ASSERT_EQ(x.size(), y.size()) << name;
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << name;
  }
}

TEST(RailSamplingCache, OffInTheCaseOrTheEnvironmentStoresNothing) {
  const auto dir = fresh_dir("rail_cache_off");
  const auto cache = dir / "cache";
  {
    const CacheFolder folder(cache.string());
    const Invocation a = run("noise " + waveguide_curve((dir / "a.h5").string(),
                                                        "--set track.sampling_cache=\\\"off\\\""));
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_FALSE(std::filesystem::exists(cache));
  }
  const CacheFolder off("off");
  const Invocation b = run("noise " + waveguide_curve((dir / "b.h5").string()));
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_FALSE(std::filesystem::exists(cache));
  // the key belongs to the waveguide rail: with the beams it is refused, naming it
  const Invocation c =
      run("noise " + source_file("cases/curve_300m.toml") + " -o " + (dir / "c.h5").string() +
          " -q --set curve.creepage=\\\"estimate\\\" --set track.sampling_cache=\\\"user\\\"");
  EXPECT_NE(c.status, 0);
  EXPECT_NE(c.output.find("track.sampling_cache"), std::string::npos) << c.output;
}

// A case that changes the rail never reads another's samplings. A cache folder first holds the
// shipped rail's samplings; then each edit of the rail (pad stiffness, pad damping and sleeper
// spacing in the track file, the support, the section's outline) runs with that folder: it must
// store samplings of its own and give, to the bit, what the same edited case gives with no cache
// at all; and the edit must change the answer (else the check would prove nothing).
TEST(RailSamplingCache, EveryRailEditStoresItsOwnSamplingsAndNeverReadsAnothers) {
  namespace fs = std::filesystem;
  const fs::path dir = fresh_dir("rail_cache_edits");
  const fs::path cache = dir / "cache";
  auto edited_copy = [&](const std::string& source, const std::string& name,
                         const std::string& from, const std::string& to) {
    std::string text = rollnoise::io::file_bytes(source_file(source));
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    const fs::path out = dir / name;
    std::ofstream(out) << text;
    return out.string();
  };
  const std::string track = "models/track/uic60_ballasted.toml";
  const std::vector<std::pair<std::string, std::string>> edits = {
      {"pad stiffness",
       "--set 'track.file=\"" +
           edited_copy(track, "pad.toml", "pad_stiffness = 350e6", "pad_stiffness = 500e6") +
           "\"'"},
      {"pad damping", "--set 'track.file=\"" +
                          edited_copy(track, "damping.toml", "pad_loss_factor = 0.25       # eta_p",
                                      "pad_loss_factor = 0.35       # eta_p") +
                          "\"'"},
      {"sleeper spacing",
       "--set 'track.file=\"" +
           edited_copy(track, "spacing.toml", "sleeper_spacing = 0.6", "sleeper_spacing = 0.65") +
           "\"'"},
      {"support", "--set 'track.support=\"discrete\"'"},
      {"section", "--set 'track.rail_section=\"" +
                      edited_copy("models/rail/uic60_outline.csv", "section.csv",
                                  "8.25,36\n8.25,120", "9.5,36\n9.5,120") +
                      "\"'"},
  };
  const fs::path base = dir / "base.h5";
  {
    const CacheFolder folder(cache.string());
    const Invocation a = run("noise " + waveguide_curve(base.string()));
    ASSERT_EQ(a.status, 0) << a.output;
  }
  const std::vector<double> base_force = numbers_of(base, "/noise/bands/force_level");
  for (const auto& [what, set] : edits) {
    const std::size_t before = listing(cache).size();
    std::string stem = what;
    std::replace(stem.begin(), stem.end(), ' ', '_');
    const fs::path with_cache = dir / (stem + "_cached.h5"),
                   without = dir / (stem + "_uncached.h5");
    {
      const CacheFolder folder(cache.string());
      const Invocation a = run("noise " + waveguide_curve(with_cache.string(), set));
      ASSERT_EQ(a.status, 0) << what << "\n" << a.output;
    }
    EXPECT_GT(listing(cache).size(), before) << what << ": no samplings of its own stored";
    {
      const CacheFolder off("off");
      const Invocation b = run("noise " + waveguide_curve(without.string(), set));
      ASSERT_EQ(b.status, 0) << what << "\n" << b.output;
    }
    const std::vector<double> x = numbers_of(with_cache, "/noise/bands/force_level"),
                              y = numbers_of(without, "/noise/bands/force_level");
    ASSERT_EQ(x.size(), y.size()) << what;
    ASSERT_EQ(x.size(), base_force.size()) << what;
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << what;
    double moved = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
      moved = std::max(moved, std::abs(x[i] - base_force[i]));
    EXPECT_GT(moved, 0.01) << what << ": the edit does not change the band levels";
    std::printf("%-16s largest band change %.2f dB, %zu cache files\n", what.c_str(), moved,
                listing(cache).size());
  }
}
