#include "vehicle/curve_state.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "noise/kalker_linear.hpp"
#include "vehicle/bogie_equilibrium.hpp"

namespace rollnoise::noise {
namespace {

// Kalker's f11, f22 of the Hertz estimate at the contact for the load (N).
Eigen::Vector2d kalker_at(const CurveStateInput& in, const geometry::ContactGeometry& c,
                          double load) {
  const contact::HertzContact hz = geometry::hertz_estimate(c, load, in.material, in.grid);
  const Eigen::Matrix3d f =
      kalker_creep_matrix(hz.a, hz.b, in.material);
  return {f(0, 0), f(1, 1)};
}

// The state of the bogie in equilibrium (bogie_equilibrium.hpp): the leading axle's position, the
// leading outer wheel's contact state at the solution (the solver's own, not recomputed); no
// Kalker coefficients (f11, f22 stay 0: the estimate's).
CurveContactState equilibrium_state(const CurveStateInput& in) {
  BogieEquilibriumInput b;
  b.curve = in;
  b.vehicle = in.vehicle;
  b.guess = estimated_guess(in);
  auto e = std::make_shared<const BogieEquilibrium>(solve_bogie_equilibrium(b));
  CurveContactState s;
  s.equilibrium = e;
  s.wheel_load = in.wheel_load;
  s.lateral = e->lateral[0];
  s.yaw = e->yaw[0];
  s.load_transfer = e->load_transfer;
  s.position_iterations = e->iterations;
  s.wheel = e->wheels.front();
  s.contact = s.wheel.contact;
  s.inner_rolling_radius = s.wheel.other_rolling_radius;
  s.creepage = s.wheel.creepage;
  s.loaded = s.wheel.loaded;
  s.tread_load = s.wheel.vertical_load;
  s.lateral_creep_force = s.loaded->creep_force[1];
  s.normal_force = s.loaded->normal_force;
  return s;
}

}  // namespace

// The wheel's input at the axle position (u, psi): profiles, material, grid, curve, friction.
WheelContactInput wheel_input(const CurveStateInput& in, WheelId id, double u, double psi) {
  WheelContactInput w;
  w.pair = in.pair;
  w.material = in.material;
  w.grid = in.grid;
  w.lowering_nx = in.lowering_nx;
  w.inverse_radius = std::isinf(in.radius) ? 0.0 : 1.0 / in.radius;
  w.speed = in.speed;
  w.friction = in.friction;
  w.spin_offset = in.spin_offset;
  w.wheel = id;
  w.lateral = u;
  w.yaw = psi;
  return w;
}

std::string multibody_key(WheelId id, const std::string& what) {
  return std::string(is_leading(id) ? "wheelset." : "trailing_wheelset.") +
         (is_outer(id) ? "" : "inner_") + what;
}

bool CurveStateInput::valid() const {
  const auto finite_in = [](double v, double bound) { return std::isfinite(v) && std::abs(v) <= bound; };
  bool ok = pair && radius > 0.0 && std::isfinite(cant_deficiency) && cg_height >= 0.0 && std::isfinite(cg_height) &&
            wheel_load > 0.0 && std::isfinite(wheel_load) && speed > 0.0 && std::isfinite(speed) && friction > 0.0;
  if (!ok || !multibody) return ok;
  ok = finite_in(lateral, 0.02) && finite_in(yaw, 0.05) && finite_in(trailing_lateral, 0.02) &&
       finite_in(trailing_yaw, 0.05) && (!creepage || creepage->allFinite());
  for (std::size_t i = 0; i < wheel_loads.size(); ++i) {
    ok = ok && (!wheel_loads[i] || (*wheel_loads[i] > 0.0 && std::isfinite(*wheel_loads[i])));
    ok = ok && (!wheel_creepages[i] || wheel_creepages[i]->allFinite());
  }
  return ok;
}

double cant_deficiency_load_transfer(double wheel_load, double cant_deficiency, double cg_height,
                                     double contact_distance) {
  // (K4): the unbalanced lateral force m g h_d / s at the height h_cg is balanced by the wheel
  // load differences +-dQ of the n axles over s: m g h_d h_cg / s = n dQ s, m g = 2 n Q.
  return 2.0 * wheel_load * cant_deficiency * cg_height / (contact_distance * contact_distance);
}

double flange_vertical_load(double lateral_force, double flange_angle, double mu) {
  // (K6) with Nadal's friction direction (curving.hpp).
  const double d = flange_angle;
  return std::abs(lateral_force) * (std::cos(d) + mu * std::sin(d)) /
         (std::sin(d) - mu * std::cos(d));
}

CurveContactState estimated_curve_position(const CurveStateInput& in) {
  const geometry::WheelRailPair& pair = *in.pair;
  const double r0 = pair.wheelset().nominal_radius;
  const double l0 = geometry::find_contact(pair, {0.0, 0.0}).y;  // the centred contact point
  const double Q = in.wheel_load;
  CurveContactState s;
  s.wheel_load = Q;
  s.estimated = true;
  BogieCurvingInput b;
  b.radius = in.radius;
  b.speed = in.speed;
  b.cant_deficiency = in.cant_deficiency;
  b.wheelbase = in.wheelbase;
  b.wheel_radius = r0;
  b.contact_half_distance = l0;
  b.wheel_load = Q;
  b.friction = in.friction;
  b.load_transfer = cant_deficiency_load_transfer(Q, in.cant_deficiency, in.cg_height, 2.0 * l0);
  b.profiles = in.table ? in.table
                        : std::make_shared<const ProfileCurvingTable>(
                              profile_curving_table(pair, 0.010, in.table_step));
  // Fixed point: f at the contact -> estimate -> contact. The contact moves by table steps at
  // most near a jump of the profile contact; a few iterations settle it.
  s.contact = geometry::find_contact(pair, {0.0, 0.0});
  for (s.position_iterations = 1; s.position_iterations <= 10; ++s.position_iterations) {
    const Eigen::Vector2d f = kalker_at(in, s.contact, Q);
    b.f11 = f(0), b.f22 = f(1);
    s.estimate = estimate_bogie_curving(b);
    const double du = std::abs(s.estimate.leading.lateral - s.lateral);
    const double dpsi = std::abs(s.estimate.leading.attack_angle - s.yaw);
    s.lateral = s.estimate.leading.lateral;
    s.yaw = s.estimate.leading.attack_angle;
    s.contact = geometry::find_contact(pair, {s.lateral, s.yaw});
    if (du < 1e-9 && dpsi < 1e-9) break;
  }
  s.f11 = b.f11, s.f22 = b.f22;
  const AxleCurving& lead = s.estimate.leading;
  s.load_transfer = s.estimate.load_transfer;
  s.tread_load = lead.tread_load_outer;
  s.two_point = lead.flange == 1 && lead.flange_force != 0.0;
  s.flange_angle = s.estimate.flange_angle;
  if (s.two_point) {
    s.flange_lateral_force = std::abs(lead.flange_force);
    s.flange_normal_force = lead.flange_normal_force;
    s.flange_vertical_load = lead.flange_vertical_load;
  }
  return s;
}

CurveContactState curve_contact_state(const CurveStateInput& in) {
  ROLLNOISE_ASSERT(
      in.valid(),
      "curve contact state input outside the model (pipeline::check_curve_state_input)");
  const geometry::WheelRailPair& pair = *in.pair;
  const double Q = in.wheel_load;

  CurveContactState s;
  s.wheel_load = Q;
  if (in.equilibrium) return equilibrium_state(in);
  if (in.multibody) {
    s.lateral = in.lateral;
    s.yaw = in.yaw;
    s.contact = geometry::find_contact(pair, {s.lateral, s.yaw});
    const Eigen::Vector2d f = kalker_at(in, s.contact, Q);
    s.f11 = f(0), s.f22 = f(1);
    s.tread_load = Q;
  } else {
    s = estimated_curve_position(in);
  }
  // (K2') with the actual contact and (K8) = (V1): the wheel lowered vertically under its whole
  // vertical load Q_o = Q + dQ on the curved reference surface of the rail profile
  // (noise/wheel_contact.hpp, geometry/curved_contact.hpp), N and F_y from the steady rolling
  // solution of its patch. A patch that wraps from the flange root onto the flank carries the
  // flank's share itself: the estimate's flange share is reported, not added.
  WheelContactInput w = wheel_input(in, WheelId::leading_outer, s.lateral, s.yaw);
  w.vertical_load = Q + s.load_transfer;
  w.creepage = in.creepage;
  s.wheel = wheel_contact(w);
  s.contact = s.wheel.contact;
  s.inner_rolling_radius = s.wheel.other_rolling_radius;
  s.creepage = s.wheel.creepage;
  s.loaded = s.wheel.loaded;
  s.tread_load = w.vertical_load;
  s.lateral_creep_force = s.loaded->creep_force[1];
  s.normal_force = s.loaded->normal_force;
  return s;
}

std::vector<WheelContact> bogie_wheel_contacts(const CurveStateInput& in,
                                               const CurveContactState& s,
                                               const std::vector<WheelId>& wheels) {
  std::vector<WheelContact> out;
  for (WheelId id : wheels) {
    if (s.equilibrium) {  // the solver's own contact states at the solution
      out.push_back(s.equilibrium->wheels[static_cast<std::size_t>(id)]);
      continue;
    }
    if (id == WheelId::leading_outer) {
      out.push_back(s.wheel);
      continue;
    }
    const bool lead = is_leading(id), outer = is_outer(id);
    const double u = lead ? s.lateral : s.estimated ? s.estimate.trailing.lateral : in.trailing_lateral;
    const double psi = lead ? s.yaw : s.estimated ? s.estimate.trailing.attack_angle : in.trailing_yaw;
    WheelContactInput w = wheel_input(in, id, u, psi);
    const std::size_t k = static_cast<std::size_t>(id);
    if (s.estimated)  // (K4): Q +- dQ
      w.vertical_load = s.wheel_load + (outer ? s.load_transfer : -s.load_transfer);
    else
      w.vertical_load = in.wheel_loads[k]           ? *in.wheel_loads[k]
                        : in.static_wheel_load > 0.0 ? in.static_wheel_load
                                                     : in.wheel_load;
    if (in.multibody) w.creepage = in.wheel_creepages[k];
    out.push_back(wheel_contact(w));
  }
  return out;
}

contact::ContactPatch solve_curve_patch(const CurveStateInput& in, const CurveContactState& s) {
  return geometry::solve_wheel_rail_patch(*in.pair, s.contact, s.normal_force, in.material,
                                          in.grid);
}

}  // namespace rollnoise::noise
