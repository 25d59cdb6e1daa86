// Nothing lost, nothing stale. A full disk (a file-size limit, a full tmpfs, /dev/full as
// stdout) gives exit 1 naming the file and the reason, no output and no temporary; a case file is
// read once (process substitution, a FIFO); output names near NAME_MAX; the case text and the
// command line above HDF5's 64 kB attribute limit; model files bounded before they are read; -q
// leaves out the band table of noise. The study items (stale results, the lock, the exit status,
// collect's outputs) are in tests/study/study_hostile_test.cpp.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "io/output_files.hpp"

namespace fs = std::filesystem;
using namespace rollnoise::cli_test;

namespace {

// `command` run by bash (process substitution) with stdout and stderr captured and, if
// `file_size_limit` > 0, RLIMIT_FSIZE set to it in the child (as `ulimit -f` would): a write
// beyond it fails with EFBIG (or kills by SIGXFSZ, exit 153, if the program does not ignore it).
Invocation run_bash(const std::string& command, rlim_t file_size_limit = 0) {
  int out[2];
  if (::pipe(out) != 0) return {-1, "pipe failed"};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out[1], 1);
    ::dup2(out[1], 2);
    ::close(out[0]);
    ::close(out[1]);
    ::signal(SIGXFSZ, SIG_DFL);  // as in a fresh shell
    if (file_size_limit > 0) {
      const rlimit lim{file_size_limit, file_size_limit};
      ::setrlimit(RLIMIT_FSIZE, &lim);
    }
    ::execl("/bin/bash", "bash", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = ::read(out[0], buf, sizeof buf)) > 0;) text.append(buf, std::size_t(n));
  ::close(out[0]);
  int st = 0;
  ::waitpid(pid, &st, 0);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st), text};
}

const std::string kProgram = ROLLNOISE_BINARY;
// The paper's Hertzian case on a small grid (a steady run of a few ms; its file is 16 kB, 49 kB on
// the case's own 34 x 25 grid).
const std::string kSmall = " --set grid.nx=16 --set grid.ny=12";

// A failed write: exit 1, the output named with the reason, and nothing left in the folder.
void expect_lost_write(const Invocation& r, const fs::path& folder, const std::string& output,
                       const std::string& reason) {
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(output), std::string::npos) << "the message names the output:\n"
                                                      << r.output;
  EXPECT_NE(r.output.find(reason), std::string::npos) << "the message gives the reason:\n"
                                                      << r.output;
  EXPECT_TRUE(listing(folder).empty())
      << "left behind: " << ::testing::PrintToString(listing(folder));
}

}  // namespace

// ---- item 1: a full disk ----

TEST(FullDisk, SteadyBeyondAFileSizeLimitExitsOneAndLeavesNoTemporaryNorOutput) {
  const fs::path d = fresh_dir("fsize_steady");
  const std::string out = (d / "out.h5").string();
  // the default 34 x 25 grid: a file of ~49 kB against 20 kB
  const Invocation r = run_bash(kProgram + " steady " + paper_case() + " -q -o " + out, 20000);
  expect_lost_write(r, d, out, "File too large");
}

TEST(FullDisk, TextOutputBeyondAFileSizeLimitIsAnErrorAndItsTemporaryIsRemoved) {
  // the writer of every CSV and text output, in a child process under a 1000-byte limit
  const fs::path d = fresh_dir("fsize_text");
  const std::string csv = (d / "t.csv").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);  // as rollnoise does (cli/run_files.cpp)
    const rlimit lim{1000, 1000};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    int code = 3;
    try {
      auto t = rollnoise::io::write_text_file(csv, "--csv",
                                              [](std::ostream& o) { o << std::string(5000, 'x'); });
      code = 0;  // no error: the lost bytes went unnoticed
    } catch (const std::runtime_error& e) {
      code = std::string(e.what()).find("File too large") != std::string::npos ? 1 : 2;
    }
    ::_exit(code);  // (the temporary was removed by the unwinding)
  }
  int st = 0;
  ::waitpid(pid, &st, 0);
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 1) << "0: no error, 2: an error without the reason";
  EXPECT_TRUE(listing(d).empty()) << ::testing::PrintToString(listing(d));
}

TEST(FullDisk, SteadyOnAFullTmpfsExitsOneAndLeavesNothing) {
  // a 40 kB tmpfs in a private mount namespace (gone with the command); skipped where mounting is
  // not allowed
  const fs::path d = fresh_dir("tmpfs");
  const Invocation probe = run_bash("unshare -m sh -c 'mount -t tmpfs -o size=40k tmpfs " +
                                    d.string() + " && echo mounted'");
  if (probe.output.find("mounted") == std::string::npos)
    GTEST_SKIP() << "cannot mount a tmpfs here: " << probe.output;
  const std::string out = (d / "out.h5").string();
  const Invocation r = run_bash("unshare -m sh -c 'mount -t tmpfs -o size=40k tmpfs " + d.string() +
                                " && " + kProgram + " steady " + paper_case() + " -q -o " + out +
                                "; s=$?; echo listing:; ls -A " + d.string() + "; exit $s'");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  const auto listed = r.output.find("listing:\n");
  ASSERT_NE(listed, std::string::npos) << r.output;
  EXPECT_EQ(r.output.substr(listed), "listing:\n") << "left on the full disk:\n" << r.output;
}

// ---- item 2: lost standard output ----

