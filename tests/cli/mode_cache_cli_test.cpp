// The wheel's mode cache through the program (wheel.mode_cache, ROLLNOISE_CACHE_DIR;
// docs/interface.md "The wheel's mode cache"): the first run of an FE wheel stores its modes along
// the tread and its radiation (docs/sound.md Sec. 5), the second reads them and writes the same
// numbers, sound powers included; "off" (key or environment) stores nothing of the wheel.
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

// The shipped curve case with its leading outer wheel alone, coarse: a 30 mm FE mesh, n <= 3,
// 2.5 kHz, four lines per band up to 500 Hz (~0.2 s a run).
std::string coarse_curve(const std::string& out, const std::string& more = "") {
  return source_file("cases/curve_300m.toml") + " -o " + out +
         " -q --set 'curve.creepage=\"estimate\"' --set 'curve.wheels=[\"leading_outer\"]' --set "
         "noise.band_max=500 --set "
         "noise.points_per_band=4 --set noise.band_refinement=0 --set wheel.mesh_size=0.03 --set "
         "wheel.n_max=3 --set wheel.f_max=2500.0 " +
         more;
}

std::vector<double> dataset(const std::filesystem::path& file, const std::string& name) {
  const rollnoise::io::Hdf5Reader h(file.string());
  EXPECT_TRUE(h.ok()) << file;
  return h.numbers(name).value_or(std::vector<double>{});
}

}  // namespace

TEST(ModeCache, SecondRunReadsTheModesAndWritesTheSameNumbers) {
  const auto dir = fresh_dir("mode_cache");
  const auto cache = dir / "cache";
  const CacheFolder folder(cache.string());
  const auto first = dir / "first.h5", second = dir / "second.h5";
  const Invocation a = run("noise " + coarse_curve(first.string()));
  ASSERT_EQ(a.status, 0) << a.output;
  // one file for the wheel's modes, one for its radiation, and the rail's two; no temporary
  ASSERT_EQ(listing(cache, "wheel-modes-").size(), 1u);
  ASSERT_EQ(listing(cache, "wheel-radiation-").size(), 1u);
  const std::vector<std::string> files = listing(cache);
  ASSERT_EQ(files.size(), 4u);
  std::vector<std::filesystem::file_time_type> stored;
  for (const auto& f : files) stored.push_back(std::filesystem::last_write_time(cache / f));
  const Invocation b = run("noise " + coarse_curve(second.string()));
  ASSERT_EQ(b.status, 0) << b.output;
  ASSERT_EQ(listing(cache), files);
  for (std::size_t i = 0; i < files.size(); ++i)
    EXPECT_EQ(std::filesystem::last_write_time(cache / files[i]), stored[i]) << files[i];  // read
  // the band levels of forces and wheel and rail velocities: the whole loop, the wheel's modes in
  // it
  for (const char* name : {"/noise/bands/force_level", "/noise/bands/velocity_level",
                           "/noise/wheels/leading_outer/bands/velocity_level", "/noise/sound/power",
                           "/sound/radiation_efficiency/wheel/sigma", "/track/decay_rate/vertical"}) {
    const std::vector<double> x = dataset(first, name), y = dataset(second, name);
    ASSERT_FALSE(x.empty()) << name;
    ASSERT_EQ(x.size(), y.size()) << name;
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << name;
  }
}

TEST(ModeCache, OffInTheCaseOrTheEnvironmentStoresNothing) {
  const auto dir = fresh_dir("mode_cache_off");
  const auto cache = dir / "cache";
  {
    const CacheFolder folder(cache.string());
    const Invocation a =
        run("noise " + coarse_curve((dir / "a.h5").string(), "--set wheel.mode_cache=\\\"off\\\""));
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_TRUE(listing(cache, "wheel-").empty());  // the rail's tables may be kept
  }
  std::filesystem::remove_all(cache);
  const CacheFolder off("off");
  const Invocation b = run("noise " + coarse_curve((dir / "b.h5").string()));
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_FALSE(std::filesystem::exists(cache));
  // the key belongs to the FE wheel: with another wheel model it is refused, naming it
  const Invocation c =
      run("noise " + source_file("cases/curve_300m.toml") + " -o " + (dir / "c.h5").string() +
          " -q --set curve.creepage=\\\"estimate\\\" --set wheel.model=\\\"table\\\" --set "
          "wheel.mode_cache=\\\"user\\\"");
  EXPECT_NE(c.status, 0);
  EXPECT_NE(c.output.find("wheel.mode_cache"), std::string::npos) << c.output;
}
