#include "pipeline/curve_setup.hpp"

#include <limits>
#include <string>

#include "core/errors.hpp"

#include "noise/kalker_linear.hpp"
#include "pipeline/curve_input_checks.hpp"

namespace rollnoise::pipeline {

double CurveSetup::rolling_radius(const NoiseCase& nc) const {
  return state ? state->contact.rolling_radius : estimated ? curving.rolling_radius : nc.wheel_radius;
}

noise::CurveStateInput curve_state_input(const ContactCase& c, const NoiseCase& nc) {
  noise::CurveStateInput in;
  in.pair = c.profiles;
  in.material = c.material;
  in.grid = c.grid_options;
  in.radius = nc.curve_radius > 0.0 ? nc.curve_radius : std::numeric_limits<double>::infinity();
  in.speed = c.speed;
  in.cant_deficiency = nc.cant_deficiency;
  in.wheelbase = nc.wheelbase;
  in.cg_height = nc.cg_height;
  in.wheel_load = c.normal_force;
  in.friction = c.mu;
  in.spin_offset = c.spin_offset;
  in.multibody = nc.multibody;
  in.equilibrium = nc.equilibrium;
  in.vehicle = nc.vehicle;
  if (nc.multibody) {
    in.lateral = nc.wheelset_lateral;
    in.yaw = nc.wheelset_yaw;
    if (nc.wheelset_load) in.wheel_load = *nc.wheelset_load;
    in.creepage = nc.wheelset_creepage;
    in.trailing_lateral = nc.trailing_lateral;
    in.trailing_yaw = nc.trailing_yaw;
    in.wheel_loads = nc.wheel_loads;
    in.wheel_creepages = nc.wheel_creepages;
    in.static_wheel_load = c.normal_force;
  }
  check_curve_state_input(in);
  // the bogie estimate on the profiles: its table; estimate and equilibrium: Nadal's limit at the
  // flange (a flange friction beyond it climbs the flange: outside both models)
  if (!in.multibody) {
    in.table = curving_profile_table(in);
    noise::BogieCurvingInput b;
    b.friction = in.friction;
    b.profiles = in.table;
    check_flange_friction(noise::flange_friction(b), "friction.mu");
  }
  return in;
}

noise::BogieCurvingInput bogie_curving_input(const ContactCase& c, const NoiseCase& nc) {
  const Eigen::Matrix3d fk = noise::kalker_creep_matrix(c.a, c.b, c.material);
  noise::BogieCurvingInput in;
  in.radius = nc.curve_radius;
  in.speed = c.speed;
  in.cant_deficiency = nc.cant_deficiency;
  in.wheelbase = nc.wheelbase;
  in.wheel_radius = nc.wheel_radius;
  in.conicity = nc.conicity;
  in.flange_clearance = nc.flange_clearance;
  in.wheel_load = c.normal_force;
  in.friction = c.mu;
  in.f11 = fk(0, 0);
  in.f22 = fk(1, 1);
  return in;
}

std::vector<noise::WheelId> curve_wheel_ids(const CurveSetup& s, const NoiseCase& nc) {
  if (!s.state) return {};
  return listed_wheel_ids(nc);
}

std::vector<noise::WheelId> listed_wheel_ids(const NoiseCase& nc) {
  if (nc.wheels.empty()) {  // the default
    if (nc.curve_radius > 0.0) return {noise::kAllWheels.begin(), noise::kAllWheels.end()};
    return {noise::WheelId::leading_outer};
  }
  std::vector<noise::WheelId> ids;
  for (const std::string& name : nc.wheels) {
    const auto id = noise::wheel_from_name(name);
    if (!id) throw InputError("curve.wheels", "\"" + name + "\" is not a wheel");
    ids.push_back(*id);
  }
  return ids;
}

std::vector<noise::WheelContact> curve_wheels(const CurveSetup& s, const NoiseCase& nc) {
  const std::vector<noise::WheelId> ids = curve_wheel_ids(s, nc);
  if (ids.empty()) return {};
  return noise::bogie_wheel_contacts(*s.state_input, *s.state, ids);
}

CurvePlacement resolve_curve(const ContactCase& c, const NoiseCase& nc) {
  CurvePlacement p;
  CurveSetup& s = p.curve;
  s.position = {0.0, 0.0, nc.contact_angle};
  if (c.profiles && (nc.estimate_creepage || nc.multibody)) {
    s.state_input = curve_state_input(c, nc);
    s.state = noise::curve_contact_state(*s.state_input);
    s.estimated = s.state->estimated;
    s.curving = s.state->estimate;
    p.contact = placed_contact_at(c, s.state->contact, s.state->normal_force);
    const Eigen::Vector3d& xi = s.state->creepage;
    p.contact.creepage = {xi(0), xi(1), xi(2)};
    s.position = s.state->position();
    return p;
  }
  p.contact = placed_contact(c);
  const ContactCase& placed = p.contact;
  if (nc.estimate_creepage && nc.curve_radius > 0.0) {
    s.estimated = true;
    const noise::BogieCurvingInput in = bogie_curving_input(placed, nc);
    check_bogie_curving_input(in);
    s.curving = noise::estimate_bogie_curving(in);
    p.contact.creepage = {s.curving.xi_x, s.curving.xi_y, s.curving.phi};
    s.position = s.curving.position();
  }
  if (placed.profiles)  // curve.creepage = "case": the case's contact point
    s.position = {placed.contact_point.wheel_s, placed.contact_point.rail_y, placed.contact_point.contact_angle};
  return p;
}

}  // namespace rollnoise::pipeline
