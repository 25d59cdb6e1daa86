// Output files (faults around the input, provenance): an output that is an input or another
// output, a folder, or in a folder that does not exist or takes no file is refused before any
// computation (exit 2, the option and the path named, nothing left, the input unchanged); outputs
// are written to unique temporaries renamed atomically (two concurrent runs to one file each leave
// a complete file, a killed run leaves nothing); stdout is line-buffered; every HDF5 file records
// program_version, command_line, date (and seed where randomness is used) on its root group.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"
#include "io/case_schema.hpp"
#include "io/output_files.hpp"
#include "support/test_helpers.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace rollnoise::cli_test;

namespace {

using rollnoise::test_support::slurp;

// The paper's Hertzian case copied into `d` as c.toml.
fs::path copy_case(const fs::path& d) {
  const fs::path c = d / "c.toml";
  fs::copy_file(paper_case(), c);
  return c;
}

// A refusal: exit 2, the message names the option and the path, and took no computation.
void expect_refused(const Invocation& r, const std::string& option, const std::string& path) {
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("error: " + option + " " + path), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("normal problem"), std::string::npos) << "refused after computing:\n"
                                                                << r.output;
}

// A string attribute of the root group, or "(missing)".
std::string root_attribute(const fs::path& file, const char* name) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return "(no file)";
  std::string s = "(missing)";
  if (H5Aexists(f, name) > 0) {
    const hid_t a = H5Aopen(f, name, H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    if (H5Tget_class(t) == H5T_STRING) {
      s.assign(H5Tget_size(t), '\0');
      H5Aread(a, t, s.data());
      s = s.c_str();
    } else {
      unsigned long long v = 0;
      H5Aread(a, H5T_NATIVE_ULLONG, &v);
      s = std::to_string(v);
    }
    H5Tclose(t);
    H5Aclose(a);
  }
  H5Fclose(f);
  return s;
}

