// Wall-clock timing of a run's stages (the seconds_* fields of the pipeline results).
#pragma once

#include <chrono>

namespace rollnoise {

using Clock = std::chrono::steady_clock;

// Seconds from `start` to now.
inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace rollnoise
