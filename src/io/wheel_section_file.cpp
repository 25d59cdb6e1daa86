#include "io/wheel_section_file.hpp"

#include "core/errors.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {

dynamics::WheelSection read_wheel_section(const std::string& path) {
  dynamics::WheelSection s;
  bool header = false;
  for_each_data_line(
      path, "wheel section file", [&](const std::string& where, const std::string& t) {
        const auto cells = split_csv(t);
        if (!header) {
          if (t != "r_mm,z_mm,segment")
            throw InputError(where,
                             where + ": expected the header 'r_mm,z_mm,segment', got '" + t + "'");
          header = true;
          return;
        }
        if (cells.size() != 3)
          throw InputError(where, where + ": expected 3 fields (r_mm, z_mm, segment), got " +
                                      std::to_string(cells.size()));
        double r, z;
        if (!parse_finite(cells[0], r) || !(r > 0))
          throw InputError(where + ":r_mm",
                           where + ": field 'r_mm' must be a positive number: '" + cells[0] + "'");
        if (!parse_finite(cells[1], z))
          throw InputError(where + ":z_mm",
                           where + ": field 'z_mm' is not a finite number: '" + cells[1] + "'");
        const int index = static_cast<int>(s.outline.size());
        if (cells[2] == "bore")
          s.bore_segments.push_back(index);
        else if (cells[2] == "tread")
          s.tread_segments.push_back(index);
        else if (cells[2] != "free")
          throw InputError(
              where + ":segment",
              where + ": field 'segment' must be bore, tread or free, got '" + cells[2] + "'");
        s.outline.emplace_back(r * 1e-3, z * 1e-3);
      });
  if (!header) throw InputError(path, path + ": no header line (empty wheel section file)");
  if (s.outline.size() < 3)
    throw InputError(path, path + ": a wheel section needs at least 3 points");
  if (s.bore_segments.empty()) throw InputError(path, path + ": no segment marked 'bore'");
  if (s.tread_segments.empty()) throw InputError(path, path + ": no segment marked 'tread'");
  return s;
}

}  // namespace rollnoise::io
