// The default output of a command, CASENAME.COMMAND.h5: two commands of one case keep both results,
// and the default never replaces a file that another command wrote (only -o naming it does).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"
#include "io/output_files.hpp"

namespace fs = std::filesystem;
using namespace rollnoise::cli_test;

namespace {

// `rollnoise ARGS` run in folder `dir` (the default output goes there); status and stdout + stderr.
Invocation run_in_folder(const fs::path& dir, const std::string& args) {
  return run_shell("cd '" + dir.string() + "' && " + ROLLNOISE_BINARY + " " + args + " 2>&1");
}

const std::string kSmallCreep = " -q --set grid.nx=20 --set grid.ny=15 --set frequency.count=7";

}  // namespace

TEST(DefaultOutput, TwoCommandsOfOneCaseKeepBothResults) {
  const fs::path d = fresh_dir("default_two_commands");
  ASSERT_EQ(run_in_folder(d, "steady " + paper_case() + " -q").status, 0);
  const Invocation creep = run_in_folder(d, "creep " + paper_case() + kSmallCreep);
  ASSERT_EQ(creep.status, 0) << creep.output;
  EXPECT_EQ(listing(d),
            (std::vector<std::string>{"hertz_paper.creep.h5", "hertz_paper.steady.h5"}));
  EXPECT_EQ(rollnoise::io::recorded_command((d / "hertz_paper.steady.h5").string()), "steady");
  EXPECT_EQ(rollnoise::io::recorded_command((d / "hertz_paper.creep.h5").string()), "creep");
}

TEST(DefaultOutput, RerunOfTheSameCommandReplacesItsResult) {
  const fs::path d = fresh_dir("default_rerun");
  ASSERT_EQ(run_in_folder(d, "steady " + paper_case() + " -q").status, 0);
  const Invocation again = run_in_folder(d, "steady " + paper_case() + " -q");
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(listing(d), (std::vector<std::string>{"hertz_paper.steady.h5"}));
}

TEST(DefaultOutput, DefaultNameWrittenByAnotherCommandIsRefusedNamingOption) {
  const fs::path d = fresh_dir("default_other_command");
  const fs::path target = d / "hertz_paper.creep.h5";
  ASSERT_EQ(run("steady " + paper_case() + " -q -o " + target.string()).status, 0);
  const Invocation refused = run_in_folder(d, "creep " + paper_case() + kSmallCreep);
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("-o"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("rollnoise steady"), std::string::npos) << refused.output;
  EXPECT_EQ(rollnoise::io::recorded_command(target.string()), "steady");  // untouched
  // -o naming it explicitly replaces it
  const Invocation named =
      run_in_folder(d, "creep " + paper_case() + kSmallCreep + " -o hertz_paper.creep.h5");
  EXPECT_EQ(named.status, 0) << named.output;
  EXPECT_EQ(rollnoise::io::recorded_command(target.string()), "creep");
}

TEST(DefaultOutput, DefaultNameHoldingNoRollnoiseResultIsRefused) {
  const fs::path d = fresh_dir("default_foreign");
  { std::ofstream(d / "hertz_paper.steady.h5") << "not HDF5\n"; }
  const Invocation refused = run_in_folder(d, "steady " + paper_case() + " -q");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("no rollnoise result"), std::string::npos) << refused.output;
  EXPECT_EQ(file_contents((d / "hertz_paper.steady.h5").string()), "not HDF5\n");
}
