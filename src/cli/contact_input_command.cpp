// rollnoise contact-input CASE.toml [-o DIR] [--steady]: CONTACT's input for the same problem,
// DIR/CASENAME.inp (io/contact_input.hpp; docs/contact_interop.md). Hertzian cases: module 3,
// transient when the case has an [excitation] (unless --steady); profile cases: module 1, with
// the two profile files copied into DIR (CONTACT reads them next to the input); profile cases in a
// curve (curve.radius > 0): one module-1 input per wheel of the bogie, DIR/CASENAME_<wheel>.inp,
// with each wheel's curve contact state (docs/contact_interop.md Sec. 1).
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
#include "io/noise_case.hpp"
#include "io/output_files.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/limits.hpp"
#include "vehicle/curve_state.hpp"

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

// A profile case in a curve: one module-1 input per wheel of the bogie, DIR/CASE_<wheel>.inp,
// each wheel's state from the curve contact state (pipeline::resolve_curve, then
// noise::bogie_wheel_contacts: what `rollnoise noise` places each wheel by), the profiles copied.
int write_curve_wheels(const io::CaseReader& reader, const std::string& dir) {
  const io::NoiseInputs in = io::read_noise_inputs(reader);
  const pipeline::CurvePlacement placement =
      io::within_case(reader, [&] { return pipeline::resolve_curve(in.contact, in.noise); });
  const pipeline::CurveSetup& curve = placement.curve;
  if (!curve.state || !curve.state_input)
    reader.fail("curve.creepage",
                "contact-input: a curve is written from its curve contact state (curve.creepage = "
                "\"estimate\" or \"multibody\"); \"case\" has none");
  const std::vector<noise::WheelId> ids(noise::kAllWheels.begin(), noise::kAllWheels.end());
  const std::vector<noise::WheelContact> wheels = io::within_case(
      reader, [&] { return noise::bogie_wheel_contacts(*curve.state_input, *curve.state, ids); });
  const std::string rail = io::resolve_model_file(reader, "contact.rail_profile");
  const std::string wheel = io::resolve_model_file(reader, "contact.wheel_profile");
  std::vector<io::OutputFile> outputs;
  std::vector<std::pair<std::string, std::string>> texts;  // path, text
  for (const noise::WheelContact& w : wheels) {
    const std::string path =
        (fs::path(dir) / (reader.name() + "_" + noise::wheel_name(w.wheel) + ".inp")).string();
    outputs.push_back({"-o", path});
    texts.push_back({path, io::within_case(reader, [&] {
                       const pipeline::ContactCase placed =
                           pipeline::placed_contact_at(in.contact, w.contact, w.normal_force());
                       return io::module1_wheel_input(
                           placed, w, 1.0 / in.noise.curve_radius,
                           io::contact_input_comments(
                               reader.name(), reader.source(),
                               std::string("module 1, wheel-rail contact, steady rolling: the ") +
                                   noise::wheel_name(w.wheel) + " wheel of the curve's bogie"),
                           fs::path(rail).filename().string(), fs::path(wheel).filename().string());
                     })});
  }
  std::vector<std::pair<std::string, std::string>> copies;  // profile files: from, to
  for (const std::string& p : {rail, wheel}) {
    copies.push_back({p, (fs::path(dir) / fs::path(p).filename()).string()});
    outputs.push_back({"-o", copies.back().second});
  }
  io::check_outputs(outputs, io::case_input_files(reader));
  std::vector<io::TemporaryFile> files;
  for (const auto& [path, text] : texts)
    files.push_back(io::write_text_file(path, "-o", [&](std::ostream& out) { out << text; }));
  for (const auto& [from, to] : copies) {
    const std::string& bytes = io::read_input(from, from, "the profile");
    files.push_back(io::write_text_file(to, "-o", [&](std::ostream& out) { out << bytes; }));
  }
  for (auto& f : files) f.commit();
  std::printf(
      "%s: CONTACT module 1, curve R = %.6g m, one input per wheel (right wheel of its own frame; "
      "the "
      "inner wheels mirrored), profiles copied beside them:\n",
      reader.name().c_str(), in.noise.curve_radius);
  for (size_t i = 0; i < wheels.size(); ++i)
    std::printf("  %-14s u %6.2f mm psi %6.2f mrad Q %6.1f kN -> %s\n",
                noise::wheel_name(wheels[i].wheel), 1e3 * wheels[i].lateral, 1e3 * wheels[i].yaw,
                1e-3 * wheels[i].vertical_load, texts[i].first.c_str());
  return 0;
}

}  // namespace

int run_contact_input(const CommonOptions& o, bool steady_only) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  if (reader.string("contact.geometry") == "profiles" && reader.real("curve.radius") > 0.0) {
    const std::string dir = o.output.empty() ? "." : o.output;
    if (fs::exists(dir) && !fs::is_directory(dir))
      throw InputError("-o", "-o " + dir + ": not a folder");
    fs::create_directories(dir);
    return write_curve_wheels(reader, dir);
  }
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
