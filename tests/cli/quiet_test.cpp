// -q: a successful run prints nothing at all (no progress, no summary); warnings and errors still
// reach stderr.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_support.hpp"

using namespace rollnoise::cli_test;

namespace {

const std::string kCoarseGrid = " --set grid.nx=20 --set grid.ny=15";

// The shipped curve case, its leading outer wheel alone and coarse (as the mode cache's tests).
std::string coarse_noise_case() {
  return source_file("cases/curve_300m.toml") +
         " --set 'curve.creepage=\"estimate\"' --set 'curve.wheels=[\"leading_outer\"]' --set "
         "noise.band_max=500 --set "
         "noise.points_per_band=4 --set noise.band_refinement=0 --set wheel.mesh_size=0.03 --set "
         "wheel.n_max=3 --set wheel.f_max=2500.0";
}

// Runs `command` with and without -q: both succeed, the quiet run prints nothing, the other does.
void expect_quiet_run_prints_nothing(const std::string& command, const std::string& out) {
  const Invocation loud = run(command + " -o " + out);
  ASSERT_EQ(loud.status, 0) << loud.output;
  EXPECT_NE(loud.output, "") << command;
  const Invocation quiet = run(command + " -o " + out + " -q");
  ASSERT_EQ(quiet.status, 0) << quiet.output;
  EXPECT_EQ(quiet.output, "") << command;
}

}  // namespace

TEST(QuietOption, SteadyPrintsNothingOnSuccess) {
  expect_quiet_run_prints_nothing("steady " + paper_case() + kCoarseGrid,
                                  (temp_dir() / "q_steady.h5").string());
}

TEST(QuietOption, CreepPrintsNothingOnSuccess) {
  expect_quiet_run_prints_nothing(
      "creep " + paper_case() + kCoarseGrid + " --set frequency.count=7",
      (temp_dir() / "q_creep.h5").string());
}

TEST(QuietOption, NoisePrintsNothingOnSuccess) {
  rollnoise::cli_test::CacheFolder cache("off");
  expect_quiet_run_prints_nothing("noise " + coarse_noise_case(),
                                  (temp_dir() / "q_noise.h5").string());
}

TEST(QuietOption, ErrorsStillReachStderr) {
  // an unknown key is an error: exit 2 and its message, also with -q
  const Invocation r = run("steady " + paper_case() + " -q --set grid.nz=3 -o " +
                           (temp_dir() / "q_bad.h5").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("grid.nz"), std::string::npos) << r.output;
}
