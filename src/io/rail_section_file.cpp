#include "io/rail_section_file.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "dynamics/rail_section.hpp"
#include "fem/mesh.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {

namespace {

// The outline's checks that name the file: enough points, an area, a flat foot at the lowest z.
void check_outline(const std::string& path, const std::vector<Eigen::Vector2d>& outline) {
  if (outline.size() < 3) throw InputError(path, path + ": a rail section needs at least 3 points");
  double zmin = outline[0].y(), zmax = zmin, ymin = outline[0].x(), ymax = ymin;
  for (const auto& p : outline) {
    zmin = std::min(zmin, p.y()), zmax = std::max(zmax, p.y());
    ymin = std::min(ymin, p.x()), ymax = std::max(ymax, p.x());
  }
  const double scale = std::max(zmax - zmin, ymax - ymin);
  if (!(std::abs(fem::polygon_signed_area(outline)) > 1e-6 * scale * scale))
    throw InputError(path, path + ": the rail section's outline encloses no area");
  const double tol = 1e-9 * scale;
  const std::size_t n = outline.size();
  bool flat_foot = false;
  for (std::size_t i = 0; i < n; ++i)
    flat_foot = flat_foot || (std::abs(outline[i].y() - zmin) < tol &&
                              std::abs(outline[(i + 1) % n].y() - zmin) < tol);
  if (!flat_foot)
    throw InputError(path, path + ": the rail's foot needs a flat bottom (two consecutive points "
                                  "at the lowest z), where the support acts");
}

}  // namespace

std::vector<Eigen::Vector2d> read_rail_section(const std::string& path) {
  std::vector<Eigen::Vector2d> outline;
  bool header = false;
  for_each_data_line(path, "rail section file", [&](const std::string& where, const std::string& t) {
    if (!header) {
      if (t != "y_mm,z_mm")
        throw InputError(where, where + ": expected the header 'y_mm,z_mm', got '" + t + "'");
      header = true;
      return;
    }
    const auto cells = split_csv(t);
    if (cells.size() != 2)
      throw InputError(where, where + ": expected 2 fields (y_mm, z_mm), got " +
                                  std::to_string(cells.size()));
    double y, z;
    if (!parse_finite(cells[0], y))
      throw InputError(where + ":y_mm",
                       where + ": field 'y_mm' is not a finite number: '" + cells[0] + "'");
    if (!parse_finite(cells[1], z))
      throw InputError(where + ":z_mm",
                       where + ": field 'z_mm' is not a finite number: '" + cells[1] + "'");
    outline.emplace_back(y * 1e-3, z * 1e-3);
  });
  if (!header) throw InputError(path, path + ": no header line (empty rail section file)");
  if (outline.size() > 1 && outline.front() == outline.back()) outline.pop_back();
  check_outline(path, outline);
  double zmin = outline[0].y();
  for (const auto& p : outline) zmin = std::min(zmin, p.y());
  for (auto& p : outline) p.y() -= zmin;
  return outline;
}

dynamics::WaveguideRailOptions waveguide_rail_options(const CaseReader& r, std::string& id) {
  dynamics::WaveguideRailOptions o;
  if (!r.has("track.rail_section")) return o;
  const std::string file = resolve_model_file(r, "track.rail_section");
  try {
    o.outline = read_rail_section(file);
  } catch (const InputError& e) {
    r.fail("track.rail_section", e.what());
  }
  o.head_bottom = dynamics::rail_head_bottom(o.outline);
  id += ", section " + file;
  return o;
}

}  // namespace rollnoise::io
