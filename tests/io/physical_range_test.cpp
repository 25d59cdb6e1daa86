// Physical ranges (KeySpec::warn_min, warn_max; src/io/case_schema.cpp): a valid but unphysical
// value is accepted with one warning line naming the key, its value and the range.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/case_schema.hpp"

namespace {

using rollnoise::io::CaseReader;
using rollnoise::io::physical_range_warnings;

std::vector<std::string> warnings_of(const std::string& toml) {
  return physical_range_warnings(CaseReader::from_string(toml, "range_case.toml"));
}

}  // namespace

TEST(PhysicalRange, FrictionAboveOneGivesOneWarningNamingKeyValueAndRange) {
  const auto w = warnings_of("[friction]\nmu = 5.0\n");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("warning: friction.mu = 5 is outside the physical range [0, 1] (", 0), 0u)
      << w[0];
}

TEST(PhysicalRange, ValuesInsideTheirRangesGiveNoWarning) {
  EXPECT_TRUE(
      warnings_of("[friction]\nmu = 0.3\n[rolling]\nspeed = 40.0\n[wheel]\npoisson_ratio = 0.3\n")
          .empty());
}

TEST(PhysicalRange, EachKeyOutsideItsRangeIsNamed) {
  const auto w = warnings_of("[rolling]\nspeed = 200.0\n[wheel]\npoisson_ratio = -0.2\n");
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("rolling.speed = 200 m/s"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("wheel.poisson_ratio = -0.2"), std::string::npos) << w[1];
}

TEST(PhysicalRange, InvalidValueIsLeftToItsReadersError) {
  EXPECT_TRUE(warnings_of("[friction]\nmu = \"high\"\n").empty());
}

// Every declared range is an interval holding the key's default (a default never warns).
TEST(PhysicalRange, EveryDeclaredRangeHoldsItsKeysDefault) {
  int ranges = 0;
  for (const auto& k : rollnoise::io::case_schema()) {
    if (k.warn_why.empty()) continue;
    ++ranges;
    EXPECT_LT(k.warn_min, k.warn_max) << k.key;
    if (k.default_value.empty()) continue;
    const double d = std::stod(k.default_value);
    EXPECT_TRUE(d >= k.warn_min && d <= k.warn_max) << k.key << " = " << d;
  }
  EXPECT_GE(ranges, 4);
}
