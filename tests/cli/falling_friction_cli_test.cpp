// friction.law = "falling" from the command line: bad or misplaced law parameters and a decay
// beyond the uniqueness limit are input errors (exit 2) naming the key, leaving no output file and
// the case unchanged; a valid falling law runs (docs/falling_friction.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"

using namespace rollnoise::cli_test;

TEST(FallingFrictionCli, BadLawParametersExitTwoNamingTheKey) {
  const std::string base = "--set grid.nx=16 --set grid.ny=12 --set 'creepage.mean=[0.001,0.001,0]' -q";
  const std::string before = file_contents(paper_case());
  const struct {
    const char* sets;
    const char* key;
  } faults[] = {
      {"--set friction.decay=2.0", "friction.decay"},  // only with law = "falling"
      {"--set friction.law=falling --set friction.decay=2.0", "friction.kinetic_ratio"},  // missing
      {"--set friction.law=falling --set friction.kinetic_ratio=1.5 --set friction.decay=2.0",
       "friction.kinetic_ratio"},
      {"--set friction.law=falling --set friction.kinetic_ratio=0.5 --set friction.decay=-1.0", "friction.decay"},
      {"--set friction.law=falling --set friction.kinetic_ratio=0.5 --set friction.decay=1e4",
       "friction.decay"},  // beyond the element-level uniqueness limit
      {"--set friction.law=rising", "friction.law"},
  };
  for (const auto& f : faults) {
    const auto out = temp_dir() / "falling_fault.h5";
    std::filesystem::remove(out);
    const auto r = run("steady " + paper_case() + " " + base + " " + f.sets + " -o " + out.string());
    EXPECT_EQ(r.status, 2) << f.sets << ": " << r.output;
    EXPECT_NE(r.output.find(f.key), std::string::npos) << f.sets << ": " << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << f.sets;
  }
  EXPECT_EQ(file_contents(paper_case()), before);
}

TEST(FallingFrictionCli, SteadyAndCreepRunWithAFallingLaw) {
  for (const char* command : {"steady", "creep"}) {
    const auto out = temp_dir() / (std::string(command) + "_falling.h5");
    const auto r = run(std::string(command) + " " + paper_case() +
                       " --set grid.nx=16 --set grid.ny=12 --set frequency.count=5 "
                       "--set 'creepage.mean=[0.002,0.001,0]' --set friction.law=falling "
                       "--set friction.kinetic_ratio=0.5 --set friction.decay=2.0 -q -o " + out.string());
    EXPECT_EQ(r.status, 0) << command << ": " << r.output;
    EXPECT_TRUE(std::filesystem::exists(out)) << command;
  }
}
