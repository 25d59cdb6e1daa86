#include "io/case_schema.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <sstream>

#include "acoustics/tsi_noise.hpp"
#include "pipeline/limits.hpp"

namespace rollnoise::io {

namespace {

// The physical ranges of the keys whose valid values include obviously unphysical ones: outside
// them a value is accepted with a warning (KeySpec::warn_min, warn_max, warn_why).
struct PhysicalRange {
  const char* key;
  double lo, hi;
  const char* why;
};
const PhysicalRange kPhysicalRanges[] = {
    {"friction.mu", 0.0, 1.0, "wheel-rail friction is about 0.1 (wet, contaminated) to 0.6 (dry, sanded)"},
    {"rolling.speed", 0.0, 150.0, "the model is for railway speeds; 150 m/s is 540 km/h"},
    {"contact.normal_force", 0.0, 250e3, "a wheel load above 250 kN is a 50 t axle load"},
    {"wheel.poisson_ratio", 0.0, 0.5, "steel's is about 0.28-0.3; a negative one is an auxetic material"},
    {"curve.cant_deficiency", -0.3, 0.3,
     "cant deficiency and excess are limited to about 0.3 m even for tilting trains (EN 13803)"},
    {"curve.cant", 0.0, 0.2, "track cant is limited to 0.16-0.2 m (EN 13803)"},
    {"curve.conicity", 0.0, 0.5, "equivalent conicities of worn and new profiles lie below about 0.5"},
    {"curve.wheel_radius", 0.2, 0.65, "railway wheels have rolling radii of about 0.3-0.6 m"},
};

// passby.category: "none" and the TSI's categories (acoustics/tsi_noise.hpp).
std::vector<std::string> passby_categories() {
  std::vector<std::string> c = {"none"};
  for (const std::string& n : acoustics::tsi_categories()) c.push_back(n);
  return c;
}

std::vector<KeySpec> with_physical_ranges(std::vector<KeySpec> schema) {
  for (const PhysicalRange& r : kPhysicalRanges)
    for (KeySpec& k : schema)
      if (k.key == r.key) k.warn_min = r.lo, k.warn_max = r.hi, k.warn_why = r.why;
  return schema;
}

}  // namespace

const std::vector<KeySpec>& case_schema() {
  using T = KeyType;
  static const std::string memory_default = [] {
    char text[40];
    std::snprintf(text, sizeof text, "%.6e", pipeline::default_memory_limit());
    return std::string(text);
  }();
  static const std::vector<KeySpec> schema = with_physical_ranges({
      // material, friction, rolling
      {"material.E", T::PositiveReal, "210e9", "Pa", "Young's modulus of wheel and rail"},
      {"material.nu", T::Real, "0.28", "-", "Poisson's ratio of wheel and rail (0 <= nu < 0.5)"},
      {"friction.mu", T::PositiveReal, "0.3", "-",
       "Coulomb friction coefficient; with friction.law = \"falling\" the static one, mu_s = mu(0)"},
      {"friction.law", T::String, "\"constant\"", "-",
       "\"constant\": mu; \"falling\": mu(v) = mu [(1 - A) exp(-B v) + A] with v the local slip "
       "speed (Polach 2005; docs/falling_friction.md)",
       {"constant", "falling"}},
      {"friction.kinetic_ratio", T::PositiveReal, "", "-",
       "falling: A = mu(inf)/mu, in (0, 1]", {}, 0, "required with friction.law = \"falling\""},
      {"friction.decay", T::Real, "", "s/m", "falling: B >= 0, the decay of mu with the slip speed", {}, 0,
       "required with friction.law = \"falling\""},
      {"rolling.speed", T::PositiveReal, "13.8888888888889", "m/s", "rolling speed V"},
      {"rolling.creepage_sampling", T::String, "\"average\"", "-",
       "how the creepage of a rolling step dt = dx/V is taken (transient solver, linear model): "
       "\"average\" its mean over [t_k - dt, t_k], as the displacement difference of paper Eq. 2 "
       "averages the displacement rate (the closest to the continuum: f11, f22 at 5 kHz within 1 % "
       "on 40 x 29); \"midstep\" at t_k - dt/2, where the difference is centred (second order); "
       "\"contact\" at t_k, CONTACT's convention (a half-step phase lead w dt/2, first order); the "
       "normal load is taken at t_k in all three",
       {"midstep", "average", "contact"}},
      // contact geometry and load
      {"contact.geometry", T::String, "\"hertz\"", "-",
       "\"hertz\": quadratic undeformed distance from the semi-axes a, b; \"profiles\": "
       "wheel and rail profiles",
       {"hertz", "profiles"}},
      {"contact.normal_force", T::PositiveReal, "", "N", "prescribed total normal force N", {}, 0,
       "required"},
      {"contact.a", T::PositiveReal, "", "m",
       "hertz: semi-axis in the rolling direction x, at contact.normal_force (fixed: another load keeps it)", {}, 0,
       "required with contact.geometry = \"hertz\" unless the radii contact.wheel_radius, contact.rail_radius "
       "are given"},
      {"contact.b", T::PositiveReal, "", "m", "hertz: lateral semi-axis y, at contact.normal_force", {}, 0,
       "required with contact.geometry = \"hertz\" unless the radii are given"},
      {"contact.wheel_radius", T::PositiveReal, "", "m",
       "hertz: the wheel's rolling radius; with contact.rail_radius (and contact.wheel_profile_radius) a and b "
       "follow from the load by Hertz theory (Johnson 1985, Sec. 4.2): h = x^2/(2 R_w) + y^2/2 (1/R_r + 1/R_p)",
       {}, 0, "optional (hertz): instead of contact.a, contact.b; requires contact.rail_radius"},
      {"contact.wheel_profile_radius", T::Real, "", "m",
       "hertz: transverse radius R_p of the wheel's profile at the contact: positive convex, negative concave "
       "(a worn, hollow tread; |R_p| must exceed contact.rail_radius)",
       {}, 0, "optional (with contact.wheel_radius): without it the tread is conical, straight across (1/R_p = 0)"},
      {"contact.rail_radius", T::PositiveReal, "", "m", "hertz: transverse radius R_r of the rail head at the contact",
       {}, 0, "optional (hertz): required with contact.wheel_radius"},
      {"contact.wheel_profile", T::String, "\"models/profiles/MBench_S1002_v3.prw\"", "-",
       "profiles: wheel profile (SIMPACK .prw or CSV y, z in mm)"},
      {"contact.rail_profile", T::String, "\"models/profiles/MBench_UIC60_v3.prr\"", "-",
       "profiles: rail profile (SIMPACK .prr or CSV y, z in mm)"},
      {"contact.lateral_displacement", T::Real, "0.0", "m", "profiles: wheelset lateral displacement"},
      {"contact.yaw", T::Real, "0.0", "rad", "profiles: wheelset yaw angle"},
      // grid
      {"grid.nx", T::Integer, "34", "-", "elements in x (rolling direction)", {}, 2},
      {"grid.ny", T::Integer, "25", "-", "elements in y (lateral)", {}, 2},
      {"grid.scale", T::PositiveReal, "1.1333333333333333", "-",
       "hertz: the potential contact area spans +-scale*a by +-scale*b (CONTACT's IPOTCN = -3); "
       "profiles: at least +-scale times the Hertz estimate (and where the gap is small)"},
      {"grid.x_min", T::Real, "", "m", "explicit grid: left edge (with x_max, y_min, y_max)", {}, 0,
       "optional (hertz): without it the grid spans +-grid.scale*a by +-grid.scale*b"},
      {"grid.x_max", T::Real, "", "m", "explicit grid: right edge", {}, 0,
       "required with grid.x_min"},
      {"grid.y_min", T::Real, "", "m", "explicit grid: lower edge", {}, 0,
       "required with grid.x_min"},
      {"grid.y_max", T::Real, "", "m", "explicit grid: upper edge", {}, 0,
       "required with grid.x_min"},
      {"grid.spin_offset", T::Real, "0.0", "-",
       "spin term of the rigid slip taken at x + spin_offset*dx: 0 = paper Eq. 21, "
       "1/6 = CONTACT's default"},
      // creepage
      {"creepage.mean", T::Real3, "[0.0, 0.0, 0.0]", "-, -, rad/m",
       "mean creepages xi_x, xi_y, phi"},
      // solver settings
      {"solver.influence", T::String, "\"auto\"", "-",
       "products A*p: \"fft\", \"dense\" or \"auto\" (by size)", {"auto", "fft", "dense"}},
      {"solver.linear_model", T::String, "\"auto\"", "-",
       "linear NSS model (creep, noise, validate): K0 by a dense Cholesky factor (\"dense\"), or "
       "applied by FFT and solved by preconditioned CG (\"matrix_free\": memory O(r x Krylov basis) "
       "instead of 8 r^2, slower where dense fits); \"auto\": dense up to 11000 reduced unknowns",
       {"auto", "dense", "matrix_free"}},
      {"solver.threads", T::Integer, "0", "-",
       "threads of the linear NSS model (creep, noise, squeal, validate): the columns of a block "
       "(FFT products, PCG solves) are shared out among them; 0 = one per hardware thread, at most 4. "
       "A noise run with several curve.wheels runs the wheels' contacts (patch, steady state, NSS "
       "model) in parallel on them instead (each model then on one), and the FE wheel's orders n "
       "too. The results do not depend on it (bit-identical)",
       {}, 0, {}, 4},
      {"solver.normal_tolerance", T::PositiveReal, "1e-12", "-",
       "normal solver: relative change of the pressure"},
      {"solver.tangential_tolerance", T::PositiveReal, "1e-12", "-",
       "tangential solvers: relative residual of the tractions"},
      {"solver.max_iterations", T::Integer, "200", "-", "tangential solver iterations", {}, 1},
      // excitation (transient / response / validate)
      {"excitation.type", T::String, "\"harmonic\"", "-", "creepage variation",
       {"none", "harmonic", "multiharmonic", "csv"}},
      {"excitation.amplitude", T::Real3, "[0.0, 0.0, 0.0]", "-, -, rad/m",
       "amplitude per creepage component (harmonic, multiharmonic)"},
      {"excitation.phase", T::Real3, "[0.0, 0.0, 0.0]", "rad",
       "harmonic: phase per component, in radians (as written to the output), within +-2 pi: "
       "amplitude cos(2 pi f t + phase)"},
      {"excitation.normal_amplitude", T::Real, "0.0", "N",
       "normal-load variation about contact.normal_force: harmonic amplitude, or multiharmonic "
       "amplitude per frequency (own seeded phases); transient only"},
      {"excitation.normal_phase", T::Real, "0.0", "rad",
       "harmonic: phase of the normal-load variation, in radians, within +-2 pi"},
      {"excitation.frequency", T::PositiveReal, "1000.0", "Hz", "harmonic: frequency"},
      {"excitation.f_min", T::PositiveReal, "100.0", "Hz", "multiharmonic: lowest frequency"},
      {"excitation.f_max", T::PositiveReal, "5000.0", "Hz", "multiharmonic: highest frequency"},
      {"excitation.count", T::Integer, "1000", "-", "multiharmonic: number of frequencies", {}, 1},
      {"excitation.seed", T::Integer, "1", "-", "multiharmonic: seed of the random phases", {}, 0, "", LONG_MAX},
      {"excitation.file", T::String, "", "-", "csv: file with columns t, xi_x, xi_y, phi and optionally dN (normal-load variation, N)", {}, 0,
       "required with excitation.type = \"csv\""},
      // transient
      {"transient.duration", T::PositiveReal, "0.01", "s", "simulated time"},
      {"transient.start", T::String, "\"steady\"", "-",
       "initial tractions: steady solution at the mean creepage, or zero", {"steady", "zero"}},
      {"transient.snapshots", T::RealList, "[]", "s", "times at which tractions are written"},
      {"transient.analysis_start", T::NonNegReal, "0.002", "s",
       "validate/response: errors and spectra use t >= analysis_start (after the start transient)"},
      // frequency axis (creep, noise, receptance)
      {"frequency.f_min", T::NonNegReal, "10.0", "Hz", "lowest frequency"},
      {"frequency.f_max", T::PositiveReal, "5000.0", "Hz", "highest frequency"},
      {"frequency.count", T::Integer, "500", "-", "number of frequencies", {}, 1},
      {"frequency.spacing", T::String, "\"log\"", "-", "frequency spacing",
       {"linear", "log", "third-octave"}},
      {"frequency.list", T::RealList, "", "Hz", "explicit list of frequencies (overrides the rest)", {},
       0, "optional: without it f_min, f_max, count and spacing give the frequencies"},
      // state-space export (statespace; docs/statespace.md)
      {"statespace.tolerance", T::PositiveReal, "1e-5", "-",
       "continuous model: the fit's order grows until its max relative error over the fitted frequencies is at most this"},
      {"statespace.max_poles", T::Integer, "60", "-", "continuous model: most poles of the fit", {}, 2},
      {"statespace.hankel_tolerance", T::PositiveReal, "1e-10", "-",
       "discrete model: Hankel singular values kept, relative to the largest"},
      // curving (noise)
      {"curve.radius", T::NonNegReal, "0.0", "m", "curve radius; 0 is tangent track"},
      {"curve.cant_deficiency", T::Real, "0.0", "m",
       "cant deficiency (positive: unbalanced force outwards); fixed whatever the speed (see curve.cant)"},
      {"curve.cant", T::Real, "", "m",
       "the track's cant D, the height difference of the rail heads; with it the cant deficiency follows from "
       "the speed: I = s V^2 / (g R) - D, s = 1.5 m (EN 13803), so that another rolling.speed gives another I",
       {}, 0, "optional (curve.radius > 0): instead of curve.cant_deficiency (both are refused)"},
      {"curve.creepage", T::String, "\"equilibrium\"", "-",
       "mean creepages and contact position: the bogie in quasi-static equilibrium on the exact contacts "
       "with its suspension ([vehicle]; contact.geometry = \"profiles\"; a Hertzian case gets the estimate), "
       "the rigid bogie's quasi-static estimate (with contact.geometry = \"profiles\" each wheel's contact "
       "state on the profiles), creepage.mean with contact.angle (hertz) or contact.lateral_displacement/yaw "
       "(profiles), or the wheelset's position from a multibody run ([wheelset])",
       {"equilibrium", "estimate", "case", "multibody"}},
      {"curve.cg_height", T::NonNegReal, "1.5", "m",
       "centre-of-gravity height above the rails for the load transfer by the cant deficiency, "
       "dQ/Q = 2 h_d h_cg / s^2 (profiles; 0: none)"},
      {"wheelset.lateral_displacement", T::Real, "0.0", "m",
       "curve.creepage = \"multibody\": lateral displacement of the wheelset towards the outer rail"},
      {"wheelset.yaw", T::Real, "0.0", "rad",
       "curve.creepage = \"multibody\": yaw angle (angle of attack, positive turning towards the outer rail)"},
      {"wheelset.wheel_load", T::PositiveReal, "", "N",
       "curve.creepage = \"multibody\": vertical load of the outer wheel's tread contact",
       {}, 0, "optional (default: contact.normal_force)"},
      {"wheelset.creepage", T::Real3, "", "-, -, rad/m",
       "curve.creepage = \"multibody\": creepages (xi_x, xi_y, phi) of the outer wheel", {}, 0,
       "optional (default: kinematic (K2) from the wheelset's position)"},
      {"wheelset.inner_wheel_load", T::PositiveReal, "", "N",
       "curve.creepage = \"multibody\": vertical load of the leading wheelset's inner wheel", {}, 0,
       "optional (default: contact.normal_force)"},
      {"wheelset.inner_creepage", T::Real3, "", "-, -, rad/m",
       "curve.creepage = \"multibody\": creepages (xi_x, xi_y, phi) of the leading inner wheel, in its "
       "own (mirrored) contact frame", {}, 0, "optional (default: kinematic (K2') from the wheelset's position)"},
      {"trailing_wheelset.lateral_displacement", T::Real, "0.0", "m",
       "curve.creepage = \"multibody\": lateral displacement of the trailing wheelset towards the outer rail"},
      {"trailing_wheelset.yaw", T::Real, "0.0", "rad",
       "curve.creepage = \"multibody\": yaw angle of the trailing wheelset (positive turning towards the outer "
       "rail)"},
      {"trailing_wheelset.wheel_load", T::PositiveReal, "", "N",
       "curve.creepage = \"multibody\": vertical load of the trailing wheelset's outer wheel", {}, 0,
       "optional (default: contact.normal_force)"},
      {"trailing_wheelset.inner_wheel_load", T::PositiveReal, "", "N",
       "curve.creepage = \"multibody\": vertical load of the trailing wheelset's inner wheel", {}, 0,
       "optional (default: contact.normal_force)"},
      {"trailing_wheelset.creepage", T::Real3, "", "-, -, rad/m",
       "curve.creepage = \"multibody\": creepages (xi_x, xi_y, phi) of the trailing outer wheel", {}, 0,
       "optional (default: kinematic (K2') from the wheelset's position)"},
      {"trailing_wheelset.inner_creepage", T::Real3, "", "-, -, rad/m",
       "curve.creepage = \"multibody\": creepages (xi_x, xi_y, phi) of the trailing inner wheel, in its own "
       "(mirrored) contact frame", {}, 0, "optional (default: kinematic (K2') from the wheelset's position)"},
      {"curve.wheels", T::StringList, "", "-",
       "profiles with curve.creepage = \"equilibrium\", \"estimate\" or \"multibody\": the wheels whose contact state is "
       "computed and written (/noise/wheels/<wheel>), each a contact of the case's one loop (coupled "
       "through wheelsets and rails with noise.contact_coupling = \"bogie\", the default)",
       {"leading_outer", "leading_inner", "trailing_outer", "trailing_inner"}, 0,
       "optional (default: all four in a curve, [\"leading_outer\"] on tangent track)"},
      {"curve.wheelbase", T::PositiveReal, "2.5", "m", "bogie wheelbase"},
      {"curve.wheel_radius", T::PositiveReal, "0.46", "m", "nominal rolling radius"},
      {"curve.conicity", T::PositiveReal, "0.15", "-", "equivalent conicity of the conical tread"},
      {"curve.flange_clearance", T::PositiveReal, "0.005", "m", "lateral play to flange contact"},
      {"contact.angle", T::Real, "0.0", "rad", "contact angle (curve.creepage = \"case\")"},
      // the bogie in equilibrium (curve.creepage = "equilibrium"; defaults: a representative passenger bogie of 2.5 m
      // wheelbase, docs/noise_loop.md Sec. 7.4)
      {"vehicle.carbody_mass", T::NonNegReal, "0.0", "kg",
       "curve.creepage = \"equilibrium\": mass of the whole car body, half of it on the bogie (0: the rest of "
       "the static load, 8 contact.normal_force / g - 2 frame - 4 wheelsets)"},
      {"vehicle.frame_mass", T::NonNegReal, "2600.0", "kg", "curve.creepage = \"equilibrium\": one bogie frame"},
      {"vehicle.wheelset_mass", T::NonNegReal, "1500.0", "kg", "curve.creepage = \"equilibrium\": one wheelset"},
      {"vehicle.primary_longitudinal_stiffness", T::NonNegReal, "12.0e6", "N/m",
       "curve.creepage = \"equilibrium\": primary suspension, longitudinal, per axlebox (the wheelset's yaw "
       "stiffness to the frame is 2 k_x b^2)"},
      {"vehicle.primary_lateral_stiffness", T::PositiveReal, "4.5e6", "N/m",
       "curve.creepage = \"equilibrium\": primary suspension, lateral, per axlebox"},
      {"vehicle.axlebox_semi_spacing", T::PositiveReal, "1.0", "m",
       "curve.creepage = \"equilibrium\": lateral distance b of the primary springs from the axle centre"},
      {"vehicle.secondary_yaw_stiffness", T::NonNegReal, "3.0e5", "N m/rad",
       "curve.creepage = \"equilibrium\": secondary suspension, yaw of the frame against the car body, per bogie"},
      {"vehicle.bogie_centre_distance", T::NonNegReal, "19.0", "m",
       "curve.creepage = \"equilibrium\": distance 2L of the bogie centres (the car body, on the chord, is "
       "turned by L/R against each bogie's tangent)"},
      {"vehicle.bogie", T::String, "\"front\"", "-",
       "curve.creepage = \"equilibrium\": which bogie of the car", {"front", "rear"}},
      // structures and roughness (noise, receptance)
      {"track.file", T::String, "\"models/track/uic60_ballasted.toml\"", "-",
       "track parameter file (relative to the case file, its parent folder or the source tree)"},
      {"track.support", T::String, "\"discrete\"", "-", "rail support model", {"discrete", "continuous"}},
      {"track.position", T::NonNegReal, "0.3", "m", "contact position from a sleeper (0.3 = mid-span)"},
      {"track.model", T::String, "\"beam\"", "-",
       "rail model: \"beam\" (Timoshenko beams, vertical and lateral) or \"waveguide\" (2.5D finite "
       "elements of the UIC60 section or track.rail_section: torsion, cross-section deformation; continuous or "
       "discrete support)",
       {"beam", "waveguide"}},
      {"track.rail_section", T::String, "", "-",
       "model = \"waveguide\": the rail's cross-section outline (CSV y_mm, z_mm: a closed polygon, z up, "
       "flat foot at the lowest z; e.g. models/rail/uic60_outline.csv)", {}, 0,
       "optional: the built-in UIC60 (60E1) outline, identical to models/rail/uic60_outline.csv"},
      {"track.sampling_cache", T::String, "\"user\"", "-",
       "model = \"waveguide\": user: keep the rail's frequency samplings at the contacts in the user's "
       "cache directory ($ROLLNOISE_CACHE_DIR, else $XDG_CACHE_HOME/rollnoise or ~/.cache/rollnoise) "
       "and read them in later runs of the same track, section, contact points and frequency lines, "
       "and build; off: compute them in every run. ROLLNOISE_CACHE_DIR=off switches it off for every case",
       {"user", "off"}},
      {"wheel.wheelset", T::String, "\"models/wheel/wheelset_920mm.toml\"", "-", "rigid wheelset file"},
      {"wheel.modes", T::String, "\"models/wheel/wheel_920mm_modes.csv\"", "-", "wheel modes file"},
      // the FE wheel (docs/models.md Sec. 3.4; dynamics/wheel_fe.hpp)
      {"wheel.model", T::String, "\"table\"", "-",
       "the wheel's flexible modes: \"table\" (wheel.modes at one contact point), \"fe\" (the "
       "axisymmetric FE modes of wheel.section) or \"shapes\" (a user's FE modes along the tread, "
       "wheel.shapes); fe and shapes take the shapes at the contact's position on the tread",
       {"table", "fe", "shapes"}},
      {"wheel.shapes", T::String, "", "-",
       "model = \"shapes\": mode shapes along the tread (CSV mode, n, frequency_Hz, damping_ratio, s_mm, "
       "r_mm, u_r, u_theta, u_z; mass-normalised; docs/interface.md)", {}, 0, "required with wheel.model = \"shapes\""},
      {"wheel.section", T::String, "\"models/wheel/wheel_920mm_section.csv\"", "-",
       "model = \"fe\": the wheel's cross-section outline (CSV r_mm, z_mm, segment)"},
      {"wheel.bore", T::String, "\"clamped\"", "-",
       "model = \"fe\": bore condition; clamped, because a rigid axle seat transmits only the n = 0, 1 "
       "resultants, so for n >= 2 the clamp is exact; n = 0, 1 come from the rigid wheelset",
       {"clamped"}},
      {"wheel.youngs_modulus", T::PositiveReal, "2.1e11", "Pa", "model = \"fe\": Young's modulus of the wheel"},
      {"wheel.poisson_ratio", T::Real, "0.3", "-", "model = \"fe\": Poisson's ratio of the wheel, in (-1, 0.5)"},
      {"wheel.density", T::PositiveReal, "7850", "kg/m^3", "model = \"fe\": density of the wheel"},
      {"wheel.mesh_size", T::PositiveReal, "0.008", "m", "model = \"fe\": target element size of the section mesh"},
      {"wheel.n_max", T::Integer, "10", "-", "model = \"fe\": highest number of nodal diameters", {}, 0, "", 50},
      {"wheel.f_max", T::PositiveReal, "6000", "Hz", "model = \"fe\": highest natural frequency kept"},
      {"wheel.mode_cache", T::String, "\"user\"", "-",
       "model = \"fe\": user: keep the modes along the tread in the user's cache directory "
       "($ROLLNOISE_CACHE_DIR, else $XDG_CACHE_HOME/rollnoise or ~/.cache/rollnoise) and read them "
       "in later runs of the same wheel (section file, material, mesh, n_max, f_max) and build; "
       "off: compute them in every run. ROLLNOISE_CACHE_DIR=off switches it off for every case",
       {"user", "off"}},
      {"wheel.damping_n0", T::PositiveReal, "1e-3", "-",
       "model = \"fe\": modal damping ratio of the n = 0 modes (Thompson 2009 Ch. 5, solid wheel)"},
      {"wheel.damping_n1", T::PositiveReal, "1e-2", "-",
       "model = \"fe\": modal damping ratio of the n = 1 modes (coupled to the axle; Thompson 2009 Ch. 5)"},
      {"wheel.damping_axial", T::PositiveReal, "1e-4", "-",
       "model = \"fe\": modal damping ratio of the axial n >= 2 modes (Thompson 2009 Ch. 5, solid wheel)"},
      {"wheel.damping_radial", T::PositiveReal, "1e-4", "-",
       "model = \"fe\": modal damping ratio of the radial n >= 2 modes (Thompson 2009 Ch. 5, solid wheel)"},
      {"wheel.damping_circumferential", T::PositiveReal, "1e-4", "-",
       "model = \"fe\": modal damping ratio of the circumferential n >= 2 modes"},
      {"wheel.rotation", T::String, "\"split\"", "-",
       "model = \"fe\": \"split\": the fixed contact sees each n >= 1 mode pair of the rotating wheel at "
       "f_n +- n Omega / 2 pi, Omega = V / r0 (Thompson 2009 Ch. 5; docs/models.md Sec. 3.4); \"none\": the wheel at rest",
       {"split", "none"}},
      {"roughness.rail", T::String, "\"iso3095\"", "-",
       "rail roughness: \"iso3095\" (EN ISO 3095:2013 limit), \"cnossos-average\" (CNOSSOS-EU average "
       "network) or a CSV file (wavelength m, level dB re 1 um)"},
      {"roughness.wheel", T::String, "\"cast-iron\"", "-",
       "wheel roughness: \"cast-iron\", \"disc-braked\" or a CSV file"},
      {"roughness.filter", T::String, "\"isotropic\"", "-", "contact filter",
       {"isotropic", "correlated", "none"}},
      {"noise.contact_model", T::String, "\"nss\"", "-",
       "tangential contact: the linear NSS model or Kalker's steady linear theory", {"nss", "kalker"}},
      {"noise.normal_coupling", T::String, "\"on\"", "-",
       "normal -> tangential friction coupling F~t = -f xi~ + g Fz in the loop (NSS model's g; Kalker's "
       "theory has g = 0); \"on\" also solves the loop without it (/noise/uncoupled)",
       {"on", "off"}},
      {"noise.contact_coupling", T::String, "\"bogie\"", "-",
       "curve.wheels: \"bogie\" couples the contacts of the case's loop (each wheel, a flange patch) "
       "through the rigid wheelsets and the rails' transfer receptances between the contact points, "
       "with any track.model; \"none\" solves each contact alone (docs/noise_loop.md Sec. 5.3)",
       {"bogie", "none"}},
      {"noise.second_patch", T::String, "\"off\"", "-",
       "\"coupled\": the flange patch of a two-point contact (the leading outer wheel at its flange) "
       "enters the bogie loop as a second contact of that wheel (noise.contact_coupling = \"bogie\"; "
       "/noise/wheels/leading_outer/patches/1, docs/noise_loop.md Sec. 7.3); \"off\": one patch per wheel",
       {"off", "coupled"}},
      {"noise.second_patch_roughness", T::String, "\"none\"", "-",
       "roughness of the second patch: \"none\" (excited only through the coupling to the tread "
       "contacts) or \"own\" (its own uncorrelated source, the case's roughness spectra with its contact "
       "filter)",
       {"none", "own"}},
      {"noise.squeal_wheelsets", T::String, "\"off\"", "-",
       "squeal: \"on\" also finds the roots of each wheelset of curve.wheels with both its contacts "
       "(/squeal/wheels; profiles: each wheel's curve state; Hertzian curve cases: each wheel's "
       "Hertz state from the bogie estimate; with noise.second_patch = \"coupled\" the flange "
       "patch too; slow: minutes, docs/squeal.md Sec. 8.2)",
       {"off", "on"}},
      {"noise.compare", T::String, "\"quasi-steady\"", "-",
       "comparison baseline: the quasi-steady contact of the same state (NSS f(0), g(0); "
       "/noise/quasi_steady), Kalker's full-adhesion coefficients (/noise/kalker) or none",
       {"quasi-steady", "kalker", "none"}},
      {"noise.compare_kalker", T::String, "", "-",
       "deprecated alias of noise.compare: \"yes\" = \"kalker\", \"no\" = \"none\"", {"yes", "no"}, 0,
       "optional (default: noise.compare decides)"},
      {"noise.band_min", T::PositiveReal, "100.0", "Hz", "lowest 1/3-octave band centre"},
      {"noise.band_max", T::PositiveReal, "5000.0", "Hz", "highest 1/3-octave band centre"},
      {"noise.points_per_band", T::Integer, "48", "-", "narrow-band frequencies per 1/3-octave band", {}, 4},
      {"noise.band_refinement", T::Integer, "6", "-",
       "levels of narrow-band lines added where the band's lines do not resolve a peak of the "
       "response (neighbouring |H|^2 differing by more than 3 dB), each level cutting such a "
       "line's cell in three; the band levels use them, the narrow-band outputs stay on the "
       "case's lines (docs/noise_loop.md Sec. 6.1); 0: off",
       {}, 0, "", 8},
      // corrugation (docs/corrugation.md; pipeline/corrugation.hpp)
      {"corrugation.wavelength_min", T::PositiveReal, "0.01", "m",
       "corrugation: the shortest rail wavelength (its frequency V / lambda within the grid's Nyquist limit)"},
      {"corrugation.wavelength_max", T::PositiveReal, "0.5", "m", "corrugation: the longest rail wavelength"},
      {"corrugation.points", T::Integer, "160", "-", "corrugation: wavelengths, log-spaced", {}, 2, "", 100000},
      {"wear.law", T::String, "\"frictional_work\"", "-",
       "corrugation: the wear law, depth rate = K x frictional power density; \"frictional_work\": K = "
       "wear.coefficient (m^3/J); \"archard\": K = wear.coefficient / (friction.mu wear.hardness) "
       "(docs/corrugation.md Sec. 3)",
       {"frictional_work", "archard"}},
      {"wear.coefficient", T::PositiveReal, "6.75e-13", "m^3/J or -",
       "corrugation: frictional_work: volume worn per dissipated energy (6.75e-13 m^3/J: mild regime, "
       "Braghin et al. 2006); archard: the dimensionless k (1e-4 mild .. 4e-3 severe, Jendel 2002; "
       "default 1e-4 with law = \"archard\")"},
      {"wear.hardness", T::PositiveReal, "2.8e9", "Pa", "corrugation: the rail's hardness H (archard)"},
      // the sound power (docs/sound.md; pipeline/sound_power.hpp)
      {"noise.sound", T::String, "\"on\"", "-",
       "the sound power of the wheels (axisymmetric BEM of the FE wheel's modes), the rails (2D BEM of "
       "the section and the response along the rail; the waveguide's deforming section wavenumber by "
       "wavenumber) and the sleepers (baffled pistons) per band, "
       "A-weighted totals and the track decay rates (/noise/sound, /track/decay_rate; docs/sound.md)",
       {"on", "off"}},
      {"sound.rail_ground", T::String, "\"free\"", "-",
       "the rail's radiation: \"free\" (the section in free field: ballast is porous and absorbs) or "
       "\"rigid\" (a reflecting plane at the foot, e.g. slab track)",
       {"free", "rigid"}},
      {"sound.sleeper_length", T::PositiveReal, "1.3", "m",
       "the radiating length of the sleeper per rail (half a 2.6 m monobloc sleeper)"},
      {"sound.sleeper_width", T::PositiveReal, "0.25", "m", "the sleeper's radiating width"},
      // the train and the pass-by (passby; docs/sound.md Sec. 6, pipeline/passby.hpp)
      {"train.vehicles", T::Integer, "1", "-",
       "passby: the number of vehicles, each train.vehicle_length long with two two-axle bogies "
       "(without [[train.vehicle]] entries)",
       {}, 1, "", 1000},
      {"train.vehicle_length", T::PositiveReal, "26.4", "m", "passby: a vehicle's length over buffers"},
      {"train.bogie_distance", T::PositiveReal, "19.0", "m",
       "passby: the distance between a vehicle's bogie centres (wheelbase < bogie_distance < vehicle_length)"},
      {"train.wheelbase", T::PositiveReal, "", "m", "passby: the bogies' wheelbase", {}, 0,
       "optional (default: curve.wheelbase, the bogie the noise run computes)"},
      {"train.vehicle", T::TableList, "", "-",
       "passby: a train of different vehicles, front to rear: [[train.vehicle]] entries, each with count "
       "(vehicles alike, default 1), length, bogie_distance and wheelbase (m; default the [train] values)",
       {}, 0, "optional: without it train.vehicles alike vehicles"},
      {"passby.distance", T::PositiveReal, "7.5", "m",
       "passby: the receiver's distance from the track centre (EN ISO 3095:2013: 7.5 m)"},
      {"passby.height", T::Real, "1.2", "m",
       "passby: the receiver's height above the top of the rail (EN ISO 3095:2013: 1.2 m)"},
      {"passby.ground", T::String, "\"reflecting\"", "-",
       "passby: the ground plane 0.3 m below the rail top: its image source added in energy (reflecting, "
       "Q = 1) or not (absorbing, Q = 0); the sleepers radiate into the half space either way",
       {"reflecting", "absorbing"}},
      {"passby.rail_directivity", T::String, "\"monopole\"", "-",
       "passby: the rails' line sources: a monopole (their vertical and lateral radiation together) "
       "or a dipole along the vertical or the lateral (one motion alone; docs/sound.md Sec. 6)",
       {"monopole", "vertical-dipole", "lateral-dipole"}},
      {"passby.time_step", T::PositiveReal, "0.01", "s",
       "passby: the step of the level history (the F time weighting's tau is 0.125 s)"},
      {"passby.category", T::String, "\"none\"", "-",
       "passby: the vehicle category whose TSI Noise limit of L_pAeq,Tp(80 km/h) is printed beside the "
       "level (Regulation (EU) No 1304/2014 Annex 4.2.3 Table 4, amended by (EU) 2019/774)",
       passby_categories()},
      // limits (pipeline/limits.hpp; docs/conventions.md, Limits)
      {"limits.memory", T::PositiveReal, memory_default, "B",
       "memory a run may use, estimated before allocating (default: half the physical memory of this machine)"},
      {"limits.steps", T::Integer, "1000000", "-",
       "the most time steps of a run, points of a sweep, or frequencies of an axis, excitation or bands",
       {}, 1, "", LONG_MAX},
  });
  return schema;
}

const KeySpec* find_key(const std::string& key) {
  for (const auto& k : case_schema())
    if (k.key == key) return &k;
  return nullptr;
}

std::string describe_schema() {
  // One block per table in the order of first appearance (the schema lists some keys next to
  // the ones they work with, e.g. contact.angle with the [curve] keys).
  std::vector<std::string> tables;
  for (const auto& k : case_schema()) {
    const std::string t = k.key.substr(0, k.key.find('.'));
    if (std::find(tables.begin(), tables.end(), t) == tables.end()) tables.push_back(t);
  }
  std::ostringstream os;
  os << "Case keys (TOML tables and keys; --set TABLE.KEY=VALUE overrides one). Each key shows\n"
        "its default, or whether it is required or optional when it has none.\n";
  for (const auto& t : tables) {
    os << "\n[" << t << "]\n";
    for (const auto& k : case_schema()) {
      if (k.key.compare(0, t.size() + 1, t + ".") != 0) continue;
      os << "  " << k.key.substr(t.size() + 1) << " = "
         << (k.default_value.empty() ? "(" + k.absent + ")" : k.default_value);
      if (k.units != "-") os << "   [" << k.units << "]";
      os << "\n      " << k.help;
      if (!k.allowed.empty()) {
        os << " (one of:";
        for (const auto& a : k.allowed) os << " \"" << a << "\"";
        os << ")";
      }
      if (k.type == KeyType::Integer) os << " (integer >= " << k.minimum << ")";
      if (!k.warn_why.empty())
        os << "; physical range [" << k.warn_min << ", " << k.warn_max << "], a warning outside";
      os << "\n";
    }
  }
  return os.str();
}

}  // namespace rollnoise::io
