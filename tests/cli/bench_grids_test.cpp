// `bench --nx` is checked before anything runs: at least two grids, coarse to
// fine, each fine enough for the patch; otherwise exit 2 naming --nx and no file.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_support.hpp"

using namespace rollnoise::cli_test;

TEST(BenchCommand, GridListsThatCannotGiveATableAreRefusedNamingNx) {
  const auto out = temp_dir() / "bench_bad.h5";
  const auto csv = temp_dir() / "bench_bad.csv";
  for (const char* grids : {"3,10", "20,10", "0,10", "10", "10,10", "-4,10", "10,5000"}) {
    const auto r = run("bench " + paper_case() + " --nx=" + grids + " -o " + out.string() + " --csv " + csv.string());
    EXPECT_EQ(r.status, 2) << grids << ": " << r.output;
    EXPECT_NE(r.output.find("--nx"), std::string::npos) << grids << ": " << r.output;
    EXPECT_EQ(r.output.find("nan"), std::string::npos) << grids << ": " << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << grids;
    EXPECT_FALSE(std::filesystem::exists(csv)) << grids;
  }
}
