// rollnoise cnossos: the case's noise run as CNOSSOS-EU transfer functions (pipeline/cnossos.hpp)
// in NoiseModelling's railway JSON layout (io/cnossos_output.hpp), and the Directive's sound power
// per metre of track for a flow of the case's train (--flow vehicles per hour).
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/train_noise.hpp"
#include "core/errors.hpp"
#include "io/cnossos_output.hpp"
#include "io/noise_case.hpp"
#include "io/passby_case.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/cnossos.hpp"
#include "pipeline/noise_pipeline.hpp"
#include "pipeline/passby.hpp"

namespace rollnoise::cli {

namespace {

void print_cnossos(const pipeline::CnossosTransfer& t, const pipeline::CnossosLinePower& p,
                   double axles, double flow, double speed) {
  std::printf(
      "  band (Hz)  L_R,TOT (dB re 1 um)  L_H,TR (dB)  L_H,VEH (dB)  L_W',eq,line (dB re 1 "
      "pW/m)\n");
  for (std::size_t i = 0; i < pipeline::kCnossosBands; ++i)
    std::printf("  %8.0f  %10.2f  %12.2f  %12.2f  %14.2f%s\n", pipeline::cnossos_centres()[i],
                t.roughness[i], t.track[i], t.vehicle[i], p.band[i],
                t.computed[i] ? "" : "   (filled: nearest computed band)");
  std::printf(
      "  L_W',eq,line = %.2f dB(A) re 1 pW/m for Q = %g vehicles/h of N_a = %g axles at v = %.1f "
      "km/h "
      "(Directive (EU) 2015/996 Annex II eqs. 2.3.2, 2.3.8-2.3.10)\n",
      p.total_a, flow, axles, speed);
}

}  // namespace

int run_cnossos(const CommonOptions& o, double flow) {
  if (!(flow > 0.0) || !std::isfinite(flow))
    throw InputError("--flow", "--flow must be a positive number of vehicles per hour");
  const TrainNoise run = run_train_noise(o, "cnossos");
  const io::CaseReader& reader = run.reader;
  const pipeline::NoiseResult& r = run.noise;
  const pipeline::CnossosTransfer t = io::within_case(reader, [&] {
    return pipeline::cnossos_transfer(*r.sound, run.wheels, r.reported_wheel().bands.roughness_level);
  });
  const double speed = 3.6 * r.mean.contact().speed;  // km/h
  const double axles = static_cast<double>(pipeline::train_axles(run.train.train).size()) /
                       static_cast<double>(run.train.train.size());
  const pipeline::CnossosLinePower p = pipeline::cnossos_line_power(t, axles, flow, speed);

  const std::string out = output_path(o, reader.name());
  io::write_cnossos(out, "-o", t, {reader.name(), speed, 2000.0 * run.in.noise.wheel_radius});
  std::printf(
      "%s: CNOSSOS-EU transfer functions per axle (track: rail and sleepers; vehicle: the wheels), "
      "24 bands "
      "50 Hz - 10 kHz\n",
      reader.name().c_str());
  print_cnossos(t, p, axles, flow, speed);
  bool filled = false;
  for (bool c : t.computed) filled = filled || !c;
  if (filled)
    std::fprintf(
        stderr,
        "note: bands outside the case's noise.band_min .. noise.band_max were not computed: they "
        "hold "
        "the nearest computed band's values (marked 'filled'; in the JSON's rollnoise.computed)\n");
  if (!r.sound->wheel_note.empty()) std::fprintf(stderr, "note: %s\n", r.sound->wheel_note.c_str());
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
