// --sweep arguments (io/sweep.hpp) and the size check (pipeline/limits.hpp) at library level: the
// three forms parse into their parts, and absurd counts are compared without overflow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "io/sweep.hpp"
#include "pipeline/limits.hpp"

using namespace rollnoise;

TEST(SweepParse, ComponentRangeGivesKeyIndexBoundsAndCount) {
  const io::SweepSpec s = io::parse_sweep("creepage.mean[2]=-0.1:1e-1:5");
  EXPECT_EQ(s.key, "creepage.mean");
  EXPECT_EQ(s.component, 2);
  EXPECT_EQ(s.lo, -0.1);
  EXPECT_EQ(s.hi, 0.1);
  EXPECT_EQ(s.n, 5);
  EXPECT_TRUE(s.list.empty());
}

TEST(SweepParse, TomlListGivesOneValuePerPoint) {
  const io::SweepSpec s = io::parse_sweep("grid.nx=[20, 30, 40]");
  EXPECT_EQ(s.key, "grid.nx");
  EXPECT_EQ(s.component, -1);
  ASSERT_EQ(s.list.size(), 3u);
  EXPECT_EQ(s.list[2], "40");
}

TEST(SweepParse, PartlyNumericTokensAreRefused) {
  for (const char* arg :
       {"friction.mu=0.1:0.5:1e1", "friction.mu=0.1:0.5: 3", "friction.mu=0.1 :0.5:3",
        "friction.mu=0.1:0.5:+3", "friction.mu=nan:0.5:3", "friction.mu=0.1:inf:3",
        "creepage.mean[1 ]=0:1:3", "creepage.mean[1=0:1:3", "=0:1:3"})
    EXPECT_THROW(io::parse_sweep(arg), InputError) << arg;
}

TEST(SizeCheck, CountsBeyondLongAndNaNAreOverTheLimit) {
  pipeline::Limits l;
  l.steps = 10;
  l.memory = 1e3;
  EXPECT_NO_THROW(pipeline::check_size(l, "k", 10, "steps", 1e3));
  EXPECT_THROW(pipeline::check_size(l, "k", 11, "steps", 0), InputError);
  EXPECT_THROW(pipeline::check_size(l, "k", 2.9e13, "steps", 0), InputError);
  EXPECT_THROW(pipeline::check_size(l, "k", std::nan(""), "steps", 0), InputError);
  EXPECT_THROW(pipeline::check_size(l, "k", 1, "steps", 1001), InputError);
  EXPECT_THROW(pipeline::check_size(l, "k", 1, "steps", std::numeric_limits<double>::infinity()),
               InputError);
  try {
    pipeline::check_size(l, "transient.duration", 11, "steps", 0);
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "transient.duration");
  }
}

TEST(SizeCheck, DefaultMemoryLimitIsHalfThePhysicalMemory) {
  const double half = pipeline::default_memory_limit();
  EXPECT_GT(half, 1e8);  // any machine that runs the tests has more than 200 MB
  EXPECT_EQ(pipeline::Limits{}.memory_bytes(), half);
}
