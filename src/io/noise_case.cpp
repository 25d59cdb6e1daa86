#include "io/noise_case.hpp"

#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>

#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "dynamics/beam_rail_model.hpp"
#include "dynamics/waveguide_discrete_support.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "io/cache_files.hpp"
#include "io/frequency_axis.hpp"
#include "io/radiation_cache.hpp"
#include "io/rail_sampling_cache.hpp"
#include "io/rail_section_file.hpp"
#include "io/roughness_file.hpp"
#include "io/sound_case.hpp"
#include "io/track_file.hpp"
#include "io/wheel_fe_case.hpp"
#include "io/wheel_file.hpp"
#include "vehicle/cant.hpp"

namespace rollnoise::io {

namespace {

noise::RoughnessSpectrum roughness(const CaseReader& r, const std::string& key) {
  const std::string v = r.string(key);
  if (v == "iso3095") return noise::iso3095_2013_rail_limit();
  if (v == "cnossos-average") return noise::rail_roughness_cnossos_average();
  if (v == "cast-iron") return noise::wheel_roughness_cast_iron_block();
  if (v == "disc-braked") return noise::wheel_roughness_disc_braked();
  return read_roughness_csv(resolve_model_file(r, key));
}

const std::vector<std::string>& vehicle_keys() {
  static const std::vector<std::string> keys = {"vehicle.carbody_mass",
                                                "vehicle.frame_mass",
                                                "vehicle.wheelset_mass",
                                                "vehicle.primary_longitudinal_stiffness",
                                                "vehicle.primary_lateral_stiffness",
                                                "vehicle.axlebox_semi_spacing",
                                                "vehicle.secondary_yaw_stiffness",
                                                "vehicle.bogie_centre_distance",
                                                "vehicle.bogie"};
  return keys;
}

// [vehicle] (curve.creepage = "equilibrium"): the bogie's masses, suspension and geometry; a car
// body mass of 0 is the rest of the static load, 8 Q / g - 2 m_f - 4 m_w (InputError naming
// vehicle.carbody_mass when the frames and wheelsets alone weigh more).
noise::VehicleParameters read_vehicle(const CaseReader& r) {
  noise::VehicleParameters v;
  v.frame_mass = r.real("vehicle.frame_mass");
  v.wheelset_mass = r.real("vehicle.wheelset_mass");
  v.carbody_mass = r.real("vehicle.carbody_mass");
  if (v.carbody_mass == 0.0 && r.has("contact.normal_force")) {
    v.carbody_mass = 8.0 * r.real("contact.normal_force") / noise::kGravity - 2.0 * v.frame_mass -
                     4.0 * v.wheelset_mass;
    if (!(v.carbody_mass > 0.0))
      r.fail("vehicle.carbody_mass",
             "the frames and wheelsets weigh more than the static load "
             "8 contact.normal_force / g: give the car body's mass");
  }
  v.primary_longitudinal_stiffness = r.real("vehicle.primary_longitudinal_stiffness");
  v.primary_lateral_stiffness = r.real("vehicle.primary_lateral_stiffness");
  v.axlebox_semi_spacing = r.real("vehicle.axlebox_semi_spacing");
  v.secondary_yaw_stiffness = r.real("vehicle.secondary_yaw_stiffness");
  v.bogie_centre_distance = r.real("vehicle.bogie_centre_distance");
  v.rear_bogie = r.string("vehicle.bogie") == "rear";
  return v;
}

// curve.creepage and the keys it admits or excludes: [wheelset], [trailing_wheelset] with
// "multibody", curve.wheels with the profiles, the case's own contact state with "case".
void read_curve_creepage_mode(const CaseReader& r, NoiseCase& c) {
  const std::string mode = r.string("curve.creepage");
  c.equilibrium = mode == "equilibrium";
  c.estimate_creepage = mode == "estimate" || c.equilibrium;
  c.multibody = mode == "multibody";
  for (const std::string& key : vehicle_keys())
    if (r.has(key) && !c.equilibrium)
      r.fail(key, "only used with curve.creepage = \"equilibrium\"");
  if (c.multibody && r.string("contact.geometry") != "profiles")
    r.fail("curve.creepage", "\"multibody\" needs contact.geometry = \"profiles\"");
  for (const char* key :
       {"wheelset.lateral_displacement", "wheelset.yaw", "wheelset.wheel_load", "wheelset.creepage",
        "wheelset.inner_wheel_load", "wheelset.inner_creepage",
        "trailing_wheelset.lateral_displacement", "trailing_wheelset.yaw",
        "trailing_wheelset.wheel_load", "trailing_wheelset.inner_wheel_load",
        "trailing_wheelset.creepage", "trailing_wheelset.inner_creepage"})
    if (r.has(key) && !c.multibody) r.fail(key, "only used with curve.creepage = \"multibody\"");
  if (r.has("curve.wheels")) {
    if (r.string("contact.geometry") != "profiles" || r.string("curve.creepage") == "case")
      r.fail("curve.wheels",
             "needs contact.geometry = \"profiles\" and curve.creepage = \"equilibrium\", "
             "\"estimate\" or "
             "\"multibody\"");
    c.wheels = r.string_list("curve.wheels");
    if (c.wheels.empty()) r.fail("curve.wheels", "names no wheel");
    for (std::size_t i = 0; i < c.wheels.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (c.wheels[i] == c.wheels[j])
          r.fail("curve.wheels", "names \"" + c.wheels[i] + "\" twice");
  }
  if (r.string("contact.geometry") == "profiles" && r.string("curve.creepage") != "case")
    for (const char* key : {"contact.lateral_displacement", "contact.yaw", "creepage.mean"})
      if (r.has(key))
        r.fail(key,
               "the curve contact state sets it (curve.creepage = \"case\" to give it, or "
               "\"multibody\" with [wheelset])");
}

// The multibody contact state of the bogie's wheelsets (curve.creepage = "multibody"): positions,
// and per wheel its load and creepage where given.
void read_multibody_wheelsets(const CaseReader& r, NoiseCase& c) {
  c.wheelset_lateral = r.real("wheelset.lateral_displacement");
  c.wheelset_yaw = r.real("wheelset.yaw");
  if (r.has("wheelset.wheel_load")) c.wheelset_load = r.real("wheelset.wheel_load");
  if (r.has("wheelset.creepage")) {
    const auto xi = r.real3("wheelset.creepage");
    c.wheelset_creepage = Eigen::Vector3d(xi[0], xi[1], xi[2]);
  }
  c.trailing_lateral = r.real("trailing_wheelset.lateral_displacement");
  c.trailing_yaw = r.real("trailing_wheelset.yaw");
  // per wheel, in the order of noise::WheelId (leading outer/inner, trailing outer/inner)
  const char* loads[4] = {nullptr, "wheelset.inner_wheel_load", "trailing_wheelset.wheel_load",
                          "trailing_wheelset.inner_wheel_load"};
  const char* creeps[4] = {nullptr, "wheelset.inner_creepage", "trailing_wheelset.creepage",
                           "trailing_wheelset.inner_creepage"};
  for (int k = 1; k < 4; ++k) {
    if (r.has(loads[k])) c.wheel_loads[k] = r.real(loads[k]);
    if (r.has(creeps[k])) {
      const auto xi = r.real3(creeps[k]);
      c.wheel_creepages[k] = Eigen::Vector3d(xi[0], xi[1], xi[2]);
    }
  }
}

// curve.cant_deficiency, or from curve.cant and the speed (vehicle/cant.hpp, EN 13803), so that a
// study of the speed on a canted curve varies the deficiency; giving both is refused.
double read_cant_deficiency(const CaseReader& r) {
  if (!r.has("curve.cant")) return r.real("curve.cant_deficiency");
  if (r.has("curve.cant_deficiency"))
    r.fail("curve.cant_deficiency",
           "give either curve.cant (the deficiency then follows from rolling.speed and curve.radius) or "
           "curve.cant_deficiency, not both");
  const double cant = r.real("curve.cant"), radius = r.real("curve.radius");
  if (!(radius > 0.0)) r.fail("curve.cant", "applies to a curve (curve.radius > 0), not to tangent track");
  return noise::cant_deficiency_from_cant(r.real("rolling.speed"), radius, cant);
}

// [curve]: radius, cant deficiency, the curve creepage state and the bogie's parameters.
void read_curve(const CaseReader& r, InputProblems& problems, NoiseCase& c) {
  problems.check([&] {
    c.curve_radius = r.real("curve.radius");
    if (c.curve_radius > 0.0 && c.curve_radius < 50.0)
      r.fail("curve.radius", "below 50 m is outside the curving estimate's range");
  });
  problems.check([&] { c.cant_deficiency = read_cant_deficiency(r); });
  problems.check([&] { c.cg_height = r.real("curve.cg_height"); });
  problems.check([&] {
    read_curve_creepage_mode(r, c);
    if (c.multibody) read_multibody_wheelsets(r, c);
    if (c.equilibrium) c.vehicle = read_vehicle(r);
  });
  problems.check([&] { c.wheelbase = r.real("curve.wheelbase"); });
  problems.check([&] { c.wheel_radius = r.real("curve.wheel_radius"); });
  problems.check([&] { c.conicity = r.real("curve.conicity"); });
  problems.check([&] { c.flange_clearance = r.real("curve.flange_clearance"); });
  problems.check([&] { c.contact_angle = r.real("contact.angle"); });
}

// [track]: the rail model (beams or waveguide, continuous or discrete support); its identity keys
// the rail's cached tables.
void read_track(const CaseReader& r, NoiseCase& c) {
  std::string track_section;
  const std::string file = resolve_model_file(r, "track.file");
  const dynamics::TrackParameters track = read_track_parameters(file);
  const std::string support = r.string("track.support");
  const double position = r.real("track.position");
  const std::string model = r.string("track.model");
  for (const char* key : {"track.rail_section", "track.sampling_cache"})
    if (model != "waveguide" && r.has(key))
      r.fail(key, "applies to track.model = \"waveguide\" only");
  if (model == "waveguide") {
    dynamics::WaveguideRailOptions o = waveguide_rail_options(r, track_section);
    // the samplings kept between runs (io/rail_sampling_cache.hpp)
    if (r.string("track.sampling_cache") == "user")
      if (const std::optional<std::string> directory = cache_directory()) {
        const std::string section =
            r.has("track.rail_section") ? resolve_model_file(r, "track.rail_section") : "";
        o.archive_identity = rail_sampling_identity(file, section, position);
        if (!o.archive_identity.empty())
          o.archive = std::make_shared<const RailSamplingCache>(*directory);
      }
    // the sampling's direct frequencies on the case's threads (not in the id: the values do not
    // depend on them)
    o.sampling.threads = resolved_threads(static_cast<int>(r.integer("solver.threads")));
    if (support == "discrete")
      c.rail = std::make_unique<dynamics::DiscreteWaveguideRailModel>(track, o, position);
    else
      c.rail = std::make_unique<dynamics::WaveguideRailModel>(track, o);
  } else {
    c.rail = std::make_unique<dynamics::BeamRailModel>(track,
                                                       support == "discrete"
                                                           ? dynamics::TrackSupport::kDiscrete
                                                           : dynamics::TrackSupport::kContinuous,
                                                       position);
  }
  char pos[32];
  std::snprintf(pos, sizeof pos, "%.17g", position);
  const std::string id =
      "track " + file + ", " + model + ", " + support + ", " + pos + track_section;
  // the rail's response along its length for the sound power, kept in the cache under the track's
  // values (io/radiation_cache.hpp)
  const std::string identity = rail_identity(id, track);
  c.sound.rail_line_table = [identity](const dynamics::RailModel& rail,
                                       const std::vector<double>& positions,
                                       const std::vector<double>& grid, int gauss, int threads) {
    return rail_line_gram_cached(rail, identity, positions, grid, gauss, threads);
  };
  c.sound.section_gram_table = [identity](const dynamics::RailModel& rail,
                                          const std::vector<dynamics::RailLoadPoint>& points,
                                          const pipeline::SectionRadiationTable& table,
                                          const std::vector<double>& grid,
                                          const acoustics::Fluid& fluid, int threads) {
    return section_grams_cached(rail, identity, points, table, grid, fluid, threads);
  };
}

// [wheel]: the FE wheel or the wheelset with a mode table.
void read_wheel(const CaseReader& r, InputProblems& problems, NoiseCase& c,
                std::optional<WheelFeCase>& fe) {
  const std::string wheelset = resolve_model_file(r, "wheel.wheelset");
  if ((fe = read_wheel_fe_case(r, problems))) {  // [wheel] model = "fe" (io/wheel_fe_case.hpp)
    c.wheel =
        std::make_unique<dynamics::WheelModel>(fe_wheel_model(*fe, read_wheelset(wheelset)));
    return;
  }
  const std::string modes = resolve_model_file(r, "wheel.modes");
  c.wheel =
      std::make_unique<dynamics::WheelModel>(read_wheelset(wheelset), read_wheel_modes(modes));
}

// [roughness] and [noise]: the spectra, the contact filter, the loop's options and the bands.
void read_roughness_and_loop(const CaseReader& r, InputProblems& problems, NoiseCase& c) {
  problems.check([&] { c.rail_roughness = roughness(r, "roughness.rail"); });
  problems.check([&] { c.wheel_roughness = roughness(r, "roughness.wheel"); });
  problems.check([&] {
    const std::string filter = r.string("roughness.filter");
    c.filter = filter == "none"         ? noise::ContactFilterModel::kNone
               : filter == "correlated" ? noise::ContactFilterModel::kCorrelated
                                        : noise::ContactFilterModel::kIsotropic;
  });
  problems.check([&] { c.use_nss = r.string("noise.contact_model") == "nss"; });
  problems.check([&] { c.normal_coupling = r.string("noise.normal_coupling") == "on"; });
  problems.check([&] { c.squeal_wheelsets = r.string("noise.squeal_wheelsets") == "on"; });
  problems.check([&] {
    c.second_patch = r.string("noise.second_patch") == "coupled";
    if (c.second_patch && r.string("noise.contact_coupling") == "none")
      r.fail("noise.second_patch",
             "a second patch is a contact of the bogie loop: \"coupled\" needs "
             "noise.contact_coupling = \"bogie\"");
  });
  problems.check(
      [&] { c.second_patch_roughness = r.string("noise.second_patch_roughness") == "own"; });
  problems.check([&] {
    c.contact_coupling = r.string("noise.contact_coupling") == "none"
                             ? pipeline::NoiseCase::ContactCoupling::kNone
                             : pipeline::NoiseCase::ContactCoupling::kBogie;
  });
  problems.check([&] {
    const std::string compare = r.string("noise.compare");
    c.compare = compare == "kalker" ? NoiseCase::Baseline::kKalker
                : compare == "none" ? NoiseCase::Baseline::kNone
                                    : NoiseCase::Baseline::kQuasiSteady;
    if (r.has("noise.compare_kalker")) {  // deprecated alias: "yes" -> "kalker", "no" -> "none"
      const std::string mapped = r.string("noise.compare_kalker") == "yes" ? "kalker" : "none";
      if (r.has("noise.compare") && compare != mapped)
        r.fail("noise.compare_kalker", "deprecated alias of noise.compare = \"" + mapped +
                                           "\" contradicts noise.compare = \"" + compare +
                                           "\"; remove it");
      c.compare = mapped == "kalker" ? NoiseCase::Baseline::kKalker : NoiseCase::Baseline::kNone;
      c.notice = "noise.compare_kalker is deprecated: read as noise.compare = \"" + mapped + "\"";
    }
  });
  problems.check([&] {
    c.band_min = r.real("noise.band_min");
    c.band_max = r.real("noise.band_max");
    if (c.band_max < c.band_min) r.fail("noise.band_max", "must not be below noise.band_min");
  });
  problems.check([&] { c.points_per_band = static_cast<int>(r.integer("noise.points_per_band")); });
  problems.check([&] { c.band_refinement = static_cast<int>(r.integer("noise.band_refinement")); });
}

}  // namespace

NoiseCase read_noise_case(const CaseReader& r, InputProblems& problems) {
  NoiseCase c;
  read_curve(r, problems, c);
  problems.check([&] { read_track(r, c); });
  std::optional<WheelFeCase> fe;
  problems.check([&] { read_wheel(r, problems, c, fe); });
  read_roughness_and_loop(r, problems, c);
  problems.check([&] {
    const std::vector<Eigen::Vector2d> section =
        r.has("track.rail_section") ? read_rail_section(resolve_model_file(r, "track.rail_section"))
                                    : std::vector<Eigen::Vector2d>{};
    // read_track's (the track's identity)
    auto line_table = std::move(c.sound.rail_line_table);
    auto section_grams = std::move(c.sound.section_gram_table);
    c.sound = read_sound_case(r, problems, fe, section);
    c.sound.rail_line_table = std::move(line_table);
    c.sound.section_gram_table = std::move(section_grams);
  });
  return c;
}

}  // namespace rollnoise::io

namespace rollnoise::io {

NoiseInputs read_noise_inputs(const CaseReader& r, std::vector<double>* freq) {
  InputProblems problems;
  NoiseInputs in;
  if (freq) problems.check([&] { *freq = read_frequency_axis(r); });
  in.contact = read_contact_case(r, problems);
  in.noise = read_noise_case(r, problems);
  problems.throw_if_any();
  return in;
}

}  // namespace rollnoise::io
