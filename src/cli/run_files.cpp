#include "cli/run_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"

namespace rollnoise::cli {

void start_process(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  // beyond a file-size limit (ulimit -f) a write then fails with EFBIG, which the writers report
  // (exit 1, temporaries removed), instead of SIGXFSZ killing the process mid-write
  std::signal(SIGXFSZ, SIG_IGN);
  io::record_invocation(argc, argv);
}

int finish_process(int status) {
  std::cout.flush();
  errno = 0;
  const bool flush_failed = std::fflush(stdout) != 0;
  const int err = flush_failed ? errno : 0;
  if (!flush_failed && !std::ferror(stdout) && std::cout) return status;
  std::fprintf(stderr, "rollnoise: error: cannot write the standard output%s%s: output lost\n",
               err ? ": " : "", err ? std::strerror(err) : "");
  return 1;
}

void silence_stdout() {
  std::cout.flush();
  std::fflush(stdout);
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null < 0) return;  // no /dev/null: the summary is printed after all
  ::dup2(null, STDOUT_FILENO);
  ::close(null);
}

namespace {

// The default output replaces only a result of the same command (see the header).
void check_default_output(const CommonOptions& o, const std::string& path) {
  if (!o.output.empty() || !std::filesystem::exists(path)) return;
  const std::optional<std::string> writer = io::recorded_command(path);
  if (writer && *writer == o.command) return;
  throw InputError("-o", "-o not given: the default output " + path +
                             (writer ? " holds the result of `rollnoise " + *writer + "`"
                                     : " exists and is no rollnoise result") +
                             "; to replace it, name it with -o " + path + ", or choose another -o");
}

}  // namespace

void check_run_files(const CommonOptions& o, const std::string& csv) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  std::vector<io::OutputFile> outputs;
  outputs.push_back({"-o", output_path(o, reader.name())});
  check_default_output(o, outputs.back().path);
  for (const std::string& line : io::physical_range_warnings(reader)) std::fprintf(stderr, "%s\n", line.c_str());
  if (!csv.empty()) outputs.push_back({"--csv", csv});
  io::check_outputs(outputs, io::case_input_files(reader));
}

}  // namespace rollnoise::cli
