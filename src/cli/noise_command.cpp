// rollnoise noise: contact-force spectra from roughness for a train in a curve, and rollnoise
// receptance: the receptances the loop couples (docs/noise_loop.md). Read the case, run the noise
// pipeline (pipeline/noise_pipeline.hpp: curve state -> contact -> structures -> loop -> bands),
// write /noise/* or /receptance/* (io/noise_output.hpp) and print a summary.
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "io/noise_case.hpp"
#include "io/noise_output.hpp"
#include "io/rail_waves_output.hpp"
#include "nss/linear_model.hpp"
#include "pipeline/noise_pipeline.hpp"
#include "vehicle/bogie_equilibrium.hpp"

namespace rollnoise::cli {
namespace {

// The summary line of the curve contact state.
void print_contact_state(const pipeline::CurveSetup& curve) {
  if (!curve.state) return;
  const noise::CurveContactState& st = *curve.state;
  std::printf(
      "  contact (%s): u = %.2f mm, psi = %.2f mrad; on the wheel at s = %.1f mm, on the rail at "
      "%.1f mm, "
      "r = %.4f m; Q = %.1f kN + dQ %.1f kN, patch %.1f kN (N = %.1f kN); %s",
      st.equilibrium ? "bogie equilibrium"
      : st.estimated ? "bogie estimate"
                     : "multibody",
      1e3 * st.lateral, 1e3 * st.yaw, 1e3 * st.contact.wheel_s, 1e3 * st.contact.rail_y,
      st.contact.rolling_radius, 1e-3 * st.wheel_load, 1e-3 * st.load_transfer,
      1e-3 * st.tread_load, 1e-3 * st.normal_force,
      st.two_point ? "two-point: flange " : "one-point\n");
  if (st.two_point)
    std::printf("%.1f kN vertical in the estimate (N_f %.1f kN at %.3f rad; not added: the patch carries the wheel "
                "load)\n",
                1e-3 * st.flange_vertical_load, 1e-3 * st.flange_normal_force, st.flange_angle);
  if (st.equilibrium) {
    const noise::BogieEquilibrium& e = *st.equilibrium;
    std::printf(
        "  bogie equilibrium: leading u %.2f mm psi %.2f mrad, trailing u %.2f mm psi %.2f mrad, "
        "frame %.2f mm %.2f mrad; largest residual %.2e N (%.1e of Q%s), %d Newton iterations in "
        "%d continuation steps, %d axle contact evaluations\n",
        1e3 * e.lateral[0], 1e3 * e.yaw[0], 1e3 * e.lateral[1], 1e3 * e.yaw[1],
        1e3 * e.bogie_lateral, 1e3 * e.bogie_yaw, e.max_residual(),
        e.max_residual() / st.wheel_load, e.converged ? "" : "; NOT converged to 1e-6: stalled",
        e.iterations, e.continuation_steps, e.contact_evaluations);
  }
  if (st.loaded)
    std::printf("  wheel lowered under %.1f kN on the curved surface: force on the wheel (%.1f, %.1f, %.1f) kN "
                "(longitudinal, lateral towards the outer rail, up), contact angles %.3f..%.3f rad\n",
                1e-3 * st.loaded->vertical_load, 1e-3 * st.loaded->force_track[0], 1e-3 * st.loaded->force_track[1],
                1e-3 * st.loaded->force_track[2], st.loaded->angle_min, st.loaded->angle_max);
}

// One wheel's (or patch's) line: axle position, contact on wheel and rail, angle, creepages,
// vertical load, N, force on the wheel in the track frame; the Fz levels summed over the bands.
void print_wheel_line(const pipeline::WheelNoise& wn, const char* label) {
  if (!wn.state) return;  // the case's one contact: its state is the summary's
  const noise::WheelContact& w = *wn.state;
  const auto f = w.force_track();
  double total = 0.0;  // the power sum of the Fz band levels (dB re 1 N)
  for (const auto& l : wn.bands.force_level) total += std::pow(10.0, 0.1 * l[0]);
  std::printf("  %-14s u %5.2f mm psi %6.2f mrad | wheel s %6.1f mm rail %6.1f mm angle %.3f rad | xi (%.2e, %.2e, "
              "%.3f rad/m) | Q %5.1f kN N %5.1f kN | F (%5.1f, %5.1f, %5.1f) kN | Fz %.1f dB re 1 N (all bands)\n",
              label, 1e3 * w.lateral, 1e3 * w.yaw, 1e3 * w.contact.wheel_s, 1e3 * w.contact.rail_y,
              w.contact.contact_angle, w.creepage(0), w.creepage(1), w.creepage(2), 1e-3 * w.vertical_load,
              1e-3 * w.normal_force(), 1e-3 * f[0], 1e-3 * f[1], 1e-3 * f[2], 10.0 * std::log10(total));
}

// What a contact's work cost: its linear model's size and sweep
// (/noise/wheels/<wheel>/contact_work).
void print_contact_work(const pipeline::WheelNoise& wn, const char* label) {
  const nss::LinearContactModel* m = wn.mean.model().get();
  if (!m) {
    std::printf("    %-14s %.2f s\n", label, wn.seconds);
    return;
  }
  std::printf("    %-14s %4d adhesion / %4d slip elements, r = %4d, %3d block steps, %.2f s\n",
              label, m->adhesion_elements(), m->slip_elements(), m->reduced_unknowns(),
              m->sweep_info().block_steps, wn.seconds);
}

// One line per wheel of curve.wheels, then one per second patch (noise.second_patch).
void print_wheels(const pipeline::NoiseResult& r) {
  if (!r.wheels.front().state) return;  // the case's one contact
  std::printf("  wheels (%s; lateral force towards the outer rail; %.1f s):\n",
              r.coupled_contacts ? "the wheels' patches coupled in one loop through wheelset and rails"
                                 : "each wheel's patch in the loop alone",
              r.seconds_wheels);
  for (const pipeline::WheelNoise& wn : r.wheels) print_wheel_line(wn, noise::wheel_name(wn.wheel));
  for (const pipeline::WheelNoise& p : r.patches) {
    std::printf("  second patch of %s (the flange patch, coupled; docs/noise_loop.md Sec. 7.3):\n",
                noise::wheel_name(p.wheel));
    print_wheel_line(p, "  flange");
  }
  std::printf(
      "  contact work (curve state %.2f s first; then each contact on its own thread, "
      "concurrently):\n",
      r.seconds_curve);
  for (const pipeline::WheelNoise& wn : r.wheels)
    print_contact_work(wn, noise::wheel_name(wn.wheel));
  for (const pipeline::WheelNoise& p : r.patches) print_contact_work(p, "  flange");
}

// The 1/3-octave band levels of the reported wheel in the case's loop, one line per band (left
// out with -q).
void print_band_table(const pipeline::NoiseResult& r) {
  const pipeline::WheelNoise& wn = r.reported_wheel();
  const auto& loops = r.loops;
  const auto& centres = r.axis.centres;
  std::printf("  %s, %s (/noise/bands = /noise/wheels/%s/bands):\n", noise::wheel_name(wn.wheel),
              r.coupled_contacts ? "all contacts coupled in one loop" : "each contact alone",
              noise::wheel_name(wn.wheel));
  std::printf("  levels dB re 1 N (Mz re 1 N m), %s coupling; L_r = effective roughness dB re 1 um; d* = with minus "
              "without the coupling; muFz = 20 log10|Fy_mean/N| + Fz; b* = minus the %s baseline\n",
              r.coupled ? "with" : "without", loops.has_baseline() ? r.baseline_name.c_str() : "(no)");
  std::printf("  %6s %6s %6s %6s %6s %6s | %6s %6s %6s %6s | %6s | %6s %6s\n", "band", "L_r", "Fz", "Fx", "Fy", "Mz",
              "dFz", "dFx", "dFy", "dMz", "muFz", "bFz", "bFy");
  const auto d = loops.has_uncoupled() ? noise::force_level_difference(wn.bands, wn.uncoupled_bands)
                                       : std::vector<std::array<double, 4>>{};
  const double mu_db = 20 * std::log10(std::abs(wn.mean_force.Fy / wn.mean.contact().normal_force));
  for (size_t i = 0; i < centres.size(); ++i) {
    const auto& L = wn.bands.force_level[i];
    std::printf("  %6.0f %6.1f %6.1f %6.1f %6.1f %6.1f |", noise::nominal_centre(centres[i]), wn.bands.roughness_level[i],
                L[0], L[1], L[2], L[3]);
    if (!d.empty())
      std::printf(" %6.1f %6.1f %6.1f %6.1f |", d[i][0], d[i][1], d[i][2], d[i][3]);
    else
      std::printf(" %6s %6s %6s %6s |", "-", "-", "-", "-");
    if (std::isfinite(mu_db))
      std::printf(" %6.1f |", mu_db + L[0]);
    else
      std::printf(" %6s |", "-");  // no mean lateral force (e.g. tangent track)
    if (loops.has_baseline())
      std::printf(" %6.1f %6.1f\n", L[0] - wn.baseline_bands.force_level[i][0], L[2] - wn.baseline_bands.force_level[i][2]);
    else
      std::printf(" %6s %6s\n", "-", "-");
  }
}

// The A-weighted sound powers (docs/sound.md): one line for the bogie and one per wheel.
void print_sound(const pipeline::NoiseResult& r) {
  if (!r.sound) return;
  const pipeline::SoundResult& s = *r.sound;
  auto line = [](const char* label, const std::array<double, 4>& a) {
    std::printf("    %-14s wheel %6.1f  rail %6.1f  sleepers %6.1f  total %6.1f\n", label, a[0], a[1], a[2], a[3]);
  };
  std::printf("  sound power, dB(A) re 1 pW (%.0f Hz - %.0f Hz; sound stage %.2f s)%s:\n",
              noise::nominal_centre(s.centre.front()), noise::nominal_centre(s.centre.back()), s.seconds,
              s.wheel_note.empty() ? "" : "; the wheel's column empty (see below)");
  const pipeline::SoundResult::Parts& t = s.parts;
  std::printf("    (stage: radiation tables %.2f s, rails along the line %.2f s, rails' sections %.2f s, "
              "lines %.2f s, decay rates %.2f s)\n",
              t.tables, t.rail_line, t.rail_section, t.lines, t.decay);
  line(r.wheels.size() > 1 ? "all wheels" : "the wheel", s.power_a);
  for (std::size_t i = 0; r.wheels.size() > 1 && i < s.contact_power_a.size(); ++i)
    line(noise::wheel_name(r.wheels[i].wheel), s.contact_power_a[i]);
  if (!s.wheel_note.empty()) std::fprintf(stderr, "note: %s\n", s.wheel_note.c_str());
}

}  // namespace

int run_noise(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  const pipeline::NoiseCase& nc = in.noise;
  const pipeline::NoiseResult r = io::within_case(reader, [&] { return pipeline::run_noise(std::move(in.contact), nc); });

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_noise(w, reader, nc, r);
  w.commit();

  const pipeline::ContactCase& cc = r.mean.contact();
  const auto& centres = r.axis.centres;
  char track[64] = "tangent track";  // the radius as a number: any size prints (no int cast)
  if (nc.curve_radius > 0) std::snprintf(track, sizeof track, "curve R = %.6g m", nc.curve_radius);
  std::printf("%s: %s, V = %.3g m/s; leading outer wheel: creepages (%.4g, %.4g, %.4g rad/m), "
              "contact angle %.3g rad\n",
              reader.name().c_str(), track,
              cc.speed, cc.creepage.xi_x, cc.creepage.xi_y, cc.creepage.phi, r.mean.curve().position.contact_angle);
  print_contact_state(r.mean.curve());
  std::printf("  contact: %d adhesion / %d slip elements; %zu frequencies in %zu bands; contact %.1f s, "
              "loop %.1f s, total %.1f s\n",
              r.mean.model()->adhesion_elements(), r.mean.model()->slip_elements(), r.axis.frequency.size(),
              centres.size(), r.seconds_contact, r.seconds_wheels, r.seconds_total);
  if (r.refined)
    std::printf("  band means: %ld lines added in %d refinement levels (noise.band_refinement = %d)%s\n",
                r.refined->added_lines, r.refined->levels, nc.band_refinement,
                r.refined->capped ? "; stopped at 16 x the case's lines or the case's [limits]" : "");
  print_wheels(r);
  if (!nc.notice.empty()) std::fprintf(stderr, "warning: %s\n", nc.notice.c_str());
  std::printf("  mean forces Fx %.4g N, Fy %.4g N, Mz %.4g N m, N %.4g N; g(0) = (%.4g, %.4g, %.4g m)\n",
              r.mean_force.Fx, r.mean_force.Fy, r.mean_force.Mz, cc.normal_force, r.g0(0).real(), r.g0(1).real(),
              r.g0(2).real());
  print_sound(r);
  if (!o.quiet) print_band_table(r);  // -q: the summary lines only
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

int run_receptance(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  std::vector<double> freq;
  io::NoiseInputs in = io::read_noise_inputs(reader, &freq);
  const pipeline::ReceptanceResult r =
      io::within_case(reader, [&] { return pipeline::run_receptance(std::move(in.contact), in.noise, freq); });
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_receptance(w, reader, r);
  io::write_rail_waves(w, *in.noise.rail);  // track.model = "waveguide" only
  w.commit();
  std::printf("%s: receptances at %zu frequencies (%s contact model)\nwrote %s\n", reader.name().c_str(), freq.size(),
              in.noise.use_nss ? "NSS" : "Kalker", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
