// rollnoise contact-input CASE.toml [-o DIR] [--steady]: CONTACT's input for the same problem,
// DIR/CASENAME.inp (io/contact_input.hpp; docs/contact_interop.md). Hertzian cases: module 3,
// transient when the case has an [excitation] (unless --steady); profile cases: module 1, with
// the two profile files copied into DIR (CONTACT reads them next to the input).
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "contact/creepage_history.hpp"
#include "core/errors.hpp"
#include "io/contact_case.hpp"
#include "io/contact_input.hpp"
#include "io/contact_input_wheelrail.hpp"
#include "io/excitation.hpp"
#include "io/input_file.hpp"
#include "io/output_files.hpp"
#include "pipeline/limits.hpp"

namespace rollnoise::cli {
namespace {

namespace fs = std::filesystem;

io::ContactTransient transient_of(const io::CaseReader& reader, const io::ContactCase& cc) {
  if (reader.string("transient.start") != "steady")
    reader.fail("transient.start",
                "contact-input: CONTACT's transient run starts from the steady state "
                "(transient.start = \"steady\")");
  io::ContactTransient t{io::read_excitation(reader), 0, cc.grid.dx / cc.speed};
  const double count = std::floor(reader.real("transient.duration") / t.dt + 1e-9);
  io::within_case(reader, [&] {
    pipeline::check_size(io::read_limits(reader), "transient.duration", count,
                         "time steps of dt = dx/V", 0);
  });
  t.steps = std::lround(count);
  if (t.steps < 1) reader.fail("transient.duration", "shorter than one time step dx/V");
  io::normal_load_series(reader, t.history, cc.normal_force, t.dt, t.steps);  // N_k > 0
  return t;
}

}  // namespace

int run_contact_input(const CommonOptions& o, bool steady_only) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::ContactCase cc = io::read_contact_case(reader);
  io::within_case(reader, [&] { cc = pipeline::placed_contact(std::move(cc)); });
  const std::string dir = o.output.empty() ? "." : o.output;
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InputError("-o", "-o " + dir + ": not a folder");
  fs::create_directories(dir);
  const std::string inp = (fs::path(dir) / (reader.name() + ".inp")).string();
  std::vector<io::OutputFile> outputs = {{"-o", inp}};
  std::string text;
  std::vector<std::pair<std::string, std::string>> copies;  // profile files: from, to
  if (cc.geometry == "hertz") {
    std::optional<io::ContactTransient> t;
    if (!steady_only && reader.has("excitation")) t = transient_of(reader, cc);
    const std::string what =
        t ? "module 3, transient: case 1 the steady state at the mean creepage, then " +
                std::to_string(t->steps) +
                " time steps of dt = dx/V with the creepage of rolling.creepage_sampling = \"" +
                contact::sampling_name(cc.sampling) + "\""
          : std::string("module 3, steady rolling at the mean creepage");
    text = io::within_case(reader, [&] {
      return io::module3_input(cc, io::contact_input_comments(reader.name(), reader.source(), what),
                               t);
    });
    std::printf("%s: CONTACT module 3, %s on %d x %d elements\n", reader.name().c_str(),
                t ? ("1 steady + " + std::to_string(t->steps) + " transient cases").c_str()
                  : "1 steady case",
                cc.grid.nx, cc.grid.ny);
  } else {
    const std::string rail = io::resolve_model_file(reader, "contact.rail_profile");
    const std::string wheel = io::resolve_model_file(reader, "contact.wheel_profile");
    for (const std::string& p : {rail, wheel}) {
      copies.push_back({p, (fs::path(dir) / fs::path(p).filename()).string()});
      outputs.push_back({"-o", copies.back().second});
    }
    text = io::within_case(reader, [&] {
      return io::module1_input(
          cc,
          io::contact_input_comments(reader.name(), reader.source(),
                                     "module 1, wheel-rail contact, steady rolling"),
          fs::path(rail).filename().string(), fs::path(wheel).filename().string());
    });
    std::printf(
        "%s: CONTACT module 1 (right wheel, vertical load %.6g N), profiles copied beside the "
        "input\n",
        reader.name().c_str(), cc.normal_force);
  }
  io::check_outputs(outputs, io::case_input_files(reader));
  std::vector<io::TemporaryFile> files;
  files.push_back(io::write_text_file(inp, "-o", [&](std::ostream& out) { out << text; }));
  for (const auto& [from, to] : copies) {
    const std::string& bytes = io::read_input(from, from, "the profile");
    files.push_back(io::write_text_file(to, "-o", [&](std::ostream& out) { out << bytes; }));
  }
  for (auto& f : files) f.commit();
  std::printf("wrote %s\n", inp.c_str());
  return 0;
}

}  // namespace rollnoise::cli
