// The frequency axis of a case ([frequency]): linear or logarithmic spacing between f_min and f_max,
// the 1/3-octave band centres within them, or an explicit list.
#pragma once

#include <vector>

#include "io/case_reader.hpp"

namespace rollnoise::io {

/// Read [frequency] and give its frequencies (pipeline/frequency_axis.hpp).
std::vector<double> read_frequency_axis(const CaseReader& r);

}  // namespace rollnoise::io
