#include "io/roughness_file.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {

noise::RoughnessSpectrum read_roughness_csv(const std::string& path) {
  std::vector<std::pair<double, double>> rows;
  bool header = false;
  for_each_data_line(path, "roughness file", [&](const std::string& where, const std::string& t) {
    const auto comma = t.find(',');
    const std::string c0 = trim(t.substr(0, comma));
    const std::string c1 = comma == std::string::npos ? "" : trim(t.substr(comma + 1));
    if (!header) {
      if (c0 != "wavelength_m" || c1 != "level_dB")
        throw InputError(where + ":header",
                         where + ": header must be 'wavelength_m,level_dB', got '" + t + "'");
      header = true;
      return;
    }
    double v[2];
    const std::string cells[2] = {c0, c1};
    const char* names[2] = {"wavelength_m", "level_dB"};
    for (int c = 0; c < 2; ++c)
      if (!parse_finite(cells[c], v[c]))
        throw InputError(where + ":" + names[c], where + ": field '" + names[c] +
                                                     "' is missing or not a finite number: '" +
                                                     cells[c] + "'");
    if (!(v[0] > 0.0))
      throw InputError(where + ":wavelength_m", where + ": field 'wavelength_m' must be positive");
    rows.emplace_back(v[0], v[1]);
  });
  if (!header) throw InputError(path, path + ": empty roughness file (no header)");
  std::sort(rows.begin(), rows.end(), [](auto& p, auto& q) { return p.first > q.first; });
  noise::RoughnessSpectrum s;
  s.name = path;
  for (const auto& [w, l] : rows) {
    s.wavelength.push_back(w);
    s.level.push_back(l);
  }
  try {
    s.validate();
  } catch (const std::invalid_argument& e) {  // the spectrum's contract, named by the file
    throw InputError(path, path + ": " + e.what());
  }
  return s;
}

}  // namespace rollnoise::io
