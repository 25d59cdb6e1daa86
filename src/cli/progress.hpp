// A progress bar on stderr for runs longer than a second; silent with --quiet or when stderr is not
// a terminal.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace rollnoise::cli {

class Progress {
 public:
  Progress(std::string what, long total, bool quiet)
      : what_(std::move(what)), total_(total), enabled_(!quiet && isatty(STDERR_FILENO)),
        start_(std::chrono::steady_clock::now()) {}
  ~Progress() { finish(); }
  void update(long done) {
    if (!enabled_) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (s < 1.0 || (done < total_ && s - last_ < 0.1)) return;
    last_ = s;
    const int width = 40, filled = static_cast<int>(width * done / std::max(1L, total_));
    std::fprintf(stderr, "\r%s [%s%s] %ld/%ld  %.1f s", what_.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), done, total_, s);
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
    shown_ = false;
  }

 private:
  std::string what_;
  long total_;
  bool enabled_, shown_ = false;
  std::chrono::steady_clock::time_point start_;
  double last_ = 0.0;
};

}  // namespace rollnoise::cli
