// The expansion of a study into cases, its shards, and the study file reader (docs/study.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/errors.hpp"
#include "io/study_file.hpp"
#include "pipeline/study_plan.hpp"
#include "support/test_inputs.hpp"

using namespace rollnoise;
using pipeline::Axis;
using pipeline::AxisValue;
using pipeline::StudyPlan;

namespace {

Axis numbers(const std::string& key, std::vector<double> v) {
  Axis a{key, {}};
  for (double x : v) a.values.push_back(pipeline::number_value(x));
  return a;
}

// This test process's scratch folder, removed when the process ends (the suite leaves nothing behind).
std::filesystem::path scratch() {
  static const struct Scratch {
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("rollnoise_study_plan_" + std::to_string(::getpid()));
    ~Scratch() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } s;
  return s.dir;
}

std::string write_file(const std::string& name, const std::string& text) {
  const auto d = scratch();
  std::filesystem::create_directories(d);
  const auto p = d / name;
  std::ofstream(p) << text;
  return p.string();
}

using rollnoise::test_support::study_base_case;

}  // namespace

TEST(StudyPlan, ProductVariesTheLastAxisFastestAndCoversEveryCombinationOnce) {
  StudyPlan plan;
  plan.axes = {numbers("curve.radius", {300, 500, 1000}), numbers("rolling.speed", {15, 20, 25, 30})};
  const auto cases = pipeline::expand(plan);
  ASSERT_EQ(cases.size(), 12u);
  std::set<std::pair<double, double>> seen;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    EXPECT_EQ(cases[k].index, k);
    EXPECT_EQ(cases[k].values[0].number, plan.axes[0].values[k / 4].number);
    EXPECT_EQ(cases[k].values[1].number, plan.axes[1].values[k % 4].number);
    seen.insert({cases[k].values[0].number, cases[k].values[1].number});
  }
  EXPECT_EQ(seen.size(), 12u);
  EXPECT_EQ(pipeline::overrides(plan, cases[5]), (std::vector<std::string>{"curve.radius=500.0", "rolling.speed=20.0"}));
}

TEST(StudyPlan, ZipPairsTheValuesAndRefusesAxesOfDifferentLength) {
  StudyPlan plan;
  plan.combine = pipeline::Combine::kZip;
  plan.axes = {numbers("curve.radius", {300, 500, 1000}), numbers("rolling.speed", {15, 20, 25})};
  const auto cases = pipeline::expand(plan);
  ASSERT_EQ(cases.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(cases[k].values[0].number, plan.axes[0].values[k].number);
    EXPECT_EQ(cases[k].values[1].number, plan.axes[1].values[k].number);
  }
  plan.axes[1] = numbers("rolling.speed", {15, 20});
  try {
    pipeline::expand(plan);
    FAIL() << "zip of axes of 3 and 2 values accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "axes.rolling.speed");
  }
}

TEST(StudyPlan, RangesHitTheirEndsExactlyAndNumbersReadBackBitForBit) {
  const auto lin = pipeline::linear_range(15.0, 30.0, 4);
  EXPECT_EQ(lin, (std::vector<double>{15.0, 20.0, 25.0, 30.0}));
  const auto lg = pipeline::log_range(100.0, 10000.0, 5);
  EXPECT_EQ(lg.front(), 100.0);
  EXPECT_EQ(lg.back(), 10000.0);
  for (std::size_t i = 1; i < lg.size(); ++i) EXPECT_NEAR(lg[i] / lg[i - 1], std::sqrt(10.0), 1e-12);
  for (double v : {0.1, 1.0 / 3.0, 1e-300, 6.02e23, 300.0}) {
    const AxisValue a = pipeline::number_value(v);
    EXPECT_EQ(std::strtod(a.toml.c_str(), nullptr), v) << a.toml;
    EXPECT_NE(a.toml.find_first_of(".eE"), std::string::npos) << a.toml << " would read as a TOML integer";
  }
}

TEST(StudyPlan, EveryCaseBelongsToExactlyOneShard) {
  for (long n = 1; n <= 5; ++n) {
    for (std::size_t k = 0; k < 23; ++k) {
      int owners = 0;
      for (long i = 1; i <= n; ++i) owners += pipeline::Shard{i, n}.contains(k);
      EXPECT_EQ(owners, 1) << "case " << k << " of " << n << " shards";
    }
  }
  EXPECT_EQ(pipeline::parse_shard("2/3").index, 2);
  for (const char* bad : {"0/3", "4/3", "a/3", "1/0", "1/3x", "3", "", "-1/3", "99999999999999999999/3"})
    EXPECT_THROW(pipeline::parse_shard(bad), InputError) << bad;
}

