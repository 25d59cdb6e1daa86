// The frequency axis of a case ([frequency]): linear or logarithmic spacing between f_min and
// f_max, the 1/3-octave band centres within them, or an explicit list.
#pragma once

#include <string>
#include <vector>

namespace rollnoise::pipeline {

struct FrequencyAxis {
  std::vector<double> list;     ///< explicit frequencies (Hz); when non-empty the rest is unused
  double f_min = 0.0, f_max = 0.0;  ///< Hz
  std::string spacing = "linear";   ///< "linear", "log" or "third-octave"
  long count = 1;                   ///< points of a linear or log axis
};

/// The frequencies of the axis (Hz). InputError naming frequency.f_min / frequency.f_max when a
/// log axis starts at 0 or no 1/3-octave centre lies in the range.
std::vector<double> frequencies(const FrequencyAxis& a);

}  // namespace rollnoise::pipeline
