// Running the rollnoise program from a test: its exit status and what it printed.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace rollnoise::cli_test {

struct Invocation {
  int status;
  std::string output;  // stdout + stderr
};

/// A shell command line; its exit status and output (stdout, and stderr where it redirects it).
inline Invocation run_shell(const std::string& cmd) {
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), buf.size(), p)) out += buf.data();
  const int st = pclose(p);
  return {WEXITSTATUS(st), out};
}

/// `rollnoise ARGS` through the shell (ARGS may hold redirections); exit status and output.
inline Invocation run(const std::string& args) {
  return run_shell(std::string(ROLLNOISE_BINARY) + " " + args + " 2>&1");
}

/// A scratch folder of this test process, removed with everything in it when the process ends
/// (the suite leaves nothing in the temporary directory).
inline std::filesystem::path temp_dir() {
  static const struct Scratch {
    pid_t owner = ::getpid();
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("rollnoise_cli_" + std::to_string(::getpid()));
    ~Scratch() {
      std::error_code ec;
      if (::getpid() == owner) std::filesystem::remove_all(dir, ec);
    }
  } scratch;
  std::filesystem::create_directories(scratch.dir);
  return scratch.dir;
}

/// A fresh empty folder `name` in temp_dir(), for one test.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = temp_dir() / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

/// The names in folder `d` that begin with `prefix` (all: ""), sorted; none when `d` is missing.
inline std::vector<std::string> listing(const std::filesystem::path& d, const std::string& prefix = "") {
  std::vector<std::string> names;
  if (!std::filesystem::exists(d)) return names;
  for (const auto& e : std::filesystem::directory_iterator(d))
    if (e.path().filename().string().rfind(prefix, 0) == 0) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline std::string source_file(const std::string& relative) {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/" + relative;
}

inline std::string paper_case() { return source_file("cases/hertz_paper.toml"); }

/// The whole text of a file (empty if it cannot be read): to check that an input stays unchanged.
inline std::string file_contents(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// ROLLNOISE_CACHE_DIR for the runs of one scope (the suite runs with it "off": CMakeLists.txt).
class CacheFolder {
 public:
  explicit CacheFolder(const std::string& value) {
    if (const char* v = std::getenv("ROLLNOISE_CACHE_DIR")) old_ = v;
    ::setenv("ROLLNOISE_CACHE_DIR", value.c_str(), 1);
  }
  ~CacheFolder() {
    if (old_)
      ::setenv("ROLLNOISE_CACHE_DIR", old_->c_str(), 1);
    else
      ::unsetenv("ROLLNOISE_CACHE_DIR");
  }
  CacheFolder(const CacheFolder&) = delete;
  CacheFolder& operator=(const CacheFolder&) = delete;

 private:
  std::optional<std::string> old_;
};

}  // namespace rollnoise::cli_test
