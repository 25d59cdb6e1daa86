#include "io/tread_shapes_file.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {
namespace {

constexpr const char* kHeader = "mode,n,frequency_Hz,damping_ratio,s_mm,r_mm,u_r,u_theta,u_z";
constexpr const char* kFields[9] = {
    "mode", "n", "frequency_Hz", "damping_ratio", "s_mm", "r_mm", "u_r", "u_theta", "u_z"};

struct Row {
  int mode = 0, n = 0;
  double v[9] = {};
};

Row parse_row(const std::string& where, const std::string& line) {
  const auto cells = split_csv(line);
  if (cells.size() != 9)
    throw InputError(where, where + ": expected 9 fields (" + kHeader + "), got " +
                                std::to_string(cells.size()));
  Row row;
  for (int i = 0; i < 9; ++i)
    if (!parse_finite(cells[i], row.v[i]))
      throw InputError(
          where + ":" + kFields[i],
          where + ": field '" + kFields[i] + "' is not a finite number: '" + cells[i] + "'");
  for (int i : {0, 1})
    if (row.v[i] < 0 || row.v[i] != std::floor(row.v[i]) || row.v[i] > 1e6)
      throw InputError(where + ":" + kFields[i],
                       where + ": field '" + kFields[i] + "' must be an integer >= 0");
  row.mode = static_cast<int>(row.v[0]), row.n = static_cast<int>(row.v[1]);
  const auto positive = [&](int i) {
    if (!(row.v[i] > 0))
      throw InputError(where + ":" + kFields[i],
                       where + ": field '" + kFields[i] + "' must be > 0");
  };
  positive(2), positive(5);
  if (!(row.v[3] >= 0 && row.v[3] < 1))
    throw InputError(where + ":damping_ratio",
                     where + ": field 'damping_ratio' must lie in [0, 1)");
  return row;
}

}  // namespace

dynamics::WheelFeModes read_tread_shapes(const std::string& path) {
  dynamics::WheelFeModes w;
  std::vector<std::vector<double>> s_of_mode;
  std::vector<std::vector<Eigen::Vector3d>> u_of_mode;
  bool header = false;
  int last_mode = -1;
  for_each_data_line(
      path, "tread shapes file", [&](const std::string& where, const std::string& t) {
        if (!header) {
          if (t != kHeader)
            throw InputError(where,
                             where + ": expected the header '" + kHeader + "', got '" + t + "'");
          header = true;
          return;
        }
        const Row row = parse_row(where, t);
        if (row.mode != last_mode) {  // a new mode
          if (row.mode != static_cast<int>(w.modes.size()))
            throw InputError(
                where + ":mode",
                where + ": modes must be numbered 0, 1, 2, ... with their lines together");
          dynamics::WheelFeMode m;
          m.n = row.n, m.frequency = row.v[2], m.damping_ratio = row.v[3], m.nodal_circles = -1;
          w.modes.push_back(m);
          s_of_mode.emplace_back(), u_of_mode.emplace_back();
          if (row.mode == 0) w.tread_r.clear();
          last_mode = row.mode;
        }
        auto& m = w.modes.back();
        if (row.n != m.n || row.v[2] != m.frequency || row.v[3] != m.damping_ratio)
          throw InputError(
              where,
              where +
                  ": n, frequency_Hz and damping_ratio must be the same on every line of a mode");
        const double s = row.v[4] * 1e-3;
        if (!s_of_mode.back().empty() && !(s > s_of_mode.back().back()))
          throw InputError(where + ":s_mm",
                           where + ": s_mm must be strictly ascending within a mode");
        s_of_mode.back().push_back(s);
        if (row.mode == 0) w.tread_r.push_back(row.v[5] * 1e-3);
        u_of_mode.back().emplace_back(row.v[6], row.v[7], row.v[8]);
      });
  if (!header) throw InputError(path, path + ": no header line (empty tread shapes file)");
  if (w.modes.empty()) throw InputError(path, path + ": no mode");
  w.tread_s = s_of_mode.front();
  if (w.tread_s.size() < 2) throw InputError(path, path + ": a mode needs at least 2 tread points");
  for (std::size_t k = 0; k < w.modes.size(); ++k) {
    if (s_of_mode[k] != w.tread_s)
      throw InputError(
          path, path + ": mode " + std::to_string(k) + " is not given on the s_mm of mode 0");
    auto& m = w.modes[k];
    m.tread_shape.resize(w.tread_s.size(), 3);
    for (std::size_t i = 0; i < w.tread_s.size(); ++i)
      m.tread_shape.row(i) = u_of_mode[k][i].transpose();
    m.family = dynamics::tread_family(m.tread_shape);
  }
  return w;
}

TemporaryFile write_tread_shapes(const std::string& path, const std::string& option,
                                 const dynamics::WheelFeModes& w) {
  return write_text_file(path, option, [&](std::ostream& out) {
    out << "# mode shapes along the tread (rollnoise modes): mass-normalised (modal mass 1 kg); "
           "u_r = U_r cos n theta,\n"
           "# u_theta = U_theta sin n theta, u_z = U_z cos n theta; s, r in mm, u in m kg^-1/2; "
           "damping_ratio 0: by family\n"
        << kHeader << "\n";
    char line[400];
    for (std::size_t k = 0; k < w.modes.size(); ++k) {
      const auto& m = w.modes[k];
      for (std::size_t i = 0; i < w.tread_s.size(); ++i) {
        std::snprintf(line, sizeof line, "%zu,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", k,
                      m.n, m.frequency, m.damping_ratio, 1e3 * w.tread_s[i], 1e3 * w.tread_r[i],
                      m.tread_shape(i, 0), m.tread_shape(i, 1), m.tread_shape(i, 2));
        out << line;
      }
    }
  });
}

}  // namespace rollnoise::io
