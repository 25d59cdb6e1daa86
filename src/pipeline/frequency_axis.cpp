#include "pipeline/frequency_axis.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "noise/roughness.hpp"

namespace rollnoise::pipeline {

std::vector<double> frequencies(const FrequencyAxis& a) {
  if (!a.list.empty()) return a.list;
  const double f0 = a.f_min, f1 = a.f_max;
  std::vector<double> f;
  if (a.spacing == "third-octave") {
    // exact base-10 band centres (IEC 61260) from 0.1 Hz, the limits selecting bands by nominal
    // centre as for the noise bands (noise::third_octave_centres: f_max = 5000 includes 5012 Hz)
    if (f1 >= f0 && noise::third_octave_index(f1) >= -40)  // band -40: 0.1 Hz
      f = noise::third_octave_centres(std::max(f0, 0.1), f1);
    if (f.empty()) throw InputError("frequency.f_max", "no 1/3-octave band centre between f_min and f_max");
    return f;
  }
  const long n = a.count;
  if (a.spacing == "log" && !(f0 > 0)) throw InputError("frequency.f_min", "must be positive for log spacing");
  for (long i = 0; i < n; ++i) {
    const double u = n == 1 ? 0.0 : double(i) / double(n - 1);
    f.push_back(a.spacing == "log" ? f0 * std::pow(f1 / f0, u) : f0 + (f1 - f0) * u);
  }
  return f;
}

}  // namespace rollnoise::pipeline
