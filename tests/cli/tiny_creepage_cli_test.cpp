// Tiny non-zero creepages are valid input; steady and creep solve them (exit 0)
// and the tractions are finite (the library test tests/contact/tiny_creepage_test.cpp checks that
// they scale linearly with the creepage).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_support.hpp"

using namespace rollnoise::cli_test;

TEST(TinyCreepage, SteadyAndCreepSolveCreepagesOf1em50) {
  for (const char* command : {"steady", "creep"})
    for (const char* mean : {"[1e-50,0,0]", "[0,1e-50,0]", "[0,0,1e-50]"}) {
      const auto out = temp_dir() / (std::string(command) + "_tiny.h5");
      const auto r = run(std::string(command) + " " + paper_case() + " --set grid.nx=16 --set grid.ny=12 " +
                         "--set frequency.count=5 --set 'creepage.mean=" + mean + "' -q -o " + out.string());
      EXPECT_EQ(r.status, 0) << command << " " << mean << ": " << r.output;
      EXPECT_TRUE(std::filesystem::exists(out)) << command << " " << mean;
      EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
    }
}
