// rollnoise noise: contact-force spectra from roughness for a train in a curve (DESIGN.md Sec. 4).
//
//   1. mean creepages and contact position: the quasi-static bogie estimate for the curve
//      (src/noise/curving.hpp), or the case's creepage.mean and contact.angle;
//   2. the contact patch, steady rolling at the mean creepage, the linear NSS model and its creep
//      coefficients f(w) at the narrow-band frequencies (one sweep, reused for every output);
//   3. wheel and rail receptances at the contact point (computed once), the contact receptance
//      (1/k_H normal, (V/(i w)) f^{-1} tangential), the closed loop per frequency per unit roughness;
//   4. the effective roughness (wheel + rail, contact filter) and the 1/3-octave levels.
// With noise.compare_kalker = "yes" step 3 is repeated with Kalker's steady coefficients.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/contact_setup.hpp"
#include "contact/hertz.hpp"
#include "io/contact_output.hpp"
#include "io/frequency_axis.hpp"
#include "io/noise_case.hpp"
#include "noise/bands.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/curving.hpp"
#include "noise/kalker_linear.hpp"
#include "noise/loop.hpp"

namespace rollnoise::cli {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

void write_bands(io::Hdf5Writer& w, const std::string& g, const noise::BandLevels& b, bool roughness) {
  const std::size_t nb = b.centre.size();
  std::vector<double> fl, vl;
  for (const auto& l : b.force_level) fl.insert(fl.end(), l.begin(), l.end());
  for (const auto& l : b.velocity_level)
    for (const auto& side : l) vl.insert(vl.end(), side.begin(), side.end());
  w.write(g + "/centre", b.centre, {nb}, "Hz");
  w.write(g + "/force_level", fl, {nb, 4}, "dB re 1 N (Fz, Fx, Fy), re 1 N m (Mz)");
  w.write(g + "/velocity_level", vl, {nb, 2, 4},
          "dB re 1e-9 m/s (z, x, y), re 1e-9 rad/s (rot z); [wheel, rail]");
  if (roughness) w.write(g + "/roughness_level", b.roughness_level, {nb}, "dB re 1 um (effective, after the contact filter)");
}

std::vector<std::complex<double>> flatten4(const std::vector<noise::Vector4c>& v) {
  std::vector<std::complex<double>> out;
  for (const auto& x : v) out.insert(out.end(), {x(0), x(1), x(2), x(3)});
  return out;
}

// The case, its noise part and the mean state of the leading outer wheel (step 1).
struct NoiseSetup {
  io::CaseReader reader;
  io::NoiseCase noise;
  io::ContactCase contact;
  noise::ContactPosition position;
  noise::CurvingEstimate curving;
  bool estimated = false;
};

NoiseSetup prepare(const CommonOptions& o) {
  NoiseSetup s{io::CaseReader::from_file(o.case_file, o.overrides), {}, {}, {}, {}, false};
  s.noise = io::read_noise_case(s.reader);
  s.contact = io::read_contact_case(s.reader);
  io::ContactCase& cc = s.contact;
  const io::NoiseCase& nc = s.noise;
  s.position = {0.0, 0.0, nc.contact_angle};
  s.estimated = nc.estimate_creepage && nc.curve_radius > 0.0;
  if (s.estimated) {
    const Eigen::Matrix3d fk =
        noise::kalker_creep_matrix(cc.a, cc.b, cc.material.shear_modulus(), cc.material.nu);
    noise::BogieCurvingInput in;
    in.radius = nc.curve_radius;
    in.speed = cc.speed;
    in.cant_deficiency = nc.cant_deficiency;
    in.wheelbase = nc.wheelbase;
    in.wheel_radius = nc.wheel_radius;
    in.conicity = nc.conicity;
    in.flange_clearance = nc.flange_clearance;
    in.wheel_load = cc.normal_force;
    in.friction = cc.mu;
    in.f11 = fk(0, 0);
    in.f22 = fk(1, 1);
    s.curving = noise::estimate_bogie_curving(in);
    cc.creepage = {s.curving.xi_x, s.curving.xi_y, s.curving.phi};
    s.position = s.curving.position();
    // the case as run records the creepage used
    std::ostringstream v;
    v.precision(12);
    v << "creepage.mean=[" << s.curving.xi_x << ", " << s.curving.xi_y << ", " << s.curving.phi << "]";
    s.reader = s.reader.with(v.str());
  }
  return s;
}

}  // namespace

