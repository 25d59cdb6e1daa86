#include "noise/wheel_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"

namespace rollnoise::noise {

const char* wheel_name(WheelId w) {
  switch (w) {
    case WheelId::leading_outer:
      return "leading_outer";
    case WheelId::leading_inner:
      return "leading_inner";
    case WheelId::trailing_outer:
      return "trailing_outer";
    case WheelId::trailing_inner:
      return "trailing_inner";
  }
  return "?";
}

std::optional<WheelId> wheel_from_name(const std::string& name) {
  for (WheelId w : kAllWheels)
    if (name == wheel_name(w)) return w;
  return std::nullopt;
}

std::array<double, 3> WheelContact::force_track() const {
  const std::array<double, 3>& f = loaded->force_track;  // lateral towards this side's field side
  return {f[0], is_outer(wheel) ? f[1] : -f[1], f[2]};
}

Eigen::Vector3d kinematic_creepage(const geometry::ContactGeometry& c, double other_rolling_radius,
                                   double nominal_radius, double kappa) {
  const double gamma = c.contact_angle, rc = c.rolling_radius;
  // (K2'): c.y and c.local_pose.yaw are this side's (mirrored for the left wheel).
  return {kappa * c.y - (rc - other_rolling_radius) / (2.0 * nominal_radius),
          -c.local_pose.yaw / std::cos(gamma), -std::sin(gamma) / rc - kappa * std::cos(gamma)};
}

geometry::VerticalLoadInput vertical_load_input(const WheelContactInput& in,
                                                const Eigen::Vector3d& creepage,
                                                double vertical_load) {
  geometry::VerticalLoadInput v;
  v.vertical_load = vertical_load;
  v.material = in.material;
  v.grid = in.grid;
  v.grid.nx = std::min(v.grid.nx, in.lowering_nx);
  v.settle = in.lowering_settle;
  v.gap_regions = in.gap_regions;
  v.max_iterations = in.lowering_settle < 1e-5 ? 100 : v.max_iterations;
  v.rolling = contact::SteadyRollingInput(in.friction, in.speed,
                                          {creepage(0), creepage(1), creepage(2)}, in.spin_offset);
  return v;
}

WheelContact wheel_contact(const WheelContactInput& in) {
  if (!in.pair)  // a contract: the pipeline builds a wheel's contact only with contact.geometry = "profiles"
    throw std::invalid_argument("a wheel's contact state needs the profiles");
  if (!(in.vertical_load > 0.0) || !std::isfinite(in.vertical_load))
    throw InputError("curve.wheels",
                     std::string("the vertical load of the ") + wheel_name(in.wheel) +
                         " wheel must be positive (a lifted wheel is not modelled)");
  const geometry::WheelRailPair& pair = *in.pair;
  const bool outer = is_outer(in.wheel);
  const geometry::Side side = outer ? geometry::Side::Right : geometry::Side::Left;
  const geometry::Side other = outer ? geometry::Side::Left : geometry::Side::Right;
  WheelContact w;
  w.wheel = in.wheel;
  w.lateral = in.lateral;
  w.yaw = in.yaw;
  const geometry::WheelsetPose pose = pair.equilibrium({in.lateral, in.yaw});  // both wheels'
  w.contact = geometry::find_contact_at_pose(pair, pose, side);
  w.other_rolling_radius = geometry::find_contact_at_pose(pair, pose, other).rolling_radius;
  const double kappa = outer ? in.inverse_radius : -in.inverse_radius;
  w.creepage_given = in.creepage.has_value();
  w.creepage = in.creepage ? *in.creepage
                           : kinematic_creepage(w.contact, w.other_rolling_radius,
                                                pair.wheelset().nominal_radius, kappa);
  const double r0 = pair.wheelset().nominal_radius;
  if (!in.creepage &&
      in.axle_spin) {  // the axle's own rolling speed (WheelContactInput::axle_spin)
    const double rate = (1.0 + *in.axle_spin) / r0, gamma = w.contact.contact_angle;
    w.creepage(0) = kappa * w.contact.y + 1.0 - rate * w.contact.rolling_radius;
    w.creepage(2) = -rate * std::sin(gamma) - kappa * std::cos(gamma);
  }
  w.vertical_load = in.vertical_load;
  // Lowered vertically under Q_w on the curved surface (curved_contact.hpp), in this side's frame:
  // its yaw c.local_pose.yaw and curvature kappa.
  geometry::VerticalLoadInput v = vertical_load_input(in, w.creepage, in.vertical_load);
  v.curved = true;
  v.yaw = w.contact.local_pose.yaw;
  v.inverse_radius = kappa;
  if (!in.creepage && in.axle_spin) v.rolling_rate = (1.0 + *in.axle_spin) / r0;
  v.start = in.start;
  v.keep_factors = in.keep_factors;
  w.loaded = std::make_shared<const geometry::LoadedContact>(
      geometry::lower_under_vertical_load(pair, w.contact, v));
  return w;
}

}  // namespace rollnoise::noise
