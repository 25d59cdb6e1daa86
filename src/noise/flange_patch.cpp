#include "noise/flange_patch.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace rollnoise::noise {

std::optional<geometry::ContactGeometry> flank_contact(const geometry::WheelRailPair& pair,
                                                       double u0, double psi, double min_angle) {
  constexpr double kStep = 1e-5;  // m
  for (int k = 0; k <= 400; ++k) {
    const geometry::ContactGeometry c =
        geometry::find_contact(pair, {u0 + k * kStep, psi}, geometry::Side::Right);
    if (c.contact_angle >= min_angle) return c;
  }
  return std::nullopt;
}

std::optional<WheelContact> flange_patch_contact(const CurveStateInput& in,
                                                 const CurveContactState& s) {
  if (!s.two_point || !(s.flange_vertical_load > 0.0) || !(s.flange_angle > 0.0))
    return std::nullopt;
  const geometry::WheelRailPair& pair = *in.pair;
  const std::optional<geometry::ContactGeometry> flank =
      flank_contact(pair, s.lateral, s.yaw, s.flange_angle - 0.1);
  if (!flank)
    throw NumericalError("the flange patch: no contact on the flank within 4 mm of the axle's u");
  const WheelContactInput w = wheel_input(in, WheelId::leading_outer, s.lateral, s.yaw);
  WheelContact f;
  f.wheel = WheelId::leading_outer;
  f.lateral = s.lateral;
  f.yaw = s.yaw;
  f.contact = *flank;
  f.other_rolling_radius = s.inner_rolling_radius;
  f.creepage = kinematic_creepage(f.contact, f.other_rolling_radius, pair.wheelset().nominal_radius,
                                  w.inverse_radius);
  f.vertical_load = s.flange_vertical_load;
  // A planar patch at the flank's angle, lowered under Q_f ((V1) of loaded_contact.hpp).
  geometry::VerticalLoadInput v = vertical_load_input(w, f.creepage, s.flange_vertical_load);
  v.max_iterations = 200;  // contraction factor mu tan(delta) ~ 0.8 at 70 degrees
  f.loaded = std::make_shared<const geometry::LoadedContact>(
      geometry::lower_under_vertical_load(pair, f.contact, v));
  return f;
}

}  // namespace rollnoise::noise
