#include "io/noise_output.hpp"

#include <sstream>

#include "io/contact_output.hpp"
#include "io/sound_output.hpp"
#include "nss/linear_model.hpp"
#include "vehicle/bogie_equilibrium.hpp"

namespace rollnoise::io {
namespace {

// The directions of every velocity output: the structures' own, not the contact frame's.
constexpr const char* kVelocityDirections =
    "the structures' directions, in the wheel's side frame: z vertical (the wheel's radial direction at its "
    "contact, the rail's vertical), x longitudinal, y lateral towards this wheel's field side (the wheel's axial "
    "direction, the rail's lateral), rot z about the vertical";

std::vector<double> flatten_levels(const noise::BandLevels& b) {
  std::vector<double> fl;
  for (const auto& l : b.force_level) fl.insert(fl.end(), l.begin(), l.end());
  return fl;
}

void write_bands(Hdf5Writer& w, const std::string& g, const noise::BandLevels& b, bool roughness) {
  const std::size_t nb = b.centre.size();
  std::vector<double> fl, vl;
  for (const auto& l : b.force_level) fl.insert(fl.end(), l.begin(), l.end());
  for (const auto& l : b.velocity_level)
    for (const auto& side : l) vl.insert(vl.end(), side.begin(), side.end());
  w.write(g + "/centre", b.centre, {nb}, "Hz");
  w.write(g + "/force_level", fl, {nb, 4}, "dB re 1 N (Fz, Fx, Fy), re 1 N m (Mz)");
  w.write(g + "/velocity_level", vl, {nb, 2, 4},
          std::string("dB re 1e-9 m/s (z, x, y), re 1e-9 rad/s (rot z); [wheel, rail]; ") + kVelocityDirections);
  if (roughness) {
    w.write(g + "/roughness_level", b.roughness_level, {nb}, "dB re 1 um (effective, after the contact filter)");
    w.write(g + "/lines", b.samples, {nb},
            "- (narrow-band lines the band mean used: the case's and those noise.band_refinement added)");
  }
}

std::vector<std::complex<double>> flatten4(const std::vector<noise::Vector4c>& v) {
  std::vector<std::complex<double>> out;
  for (const auto& x : v) out.insert(out.end(), {x(0), x(1), x(2), x(3)});
  return out;
}

// Row-major flattening of a list of matrices or vectors.
template <class Matrix>
std::vector<std::complex<double>> flatten(const std::vector<Matrix>& v) {
  std::vector<std::complex<double>> out;
  for (const auto& m : v)
    for (int j = 0; j < m.rows(); ++j)
      for (int k = 0; k < m.cols(); ++k) out.push_back(m(j, k));
  return out;
}

// One loop variant: its force per unit roughness and its band levels under `group`.
void write_variant(Hdf5Writer& w, const std::string& group, const noise::LoopResult& r, const noise::BandLevels& b,
                   const std::string& what) {
  w.write(group + "/force", flatten4(r.force), {r.force.size(), 4},
          "per unit roughness: Fz, Fx, Fy (N/m), Mz (N m/m); contact frame, on the wheel; " + what);
  write_bands(w, group + "/bands", b, false);
}

}  // namespace

void write_contact_state(Hdf5Writer& w, const std::string& group, const pipeline::NoiseCase& nc,
                         const pipeline::ContactCase& cc, const pipeline::CurveSetup& curve, double normal_stiffness) {
  const noise::ContactPosition& p = curve.position;
  const std::string g = group + "/";
  w.write(g + "normal_stiffness", normal_stiffness, "N/m");
  w.write(g + "angle", p.contact_angle, "rad");
  w.write(g + "position_wheel", p.wheel_shift_y,
          "m (wheel profile coordinate from the nominal running circle, field side > 0)");
  w.write(g + "position_rail", p.rail_offset_y, "m (rail profile coordinate from the rail's centre line, field side > 0)");
  w.write(g + "normal_force", cc.normal_force, "N");
  w.write(g + "creepage", std::vector<double>{cc.creepage.xi_x, cc.creepage.xi_y, cc.creepage.phi}, {3},
          "-, -, rad/m");
  const noise::CurveContactState* st = curve.state ? &*curve.state : nullptr;
  w.write(g + "rolling_radius", curve.rolling_radius(nc), "m");
  w.write(g + "two_point", std::vector<int>{st && st->two_point ? 1 : 0}, {}, "-");
  w.write(g + "flange_normal_force", st ? st->flange_normal_force : 0.0, "N");
  w.write(g + "flange_vertical_load", st ? st->flange_vertical_load : 0.0, "N");
  w.write(g + "flange_angle", st ? st->flange_angle : 0.0, "rad");
  if (st) {
    w.write(g + "wheel_load", st->wheel_load, "N");
    w.write(g + "load_transfer", st->load_transfer, "N");
    w.write(g + "tread_load", st->tread_load, "N (vertical)");
    w.write(g + "wheelset_lateral", st->lateral, "m");
    w.write(g + "wheelset_yaw", st->yaw, "rad");
    if (st->loaded) {
      const auto& f = st->loaded->force_track;
      w.write(g + "force_track", std::vector<double>{f[0], f[1], f[2]}, {3},
              "N (on the wheel: longitudinal, lateral towards the outer rail, up)");
      w.write(g + "angle_range", std::vector<double>{st->loaded->angle_min, st->loaded->angle_max},
              {2}, "rad (contact angles over the loaded patch on the curved surface)");
    }
  }
}

namespace {

// What the wheel's contact cost (docs/interface.md, /noise/wheels): its linear model's size and
// sweep, and the wall time of its contact work.
void write_contact_work(Hdf5Writer& w, const std::string& g, const pipeline::WheelNoise& wn) {
  w.write(g + "seconds", wn.seconds,
          "s (wall time of the wheel's contact state, patch, steady rolling, linear model and "
          "f, g; the wheels run concurrently)");
  const nss::LinearContactModel* model = wn.mean.model().get();
  if (!model) return;  // Kalker's coefficients (noise.contact_model = "kalker")
  w.write(g + "elements", std::vector<int>{model->adhesion_elements(), model->slip_elements()}, {2},
          "- (adhesion, slip elements of the steady state the model is linearised about)");
  w.write(g + "reduced_unknowns", std::vector<int>{model->reduced_unknowns()}, {},
          "- (r = 2 adhesion + slip: the order of the linear model's step matrix K0)");
  const nss::SweepInfo& sweep = model->sweep_info();
  w.write(
      g + "block_steps", std::vector<int>{sweep.block_steps}, {},
      "- (block Krylov steps of the frequency sweep; the exact recursion's steps where the Krylov "
      "model failed its check; 0 on the Hessenberg route)");
}

// Whether the flange of wheel `id`'s axle touches its rail on this wheel's side in the bogie's
// curving estimate (K6; the leading outer wheel's is /noise/contact/two_point): the outer wheel for
// an outer-flange contact, the inner one for an inner-flange contact; 0 without an estimate.
int wheel_two_point(const pipeline::CurveSetup& curve, noise::WheelId id) {
  if (!curve.estimated) return 0;
  const noise::AxleCurving& axle = noise::is_leading(id) ? curve.curving.leading : curve.curving.trailing;
  return axle.flange == (noise::is_outer(id) ? 1 : -1) && axle.flange_force != 0.0 ? 1 : 0;
}

void write_wheel(Hdf5Writer& w, const std::string& group, const pipeline::WheelNoise& wn) {
  const std::string g = group + "/contact/";
  w.write(g + "normal_stiffness", wn.mean.normal_stiffness(), "N/m");
  if (wn.state) {
    const noise::WheelContact& st = *wn.state;
    const geometry::LoadedContact& loaded = *st.loaded;
    w.write(g + "angle", st.contact.contact_angle, "rad");
    w.write(g + "position_wheel", st.contact.wheel_s,
            "m (wheel profile coordinate from the nominal running circle, field side > 0)");
    w.write(g + "position_rail", st.contact.rail_y,
            "m (rail profile coordinate from the rail's centre line, field side > 0)");
    w.write(g + "lateral_position", st.contact.y, "m (contact point from the track centre line, this side)");
    w.write(g + "normal_force", st.normal_force(), "N");
    w.write(g + "creepage", std::vector<double>{st.creepage(0), st.creepage(1), st.creepage(2)}, {3},
            "-, -, rad/m (the wheel's own contact frame; mirrored for an inner wheel)");
    w.write(g + "creepage_given", std::vector<int>{st.creepage_given ? 1 : 0}, {}, "-");
    w.write(g + "rolling_radius", st.contact.rolling_radius, "m");
    w.write(g + "vertical_load", st.vertical_load, "N");
    w.write(g + "wheelset_lateral", st.lateral, "m");
    w.write(g + "wheelset_yaw", st.yaw, "rad");
    w.write(g + "creep_force", std::vector<double>{loaded.creep_force[0], loaded.creep_force[1]}, {2},
            "N (on the wheel, contact frame of the curved patch at the contact point: Fx, Fy)");
    const auto f = st.force_track();
    w.write(g + "force_track", std::vector<double>{f[0], f[1], f[2]}, {3},
            "N (on the wheel: longitudinal, lateral towards the outer rail, up)");
    w.write(g + "angle_range", std::vector<double>{loaded.angle_min, loaded.angle_max}, {2},
            "rad (contact angles over the loaded patch on the curved surface)");
  } else {  // the case's one contact (no curve contact state): its placed case
    const pipeline::ContactCase& c = wn.mean.contact();
    w.write(g + "angle", wn.position.contact_angle, "rad");
    w.write(g + "normal_force", c.normal_force, "N");
    w.write(g + "creepage", std::vector<double>{c.creepage.xi_x, c.creepage.xi_y, c.creepage.phi}, {3},
            "-, -, rad/m (contact frame)");
  }
  w.write(g + "loop_mean_force", std::vector<double>{wn.mean_force.Fx, wn.mean_force.Fy, wn.mean_force.Mz}, {3},
          "N, N, N m (steady state on the loop's planar patch at N: Fx, Fy, Mz)");
  w.write(group + "/bands/force_level", flatten_levels(wn.bands), {wn.bands.centre.size(), 4},
          "dB re 1 N (Fz, Fx, Fy), re 1 N m (Mz)");
  write_contact_work(w, group + "/contact_work/", wn);
  std::vector<double> vl;
  for (const auto& l : wn.bands.velocity_level)
    for (const auto& side : l) vl.insert(vl.end(), side.begin(), side.end());
  w.write(group + "/bands/velocity_level", vl, {wn.bands.centre.size(), 2, 4},
          std::string("dB re 1e-9 m/s (z, x, y), re 1e-9 rad/s (rot z); [wheel, rail]; ") + kVelocityDirections);
}

// Contact a's response to its own roughness source (the source that drives it directly), as a
// single-contact result; empty for a contact without a source of its own (a second patch).
noise::LoopResult own_response(const noise::ContactSetLoopResult& loop, int a) {
  for (int e = 0; e < loop.sources(); ++e)
    if (loop.rho(a, e) != 0.0) return noise::contact_response(loop, a, e);
  return {};
}

// The narrow-band response of contact a on the case's lines (same layout and units as
// /noise/force, wheel_velocity, rail_velocity) under the contact's own roughness source (left out
// for a contact without one), and `force_by_source` under every source.
void write_narrow_band(Hdf5Writer& w, const std::string& group, const pipeline::NoiseResult& r, int a) {
  const std::size_t nf = r.axis.frequency.size();
  const std::string per = "per unit roughness of this contact's own source: ";
  const noise::ContactSetLoopResult& loop = r.loops.main;
  if (const noise::LoopResult x = own_response(loop, a); !x.frequency.empty()) {
    w.write(group + "/force", flatten4(x.force), {nf, 4},
            per + "Fz, Fx, Fy (N/m), Mz (N m/m); contact frame, on the wheel");
    w.write(group + "/wheel_velocity", flatten4(x.wheel_velocity), {nf, 4},
            per + "(m/s)/m, (rad/s)/m; " + kVelocityDirections);
    w.write(group + "/rail_velocity", flatten4(x.rail_velocity), {nf, 4},
            per + "(m/s)/m, (rad/s)/m; " + kVelocityDirections);
  }
  const int sources = loop.sources();
  std::vector<std::complex<double>> f;
  f.reserve(nf * static_cast<std::size_t>(sources) * 4);
  for (const Eigen::MatrixXcd& F : loop.force)
    for (int e = 0; e < sources; ++e)
      for (int i = 0; i < 4; ++i) f.push_back(F(4 * a + i, e));
  w.write(group + "/force_by_source", f, {nf, static_cast<std::size_t>(sources), 4},
          "per unit roughness of each source (/noise/wheels/sources): Fz, Fx, Fy (N/m), Mz (N m/m); "
          "contact frame, on the wheel; [frequency, source, component]");
}

}  // namespace

void write_wheels(Hdf5Writer& w, const pipeline::NoiseResult& r) {
  std::vector<std::string> sources;  // the contacts with a roughness source, in the loop's order
  int a = 0;
  for (const pipeline::WheelNoise& wn : r.wheels) {
    const std::string g = std::string("/noise/wheels/") + noise::wheel_name(wn.wheel);
    write_wheel(w, g, wn);
    w.write(g + "/contact/two_point", std::vector<int>{wheel_two_point(r.mean.curve(), wn.wheel)}, {},
            "- (1: the axle's flange touches the rail on this wheel's side, the curving estimate's two-point "
            "contact; 0 otherwise or without the estimate)");
    write_narrow_band(w, g, r, a++);
    sources.push_back(noise::wheel_name(wn.wheel));
  }
  for (const pipeline::WheelNoise& p : r.patches) {  // one second patch per wheel (the flange)
    const std::string name = std::string(noise::wheel_name(p.wheel)) + "/patches/1";
    write_wheel(w, "/noise/wheels/" + name, p);
    write_narrow_band(w, "/noise/wheels/" + name, r, a);
    if (r.loops.main.rho.row(a).cwiseAbs().maxCoeff() > 0.0) sources.push_back(name);
    w.attribute("/noise/wheels/" + name, "patch",
                "the flange patch of the two-point contact (noise.second_patch = \"coupled\", "
                "docs/noise_loop.md Sec. 7.3): its own contact frame, position on the flank, contact "
                "model at its own mean state; bands and force_by_source from the coupled loop");
    ++a;
  }
  w.write("/noise/wheels/sources", sources, "-");
  w.attribute("/noise/wheels", "loop", loop_description(r));
  w.attribute("/noise/wheels", "frames",
              "contact and creepage in each wheel's own contact frame (y_c to its field side, mirrored for "
              "the inner wheels); force_track in the track frame with the lateral component towards the "
              "outer rail");
}

std::string loop_description(const pipeline::NoiseResult& r) {
  const std::size_t n = r.wheels.size() + r.patches.size();
  std::string s;
  if (n == 1)
    s = "one contact (a loop of one contact: the wheel's and the rail's receptances at its contact and its own "
        "contact receptance; docs/noise_loop.md Sec. 5.1)";
  else if (r.coupled_contacts)
    s = "coupled (noise.contact_coupling = \"bogie\"): the " + std::to_string(n) +
        " contacts in one loop (docs/noise_loop.md Sec. 5.2-5.3: rigid wheelset between the two wheels of an axle, "
        "each rail's transfer receptance between the two axles, each contact's own contact receptance)";
  else
    s = "each contact alone (noise.contact_coupling = \"none\"; docs/noise_loop.md Sec. 5.2: its own patch, "
        "creepages and receptances at its contact, not coupled through the wheelset or the track)";
  return s + "; one uncorrelated roughness source per wheel, band levels the power sum over the sources; the "
             "top-level /noise is " + std::string(noise::wheel_name(r.reported_wheel().wheel)) + "'s answer in it";
}

namespace {

// /curving: the bogie in equilibrium (curve.creepage = "equilibrium" with the profiles; on tangent
// track every value 0), vehicle/bogie_equilibrium.hpp.
void write_curving(Hdf5Writer& w, const pipeline::CurveSetup& curve) {
  if (!curve.state || !curve.state->equilibrium) return;
  const noise::BogieEquilibrium& e = *curve.state->equilibrium;
  w.write("/curving/wheelset_lateral", std::vector<double>{e.lateral[0], e.lateral[1]}, {2},
          "m (leading, trailing wheelset; towards the outer rail, from the track centre line)");
  w.write("/curving/wheelset_yaw", std::vector<double>{e.yaw[0], e.yaw[1]}, {2},
          "rad (leading, trailing wheelset; angle of attack to the local radial, positive turning "
          "towards the outer "
          "rail)");
  w.write("/curving/bogie_lateral", e.bogie_lateral, "m (frame centre, towards the outer rail)");
  w.write("/curving/bogie_yaw", e.bogie_yaw, "rad (frame, to the track tangent at its centre)");
  w.write("/curving/residual", std::vector<double>(e.residual.begin(), e.residual.end()),
          {e.residual.size()},
          "N, N m, N m, N, N m, N m, N, N m (equilibrium equations: leading wheelset lateral, yaw, "
          "spin (torque about "
          "the axle); trailing wheelset lateral, yaw, spin; frame lateral, yaw)");
  w.write("/curving/iterations", std::vector<int>{e.iterations}, {},
          "- (Newton iterations over all continuation "
          "steps)");
  w.write("/curving/continuation_steps", std::vector<int>{e.continuation_steps}, {}, "-");
  w.write("/curving/contact_evaluations", std::vector<int>{e.contact_evaluations}, {},
          "- (axle contact-force evaluations, two wheel contacts each)");
  w.write("/curving/load_transfer", e.load_transfer, "N (dQ: outer wheels Q + dQ, inner Q - dQ)");
}

}  // namespace

CaseReader case_as_run(const CaseReader& r, const pipeline::ContactCase& c, const pipeline::CurveSetup& curve) {
  if (!curve.creepage_from_curve()) return r;
  std::ostringstream v;
  v.precision(12);
  v << "creepage.mean=[" << c.creepage.xi_x << ", " << c.creepage.xi_y << ", " << c.creepage.phi << "]";
  return r.with(v.str());
}

void write_noise(Hdf5Writer& w, const CaseReader& reader, const pipeline::NoiseCase& nc,
                 const pipeline::NoiseResult& r) {
  using Baseline = pipeline::NoiseCase::Baseline;
  const pipeline::WheelNoise& wn = r.reported_wheel();
  const int a = static_cast<int>(r.reported);
  write_mean_state(w, case_as_run(reader, r.mean.contact(), r.mean.curve()), r.mean.patch(), r.mean.contact().creepage,
                   r.mean.steady());
  const std::vector<double>& freq = r.axis.frequency;
  const std::size_t nf = freq.size();
  const std::string own = "per unit roughness of the wheel's own source: ";
  const noise::LoopResult main = own_response(r.loops.main, a);
  w.write("/noise/frequency", freq, {nf}, "Hz");
  w.write("/noise/force", flatten4(main.force), {nf, 4},
          own + "Fz, Fx, Fy (N/m), Mz (N m/m); contact frame, on the wheel");
  w.write("/noise/wheel_velocity", flatten4(main.wheel_velocity), {nf, 4},
          own + "(m/s)/m, (rad/s)/m; " + kVelocityDirections);
  w.write("/noise/rail_velocity", flatten4(main.rail_velocity), {nf, 4},
          own + "(m/s)/m, (rad/s)/m; " + kVelocityDirections);
  write_bands(w, "/noise/bands", wn.bands, true);
  w.attribute("/noise", "wheel", noise::wheel_name(wn.wheel));
  w.attribute("/noise", "loop", loop_description(r));
  w.attribute("/noise", "contact_model", nc.use_nss ? "linear NSS model" : "Kalker's steady linear theory");
  w.attribute("/noise", "normal_coupling", nc.normal_coupling ? "on" : "off");
  w.attribute("/noise", "compare", r.loops.has_baseline() ? r.baseline_name : "none");
  w.attribute("/noise", "band_average",
              r.refined ? "mean of |H|^2 over the narrow-band lines inside each band: the case's (/noise/frequency) and "
                          "those added where they did not resolve a peak (noise.band_refinement; docs/noise_loop.md Sec. 6.1)"
                        : "mean of |H|^2 over the narrow-band samples inside each band (docs/noise_loop.md Sec. 6)");
  w.attribute("/noise", "band_lines_added", static_cast<std::uint64_t>(r.refined ? r.refined->added_lines : 0));
  w.write("/noise/creep/f", flatten(r.creep), {nf, 3, 3}, "f_jk with F~ = -f xi~ + g N~ (N, N m, N m^2), rows Fx, Fy, Mz");
  w.write("/noise/creep/g", flatten(r.load), {nf, 3},
          "g with F~ = -f xi~ + g N~, N~ = Fz (-, -, m) for Fx, Fy, Mz; used when normal_coupling is on");
  write_contact_state(w, "/noise/contact", nc, r.mean.contact(), r.mean.curve(), r.mean.normal_stiffness());
  write_wheels(w, r);
  write_sound(w, r);
  write_curving(w, r.mean.curve());
  if (r.mean.curve().estimated) {
    w.write("/noise/curving/radius", nc.curve_radius, "m");
    w.write("/noise/curving/attack_angle", r.mean.curve().curving.leading.attack_angle, "rad");
    w.write("/noise/curving/lateral", r.mean.curve().curving.leading.lateral, "m");
    w.write("/noise/curving/flange_force", r.mean.curve().curving.leading.flange_force, "N");
  }
  if (r.loops.has_uncoupled()) {
    write_variant(w, "/noise/uncoupled", own_response(r.loops.uncoupled, a), wn.uncoupled_bands,
                  "the same contacts with g = 0");
    std::vector<double> d;
    for (const auto& x : noise::force_level_difference(wn.bands, wn.uncoupled_bands)) d.insert(d.end(), x.begin(), x.end());
    w.write("/noise/bands/coupling_difference", d, {r.axis.centres.size(), 4},
            "dB, force band levels with minus without the normal -> tangential coupling (Fz, Fx, Fy, Mz)");
  }
  if (r.loops.has_baseline()) {
    write_variant(w, "/noise/" + r.baseline_name, own_response(r.loops.baseline, a), wn.baseline_bands,
                  nc.compare == Baseline::kKalker ? "Kalker's steady coefficients (full adhesion, g = 0)"
                                                  : "quasi-steady contact f(0), g(0) of the same state");
    if (nc.compare == Baseline::kQuasiSteady) {
      w.write("/noise/quasi_steady/f", flatten(std::vector<Eigen::Matrix3cd>{r.f0}), {3, 3},
              "f(0) (N, N m, N m^2), rows Fx, Fy, Mz (the real part is used)");
      w.write("/noise/quasi_steady/g", flatten(std::vector<noise::LoadCoefficients>{r.g0}), {3},
              "g(0) (-, -, m) (the real part is used)");
    }
  }
}

void write_receptance(Hdf5Writer& w, const CaseReader& reader, const pipeline::ReceptanceResult& r) {
  const std::string units =
      "m/N, m/(N m), rad/N, rad/(N m); order normal, x, y, rotation about the normal (contact frame)";
  write_mean_state(w, case_as_run(reader, r.mean.contact(), r.mean.curve()), r.mean.patch(), r.mean.contact().creepage,
                   r.mean.steady());
  const std::size_t nf = r.frequency.size();
  w.write("/receptance/frequency", r.frequency, {nf}, "Hz");
  w.write("/receptance/wheel", flatten(r.structures.wheel_contact), {nf, 4, 4}, units);
  w.write("/receptance/rail", flatten(r.structures.rail_contact), {nf, 4, 4}, units);
  w.write("/receptance/contact", flatten(r.contact_receptance), {nf, 4, 4}, units);
}

}  // namespace rollnoise::io
