// rollnoise noise: contact-force spectra from roughness for a train in a curve (docs/noise_loop.md).
//
//   1. mean creepages and contact position: with profiles the curve contact state
//      (src/noise/curve_state.hpp: bogie estimate or multibody input, contact, loads, creepages),
//      with the Hertzian patch the quasi-static bogie estimate (src/noise/curving.hpp), or the
//      case's creepage.mean and contact;
//   2. the contact patch, steady rolling at the mean creepage, the linear NSS model and its creep
//      coefficients f(w) at the narrow-band frequencies (one sweep, reused for every output);
//   3. wheel and rail receptances at the contact point (computed once), the contact receptance
//      (1/k_H normal, (V/(i w)) f^{-1} tangential, the normal -> tangential coupling by g), the
//      closed loop per frequency per unit roughness for the variants of noise/loop_variants.hpp:
//      with the coupling (noise.normal_coupling = "on": also without it, /noise/uncoupled) and the
//      baseline of noise.compare (the quasi-steady contact f(0), g(0), or Kalker's coefficients);
//   4. the effective roughness (wheel + rail, contact filter) and the 1/3-octave levels.
#include <chrono>
#include <optional>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/contact_setup.hpp"
#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/halfspace_operator.hpp"
#include "contact/normal_solver.hpp"
#include "io/contact_output.hpp"
#include "io/frequency_axis.hpp"
#include "io/noise_case.hpp"
#include "noise/bands.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/curve_state.hpp"
#include "noise/curving.hpp"
#include "noise/kalker_linear.hpp"
#include "noise/loop.hpp"
#include "noise/loop_variants.hpp"

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

template <class Vector>
std::vector<std::complex<double>> flatten(const std::vector<Vector>& v) {
  std::vector<std::complex<double>> out;
  for (const auto& m : v)
    for (int j = 0; j < m.rows(); ++j)
      for (int k = 0; k < m.cols(); ++k) out.push_back(m(j, k));
  return out;
}

// One loop variant: its force per unit roughness and its band levels under `group`.
void write_variant(io::Hdf5Writer& w, const std::string& group, const noise::LoopResult& r,
                   const noise::BandLevels& b, const std::string& what) {
  w.write(group + "/force", flatten4(r.force), {r.force.size(), 4},
          "per unit roughness: Fz, Fx, Fy (N/m), Mz (N m/m); contact frame, on the wheel; " + what);
  write_bands(w, group + "/bands", b, false);
}

// The case, its noise part and the mean state of the leading outer wheel (step 1).
// The case, its noise part and the mean state of the leading outer wheel (step 1): with profiles
// the curve contact state (src/noise/curve_state.hpp), with the Hertzian case the bogie estimate
// on the conical tread and the case's patch.
struct NoiseSetup {
  io::CaseReader reader;
  io::NoiseCase noise;
  io::ContactCase contact;
  noise::ContactPosition position;
  noise::CurvingEstimate curving;
  bool estimated = false;
  std::optional<noise::CurveContactState> state;  ///< profiles (estimate or multibody)
};

NoiseSetup prepare(const CommonOptions& o) {
  NoiseSetup s{io::CaseReader::from_file(o.case_file, o.overrides), {}, {}, {}, {}, false, {}};
  s.noise = io::read_noise_case(s.reader);
  s.contact = io::read_contact_case(s.reader);
  io::ContactCase& cc = s.contact;
  const io::NoiseCase& nc = s.noise;
  s.position = {0.0, 0.0, nc.contact_angle};
  if (cc.profiles && (nc.estimate_creepage || nc.multibody)) {
    const noise::CurveStateInput in = io::curve_state_input(s.reader, cc, nc);
    s.state = noise::curve_contact_state(in);
    s.estimated = s.state->estimated;
    s.curving = s.state->estimate;
    cc.contact_point = s.state->contact;
    cc.normal_force = s.state->normal_force;
    const auto hz = geometry::hertz_estimate(cc.contact_point, cc.normal_force, cc.material, cc.grid_options);
    cc.a = hz.a, cc.b = hz.b;
    const Eigen::Vector3d& xi = s.state->creepage;
    cc.creepage = {xi(0), xi(1), xi(2)};
    s.position = s.state->position();
  } else if (nc.estimate_creepage && nc.curve_radius > 0.0) {
    s.estimated = true;
    s.curving = noise::estimate_bogie_curving(io::bogie_curving_input(cc, nc));
    cc.creepage = {s.curving.xi_x, s.curving.xi_y, s.curving.phi};
    s.position = s.curving.position();
  }
  if (cc.profiles && !s.state)  // curve.creepage = "case": the case's contact point
    s.position = {cc.contact_point.wheel_s, cc.contact_point.rail_y, cc.contact_point.contact_angle};
  if (s.state || s.estimated) {  // the case as run records the creepage used
    std::ostringstream v;
    v.precision(12);
    v << "creepage.mean=[" << cc.creepage.xi_x << ", " << cc.creepage.xi_y << ", " << cc.creepage.phi << "]";
    s.reader = s.reader.with(v.str());
  }
  return s;
}

