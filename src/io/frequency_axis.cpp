#include "io/frequency_axis.hpp"

#include <cmath>

namespace rollnoise::io {

std::vector<double> read_frequency_axis(const CaseReader& r) {
  if (r.has("frequency.list")) {
    const auto list = r.real_list("frequency.list");
    if (list.empty()) r.fail("frequency.list", "must not be empty");
    for (double f : list)
      if (f < 0) r.fail("frequency.list", "frequencies must not be negative");
    return list;
  }
  const double f0 = r.real("frequency.f_min"), f1 = r.real("frequency.f_max");
  if (f1 < f0) r.fail("frequency.f_max", "must not be below frequency.f_min");
  const std::string spacing = r.string("frequency.spacing");
  std::vector<double> f;
  if (spacing == "third-octave") {
    // exact base-10 band centres 10^(n/10) Hz (IEC 61260)
    for (int n = -10; n <= 50; ++n) {
      const double c = std::pow(10.0, n / 10.0);
      if (c >= f0 * (1 - 1e-9) && c <= f1 * (1 + 1e-9)) f.push_back(c);
    }
    if (f.empty()) r.fail("frequency.f_max", "no 1/3-octave band centre between f_min and f_max");
    return f;
  }
  const long n = r.integer("frequency.count");
  if (spacing == "log" && !(f0 > 0)) r.fail("frequency.f_min", "must be positive for log spacing");
  for (long i = 0; i < n; ++i) {
    const double u = n == 1 ? 0.0 : double(i) / double(n - 1);
    f.push_back(spacing == "log" ? f0 * std::pow(f1 / f0, u) : f0 + (f1 - f0) * u);
  }
  return f;
}

}  // namespace rollnoise::io
