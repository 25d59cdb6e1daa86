// `rollnoise study` and `rollnoise collect` end to end: a study's cases
// equal the single runs bit for bit, shards under GNU parallel equal the local run, a killed study
// resumes without recomputing, and a failing case is recorded while the others complete.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/stat.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "../cli/cli_support.hpp"
#include "support/test_inputs.hpp"

namespace fs = std::filesystem;
using rollnoise::cli_test::run;

namespace {

// Every dataset of a file: its raw bytes (as stored), by path; wall-clock times (".../seconds", e.g.
// a contact's contact_work/seconds) left out: they differ between runs.
std::map<std::string, std::string> datasets(const std::string& path) {
  std::map<std::string, std::string> out;
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return out;
  auto visit = [](hid_t obj, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type != H5O_TYPE_DATASET) return 0;
    const std::string path(name);
    if (path.size() >= 8 && path.compare(path.size() - 8, 8, "/seconds") == 0) return 0;
    const hid_t set = H5Dopen2(obj, name, H5P_DEFAULT);
    const hid_t type = H5Dget_type(set);
    const hid_t space = H5Dget_space(set);
    const std::size_t n = std::size_t(H5Sget_simple_extent_npoints(space)) * H5Tget_size(type);
    std::string bytes(n, '\0');
    H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
    (*static_cast<std::map<std::string, std::string>*>(data))[name] = bytes;
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(set);
    return 0;
  };
  H5Ovisit2(f, H5_INDEX_NAME, H5_ITER_NATIVE, visit, &out, H5O_INFO_BASIC);
  H5Fclose(f);
  return out;
}

using rollnoise::test_support::study_base_case;

// A folder of its own for each test.
fs::path folder(const std::string& name) {
  const fs::path d = rollnoise::cli_test::temp_dir() / ("study_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p;
}

// 12 cases over two axes: 6 radii (each its own curve state) x 2 wheel roughness spectra (sharing it).
std::string twelve_case_study(const std::string& output) {
  return "base = \"" + study_base_case() + "\"\noutput = \"" + output + "\"\n[axes]\n" +
         "\"curve.radius\" = { from = 200.0, to = 700.0, count = 6 }\n" +
         "\"roughness.wheel\" = [\"cast-iron\", \"disc-braked\"]\n";
}

std::string case_file(const fs::path& out, int k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "case_%04d.h5", k);
  return (out / buf).string();
}

}  // namespace

TEST(Study, TwelveCasesWithTwoWorkersEqualTheSingleRunsBitForBit) {
  const fs::path d = folder("twelve");
  const fs::path study = write(d / "study.toml", twelve_case_study("out"));
  const auto r = run("study " + study.string() + " -j 2");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("12 complete now"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("loops computed 6, reused 6"), std::string::npos) << r.output;
  const char* wheel[2] = {"cast-iron", "disc-braked"};
  for (int k = 0; k < 12; ++k) {
    const double radius = 200.0 + 100.0 * (k / 2);
    const std::string single = (d / ("single_" + std::to_string(k) + ".h5")).string();
    char set[128];
    std::snprintf(set, sizeof set, "--set curve.radius=%.1f --set roughness.wheel=%s", radius, wheel[k % 2]);
    ASSERT_EQ(run("noise " + study_base_case() + " " + set + " -o " + single + " -q").status, 0);
    const auto a = datasets(case_file(d / "out", k)), b = datasets(single);
    ASSERT_GT(b.size(), 30u);
    ASSERT_EQ(a.size(), b.size()) << "case " << k;
    for (const auto& [name, bytes] : b) {
      ASSERT_TRUE(a.count(name)) << name;
      EXPECT_TRUE(a.at(name) == bytes) << "case " << k << ": " << name << " differs from the single run";
    }
  }
}

TEST(Study, ThreeShardsUnderGnuParallelPlusCollectEqualTheLocalRun) {
  if (std::system("command -v parallel >/dev/null 2>&1") != 0) GTEST_SKIP() << "GNU parallel is not installed";
  const fs::path d = folder("shards");
  const fs::path local = write(d / "local.toml", twelve_case_study("local"));
  const fs::path sharded = write(d / "sharded.toml", twelve_case_study("sharded"));
  ASSERT_EQ(run("study " + local.string() + " -j 2 -q").status, 0);
  ASSERT_EQ(run("collect " + local.string()).status, 0);
  const std::string cmd = "parallel -j 3 --joblog " + (d / "joblog").string() + " " + ROLLNOISE_BINARY + " study " +
                          sharded.string() + " --shard {}/3 -j 1 -q ::: 1 2 3";
  ASSERT_EQ(std::system((cmd + " >/dev/null 2>&1").c_str()), 0) << cmd;
  const auto c = run("collect " + sharded.string());
  ASSERT_EQ(c.status, 0) << c.output;
  EXPECT_NE(c.output.find("12 complete, 0 failed, 0 missing"), std::string::npos) << c.output;
  for (int k = 0; k < 12; ++k) EXPECT_TRUE(datasets(case_file(d / "local", k)) == datasets(case_file(d / "sharded", k)));
  auto a = datasets((d / "local/study.h5").string()), b = datasets((d / "sharded/study.h5").string());
  ASSERT_EQ(a.size(), b.size());
  a.erase("study/run_time");  // wall-clock times differ between runs
  b.erase("study/run_time");
  for (const auto& [name, bytes] : a) EXPECT_TRUE(b.at(name) == bytes) << name;
  // the --list commands under GNU parallel with a job log, resumable: all already complete
  const std::string list = std::string(ROLLNOISE_BINARY) + " study " + sharded.string() + " --list | parallel -j 2 --joblog " +
                           (d / "joblog2").string() + " --resume";
  ASSERT_EQ(std::system((list + " >/dev/null 2>&1").c_str()), 0);
  std::ifstream log(d / "joblog2");
  int lines = 0;
  for (std::string line; std::getline(log, line);) ++lines;
  EXPECT_EQ(lines, 13);  // header + 12 cases
}

