#include "noise/curve_state.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "noise/kalker_linear.hpp"

namespace rollnoise::noise {
namespace {

// Kalker's f11, f22 of the Hertz estimate at the contact for the load (N).
Eigen::Vector2d kalker_at(const CurveStateInput& in, const geometry::ContactGeometry& c,
                          double load) {
  const contact::HertzContact hz = geometry::hertz_estimate(c, load, in.material, in.grid);
  const Eigen::Matrix3d f =
      kalker_creep_matrix(hz.a, hz.b, in.material.shear_modulus(), in.material.nu);
  return {f(0, 0), f(1, 1)};
}

}  // namespace

void CurveStateInput::validate() const {
  if (!pair) throw InputError("contact.geometry", "the curve contact state needs the profiles");
  if (!(radius > 0.0) || std::isnan(radius))
    throw InputError("curve.radius", "curve.radius must be positive (inf for tangent track)");
  if (!std::isfinite(cant_deficiency))
    throw InputError("curve.cant_deficiency", "curve.cant_deficiency must be finite");
  if (!(cg_height >= 0.0) || !std::isfinite(cg_height))
    throw InputError("curve.cg_height", "curve.cg_height must be >= 0 and finite");
  if (!(wheel_load > 0.0) || !std::isfinite(wheel_load))
    throw InputError(multibody ? "wheelset.wheel_load" : "contact.normal_force",
                     "the wheel load must be positive and finite");
  if (!(speed > 0.0) || !std::isfinite(speed))
    throw InputError("rolling.speed", "rolling.speed must be positive and finite");
  if (!(friction > 0.0)) throw InputError("friction.mu", "friction.mu must be positive");
  if (multibody) {
    if (!std::isfinite(lateral) || std::abs(lateral) > 0.02)
      throw InputError("wheelset.lateral_displacement",
                       "wheelset.lateral_displacement must lie within +-20 mm");
    if (!std::isfinite(yaw) || std::abs(yaw) > 0.05)
      throw InputError("wheelset.yaw", "wheelset.yaw must lie within +-0.05 rad");
    if (creepage && !creepage->allFinite())
      throw InputError("wheelset.creepage", "wheelset.creepage must be finite");
  }
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

CurveContactState curve_contact_state(const CurveStateInput& in) {
  in.validate();
  const geometry::WheelRailPair& pair = *in.pair;
  const double inv_R = std::isinf(in.radius) ? 0.0 : 1.0 / in.radius;
  const double r0 = pair.wheelset().nominal_radius;
  const double l0 = geometry::find_contact(pair, {0.0, 0.0}).y;  // the centred contact point
  const double Q = in.wheel_load;

  CurveContactState s;
  s.wheel_load = Q;
  if (in.multibody) {
    s.lateral = in.lateral;
    s.yaw = in.yaw;
    s.contact = geometry::find_contact(pair, {s.lateral, s.yaw});
    const Eigen::Vector2d f = kalker_at(in, s.contact, Q);
    s.f11 = f(0), s.f22 = f(1);
    s.tread_load = Q;
  } else {
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
  }
  const double gamma = s.contact.contact_angle, rc = s.contact.rolling_radius;
  s.inner_rolling_radius =
      geometry::find_contact(pair, {s.lateral, s.yaw}, geometry::Side::Left).rolling_radius;
  if (in.creepage) {
    s.creepage = *in.creepage;
  } else {  // (K2) with the actual contact
    s.creepage = {l0 * inv_R - (rc - s.inner_rolling_radius) / (2.0 * r0), -s.yaw / std::cos(gamma),
                  -std::sin(gamma) / rc - std::cos(gamma) * inv_R};
  }
  // (K8) = (V1): the wheel lowered vertically under its whole vertical load Q_o = Q + dQ on the
  // curved reference surface of the rail profile (geometry/curved_contact.hpp), N and F_y from the
  // steady rolling solution of its patch. A patch that wraps from the flange root onto the flank
  // carries the flank's share itself: the estimate's flange share is reported, not added.
  geometry::VerticalLoadInput v;
  v.vertical_load = Q + s.load_transfer;
  v.material = in.material;
  v.grid = in.grid;
  v.grid.nx = std::min(v.grid.nx, in.lowering_nx);  // the resultant: < 0.5 % from 16 to 24
  v.rolling = contact::SteadyRollingInput(in.friction, in.speed,
                                          {s.creepage(0), s.creepage(1), s.creepage(2)},
                                          in.spin_offset);
  v.curved = true;
  v.yaw = s.yaw;
  v.inverse_radius = inv_R;
  s.loaded = std::make_shared<const geometry::LoadedContact>(
      geometry::lower_under_vertical_load(pair, s.contact, v));
  s.tread_load = v.vertical_load;
  s.lateral_creep_force = s.loaded->creep_force[1];
  s.normal_force = s.loaded->normal_force;
  return s;
}

contact::ContactPatch solve_curve_patch(const CurveStateInput& in, const CurveContactState& s) {
  return geometry::solve_wheel_rail_patch(*in.pair, s.contact, s.normal_force, in.material,
                                          in.grid);
}

}  // namespace rollnoise::noise
