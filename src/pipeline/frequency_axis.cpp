#include "pipeline/frequency_axis.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace rollnoise::pipeline {

std::vector<double> frequencies(const FrequencyAxis& a) {
  if (!a.list.empty()) return a.list;
  const double f0 = a.f_min, f1 = a.f_max;
  std::vector<double> f;
  if (a.spacing == "third-octave") {
    // exact base-10 band centres 10^(n/10) Hz (IEC 61260)
    for (int n = -10; n <= 50; ++n) {
      const double c = std::pow(10.0, n / 10.0);
      if (c >= f0 * (1 - 1e-9) && c <= f1 * (1 + 1e-9)) f.push_back(c);
    }
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