int run_noise(const CommonOptions& o) {
  const auto t0 = Clock::now();
  NoiseSetup setup = prepare(o);
  const io::CaseReader& reader = setup.reader;
  const io::NoiseCase& nc = setup.noise;
  io::ContactCase& cc = setup.contact;
  const double G = cc.material.shear_modulus();
  const noise::ContactPosition position = setup.position;
  const noise::CurvingEstimate& curving = setup.curving;
  const bool estimated = setup.estimated;

  // 2. contact: patch, steady state, linear model, creep coefficients on the narrow-band axis
  const std::vector<double> centres = noise::third_octave_centres(nc.band_min, nc.band_max);
  if (centres.empty()) reader.fail("noise.band_max", "no 1/3-octave band between band_min and band_max");
  const std::vector<double> freq = noise::band_frequencies(centres, nc.points_per_band);
  auto patch = std::make_unique<contact::ContactPatch>(io::solve_case_patch(cc));
  const auto steady = contact::solve_steady_rolling(patch->influence, patch->normal.pn, cc.steady_input(), cc.tangential);
  const nss::LinearContactModel model(*patch, steady, {cc.mu, cc.speed, cc.spin_offset});
  if (freq.back() > model.nyquist_frequency())
    reader.fail("noise.band_max", "the band edge " + std::to_string(freq.back()) +
                                      " Hz is above the grid's Nyquist limit " +
                                      std::to_string(model.nyquist_frequency()) + " Hz: refine grid.nx");
  const auto creep = model.creep_coefficients(freq);
  const double kH = contact::hertz_from_semi_axes(cc.a, cc.b, cc.normal_force, cc.material).normal_stiffness();
  const double t_contact = seconds_since(t0);

  // 3. structures once, then the loop per contact model
  const auto t1 = Clock::now();
  const noise::StructuralReceptances structures =
      noise::structural_receptances(*nc.wheel, *nc.rail, position, freq);
  const double t_structures = seconds_since(t1);
  const auto nss_contact = noise::contact_receptances(freq, kH, cc.speed, creep);
  const Eigen::Matrix3d f_kalker = noise::kalker_creep_matrix(cc.a, cc.b, G, cc.material.nu);
  const auto kalker_contact = noise::contact_receptances(freq, kH, cc.speed, noise::steady_creep(f_kalker));
  const noise::LoopResult main = noise::solve_loop(structures, nc.use_nss ? nss_contact : kalker_contact);

  // 4. roughness and bands
  noise::ContactFilter filter;
  filter.model = nc.filter;
  filter.a = cc.a;
  filter.b = cc.b;
  const noise::ContactRoughness roughness(nc.wheel_roughness, nc.rail_roughness, cc.speed, filter);
  const noise::BandLevels bands = noise::band_levels(main, centres, roughness);

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, reader, *patch, cc.creepage, steady);
  const std::size_t nf = freq.size();
  w.write("/noise/frequency", freq, {nf}, "Hz");
  w.write("/noise/force", flatten4(main.force), {nf, 4},
          "per unit roughness: Fz, Fx, Fy (N/m), Mz (N m/m); contact frame, on the wheel");
  w.write("/noise/wheel_velocity", flatten4(main.wheel_velocity), {nf, 4}, "per unit roughness: (m/s)/m, (rad/s)/m");
  w.write("/noise/rail_velocity", flatten4(main.rail_velocity), {nf, 4}, "per unit roughness: (m/s)/m, (rad/s)/m");
  write_bands(w, "/noise/bands", bands, true);
  w.attribute("/noise", "contact_model", nc.use_nss ? "linear NSS model" : "Kalker's steady linear theory");
  w.attribute("/noise", "band_average", "mean of |H|^2 over the narrow-band samples inside each band (docs/noise_loop.md)");
  std::vector<std::complex<double>> fc;
  for (const auto& m : creep)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) fc.push_back(m(j, k));
  w.write("/noise/creep/f", fc, {nf, 3, 3}, "f_jk with F~ = -f xi~ (N, N m, N m^2), rows Fx, Fy, Mz");
  w.write("/noise/contact/normal_stiffness", kH, "N/m");
  w.write("/noise/contact/angle", position.contact_angle, "rad");
  w.write("/noise/contact/wheel_shift", position.wheel_shift_y, "m");
  w.write("/noise/contact/rail_offset", position.rail_offset_y, "m");
  if (estimated) {
    w.write("/noise/curving/radius", nc.curve_radius, "m");
    w.write("/noise/curving/attack_angle", curving.leading.attack_angle, "rad");
    w.write("/noise/curving/lateral", curving.leading.lateral, "m");
    w.write("/noise/curving/flange_force", curving.leading.flange_force, "N");
  }
  if (nc.compare_kalker && nc.use_nss) {
    const noise::LoopResult k = noise::solve_loop(structures, kalker_contact);
    write_bands(w, "/noise/kalker/bands", noise::band_levels(k, centres, roughness), false);
    w.write("/noise/kalker/force", flatten4(k.force), {nf, 4}, "per unit roughness, Kalker's steady coefficients");
  }
  w.commit();

  std::printf("%s: %s, V = %.3g m/s; leading outer wheel: creepages (%.4g, %.4g, %.4g rad/m), "
              "contact angle %.3g rad\n",
              reader.name().c_str(),
              nc.curve_radius > 0 ? ("curve R = " + std::to_string(int(nc.curve_radius)) + " m").c_str()
                                  : "tangent track",
              cc.speed, cc.creepage.xi_x, cc.creepage.xi_y, cc.creepage.phi, position.contact_angle);
  std::printf("  contact: %d adhesion / %d slip elements; %zu frequencies in %zu bands; contact %.1f s, "
              "structures %.1f s, total %.1f s\n",
              model.adhesion_elements(), model.slip_elements(), nf, centres.size(), t_contact, t_structures,
              seconds_since(t0));
  std::printf("  %8s %9s %9s %9s %9s %9s\n", "band Hz", "L_r dB", "Fz dB", "Fx dB", "Fy dB", "Mz dB");
  for (size_t i = 0; i < centres.size(); i += 3)
    std::printf("  %8.0f %9.1f %9.1f %9.1f %9.1f %9.1f\n", centres[i], bands.roughness_level[i],
                bands.force_level[i][0], bands.force_level[i][1], bands.force_level[i][2], bands.force_level[i][3]);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