// The patch of the case (at the state's contact and normal force with profiles) and its normal
// contact stiffness dN/d(delta) on the frozen contact area (contact::normal_load_sensitivity).
std::unique_ptr<contact::ContactPatch> make_patch(const io::ContactCase& cc, double* stiffness) {
  auto patch = std::make_unique<contact::ContactPatch>(io::solve_case_patch(cc));
  const contact::HalfSpaceOperator op(patch->influence, contact::Problem::Normal, 0, cc.backend);
  *stiffness = contact::normal_load_sensitivity(patch->grid, op, patch->normal).stiffness();
  return patch;
}

// /noise/contact/*: the contact state the loop ran on.
void write_contact_state(io::Hdf5Writer& w, const NoiseSetup& s, double stiffness) {
  const io::ContactCase& cc = s.contact;
  w.write("/noise/contact/normal_stiffness", stiffness, "N/m");
  w.write("/noise/contact/angle", s.position.contact_angle, "rad");
  w.write("/noise/contact/position_wheel", s.position.wheel_shift_y,
          "m (wheel profile coordinate from the nominal running circle, field side > 0)");
  w.write("/noise/contact/position_rail", s.position.rail_offset_y,
          "m (rail profile coordinate from the rail's centre line, field side > 0)");
  w.write("/noise/contact/normal_force", cc.normal_force, "N");
  w.write("/noise/contact/creepage", std::vector<double>{cc.creepage.xi_x, cc.creepage.xi_y, cc.creepage.phi}, {3}, "-, -, rad/m");
  const noise::CurveContactState* st = s.state ? &*s.state : nullptr;
  w.write("/noise/contact/rolling_radius",
          st ? st->contact.rolling_radius : s.estimated ? s.curving.rolling_radius : s.noise.wheel_radius, "m");
  w.write("/noise/contact/two_point", std::vector<int>{st && st->two_point ? 1 : 0}, {}, "-");
  w.write("/noise/contact/flange_normal_force", st ? st->flange_normal_force : 0.0, "N");
  w.write("/noise/contact/flange_vertical_load", st ? st->flange_vertical_load : 0.0, "N");
  w.write("/noise/contact/flange_angle", st ? st->flange_angle : 0.0, "rad");
  if (st) {
    w.write("/noise/contact/wheel_load", st->wheel_load, "N");
    w.write("/noise/contact/load_transfer", st->load_transfer, "N");
    w.write("/noise/contact/tread_load", st->tread_load, "N (vertical)");
    w.write("/noise/contact/wheelset_lateral", st->lateral, "m");
    w.write("/noise/contact/wheelset_yaw", st->yaw, "rad");
  }
}

