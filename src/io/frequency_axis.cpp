#include "io/frequency_axis.hpp"

#include "io/contact_case.hpp"
#include "pipeline/frequency_axis.hpp"
#include "pipeline/limits.hpp"

namespace rollnoise::io {

std::vector<double> read_frequency_axis(const CaseReader& r) {
  pipeline::FrequencyAxis a;
  if (r.has("frequency.list")) {
    a.list = r.real_list("frequency.list");
    if (a.list.empty()) r.fail("frequency.list", "must not be empty");
    for (double f : a.list)
      if (f < 0) r.fail("frequency.list", "frequencies must not be negative");
  } else {
    a.f_min = r.real("frequency.f_min"), a.f_max = r.real("frequency.f_max");
    if (a.f_max < a.f_min) r.fail("frequency.f_max", "must not be below frequency.f_min");
    a.spacing = r.string("frequency.spacing");
    if (a.spacing != "third-octave") {
      a.count = r.integer("frequency.count");
      within_case(r, [&] {
        pipeline::check_size(read_limits(r), "frequency.count", double(a.count), "frequencies",
                             pipeline::frequency_bytes(double(a.count)));
      });
    }
  }
  return within_case(r, [&] { return pipeline::frequencies(a); });
}

}  // namespace rollnoise::io
