#include "vehicle/hertz_wheels.hpp"

#include <cmath>

#include "core/assert.hpp"

namespace rollnoise::noise {

double HertzWheel::semi_axis_ratio() const {
  return std::cbrt(load_ratio);
}

std::vector<HertzWheel> hertz_wheels(const BogieCurvingInput& in, const CurvingEstimate& e,
                                     const std::vector<WheelId>& wheels) {
  ROLLNOISE_ASSERT(!in.profiles,
                   "hertz_wheels: the conical tread (profiles have their own states)");
  const double inv_R = std::isfinite(in.radius) && in.radius > 0.0 ? 1.0 / in.radius : 0.0;
  const double l0 = in.half_distance(), r0 = in.wheel_radius, gamma = e.contact_angle;
  std::vector<HertzWheel> out;
  for (WheelId id : wheels) {
    const AxleCurving& axle = is_leading(id) ? e.leading : e.trailing;
    const bool outer = is_outer(id);
    const double sign = outer ? 1.0 : -1.0;  // kappa = sign/R, psi_s = sign psi (K2')
    HertzWheel w;
    w.wheel = id;
    w.lateral = axle.lateral;
    w.yaw = axle.attack_angle;
    w.vertical_load = outer ? axle.tread_load_outer : axle.tread_load_inner;
    w.load_ratio = w.vertical_load / in.wheel_load;
    // Delta_r = r_outer - r_inner from the estimate's xi_x of the outer wheel (K2)
    const double delta_r = 2.0 * r0 * (l0 * inv_R - axle.xi_x_outer);
    w.rolling_radius = r0 + 0.5 * sign * delta_r;
    w.position = {-sign * axle.lateral, 0.0, gamma};
    w.creepage = {sign * axle.xi_x_outer, -sign * axle.attack_angle / std::cos(gamma),
                  -std::sin(gamma) / w.rolling_radius - sign * std::cos(gamma) * inv_R};
    out.push_back(w);
  }
  return out;
}

}  // namespace rollnoise::noise
