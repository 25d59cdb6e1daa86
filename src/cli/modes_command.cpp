// rollnoise modes: the FE wheel's modes (docs/interface.md "modes"): read the [wheel] keys (as
// wheel.model = "fe"), compute the modes of the section, write /modes/*, print a summary per
// family with the time taken; --csv also writes the tread shapes (io/tread_shapes_file.hpp).
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>

#include "cli/commands.hpp"
#include "dynamics/wheel_mode_family.hpp"
#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "io/modes_output.hpp"
#include "io/tread_shapes_file.hpp"
#include "io/wheel_fe_case.hpp"

namespace rollnoise::cli {

int run_modes(const CommonOptions& o, const std::string& csv) {
  const io::CaseReader reader =
      io::CaseReader::from_file(o.case_file, o.overrides).with("wheel.model=\"fe\"");
  const std::string out = output_path(o, reader.name());
  io::InputProblems problems;
  const auto fe = io::read_wheel_fe_case(reader, problems);
  problems.throw_if_any();
  const auto t0 = std::chrono::steady_clock::now();
  const auto modes = io::within_case(reader, [&] { return io::wheel_fe_modes_once(*fe); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  io::Hdf5Writer w(out);
  io::write_wheel_modes(w, *modes, fe->contact.damping);
  std::optional<io::TemporaryFile> table;  // committed with the HDF5 file, not before
  if (!csv.empty()) table.emplace(io::write_tread_shapes(csv, "--csv", *modes));
  w.commit();
  if (table) table->commit();

  std::printf(
      "%s: %zu modes of the wheel (%.1f kg) for n = 0..%d up to %.6g Hz; %zu triangles (mesh %.3g "
      "mm), %zu "
      "DOFs per n, %zu tread points; %.2f s\n",
      reader.name().c_str(), modes->modes.size(), modes->mass, fe->options.n_max, fe->options.f_max,
      modes->mesh.triangles.size(), 1e3 * fe->options.mesh_size, 3 * modes->mesh.nodes.size(),
      modes->tread_s.size(), seconds);
  // (family, circles) -> frequencies by n; a label's " #k" (dynamics::mode_labels) where two
  // modes share family, n and circles
  std::map<std::pair<std::string, int>, std::string> rows;
  const std::vector<std::string> labels = dynamics::mode_labels(modes->modes);
  for (std::size_t k = 0; k < modes->modes.size(); ++k) {
    const auto& m = modes->modes[k];
    char cell[48];
    std::snprintf(cell, sizeof cell, " n=%d%s %.0f", m.n,
                  labels[k].substr(dynamics::mode_label(m).size()).c_str(), m.frequency);
    rows[{dynamics::family_name(m.family), m.nodal_circles}] += cell;
  }
  for (const auto& [key, text] : rows)
    std::printf("  %s, %d nodal circles (Hz):%s\n", key.first.c_str(), key.second, text.c_str());
  std::printf("wrote %s%s%s\n", out.c_str(), csv.empty() ? "" : " and ", csv.c_str());
  return 0;
}

}  // namespace rollnoise::cli
