// A value outside its key's physical range: the run continues (exit 0) and one warning line names
// the key, the value and the range on stderr, also with -q.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_support.hpp"

using namespace rollnoise::cli_test;

TEST(PhysicalRangeWarning, FrictionAboveOneWarnsOnceAndTheRunContinues) {
  const Invocation r = run("steady " + paper_case() + " -q --set friction.mu=5 -o " +
                           (temp_dir() / "mu5.h5").string());
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string line = "warning: friction.mu = 5 is outside the physical range [0, 1]";
  const auto at = r.output.find(line);
  ASSERT_NE(at, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(line, at + 1), std::string::npos) << "warned twice:\n" << r.output;
}
