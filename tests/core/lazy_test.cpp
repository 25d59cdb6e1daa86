// core/lazy.hpp: a value built on first use exactly once, whichever thread asks first and however
// many ask together; copies share it; a build that throws leaves nothing built, and the next use
// builds.
#include "core/lazy.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

using rollnoise::Lazy;

TEST(Lazy, BuiltOnceOnFirstUseForAllThreadsAndCopies) {
  std::atomic<int> builds{0};
  const Lazy<std::vector<int>> v([&builds] {
    ++builds;
    return std::vector<int>(1000, 7);
  });
  EXPECT_EQ(builds.load(), 0);  // nothing before the first use
  const Lazy<std::vector<int>> copy = v;
  std::vector<std::thread> threads;
  std::atomic<long> sum{0};
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      const auto& x = (t % 2 ? v : copy).get();
      sum += x[t];
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(builds.load(), 1);
  EXPECT_EQ(sum.load(), 8 * 7);
  EXPECT_EQ(&v.get(), &copy.get());  // one value, shared
}

TEST(Lazy, BuildThatThrowsBuildsNothingAndTheNextUseBuilds) {
  int attempts = 0;
  const Lazy<int> v([&attempts] {
    if (++attempts == 1) throw std::runtime_error("first build fails");
    return 42;
  });
  EXPECT_THROW(v.get(), std::runtime_error);
  EXPECT_EQ(v.get(), 42);
  EXPECT_EQ(attempts, 2);
}