TEST(StudyPlan, SlurmArrayVariablesGiveTheShardWhateverTheArraysFirstIndex) {
  ::setenv("SLURM_ARRAY_TASK_ID", "7", 1);
  ::setenv("SLURM_ARRAY_TASK_COUNT", "4", 1);
  ::setenv("SLURM_ARRAY_TASK_MIN", "5", 1);  // --array=5-8
  const pipeline::Shard s = pipeline::shard_from_environment();
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 4);
  ::setenv("SLURM_ARRAY_TASK_ID", "9", 1);  // outside 5..8
  EXPECT_THROW(pipeline::shard_from_environment(), InputError);
  ::unsetenv("SLURM_ARRAY_TASK_ID");
  ::unsetenv("SLURM_ARRAY_TASK_COUNT");
  ::unsetenv("SLURM_ARRAY_TASK_MIN");
  EXPECT_EQ(pipeline::shard_from_environment().count, 1);
}

// --array=1-5:2 runs tasks 1, 3, 5 (COUNT 3, MIN 1, STEP 2): shards 1/3, 2/3, 3/3.
TEST(StudyPlan, SlurmArrayWithAStepGivesEveryTaskItsOwnShard) {
  ::setenv("SLURM_ARRAY_TASK_COUNT", "3", 1);
  ::setenv("SLURM_ARRAY_TASK_MIN", "1", 1);
  ::setenv("SLURM_ARRAY_TASK_STEP", "2", 1);
  for (long id : {1, 3, 5}) {
    ::setenv("SLURM_ARRAY_TASK_ID", std::to_string(id).c_str(), 1);
    const pipeline::Shard s = pipeline::shard_from_environment();
    EXPECT_EQ(s.index, (id - 1) / 2 + 1) << "task " << id;
    EXPECT_EQ(s.count, 3) << "task " << id;
  }
  for (const char* id : {"2", "7"}) {  // not a task of this array
    ::setenv("SLURM_ARRAY_TASK_ID", id, 1);
    EXPECT_THROW(pipeline::shard_from_environment(), InputError) << id;
  }
  for (const char* v : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_STEP"})
    ::unsetenv(v);
}

TEST(StudyFile, AxesKeepTheOrderWrittenAndAcceptRangesListsAndDottedKeys) {
  const std::string f = write_file("order.toml", "base = \"" + study_base_case() + "\"\noutput = \"out\"\n[axes]\n"
                                   "\"rolling.speed\" = { from = 15.0, to = 30.0, count = 4 }\n"
                                   "curve.radius = [300.0, 500]\n"
                                   "\"friction.mu\" = { from = 0.1, to = 0.4, count = 3, scale = \"log\" }\n"
                                   "\"roughness.wheel\" = [\"cast-iron\", \"disc-braked\"]\n");
  const StudyPlan plan = io::read_study_file(f);
  ASSERT_EQ(plan.axes.size(), 4u);
  EXPECT_EQ(plan.axes[0].key, "rolling.speed");
  EXPECT_EQ(plan.axes[1].key, "curve.radius");
  EXPECT_EQ(plan.axes[2].key, "friction.mu");
  EXPECT_EQ(plan.axes[3].key, "roughness.wheel");
  EXPECT_EQ(plan.axes[1].values[1].toml, "500");  // an integer stays an integer
  EXPECT_NEAR(plan.axes[2].values[1].number, 0.2, 1e-15);
  EXPECT_TRUE(std::isnan(plan.axes[3].values[0].number));
  EXPECT_EQ(plan.axes[3].values[1].toml, "'disc-braked'");
  EXPECT_EQ(plan.output, (std::filesystem::path(f).parent_path() / "out").string());
  EXPECT_EQ(pipeline::expand(plan).size(), 4u * 2 * 3 * 2);
}

TEST(StudyFile, MistakesAreInputErrorsNamingTheKey) {
  const std::string b = "base = \"" + study_base_case() + "\"\n";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {b + "[axes]\n\"curve.radiuss\" = [300.0]\n", "axes.\"curve.radiuss\""},
      {b + "[axes]\n\"curve.radius\" = []\n", "axes.\"curve.radius\""},
      {b + "[axes]\n\"curve.radius\" = { from = 1.0, to = 2.0, count = 0 }\n", "axes.\"curve.radius\".count"},
      {b + "[axes]\n\"curve.radius\" = { from = 0.0, to = 2.0, count = 3, scale = \"log\" }\n", "axes.\"curve.radius\""},
      {b + "combine = \"cross\"\n[axes]\n\"curve.radius\" = [300.0]\n", "combine"},
      {b + "colour = 1\n[axes]\n\"curve.radius\" = [300.0]\n", "colour"},
      {"base = \"nowhere.toml\"\n[axes]\n\"curve.radius\" = [300.0]\n", "base"},
      {b, "axes"},
  };
  for (const auto& [text, key] : bad) {
    try {
      io::read_study_file(write_file("bad.toml", text));
      ADD_FAILURE() << "accepted:\n" << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  }
}
