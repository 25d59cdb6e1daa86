// The waveguide rail's sampling cache through the program (track.sampling_cache,
// ROLLNOISE_CACHE_DIR; docs/interface.md "The rail's sampling cache"): the first run of a waveguide case
// stores its samplings at the contacts, the second reads them and writes the same numbers; "off"
// (key or environment) stores nothing; the key belongs to the waveguide rail.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
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
  const Invocation c = run("noise " + source_file("cases/curve_300m.toml") + " -o " +
                           (dir / "c.h5").string() + " -q --set track.sampling_cache=\\\"user\\\"");
  EXPECT_NE(c.status, 0);
  EXPECT_NE(c.output.find("track.sampling_cache"), std::string::npos) << c.output;
}