std::string group_attribute(const fs::path& file, const char* group, const char* name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t g = H5Oopen(f, group, H5P_DEFAULT);
  const hid_t a = H5Aopen(g, name, H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  std::string s(H5Tget_size(t), '\0');
  H5Aread(a, t, s.data());
  H5Tclose(t), H5Aclose(a), H5Oclose(g), H5Fclose(f);
  return s.c_str();
}

std::vector<double> dataset(const fs::path& file, const char* path) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t set = H5Dopen2(f, path, H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  std::vector<double> v(H5Sget_simple_extent_npoints(space));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(space), H5Dclose(set), H5Fclose(f);
  return v;
}

// The program started in the background with stdout and stderr to `log`.
pid_t spawn(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all = {ROLLNOISE_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = -1;
  posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  return pid;
}

// Polls `done` every 5 ms for up to `seconds`; whether it became true.
template <class Done>
bool wait_for(Done&& done, double seconds = 30.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

bool running(pid_t pid) {
  int st = 0;
  return waitpid(pid, &st, WNOHANG) == 0;
}

// A steady sweep of ~30 ms per point: runs for several seconds (it is killed much earlier).
std::vector<std::string> slow_sweep(const fs::path& c, const fs::path& out) {
  return {"steady", c.string(), "-o", out.string(), "--sweep", "friction.mu=0.1:0.5:1000"};
}

}  // namespace

// ---- fault 1: an output that is an input or another output ----

TEST(OutputSafety, OutputNamingTheCaseFileIsRefusedAndTheCaseUnchanged) {
  const fs::path d = fresh_dir("out_case");
  const fs::path c = copy_case(d);
  const std::string before = slurp(c);
  expect_refused(run("steady " + c.string() + " -o " + c.string()), "-o", c.string());
  // the same file by another spelling, a symlink and a hard link
  expect_refused(run("steady " + c.string() + " -o " + (d / "." / "c.toml").string()), "-o",
                 (d / "." / "c.toml").string());
  fs::create_symlink(c, d / "sym.h5");
  fs::create_hard_link(c, d / "hard.h5");
  expect_refused(run("steady " + c.string() + " -o " + (d / "sym.h5").string()), "-o",
                 (d / "sym.h5").string());
  expect_refused(run("transient " + c.string() + " -o " + (d / "hard.h5").string()), "-o",
                 (d / "hard.h5").string());
  EXPECT_EQ(slurp(c), before);
  EXPECT_EQ(listing(d), (std::vector<std::string>{"c.toml", "hard.h5", "sym.h5"}));
}

TEST(OutputSafety, CsvNamingTheCaseOrTheHdf5OutputIsRefused) {
  const fs::path d = fresh_dir("out_csv");
  const fs::path c = copy_case(d);
  const std::string before = slurp(c);
  const std::string h5 = (d / "x.h5").string();
  expect_refused(run("creep " + c.string() + " -o " + h5 + " --csv " + c.string()), "--csv",
                 c.string());
  // --csv and -o naming one new file (spelled differently): the second output is refused
  const std::string same = (d / ".." / d.filename() / "x.h5").string();
  const Invocation r = run("creep " + c.string() + " -o " + h5 + " --csv " + same);
  expect_refused(r, "--csv", same);
  EXPECT_NE(r.output.find("output of -o"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(c), before);
  EXPECT_EQ(listing(d), std::vector<std::string>{"c.toml"});
}

TEST(OutputSafety, OutputNamingAModelFileOfTheCaseIsRefused) {
  const fs::path d = fresh_dir("out_model");
  fs::copy_file(source_file("models/profiles/MBench_S1002_v3.prw"), d / "w.prw");
  const std::string profile = slurp(d / "w.prw");
  std::ofstream(d / "p.toml")
      << "[contact]\ngeometry = \"profiles\"\nnormal_force = 98100\nwheel_profile = \"w.prw\"\n"
         "[creepage]\nmean = [0.001, 0.001, 0.0]\n";
  std::ofstream(d / "e.csv") << "0, 0.001, 0, 0\n0.001, 0.002, 0, 0\n";
  std::ofstream(d / "h.toml") << slurp(paper_case())
                              << "\n[excitation]\ntype = \"csv\"\nfile = \"e.csv\"\n";
  const std::string csv = slurp(d / "e.csv");

  Invocation r = run("steady " + (d / "p.toml").string() + " -o " + (d / "w.prw").string());
  expect_refused(r, "-o", (d / "w.prw").string());
  EXPECT_NE(r.output.find("contact.wheel_profile"), std::string::npos) << r.output;
  r = run("transient " + (d / "h.toml").string() + " -o " + (d / "e.csv").string());
  expect_refused(r, "-o", (d / "e.csv").string());
  EXPECT_NE(r.output.find("excitation.file"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(d / "w.prw"), profile);
  EXPECT_EQ(slurp(d / "e.csv"), csv);
  EXPECT_EQ(listing(d), (std::vector<std::string>{"e.csv", "h.toml", "p.toml", "w.prw"}));
}

// Every string key whose default names a file of the source tree is a model file the check knows.
TEST(OutputSafety, EveryDefaultedFileKeyIsAnInputOfTheCheck) {
  const auto& keys = rollnoise::io::case_file_keys();
  int file_keys = 0;
  for (const auto& spec : rollnoise::io::case_schema()) {
    if (spec.type != rollnoise::io::KeyType::String || spec.default_value.size() < 3) continue;
    const std::string value =
        spec.default_value.substr(1, spec.default_value.size() - 2);  // unquoted
    if (!fs::is_regular_file(source_file(value))) continue;
    ++file_keys;
    EXPECT_NE(std::find(keys.begin(), keys.end(), spec.key), keys.end())
        << spec.key << " = " << value;
  }
  EXPECT_GE(file_keys, 5);  // wheel and rail profile, track, wheelset, modes
}

// ---- fault 3: an output that is a folder, or in a folder that takes no file ----

TEST(OutputSafety, FolderAsOutputIsRefusedBeforeComputingAndLeavesNoCsv) {
  const fs::path d = fresh_dir("out_dir");
  const fs::path c = copy_case(d);
  fs::create_directory(d / "sub");
  const std::string csv = (d / "t.csv").string();
  expect_refused(run("creep " + c.string() + " -o " + (d / "sub").string() + " --csv " + csv), "-o",
                 (d / "sub").string());
  expect_refused(run("creep " + c.string() + " -o " + (d / "x.h5").string() + " --csv " +
                     (d / "sub").string()),
                 "--csv", (d / "sub").string());
  EXPECT_TRUE(fs::is_empty(d / "sub"));
  EXPECT_EQ(listing(d), (std::vector<std::string>{"c.toml", "sub"}));
}

TEST(OutputSafety, MissingOrUnwritableFolderIsRefused) {
  const fs::path d = fresh_dir("out_nofolder");
  const fs::path c = copy_case(d);
  const std::string missing = (d / "no" / "x.h5").string();
  Invocation r = run("steady " + c.string() + " -o " + missing);
  expect_refused(r, "-o", missing);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  expect_refused(run("creep " + c.string() + " -o " + (d / "x.h5").string() + " --csv " + missing),
                 "--csv", missing);
  // /proc takes no new file, even for root (for whom access() and chmod do not tell)
  expect_refused(run("steady " + c.string() + " -o /proc/rollnoise_test.h5"), "-o",
                 "/proc/rollnoise_test.h5");
  expect_refused(run("steady " + c.string() + " -o /dev/null"), "-o", "/dev/null");
  EXPECT_EQ(listing(d), std::vector<std::string>{"c.toml"});
}

// ---- fault 2: unique temporaries, atomic rename, removal on signals ----

// With HDF5 file locking off (as on many NFS/Lustre mounts) two runs to one output used to write
// the same OUT.h5.partial: the survivor could hold a mix. Each now writes its own temporary; the
// file left is one whole run: its /case and its forces belong together.
TEST(OutputSafety, ConcurrentRunsToOneOutputLeaveOneCompleteConsistentFile) {
  const fs::path d = fresh_dir("out_concurrent");
  const fs::path c = copy_case(d);
  const fs::path out = d / "out.h5";
  const std::string cmd = "HDF5_USE_FILE_LOCKING=FALSE " + std::string(ROLLNOISE_BINARY) +
                          " steady " + c.string() + " -o " + out.string() + " --set friction.mu=";
  const int st = std::system((cmd + "0.2 > " + (d / "a.log").string() + " 2>&1 & " + cmd +
                              "0.25 > " + (d / "b.log").string() + " 2>&1; wait")
                                 .c_str());
  ASSERT_EQ(st, 0);
  const std::string a = slurp(d / "a.log"), b = slurp(d / "b.log");
  ASSERT_NE(a.find("wrote"), std::string::npos) << a;
  ASSERT_NE(b.find("wrote"), std::string::npos) << b;
  const std::string toml = group_attribute(out, "/case", "toml");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(toml, m, std::regex(R"(\bmu = (\S+))"))) << toml;
  const double mu = std::stod(m[1]);
  const bool is_a = mu == 0.2;
  ASSERT_TRUE(is_a || mu == 0.25) << toml;
  // the printed Fx of the run whose case the file holds equals the file's Fx
  const std::string& log = is_a ? a : b;
  const double printed = std::stod(log.substr(log.find("Fx = ") + 5));
  const double stored = dataset(out, "/steady/force")[0];
  EXPECT_NEAR(stored, printed, 1e-5 * std::abs(printed));
  EXPECT_EQ(listing(d), (std::vector<std::string>{"a.log", "b.log", "c.toml", "out.h5"}));
}

TEST(OutputSafety, RunKilledMidwayLeavesNoTemporaryAndNoOutput) {
  for (int sig : {SIGTERM, SIGINT}) {
    const fs::path d = fresh_dir("out_killed");
    const fs::path c = copy_case(d);
    const fs::path log = d / "log.txt";
    const pid_t pid = spawn(slow_sweep(c, d / "s.h5"), log);
    ASSERT_GT(pid, 0);
    // mid-way: the sweep has started (its header is printed) and the temporary exists
    const bool started = wait_for([&] { return slurp(log).find("points):") != std::string::npos; });
    bool temporary = false;
    for (const auto& n : listing(d)) temporary |= n.rfind(".s.h5.", 0) == 0;
    ASSERT_TRUE(started) << slurp(log);
    EXPECT_TRUE(temporary);
    ASSERT_TRUE(running(pid)) << "finished before the signal";
    kill(pid, sig);
    int st = 0;
    ASSERT_EQ(waitpid(pid, &st, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(st) && WTERMSIG(st) == sig) << "status " << st;  // the signal shows
    EXPECT_EQ(listing(d), (std::vector<std::string>{"c.toml", "log.txt"})) << "signal " << sig;
  }
}

// ---- fault 14: a redirected log fills as the run goes ----

// Fully buffered stdout reaches a file in 4 KiB blocks (the sweep needs seconds to print that
// much); line-buffered, the first lines are there as soon as they are printed.
TEST(OutputSafety, RedirectedLogHoldsTheFirstLinesWhileTheRunGoesOn) {
  const fs::path d = fresh_dir("out_log");
  const fs::path c = copy_case(d);
  const fs::path log = d / "log.txt";
  const pid_t pid = spawn(slow_sweep(c, d / "s.h5"), log);
  ASSERT_GT(pid, 0);
  std::string first;
  ASSERT_TRUE(wait_for([&] { return !(first = slurp(log)).empty(); }));
  const bool still_running = running(pid);
  kill(pid, SIGTERM);
  waitpid(pid, nullptr, 0);
  EXPECT_TRUE(still_running);
  EXPECT_LT(first.size(), 4096u) << "stdout reached the file in a full buffer";
  EXPECT_EQ(first.back(), '\n') << "stdout reached the file mid-line";
  EXPECT_NE(first.find("normal problem"), std::string::npos) << first;
}

// ---- provenance ----

TEST(OutputSafety, Hdf5FilesRecordVersionCommandLineAndDate) {
  const fs::path d = fresh_dir("out_provenance");
  const fs::path out = d / "out file.h5";  // a space: the command line must quote it
  const std::time_t before = std::time(nullptr);
  const Invocation r = run("steady " + paper_case() + " -o '" + out.string() +
                           "' --set grid.nx=20 --set grid.ny=15");
  ASSERT_EQ(r.status, 0) << r.output;

  const std::string version = root_attribute(out, "program_version");
  EXPECT_TRUE(version == "unknown" ||
              std::regex_match(version, std::regex("[0-9A-Za-z.+_-]*[0-9a-f]{7,}(-dirty)?")))
      << version;
  const std::string cmd = root_attribute(out, "command_line");
  EXPECT_NE(cmd.find(std::string(ROLLNOISE_BINARY) + " steady " + paper_case() + " -o '" +
                     out.string() + "'"),
            std::string::npos)
      << cmd;
  // the quoted command line gives the same arguments back through a shell
  const std::string back = (d / "args.txt").string();
  ASSERT_EQ(std::system(("set -- " + cmd + "; printf '%s\\n' \"$@\" > " + back).c_str()), 0);
  EXPECT_NE(slurp(back).find("\n" + out.string() + "\n"), std::string::npos) << slurp(back);

  const std::string date = root_attribute(out, "date");
  std::tm tm{};
  ASSERT_TRUE(std::regex_match(date, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"))) << date;
  strptime(date.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm);
  const std::time_t t = timegm(&tm);
  EXPECT_GE(t, before - 1);
  EXPECT_LE(t, std::time(nullptr) + 1);
  EXPECT_EQ(root_attribute(out, "seed"), "(missing)") << "steady uses no randomness";
}

TEST(OutputSafety, RandomPhasesRecordTheirSeed) {
  const fs::path out = fresh_dir("out_seed") / "r.h5";
  const Invocation r =
      run("response " + source_file("cases/paper_s33_pseudorandom.toml") + " -o " + out.string() +
          " --set grid.nx=20 --set grid.ny=15 --set excitation.count=20 --set excitation.seed=7 "
          "--set transient.duration=0.005");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(root_attribute(out, "seed"), "7");
}

TEST(OutputSafety, CreepMethodNamesTheRouteTaken) {
  const fs::path d = fresh_dir("out_method");
  const std::string common = " --set grid.nx=20 --set grid.ny=15 --set frequency.count=5";
  ASSERT_EQ(run("creep " + paper_case() + " -o " + (d / "fast.h5").string() + common).status, 0);
  ASSERT_EQ(
      run("creep " + paper_case() + " -o " + (d / "lu.h5").string() + common + " --direct").status,
      0);
  EXPECT_NE(group_attribute(d / "fast.h5", "/creep", "method").find("block Krylov"),
            std::string::npos);
  EXPECT_NE(group_attribute(d / "lu.h5", "/creep", "method").find("complex LU per frequency"),
            std::string::npos);
}

// A CSV output is written whole or not at all, and beside it no temporary stays.
TEST(OutputSafety, CsvIsCompleteAndNoTemporaryStays) {
  const fs::path d = fresh_dir("out_csvok");
  const fs::path csv = d / "t.csv";
  const Invocation r =
      run("creep " + paper_case() + " -o " + (d / "c.h5").string() + " --csv " + csv.string() +
          " --set grid.nx=20 --set grid.ny=15 --set frequency.count=7");
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(csv);
  std::string line;
  int rows = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#' && line[0] != 'f') ++rows;
  EXPECT_EQ(rows, 7);
  EXPECT_EQ(listing(d), (std::vector<std::string>{"c.h5", "t.csv"}));
}