// The summary line of the contact state.
void print_contact_state(const NoiseSetup& s) {
  if (!s.state) return;
  const noise::CurveContactState& st = *s.state;
  std::printf("  contact (%s): u = %.2f mm, psi = %.2f mrad; on the wheel at s = %.1f mm, on the rail at %.1f mm, "
              "r = %.4f m; Q = %.1f kN + dQ %.1f kN, tread %.1f kN (N = %.1f kN); %s",
              st.estimated ? "bogie estimate" : "multibody", 1e3 * st.lateral, 1e3 * st.yaw, 1e3 * st.contact.wheel_s,
              1e3 * st.contact.rail_y, st.contact.rolling_radius, 1e-3 * st.wheel_load, 1e-3 * st.load_transfer,
              1e-3 * st.tread_load, 1e-3 * st.normal_force, st.two_point ? "two-point: flange " : "one-point\n");
  if (st.two_point)
    std::printf("%.1f kN vertical (N_f %.1f kN at %.3f rad, not coupled in the loop)\n", 1e-3 * st.flange_vertical_load,
                1e-3 * st.flange_normal_force, st.flange_angle);
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
  double kH = 0.0;
  const auto patch = make_patch(cc, &kH);
  const auto steady = contact::solve_steady_rolling(patch->influence, patch->normal.pn, cc.steady_input(), cc.tangential);
  const nss::LinearContactModel model(*patch, steady, {cc.mu, cc.speed, cc.spin_offset});
  if (freq.back() > model.nyquist_frequency())
    reader.fail("noise.band_max", "the band edge " + std::to_string(freq.back()) +
                                      " Hz is above the grid's Nyquist limit " +
                                      std::to_string(model.nyquist_frequency()) + " Hz: refine grid.nx");
  const auto creep = model.creep_coefficients(freq);
  const auto load = model.normal_load_coefficients(freq);  // g, the same Markov sweep
  const double t_contact = seconds_since(t0);

  // 3. structures once, then the loop per contact model
  const auto t1 = Clock::now();
  const noise::StructuralReceptances structures =
      noise::structural_receptances(*nc.wheel, *nc.rail, position, freq);
  const double t_structures = seconds_since(t1);
  using Baseline = io::NoiseCase::Baseline;
  noise::ContactCoefficients kalker = noise::constant_coefficients(
      noise::kalker_creep_matrix(cc.a, cc.b, G, cc.material.nu).cast<std::complex<double>>(),
      noise::LoadCoefficients::Zero(), freq.size());
  kalker.load.clear();  // Kalker's linear theory (full adhesion): g = 0
  noise::LoopVariantsInput variants_in;
  variants_in.normal_stiffness = kH;
  variants_in.speed = cc.speed;
  variants_in.normal_coupling = nc.normal_coupling;
  variants_in.model = nc.use_nss ? noise::ContactCoefficients{creep, load} : kalker;
  const Eigen::Matrix3cd f0 = model.creep_coefficients({0.0})[0];
  const noise::LoadCoefficients g0 = model.normal_load_coefficients({0.0})[0];
  if (nc.compare == Baseline::kQuasiSteady) {  // the same mean state, frequency-independent
    variants_in.baseline = noise::quasi_steady_coefficients(f0, g0, freq.size());
  } else if (nc.compare == Baseline::kKalker && nc.use_nss) {
    variants_in.baseline = kalker;
  }
  const noise::LoopVariants variants = noise::solve_loop_variants(structures, variants_in);
  const noise::LoopResult& main = variants.main;

  // 4. roughness and bands
  noise::ContactFilter filter;
  filter.model = nc.filter;
  filter.a = cc.a;
  filter.b = cc.b;
  const noise::ContactRoughness roughness(nc.wheel_roughness, nc.rail_roughness, cc.speed, filter);
  const noise::BandLevels bands = noise::band_levels(main, centres, roughness);
  const std::vector<double> rough_levels = roughness.levels(centres);
  noise::BandLevels uncoupled_bands, baseline_bands;
  std::vector<std::array<double, 4>> coupling_difference;
  if (variants.has_uncoupled()) {
    uncoupled_bands = noise::band_levels(variants.uncoupled, centres, rough_levels);
    coupling_difference = noise::force_level_difference(bands, uncoupled_bands);
  }
  if (variants.has_baseline()) baseline_bands = noise::band_levels(variants.baseline, centres, rough_levels);
  const std::string baseline_name = nc.compare == Baseline::kQuasiSteady ? "quasi_steady" : "kalker";
  const contact::TangentialForces mean_force = contact::total_forces(patch->grid, steady.px, steady.py);

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
  w.attribute("/noise", "normal_coupling", nc.normal_coupling ? "on" : "off");
  w.attribute("/noise", "compare", variants.has_baseline() ? baseline_name : "none");
  w.attribute("/noise", "band_average", "mean of |H|^2 over the narrow-band samples inside each band (docs/noise_loop.md)");
  w.write("/noise/creep/f", flatten(creep), {nf, 3, 3}, "f_jk with F~ = -f xi~ + g N~ (N, N m, N m^2), rows Fx, Fy, Mz");
  w.write("/noise/creep/g", flatten(load), {nf, 3},
          "g with F~ = -f xi~ + g N~, N~ = Fz (-, -, m) for Fx, Fy, Mz; used when normal_coupling is on");
  write_contact_state(w, setup, kH);
  if (estimated) {
    w.write("/noise/curving/radius", nc.curve_radius, "m");
    w.write("/noise/curving/attack_angle", curving.leading.attack_angle, "rad");
    w.write("/noise/curving/lateral", curving.leading.lateral, "m");
    w.write("/noise/curving/flange_force", curving.leading.flange_force, "N");
  }
  if (variants.has_uncoupled()) {
    write_variant(w, "/noise/uncoupled", variants.uncoupled, uncoupled_bands, "the same contact with g = 0");
    std::vector<double> d;
    for (const auto& x : coupling_difference) d.insert(d.end(), x.begin(), x.end());
    w.write("/noise/bands/coupling_difference", d, {centres.size(), 4},
            "dB, force band levels with minus without the normal -> tangential coupling (Fz, Fx, Fy, Mz)");
  }
  if (variants.has_baseline()) {
    write_variant(w, "/noise/" + baseline_name, variants.baseline, baseline_bands,
                  nc.compare == Baseline::kKalker ? "Kalker's steady coefficients (full adhesion, g = 0)"
                                                  : "quasi-steady contact f(0), g(0) of the same state");
    if (nc.compare == Baseline::kQuasiSteady) {
      w.write("/noise/quasi_steady/f", flatten(std::vector<Eigen::Matrix3cd>{f0}), {3, 3},
              "f(0) (N, N m, N m^2), rows Fx, Fy, Mz (the real part is used)");
      w.write("/noise/quasi_steady/g", flatten(std::vector<noise::LoadCoefficients>{g0}), {3},
              "g(0) (-, -, m) (the real part is used)");
    }
  }
  w.commit();

  std::printf("%s: %s, V = %.3g m/s; leading outer wheel: creepages (%.4g, %.4g, %.4g rad/m), "
              "contact angle %.3g rad\n",
              reader.name().c_str(),
              nc.curve_radius > 0 ? ("curve R = " + std::to_string(int(nc.curve_radius)) + " m").c_str()
                                  : "tangent track",
              cc.speed, cc.creepage.xi_x, cc.creepage.xi_y, cc.creepage.phi, position.contact_angle);
  print_contact_state(setup);
  std::printf("  contact: %d adhesion / %d slip elements; %zu frequencies in %zu bands; contact %.1f s, "
              "structures %.1f s, total %.1f s\n",
              model.adhesion_elements(), model.slip_elements(), nf, centres.size(), t_contact, t_structures,
              seconds_since(t0));
  if (!nc.notice.empty()) std::fprintf(stderr, "warning: %s\n", nc.notice.c_str());
  std::printf("  mean forces Fx %.4g N, Fy %.4g N, Mz %.4g N m, N %.4g N; g(0) = (%.4g, %.4g, %.4g m)\n", mean_force.Fx,
              mean_force.Fy, mean_force.Mz, cc.normal_force, g0(0).real(), g0(1).real(), g0(2).real());
  std::printf("  levels dB re 1 N (Mz re 1 N m), %s coupling; d* = with minus without the coupling; "
              "muFz = 20 log10|Fy_mean/N| + Fz; b* = minus the %s baseline\n",
              nc.normal_coupling && !variants_in.model.load.empty() ? "with" : "without", variants.has_baseline() ? baseline_name.c_str() : "(no)");
  std::printf("  %6s %6s %6s %6s %6s %6s | %6s %6s %6s %6s | %6s | %6s %6s\n", "band", "L_r", "Fz", "Fx", "Fy", "Mz",
              "dFz", "dFx", "dFy", "dMz", "muFz", "bFz", "bFy");
  const double mu_db = 20 * std::log10(std::abs(mean_force.Fy / cc.normal_force));
  for (size_t i = 0; i < centres.size(); ++i) {
    const auto& L = bands.force_level[i];
    std::printf("  %6.0f %6.1f %6.1f %6.1f %6.1f %6.1f |", centres[i], bands.roughness_level[i], L[0], L[1], L[2], L[3]);
    if (variants.has_uncoupled()) {
      const auto& d = coupling_difference[i];
      std::printf(" %6.1f %6.1f %6.1f %6.1f |", d[0], d[1], d[2], d[3]);
    } else {
      std::printf(" %6s %6s %6s %6s |", "-", "-", "-", "-");
    }
    if (std::isfinite(mu_db))
      std::printf(" %6.1f |", mu_db + L[0]);
    else
      std::printf(" %6s |", "-");  // no mean lateral force (e.g. tangent track)
    if (variants.has_baseline())
      std::printf(" %6.1f %6.1f\n", L[0] - baseline_bands.force_level[i][0], L[2] - baseline_bands.force_level[i][2]);
    else
      std::printf(" %6s %6s\n", "-", "-");
  }
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
  double kH = 0.0;
  const auto patch = make_patch(cc, &kH);
  const auto steady = contact::solve_steady_rolling(patch->influence, patch->normal.pn, cc.steady_input(), cc.tangential);
  std::vector<noise::Receptance4> contact_r;
  if (setup.noise.use_nss) {
    const nss::LinearContactModel model(*patch, steady, {cc.mu, cc.speed, cc.spin_offset});
    if (freq.back() > model.nyquist_frequency())
      setup.reader.fail("frequency.f_max", "above the grid's Nyquist limit " + std::to_string(model.nyquist_frequency()) + " Hz");
    const auto f = model.creep_coefficients(freq);
    contact_r = setup.noise.normal_coupling
                    ? noise::contact_receptances(freq, kH, cc.speed, f, model.normal_load_coefficients(freq))
                    : noise::contact_receptances(freq, kH, cc.speed, f);
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
