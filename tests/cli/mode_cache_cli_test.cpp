// The wheel's mode cache through the program (wheel.mode_cache, ROLLNOISE_CACHE_DIR;
// docs/interface.md "The wheel's mode cache"): the first run of an FE wheel stores its modes along
// the tread, the second reads them and writes the same numbers; "off" (key or environment) stores
// nothing.
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
         " -q --set 'curve.wheels=[\"leading_outer\"]' --set noise.band_max=500 --set "
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
  ASSERT_EQ(listing(cache).size(), 1u);  // one file for the wheel, no temporary beside it
  const auto stored = std::filesystem::last_write_time(cache / listing(cache).front());
  const Invocation b = run("noise " + coarse_curve(second.string()));
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(listing(cache).size(), 1u);
  EXPECT_EQ(std::filesystem::last_write_time(cache / listing(cache).front()),
            stored);  // read, not rewritten
  // the band levels of forces and wheel and rail velocities: the whole loop, the wheel's modes in
  // it
  for (const char* name : {"/noise/bands/force_level", "/noise/bands/velocity_level",
                           "/noise/wheels/leading_outer/bands/velocity_level"}) {
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
    EXPECT_FALSE(std::filesystem::exists(cache));
  }
  const CacheFolder off("off");
  const Invocation b = run("noise " + coarse_curve((dir / "b.h5").string()));
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_FALSE(std::filesystem::exists(cache));
  // the key belongs to the FE wheel: with another wheel model it is refused, naming it
  const Invocation c =
      run("noise " + source_file("cases/curve_300m.toml") + " -o " + (dir / "c.h5").string() +
          " -q --set wheel.model=\\\"table\\\" --set wheel.mode_cache=\\\"user\\\"");
  EXPECT_NE(c.status, 0);
  EXPECT_NE(c.output.find("wheel.mode_cache"), std::string::npos) << c.output;
}