TEST(Study, AKilledStudyResumesWithoutRecomputingFinishedCases) {
  const fs::path d = folder("resume");
  // the 34 x 25 grid and 48 samples per band: about 0.2 s per case, slow enough to stop midway
  const fs::path study = write(d / "study.toml", "base = \"" + study_base_case() + "\"\noutput = \"out\"\n[axes]\n" +
                                                     "\"curve.radius\" = { from = 200.0, to = 1300.0, count = 12 }\n" +
                                                     "\"grid.nx\" = [34]\n\"grid.ny\" = [25]\n"
                                                     "\"noise.points_per_band\" = [48]\n");
  const std::string pidfile = (d / "pid").string();
  ASSERT_EQ(std::system(("(" + std::string(ROLLNOISE_BINARY) + " study " + study.string() +
                         " -j 1 -q >/dev/null 2>&1 & echo $! > " + pidfile + ")")
                            .c_str()),
            0);
  long pid = 0;
  std::ifstream(pidfile) >> pid;
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(case_file(d / "out", 2)) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(pid_t(pid), SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_TRUE(fs::exists(case_file(d / "out", 2)));
  ASSERT_FALSE(fs::exists(case_file(d / "out", 11))) << "the study ended before it was stopped";
  std::map<int, std::pair<long, long>> finished;  // case: (inode, modification time in ns)
  for (int k = 0; k < 12; ++k) {
    struct stat st {};
    if (::stat(case_file(d / "out", k).c_str(), &st) == 0)
      finished[k] = {long(st.st_ino), long(st.st_mtim.tv_sec) * 1000000000L + st.st_mtim.tv_nsec};
  }
  const auto r = run("study " + study.string() + " -j 2");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(std::to_string(finished.size()) + " already complete"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(std::to_string(12 - finished.size()) + " complete now"), std::string::npos) << r.output;
  for (const auto& [k, id] : finished) {
    struct stat st {};
    ASSERT_EQ(::stat(case_file(d / "out", k).c_str(), &st), 0);
    EXPECT_EQ(long(st.st_ino), id.first) << "case " << k << " was written again";
    EXPECT_EQ(long(st.st_mtim.tv_sec) * 1000000000L + st.st_mtim.tv_nsec, id.second) << "case " << k;
  }
  for (int k = 0; k < 12; ++k) EXPECT_TRUE(fs::exists(case_file(d / "out", k))) << k;
  for (const auto& e : fs::directory_iterator(d / "out"))
    if (e.path().filename() != ".lock") {  // the study's lock file (runner.hpp) stays
      EXPECT_EQ(e.path().filename().string().rfind("case_", 0), 0u) << "left behind: " << e.path();
    }
}

TEST(Study, AFailingCaseIsRecordedWithItsErrorAndTheOthersComplete) {
  const fs::path d = folder("failing");
  const fs::path study = write(d / "study.toml", "base = \"" + study_base_case() + "\"\noutput = \"out\"\n[axes]\n" +
                                                     "\"friction.mu\" = [0.3, -0.2, 0.4]\n");
  const auto r = run("study " + study.string() + " -j 2");
  ASSERT_EQ(r.status, 1) << "a study with a failed case is no success:\n" << r.output;
  EXPECT_NE(r.output.find("1 failed"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(case_file(d / "out", 0)));
  EXPECT_FALSE(fs::exists(case_file(d / "out", 1)));
  EXPECT_TRUE(fs::exists(case_file(d / "out", 2)));
  ASSERT_EQ(run("collect " + study.string()).status, 0);
  std::ifstream csv(d / "out/study.csv");
  std::string header, row0, row1;
  std::getline(csv, header);
  std::getline(csv, row0);
  std::getline(csv, row1);
  EXPECT_EQ(header.rfind("case,friction.mu [-],status,run_time [s]", 0), 0u) << header;
  EXPECT_NE(row0.find(",complete,"), std::string::npos) << row0;
  EXPECT_NE(row1.find(",failed,"), std::string::npos) << row1;
  EXPECT_NE(row1.find("friction.mu"), std::string::npos) << "the message names the key: " << row1;
  const auto h = datasets((d / "out/study.h5").string());
  ASSERT_TRUE(h.count("study/status"));
  const int* status = reinterpret_cast<const int*>(h.at("study/status").data());
  EXPECT_EQ(status[0], 0);
  EXPECT_EQ(status[1], 1);
  EXPECT_EQ(status[2], 0);
}