// rollnoise receptance: the wheel, rail and contact receptances alone, on the case's frequency axis,
// at the contact point and mean state of the noise case (contact frame: normal, x, y, rot normal).
int run_receptance(const CommonOptions& o) {
  NoiseSetup setup = prepare(o);
  const io::ContactCase& cc = setup.contact;
  const std::vector<double> freq = io::read_frequency_axis(setup.reader);
  for (double f : freq)
    if (!(f > 0.0)) setup.reader.fail("frequency.f_min", "receptances need positive frequencies");
  auto patch = std::make_unique<contact::ContactPatch>(io::solve_case_patch(cc));
  const auto steady = contact::solve_steady_rolling(patch->influence, patch->normal.pn, cc.steady_input(), cc.tangential);
  const double kH = contact::hertz_from_semi_axes(cc.a, cc.b, cc.normal_force, cc.material).normal_stiffness();
  std::vector<noise::Receptance4> contact_r;
  if (setup.noise.use_nss) {
    const nss::LinearContactModel model(*patch, steady, {cc.mu, cc.speed, cc.spin_offset});
    if (freq.back() > model.nyquist_frequency())
      setup.reader.fail("frequency.f_max", "above the grid's Nyquist limit " + std::to_string(model.nyquist_frequency()) + " Hz");
    contact_r = noise::contact_receptances(freq, kH, cc.speed, model.creep_coefficients(freq));
  } else {
    contact_r = noise::contact_receptances(
        freq, kH, cc.speed,
        noise::steady_creep(noise::kalker_creep_matrix(cc.a, cc.b, cc.material.shear_modulus(), cc.material.nu)));
  }
  const auto st = noise::structural_receptances(*setup.noise.wheel, *setup.noise.rail, setup.position, freq);
  auto flat = [](const std::vector<noise::Receptance4>& v) {
    std::vector<std::complex<double>> out;
    for (const auto& m : v)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out.push_back(m(i, j));
    return out;
  };
  const std::string units = "m/N, m/(N m), rad/N, rad/(N m); order normal, x, y, rotation about the normal (contact frame)";
  const std::string out = output_path(o, setup.reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, setup.reader, *patch, cc.creepage, steady);
  const std::size_t nf = freq.size();
  w.write("/receptance/frequency", freq, {nf}, "Hz");
  w.write("/receptance/wheel", flat(st.wheel_contact), {nf, 4, 4}, units);
  w.write("/receptance/rail", flat(st.rail_contact), {nf, 4, 4}, units);
  w.write("/receptance/contact", flat(contact_r), {nf, 4, 4}, units);
  w.commit();
  std::printf("%s: receptances at %zu frequencies (%s contact model)\nwrote %s\n", setup.reader.name().c_str(), nf,
              setup.noise.use_nss ? "NSS" : "Kalker", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
