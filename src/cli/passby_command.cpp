// rollnoise passby: the noise run of the case's bogie (pipeline/noise_pipeline.hpp), then its train
// passing the EN ISO 3095 receiver (pipeline/passby.hpp, docs/sound.md Sec. 6). Read the case,
// run both, write /noise/* and /passby/* (io/noise_output.hpp, io/passby_output.hpp), print the
// levels beside the TSI Noise's normalisation and limit.
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/train_noise.hpp"
#include "io/noise_case.hpp"
#include "io/noise_output.hpp"
#include "io/passby_case.hpp"
#include "io/passby_output.hpp"
#include "pipeline/noise_pipeline.hpp"
#include "pipeline/passby.hpp"

namespace rollnoise::cli {

namespace {

void print_passby(const pipeline::PassbyResult& p, const pipeline::PassbyCase& pc,
                  double noise_seconds) {
  std::printf(
      "  train: %zu vehicles, %.1f m, %zu axles; V = %.2f m/s (%.1f km/h), T_p = %.2f s; "
      "receiver %.2f m from the track centre, %.2f m above the rail, %s ground\n",
      pc.train.size(), p.length, p.axles.size(), p.speed, 3.6 * p.speed, p.passage_time,
      pc.geometry.distance, pc.geometry.height,
      pc.geometry.reflection > 0.0 ? "reflecting" : "absorbing");
  std::printf(
      "  L_pAeq,Tp %.1f dB(A), L_pAFmax %.1f dB(A), TEL %.1f dB(A) (re 20 uPa); by source "
      "(A-weighted L_eq over T_p): wheel %.1f, rail %.1f, sleepers %.1f dB(A)\n",
      p.leq_a, p.lmax_a, p.tel, p.spectrum_a[0], p.spectrum_a[1], p.spectrum_a[2]);
  std::printf(
      "  TSI Noise (Regulation (EU) No 1304/2014): L_pAeq,Tp normalised to 80 km/h %.1f dB(A)",
      p.leq_a_80);
  if (std::isfinite(p.limit_a))
    std::printf(", limit for %s %.0f dB(A): %s by %.1f dB\n", pc.category.c_str(), p.limit_a,
                p.leq_a_80 <= p.limit_a ? "below" : "ABOVE", std::abs(p.leq_a_80 - p.limit_a));
  else
    std::printf(" (passby.category = \"none\": no limit)\n");
  std::printf("  every bogie wheel's sources from the computed wheel:");
  for (std::size_t i = 0; i < 4; ++i)
    std::printf(" %s <- %s%s", noise::wheel_name(static_cast<noise::WheelId>(i)),
                noise::wheel_name(p.source_wheel[i]), i < 3 ? "," : "\n");
  std::printf("  noise run %.2f s, pass-by %.2f s\n", noise_seconds, p.seconds);
}

}  // namespace

int run_passby(const CommonOptions& o) {
  const TrainNoise run = run_train_noise(o, "passby");
  const io::CaseReader& reader = run.reader;
  const pipeline::NoiseCase& nc = run.in.noise;
  const pipeline::PassbyCase& pc = run.train;
  const pipeline::NoiseResult& r = run.noise;
  const std::vector<noise::WheelId>& wheels = run.wheels;
  const pipeline::PassbyResult p = io::within_case(
      reader, [&] { return pipeline::run_passby(pc, *r.sound, wheels, r.mean.contact().speed); });

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_noise(w, reader, nc, r);
  io::write_passby(w, p, pc);
  w.commit();

  std::printf("%s: pass-by of the bogie's sound powers (%s)\n", reader.name().c_str(),
              nc.curve_radius > 0 ? "curve" : "tangent track");
  print_passby(p, pc, r.seconds_total);
  if (!r.sound->wheel_note.empty()) std::fprintf(stderr, "note: %s\n", r.sound->wheel_note.c_str());
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
