// Reading a case reports every problem at once (io/input_problems.hpp): one InputError whose
// message names each bad key, so a user fixes a case in one round, not one key per run.
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "io/noise_case.hpp"

namespace {

using namespace rollnoise;

const char* kHertzCase = R"(
[material]
E = 2.1e11
nu = 0.28
[friction]
mu = 0.3
[rolling]
speed = 30.0
[contact]
geometry = "hertz"
normal_force = 98100.0
a = 7.18e-3
b = 5.29e-3
[creepage]
mean = [0.001, 0.0, 0.0]
[grid]
nx = 34
ny = 25
scale = 1.25
)";

std::string case_with(const std::vector<std::string>& overrides) {
  const io::CaseReader r = io::CaseReader::from_string(kHertzCase, "problems.toml", overrides);
  try {
    io::read_contact_case(r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaseProblems, AValidCaseHasNone) { EXPECT_EQ(case_with({}), ""); }

TEST(CaseProblems, EveryBadKeyIsNamedInOneError) {
  const std::string msg =
      case_with({"material.nu=0.7", "friction.mu=-0.3", "rolling.speed=-1.0", "solver.max_iterations=0"});
  for (const char* key : {"material.nu", "friction.mu", "rolling.speed", "solver.max_iterations"})
    EXPECT_NE(msg.find(key), std::string::npos) << key << " missing from:\n" << msg;
  EXPECT_NE(msg.find("4 problems"), std::string::npos) << msg;
}

TEST(CaseProblems, OneBadKeyGivesTheMessageOfThatKeyAlone) {
  const std::string msg = case_with({"material.nu=0.7"});
  EXPECT_NE(msg.find("material.nu"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("problems in the case"), std::string::npos) << msg;
}

TEST(CaseProblems, ADependentCheckStopsOnlyItsOwnGroup) {
  // a grid too coarse for the patch and a bad friction: both reported, the grid once
  const std::string msg = case_with({"grid.nx=3", "friction.mu=-1.0"});
  EXPECT_NE(msg.find("grid.nx"), std::string::npos) << msg;
  EXPECT_NE(msg.find("friction.mu"), std::string::npos) << msg;
  EXPECT_NE(msg.find("2 problems"), std::string::npos) << msg;
}

TEST(CaseProblems, TheFirstProblemsKeyIsTheErrorsKey) {
  const io::CaseReader r = io::CaseReader::from_string(kHertzCase, "problems.toml", {"material.E=-1.0", "friction.mu=-1.0"});
  try {
    io::read_contact_case(r);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "material.E");
  }
}

// A value the user's --set gave is blamed on the --set, not on the case file; one read by two
// readers is listed once.
TEST(CaseProblems, ABadSetValueNamesTheSetAndIsListedOnce) {
  const std::string msg = case_with({"friction.mu=\"abc\""});
  EXPECT_NE(msg.find("--set friction.mu: expected a number"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("problems.toml"), std::string::npos) << msg;
  const std::string noise = [] {
    try {
      io::read_noise_inputs(io::CaseReader::from_string(kHertzCase, "problems.toml", {"rolling.speed=-3.0"}));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  EXPECT_EQ(noise.find("problems in the case"), std::string::npos) << noise;
  EXPECT_NE(noise.find("--set rolling.speed: must be positive"), std::string::npos) << noise;
}

// A mistyped key, in the file or in a --set, gets the nearest declared key as a suggestion.
TEST(CaseProblems, AMistypedKeyGetsTheNearestDeclaredOne) {
  std::string msg;
  try {
    io::CaseReader::from_string(kHertzCase, "problems.toml", {"friction.muu=0.3"});
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("did you mean 'friction.mu'?"), std::string::npos) << msg;
  msg.clear();
  try {
    io::CaseReader::from_string(std::string(kHertzCase) + "[noise]\nband_maxx = 400.0\n", "problems.toml");
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("did you mean 'noise.band_max'?"), std::string::npos) << msg;
  msg.clear();
  try {  // far from every key: no suggestion
    io::CaseReader::from_string(kHertzCase, "problems.toml", {"weather.rain=1.0"});
  } catch (const InputError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("unknown key"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("did you mean"), std::string::npos) << msg;
}

}  // namespace