TEST(LostOutput, KeysAndStudyListToDevFullExitOne) {
  const fs::path d = fresh_dir("devfull");
  std::ofstream(d / "s.toml") << "base = \"" << source_file("tests/data/study/curve_small.toml")
                              << "\"\noutput = \"out\"\n[axes]\n\"friction.mu\" = [0.3, 0.4]\n";
  for (const std::string& args :
       {std::string("keys"), "study " + (d / "s.toml").string() + " --list"}) {
    const Invocation r = run_bash(kProgram + " " + args + " > /dev/full");
    EXPECT_EQ(r.status, 1) << args << ":\n" << r.output;
    EXPECT_NE(r.output.find("standard output"), std::string::npos) << args << ":\n" << r.output;
  }
}

TEST(LostOutput, StudyListBeyondAFileSizeLimitExitsOne) {
  // 100,000 cases, ~100 bytes a line: 10 MB of commands against a 1 MB limit
  const fs::path d = fresh_dir("fsize_list");
  std::ofstream(d / "s.toml")
      << "base = \"" << source_file("tests/data/study/curve_small.toml")
      << "\"\noutput = \"out\"\n[axes]\n\"friction.mu\" = { from = 0.1, to = 0.5, count = "
         "100000 }\n";
  const Invocation r = run_bash(
      kProgram + " study " + (d / "s.toml").string() + " --list > " + (d / "cases.txt").string(),
      1000000);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("standard output"), std::string::npos) << r.output;
}

// ---- item 3: inputs read once ----

TEST(ReadOnce, CaseFromProcessSubstitutionAndFromAFifoRuns) {
  const fs::path d = fresh_dir("read_once");
  Invocation r = run_bash(kProgram + " steady <(cat " + paper_case() + ") -q -o " +
                          (d / "ps.h5").string() + kSmall);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(d / "ps.h5"));

  const fs::path fifo = d / "case.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  r = run_bash("(cat " + paper_case() + " > " + fifo.string() + " &); timeout 60 " + kProgram +
               " steady " + fifo.string() + " -q -o " + (d / "fifo.h5").string() + kSmall);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(d / "fifo.h5"));
}

// ---- item 6: sizes ----

TEST(Sizes, CaseTextAndCommandLineAbove64kBAreStoredWhole) {
  // 6000 frequencies in frequency.list (unused by steady, kept in /case) and a command line of ~70
  // kB
  const fs::path d = fresh_dir("big_text");
  std::string list = "[";
  for (int i = 0; i < 6000; ++i) list += (i ? "," : "") + std::to_string(100 + i) + ".5";
  list += "]";
  std::string repeated;
  for (int i = 0; i < 1000; ++i) repeated += " --set grid.spin_offset=0.0";
  const fs::path out = d / "big.h5";
  const Invocation r = run_bash(kProgram + " steady " + paper_case() + " -q -o " + out.string() +
                                kSmall + " --set 'frequency.list=" + list + "'" + repeated +
                                " --set 'rolling.speed=13.8888888888888888888'");
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  auto attribute_size = [&](const char* object, const char* name) {
    const hid_t o = H5Oopen(f, object, H5P_DEFAULT);
    const hid_t a = H5Aopen(o, name, H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    std::string s(H5Tget_size(t), '\0');
    H5Aread(a, t, s.data());
    H5Tclose(t), H5Aclose(a), H5Oclose(o);
    return s;
  };
  const std::string toml = attribute_size("/case", "toml"),
                    cmd = attribute_size("/", "command_line");
  H5Fclose(f);
  EXPECT_GT(toml.size(), 65536u);
  EXPECT_NE(toml.find("6099.5"), std::string::npos) << "the last frequency";
  EXPECT_GT(cmd.size(), 65536u);
  EXPECT_NE(cmd.find("13.8888888888888888888"), std::string::npos) << "the last argument";
}

TEST(Sizes, DevZeroAsAModelFileIsRefusedNamingTheKeyAndTheLimit) {
  const fs::path d = fresh_dir("dev_zero");
  const Invocation r =
      run_bash(kProgram + " steady " + paper_case() + " -q -o " + (d / "z.h5").string() +
               " --set contact.geometry=profiles --set contact.wheel_profile=/dev/zero");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("contact.wheel_profile"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("limit of 268435456 bytes"), std::string::npos) << r.output;
  EXPECT_TRUE(listing(d).empty());
}

TEST(Sizes, OutputNamesUpToNameMaxAreWrittenAndLeaveNoTemporary) {
  const fs::path d = fresh_dir("long_name");
  for (std::size_t length : {249u, 255u}) {
    const std::string name = std::string(length - 3, 'n') + ".h5";
    const Invocation r =
        run_bash(kProgram + " steady " + paper_case() + " -q -o " + (d / name).string() + kSmall);
    EXPECT_EQ(r.status, 0) << length << ": " << r.output;
    EXPECT_EQ(listing(d), std::vector<std::string>{name}) << length;
    fs::remove(d / name);
  }
}

// ---- item 8: -q ----

TEST(Quiet, NoiseWithQuietPrintsOnlyWarningsAndNotes) {
  const fs::path d = fresh_dir("quiet");
  const Invocation r =
      run_bash(kProgram + " noise " + source_file("tests/data/study/curve_small.toml") + " -q -o " +
               (d / "n.h5").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("L_r"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote "), std::string::npos) << r.output;
  std::istringstream lines(r.output);  // the table wheel's note on its sound power (stderr) only
  for (std::string line; std::getline(lines, line);)
    EXPECT_TRUE(line.rfind("note: ", 0) == 0 || line.rfind("warning: ", 0) == 0) << line;
  EXPECT_TRUE(fs::exists(d / "n.h5"));
}
