// Progress on stderr: a bar for runs longer than a second when stderr is a terminal, and at the end
// one summary line ("transient: 291 of 291 steps in 6.3 s") that also reaches a log file; silent
// with --quiet.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace rollnoise::cli {

class Progress {
 public:
  /// `what` names the work and its unit, e.g. "transient" and "steps".
  Progress(std::string what, long total, bool quiet, std::string unit = "")
      : what_(std::move(what)), unit_(std::move(unit)), total_(total), quiet_(quiet),
        enabled_(!quiet && isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}
  ~Progress() {  // a run that stopped early ends the bar's line, without a summary
    if (shown_) std::fprintf(stderr, "\n");
  }
  void update(long done) {
    done_ = done;
    if (!enabled_) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (s < 1.0 || (done < total_ && s - last_ < 0.1)) return;
    last_ = s;
    const int width = 40, filled = static_cast<int>(width * done / std::max(1L, total_));
    std::fprintf(stderr, "\r%s [%s%s] %ld/%ld  %.1f s", what_.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), done, total_, s);
    shown_ = true;
  }
  /// Ends the bar and prints the summary line (once).
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
    shown_ = false;
    if (quiet_ || summarised_) return;
    summarised_ = true;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "%s: %ld of %ld%s%s in %.1f s\n", what_.c_str(), done_, total_, unit_.empty() ? "" : " ",
                 unit_.c_str(), s);
  }

 private:
  std::string what_, unit_;
  long total_, done_ = 0;
  bool quiet_, enabled_, shown_ = false, summarised_ = false;
  std::chrono::steady_clock::time_point start_;
  double last_ = 0.0;
};

}  // namespace rollnoise::cli
