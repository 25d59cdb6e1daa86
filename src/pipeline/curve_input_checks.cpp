#include "pipeline/curve_input_checks.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "geometry/wheel_rail.hpp"

namespace rollnoise::pipeline {
namespace {

// `key`: the case key that sets the field (bogie_curving_input, io/noise_case.cpp), or
// "curving.<field>" for a field no case key sets.
void positive(double v, const char* key) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(key, std::string(key) + " must be positive and finite");
}

// dQ (K4) must stay below the wheel load: the inner wheel keeps a positive load.
void check_load_transfer(double load_transfer, double wheel_load) {
  if (!std::isfinite(load_transfer) || !(std::abs(load_transfer) < wheel_load))
    throw InputError(
        "curve.cg_height",  // dQ = 2 Q h_d h_cg / s^2 (curve_state.cpp, K4)
        "the load transfer by the cant deficiency, dQ = " + std::to_string(load_transfer) +
            " N, must be finite and below the wheel load in magnitude (curve.cg_height, "
            "curve.cant_deficiency)");
}

void check_multibody(const noise::CurveStateInput& in) {
  using noise::multibody_key;
  if (!std::isfinite(in.lateral) || std::abs(in.lateral) > 0.02)
    throw InputError("wheelset.lateral_displacement",
                     "wheelset.lateral_displacement must lie within +-20 mm");
  if (!std::isfinite(in.yaw) || std::abs(in.yaw) > 0.05)
    throw InputError("wheelset.yaw", "wheelset.yaw must lie within +-0.05 rad");
  if (in.creepage && !in.creepage->allFinite())
    throw InputError("wheelset.creepage", "wheelset.creepage must be finite");
  if (!std::isfinite(in.trailing_lateral) || std::abs(in.trailing_lateral) > 0.02)
    throw InputError("trailing_wheelset.lateral_displacement",
                     "trailing_wheelset.lateral_displacement must lie within +-20 mm");
  if (!std::isfinite(in.trailing_yaw) || std::abs(in.trailing_yaw) > 0.05)
    throw InputError("trailing_wheelset.yaw", "trailing_wheelset.yaw must lie within +-0.05 rad");
  for (noise::WheelId id : noise::kAllWheels) {
    const std::string key = multibody_key(id, "wheel_load");
    const auto& q = in.wheel_loads[static_cast<std::size_t>(id)];
    if (q && (!(*q > 0.0) || !std::isfinite(*q)))
      throw InputError(key, key + " must be positive and finite");
    const auto& xi = in.wheel_creepages[static_cast<std::size_t>(id)];
    if (xi && !xi->allFinite())
      throw InputError(multibody_key(id, "creepage"),
                       multibody_key(id, "creepage") + " must be finite");
  }
}

}  // namespace

void check_flange_friction(const noise::FlangeFriction& f, const std::string& key) {
  if (f.below_nadal_limit()) return;
  char values[160];
  std::snprintf(values, sizeof values, " = %.4g: must stay below tan(delta_f) = %.4g (flange angle %.4g rad)",
                f.friction, std::tan(f.angle), f.angle);
  throw InputError(key, key + values + ", Nadal's limit, else the flange cannot carry a lateral force");
}

std::shared_ptr<const noise::ProfileCurvingTable> curving_profile_table(const noise::CurveStateInput& in) {
  try {
    return std::make_shared<const noise::ProfileCurvingTable>(
        noise::profile_curving_table(*in.pair, 0.010, in.table_step));
  } catch (const std::domain_error& e) {
    throw InputError("contact.wheel_profile",
                     std::string("the profile table of contact.wheel_profile on contact.rail_profile: ") + e.what());
  }
}

void check_curve_state_input(const noise::CurveStateInput& in) {
  if (!in.pair) throw InputError("contact.geometry", "the curve contact state needs the profiles");
  if (!(in.radius > 0.0) || std::isnan(in.radius))
    throw InputError("curve.radius", "curve.radius must be positive (inf for tangent track)");
  if (!std::isfinite(in.cant_deficiency))
    throw InputError("curve.cant_deficiency", "curve.cant_deficiency must be finite");
  if (!(in.cg_height >= 0.0) || !std::isfinite(in.cg_height))
    throw InputError("curve.cg_height", "curve.cg_height must be >= 0 and finite");
  if (!(in.wheel_load > 0.0) || !std::isfinite(in.wheel_load))
    throw InputError(in.multibody ? "wheelset.wheel_load" : "contact.normal_force",
                     "the wheel load must be positive and finite");
  if (!(in.speed > 0.0) || !std::isfinite(in.speed))
    throw InputError("rolling.speed", "rolling.speed must be positive and finite");
  if (!(in.friction > 0.0)) throw InputError("friction.mu", "friction.mu must be positive");
  if (in.multibody) return check_multibody(in);
  // the bogie estimate's inputs that come from the case (the rest from the profiles)
  positive(in.wheelbase, "curve.wheelbase");
  const double l0 =
      geometry::find_contact(*in.pair, {0.0, 0.0}).y;  // as noise::curve_contact_state
  check_load_transfer(noise::cant_deficiency_load_transfer(in.wheel_load, in.cant_deficiency,
                                                           in.cg_height, 2.0 * l0),
                      in.wheel_load);
}

void check_bogie_curving_input(const noise::BogieCurvingInput& in) {
  if (!(in.radius > 0.0) || std::isnan(in.radius))
    throw InputError("curve.radius", "curve.radius must be positive (inf for tangent track)");
  if (!(in.speed >= 0.0) || !std::isfinite(in.speed))
    throw InputError("rolling.speed", "rolling.speed must be >= 0");
  if (!std::isfinite(in.cant_deficiency))
    throw InputError("curve.cant_deficiency", "curve.cant_deficiency must be finite");
  positive(in.wheelbase, "curve.wheelbase");
  positive(in.wheel_radius, "curve.wheel_radius");
  positive(in.track_gauge, "curving.track_gauge");
  if (!(in.contact_half_distance >= 0.0))
    throw InputError("curving.contact_half_distance", "curving.contact_half_distance must be >= 0");
  if (!in.rolling_radius_difference && !in.profiles) positive(in.conicity, "curve.conicity");
  if (!std::isnan(in.contact_angle) && !(std::abs(in.contact_angle) < 0.5 * M_PI))
    throw InputError("curving.contact_angle", "curving.contact_angle must lie in (-pi/2, pi/2)");
  if (!in.profiles) positive(in.flange_clearance, "curve.flange_clearance");
  positive(in.wheel_load, "contact.normal_force");
  positive(in.friction, "friction.mu");
  check_load_transfer(in.load_transfer, in.wheel_load);
  if (!std::isnan(in.flange_angle) && !(in.flange_angle >= 0.0 && in.flange_angle < 0.5 * M_PI))
    throw InputError("curving.flange_angle", "curving.flange_angle must lie in [0, pi/2)");
  if (!std::isnan(in.flange_friction) &&
      !(in.flange_friction >= 0.0 && std::isfinite(in.flange_friction)))
    throw InputError("curving.flange_friction", "curving.flange_friction must be >= 0");
  positive(in.f11, "curving.f11");
  positive(in.f22, "curving.f22");
  // the flange friction is friction.mu unless given apart; delta_f may come from the profiles
  check_flange_friction(noise::flange_friction(in),
                        std::isnan(in.flange_friction) ? "friction.mu" : "curving.flange_friction");
}

}  // namespace rollnoise::pipeline
