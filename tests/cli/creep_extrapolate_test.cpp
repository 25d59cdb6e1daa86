// `rollnoise creep --extrapolate` end to end: the grids option is checked before anything runs
// (exit 2 naming --extrapolate-grids, no file left, the case unchanged), a frequency above the
// coarsest grid's Nyquist limit names the frequency key, and a run writes the extrapolated f and
// g with their error estimates (same shape, with units) and the grids.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"
#include "io/hdf5_reader.hpp"

using namespace rollnoise::cli_test;

namespace {

// The paper's case on coarse grids (a margin for them), two frequencies.
const std::string kCoarseExtrapolation =
    " --set grid.nx=14 --set grid.ny=10 --set grid.scale=1.25 --set 'frequency.list=[1000.0, 5000.0]'";

}  // namespace

TEST(CreepExtrapolate, BadGridFactorsAreRefusedNamingTheOptionBeforeAnythingRuns) {
  const auto out = temp_dir() / "extrapolate_bad.h5";
  const std::string before = file_contents(paper_case());
  for (const char* grids : {"1", "2,1", "1,1", "0,1", "1,1.5,2,3", "1,abc", "0.2,1"}) {
    const auto r = run("creep " + paper_case() + kCoarseExtrapolation + " --extrapolate-grids " + grids + " -o " + out.string());
    EXPECT_EQ(r.status, 2) << grids << ": " << r.output;
    EXPECT_NE(r.output.find("--extrapolate-grids"), std::string::npos) << grids << ": " << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << grids;
  }
  EXPECT_EQ(file_contents(paper_case()), before);
}

TEST(CreepExtrapolate, AFrequencyAboveTheNyquistLimitNamesTheFrequencyKey) {
  const auto out = temp_dir() / "extrapolate_nyquist.h5";
  // 14 x 10 over +-1.25 a: Nyquist V/(2 dx) = 5.4 kHz
  const auto r = run("creep " + paper_case() + kCoarseExtrapolation + " --set 'frequency.list=[1000.0, 6000.0]' --extrapolate -o " +
                     out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("frequency.list"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Nyquist"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CreepExtrapolate, WritesTheExtrapolatedCoefficientsWithTheirErrorsAndTheGrids) {
  const auto out = temp_dir() / "extrapolate.h5";
  const auto r = run("creep " + paper_case() + kCoarseExtrapolation + " --extrapolate-grids 1,1.5 -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const rollnoise::io::Hdf5Reader h5(out.string());
  ASSERT_TRUE(h5.ok());
  std::vector<std::size_t> dims;
  const auto fe = h5.numbers("/creep/f_error", &dims);
  ASSERT_TRUE(fe.has_value());
  EXPECT_EQ(dims, (std::vector<std::size_t>{2, 3, 3}));
  for (double e : *fe) EXPECT_TRUE(e >= 0.0 && std::isfinite(e));
  EXPECT_GT((*fe)[0], 0.0) << "f11 differs between the grids";
  ASSERT_TRUE(h5.numbers("/creep/g_error", &dims).has_value());
  EXPECT_EQ(dims, (std::vector<std::size_t>{2, 3}));
  for (const char* d : {"/creep/f", "/creep/g", "/creep/f_error", "/creep/g_error", "/creep/extrapolation/nx",
                        "/creep/extrapolation/dx", "/creep/extrapolation/f_order", "/creep/extrapolation/f_grids"})
    EXPECT_TRUE(h5.attribute(d, "units").has_value()) << d;
  EXPECT_EQ(*h5.numbers("/creep/extrapolation/nx"), (std::vector<double>{14, 21}));
  // two grids: the sampling's order, 2 for average (the default)
  EXPECT_EQ(*h5.numbers("/creep/extrapolation/assumed_order"), (std::vector<double>{2.0}));
  EXPECT_EQ(*h5.attribute("/creep", "creepage_sampling"), "average");
  std::filesystem::remove(out);
}
