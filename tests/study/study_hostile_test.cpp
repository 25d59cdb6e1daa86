// A study case is complete only if computed from the same inputs (the
// case as run and the bytes of every model file it reads), `collect` reports the others as stale;
// a second run on the same cases is refused naming the first; a study with a failed case exits 1;
// `collect` refuses a folder as OUTPUT/study.h5 before reading any case.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "../cli/cli_support.hpp"

namespace fs = std::filesystem;
using rollnoise::cli_test::run;

namespace {

fs::path hostile_folder(const std::string& name) {
  const fs::path d = rollnoise::cli_test::temp_dir() / ("hostile_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// tests/data/study/curve_small.toml copied into `d` with its wheel modes file beside it (so that
// the test may edit both); the other model files are found through the source tree.
fs::path copy_base(const fs::path& d) {
  const std::string src = ROLLNOISE_SOURCE_DIR;
  fs::copy_file(src + "/models/wheel/wheel_920mm_modes.csv", d / "modes.csv");
  std::string base = text_of(src + "/tests/data/study/curve_small.toml");
  const std::string from = "modes = \"models/wheel/wheel_920mm_modes.csv\"";
  base.replace(base.find(from), from.size(), "modes = \"modes.csv\"");
  std::ofstream(d / "base.toml") << base;
  return d / "base.toml";
}

void replace_in(const fs::path& p, const std::string& from, const std::string& to) {
  std::string s = text_of(p);
  ASSERT_NE(s.find(from), std::string::npos) << from;
  s.replace(s.find(from), from.size(), to);
  std::ofstream(p) << s;
}

}  // namespace

TEST(StudyInputs, EditingTheBaseCaseOrAModelFileMakesTheResultsStaleAndTheyAreComputedAgain) {
  const fs::path d = hostile_folder("stale");
  copy_base(d);
  std::ofstream(d / "s.toml")
      << "base = \"base.toml\"\noutput = \"out\"\n[axes]\n\"curve.radius\" = [300.0, 500.0]\n";
  const std::string study = (d / "s.toml").string();
  auto r = run("study " + study + " -j 1");
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_NE(r.output.find("2 complete now"), std::string::npos) << r.output;

  // friction.mu 0.3 -> 0.25 in the base case: both results are stale
  replace_in(d / "base.toml", "mu = 0.3", "mu = 0.25");
  r = run("collect " + study);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0 complete, 0 failed, 0 missing, 2 stale"), std::string::npos)
      << r.output;
  EXPECT_NE(text_of(d / "out/study.csv").find(",stale,"), std::string::npos);
  r = run("study " + study + " -j 1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 complete now, 0 already complete"), std::string::npos) << r.output;
  r = run("study " + study + " -j 1");
  EXPECT_NE(r.output.find("0 complete now, 2 already complete"), std::string::npos) << r.output;

  // one byte of a model file the cases read (a comment line in the wheel modes): stale again
  std::ofstream(d / "modes.csv", std::ios::app) << "# edited\n";
  r = run("collect " + study);
  EXPECT_NE(r.output.find("2 stale"), std::string::npos) << r.output;
  r = run("study " + study + " -j 1");
  EXPECT_NE(r.output.find("2 complete now, 0 already complete"), std::string::npos) << r.output;
}

TEST(StudyRuns, ASecondRunOnTheSameFolderIsRefusedNamingTheFirst) {
  const fs::path d = hostile_folder("lock");
  // the 34 x 25 grid and 48 samples per band: about 0.2 s per case, 2 s for the study
  std::ofstream(d / "s.toml")
      << "base = \"" << ROLLNOISE_SOURCE_DIR
      << "/tests/data/study/curve_small.toml\"\noutput = \"out\"\n[axes]\n"
         "\"curve.radius\" = { from = 200.0, to = 1300.0, count = 12 }\n"
         "\"grid.nx\" = [34]\n\"grid.ny\" = [25]\n\"noise.points_per_band\" = [48]\n";
  const std::string study = (d / "s.toml").string();
  const pid_t first = ::fork();
  if (first == 0) {
    ::execl(ROLLNOISE_BINARY, ROLLNOISE_BINARY, "study", study.c_str(), "-j", "1", "-q",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(d / "out/.lock") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the lock follows the file at once
  const auto second = run("study " + study + " -j 1 -q");
  const auto single = run("study " + study + " --case 3 -q");
  int st = 0;
  const bool still_running = ::waitpid(first, &st, WNOHANG) == 0;
  ::kill(first, SIGTERM);
  ::waitpid(first, &st, 0);
  ASSERT_TRUE(still_running) << "the first run ended before the second started";
  EXPECT_EQ(second.status, 2) << second.output;
  EXPECT_NE(second.output.find("another rollnoise study (process " + std::to_string(first) + ")"),
            std::string::npos)
      << second.output;
  EXPECT_EQ(single.status, 2) << single.output;
  EXPECT_NE(single.output.find("another rollnoise study"), std::string::npos) << single.output;
}

TEST(StudyRuns, AStudyWhoseCasesAllFailExitsOne) {
  const fs::path d = hostile_folder("all_fail");
  std::ofstream(d / "s.toml") << "base = \"" << ROLLNOISE_SOURCE_DIR
                              << "/tests/data/study/curve_small.toml\"\noutput = \"out\"\n[axes]\n"
                                 "\"friction.mu\" = [-0.2, -0.3]\n";
  const auto r = run("study " + (d / "s.toml").string() + " -j 2");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("2 failed"), std::string::npos) << r.output;
  const auto one = run("study " + (d / "s.toml").string() + " --case 1 -q");
  EXPECT_EQ(one.status, 1) << one.output;
}

TEST(StudyRuns, CollectRefusesAFolderAsItsOutputBeforeReadingTheCases) {
  const fs::path d = hostile_folder("collect_folder");
  std::ofstream(d / "s.toml") << "base = \"" << ROLLNOISE_SOURCE_DIR
                              << "/tests/data/study/curve_small.toml\"\noutput = \"out\"\n[axes]\n"
                                 "\"friction.mu\" = [0.3]\n";
  fs::create_directories(d / "out/study.h5");
  const auto r = run("collect " + (d / "s.toml").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("study.h5: is a folder"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d / "out/study.csv"));
  EXPECT_TRUE(fs::is_directory(d / "out/study.h5"));
}
