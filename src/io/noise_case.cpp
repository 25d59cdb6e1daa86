#include "io/noise_case.hpp"

#include <filesystem>
#include <limits>

#include "core/errors.hpp"
#include "io/roughness_file.hpp"
#include "io/track_file.hpp"
#include "io/wheel_file.hpp"
#include "noise/kalker_linear.hpp"


namespace rollnoise::io {

namespace {

noise::RoughnessSpectrum roughness(const CaseReader& r, const std::string& key) {
  const std::string v = r.string(key);
  if (v == "iso3095") return noise::iso3095_2013_rail_limit();
  if (v == "cast-iron") return noise::wheel_roughness_cast_iron_block();
  if (v == "disc-braked") return noise::wheel_roughness_disc_braked();
  return read_roughness_csv(resolve_model_file(r, key));
}

}  // namespace

NoiseCase read_noise_case(const CaseReader& r) {
  NoiseCase c;
  c.curve_radius = r.real("curve.radius");
  c.cant_deficiency = r.real("curve.cant_deficiency");
  c.estimate_creepage = r.string("curve.creepage") == "estimate";
  c.multibody = r.string("curve.creepage") == "multibody";
  c.cg_height = r.real("curve.cg_height");
  if (c.multibody && r.string("contact.geometry") != "profiles")
    r.fail("curve.creepage", "\"multibody\" needs contact.geometry = \"profiles\"");
  for (const char* key : {"wheelset.lateral_displacement", "wheelset.yaw", "wheelset.wheel_load", "wheelset.creepage"})
    if (r.has(key) && !c.multibody) r.fail(key, "only used with curve.creepage = \"multibody\"");
  if (r.string("contact.geometry") == "profiles" && r.string("curve.creepage") != "case")
    for (const char* key : {"contact.lateral_displacement", "contact.yaw", "creepage.mean"})
      if (r.has(key))
        r.fail(key, "the curve contact state sets it (curve.creepage = \"case\" to give it, or "
                    "\"multibody\" with [wheelset])");
  c.wheelbase = r.real("curve.wheelbase");
  c.wheel_radius = r.real("curve.wheel_radius");
  c.conicity = r.real("curve.conicity");
  c.flange_clearance = r.real("curve.flange_clearance");
  c.contact_angle = r.real("contact.angle");
  if (c.curve_radius > 0.0 && c.curve_radius < 50.0) r.fail("curve.radius", "below 50 m is outside the curving estimate's range");

  const dynamics::TrackParameters track = read_track_parameters(resolve_model_file(r, "track.file"));
  const bool discrete = r.string("track.support") == "discrete";
  c.rail = std::make_unique<dynamics::RailModel>(
      track, discrete ? dynamics::TrackSupport::kDiscrete : dynamics::TrackSupport::kContinuous,
      r.real("track.position"));
  c.wheel = std::make_unique<dynamics::WheelModel>(
      read_wheelset(resolve_model_file(r, "wheel.wheelset")),
      read_wheel_modes(resolve_model_file(r, "wheel.modes")));
  c.rail_roughness = roughness(r, "roughness.rail");
  c.wheel_roughness = roughness(r, "roughness.wheel");
  const std::string filter = r.string("roughness.filter");
  c.filter = filter == "none"         ? noise::ContactFilterModel::kNone
             : filter == "correlated" ? noise::ContactFilterModel::kCorrelated
                                      : noise::ContactFilterModel::kIsotropic;
  c.use_nss = r.string("noise.contact_model") == "nss";
  c.normal_coupling = r.string("noise.normal_coupling") == "on";
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
  c.band_min = r.real("noise.band_min");
  c.band_max = r.real("noise.band_max");
  if (c.band_max < c.band_min) r.fail("noise.band_max", "must not be below noise.band_min");
  c.points_per_band = static_cast<int>(r.integer("noise.points_per_band"));
  return c;
}

noise::CurveStateInput curve_state_input(const CaseReader& r, const ContactCase& contact,
                                         const NoiseCase& noise) {
  noise::CurveStateInput in;
  in.pair = contact.profiles;
  in.material = contact.material;
  in.grid = contact.grid_options;
  in.radius = noise.curve_radius > 0.0 ? noise.curve_radius : std::numeric_limits<double>::infinity();
  in.speed = contact.speed;
  in.cant_deficiency = noise.cant_deficiency;
  in.wheelbase = noise.wheelbase;
  in.cg_height = noise.cg_height;
  in.wheel_load = contact.normal_force;
  in.friction = contact.mu;
  in.multibody = noise.multibody;
  if (noise.multibody) {
    in.lateral = r.real("wheelset.lateral_displacement");
    in.yaw = r.real("wheelset.yaw");
    if (r.has("wheelset.wheel_load")) in.wheel_load = r.real("wheelset.wheel_load");
    if (r.has("wheelset.creepage")) {
      const auto c = r.real3("wheelset.creepage");
      in.creepage = Eigen::Vector3d(c[0], c[1], c[2]);
    }
  }
  try {
    in.validate();
  } catch (const InputError& e) {
    r.fail(e.key(), e.what());
  }
  return in;
}

noise::BogieCurvingInput bogie_curving_input(const ContactCase& contact, const NoiseCase& noise) {
  const Eigen::Matrix3d fk =
      noise::kalker_creep_matrix(contact.a, contact.b, contact.material.shear_modulus(), contact.material.nu);
  noise::BogieCurvingInput in;
  in.radius = noise.curve_radius;
  in.speed = contact.speed;
  in.cant_deficiency = noise.cant_deficiency;
  in.wheelbase = noise.wheelbase;
  in.wheel_radius = noise.wheel_radius;
  in.conicity = noise.conicity;
  in.flange_clearance = noise.flange_clearance;
  in.wheel_load = contact.normal_force;
  in.friction = contact.mu;
  in.f11 = fk(0, 0);
  in.f22 = fk(1, 1);
  return in;
}

}  // namespace rollnoise::io
