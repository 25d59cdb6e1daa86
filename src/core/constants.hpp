// Constants shared by every layer (one definition, so no translation unit keeps its own copy).
#pragma once

#include <limits>

namespace rollnoise {

inline constexpr double kPi = 3.14159265358979323846;
// A value not computed (an output's "no result", e.g. a study case that failed).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Millimetres per metre: CONTACT's input and output files are in mm.
inline constexpr double kMm = 1e3;

}  // namespace rollnoise
