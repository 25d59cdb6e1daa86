// Progress: commands that can run long end with a one-line summary on stderr (which a
// log keeps), and -q silences it; stdout (results) is the same either way.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"

using namespace rollnoise::cli_test;

namespace {

// Runs `command` with stdout discarded; its exit status and what it wrote to stderr (a log).
std::pair<int, std::string> stderr_of(const std::string& command) {
  const auto log = temp_dir() / "progress.log";
  const int status = WEXITSTATUS(std::system((std::string(ROLLNOISE_BINARY) + " " + command + " 2>" + log.string() +
                                               " >/dev/null").c_str()));
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  return {status, ss.str()};
}

}  // namespace

TEST(Progress, LongCommandsEndWithASummaryLineAndQuietSilencesIt) {
  const auto out = temp_dir() / "progress.h5";
  const std::string sweep = "steady " + paper_case() + " --set grid.nx=16 --set grid.ny=12 --sweep 'friction.mu=0.1:0.5:5' -o " +
                            out.string();
  const std::string transient = "transient " + paper_case() + " --set grid.nx=16 --set grid.ny=12 "
                                "--set transient.duration=0.001 -o " + out.string();
  for (const auto& [command, summary] : {std::pair{sweep, std::string("sweep: 5 of 5 points in ")},
                                         std::pair{transient, std::string("transient: ")}}) {
    const auto [status, log] = stderr_of(command);
    ASSERT_EQ(status, 0) << log;
    EXPECT_NE(log.find(summary), std::string::npos) << log;
    EXPECT_NE(log.find(" s\n"), std::string::npos) << log;
    const auto [quiet_status, quiet_log] = stderr_of(command + " -q");
    ASSERT_EQ(quiet_status, 0) << quiet_log;
    EXPECT_EQ(quiet_log, "") << "-q must silence the progress";
  }
}
