#include "pipeline/squeal_hertz_wheels.hpp"

#include "pipeline/curve_input_checks.hpp"
#include "vehicle/curve_state.hpp"

namespace rollnoise::pipeline {
namespace {

// The bogie estimate's input with the load transfer (K4): dQ = 2 Q h_d h_cg / s^2 over the contact
// distance s = 2 l0 (curve_state.cpp).
noise::BogieCurvingInput load_transfer_input(const ContactCase& placed, const NoiseCase& nc) {
  noise::BogieCurvingInput in = bogie_curving_input(placed, nc);
  in.load_transfer = noise::cant_deficiency_load_transfer(in.wheel_load, in.cant_deficiency,
                                                          nc.cg_height, 2.0 * in.half_distance());
  check_bogie_curving_input(in);
  return in;
}

}  // namespace

std::vector<noise::HertzWheel> hertz_curve_wheels(const ContactCase& placed, const NoiseCase& nc,
                                                  const std::vector<noise::WheelId>& wheels) {
  const noise::BogieCurvingInput in = load_transfer_input(placed, nc);
  return noise::hertz_wheels(in, noise::estimate_bogie_curving(in), wheels);
}

std::vector<noise::HertzWheel> hertz_curve_wheels(const ContactCase& placed, const NoiseCase& nc) {
  return hertz_curve_wheels(placed, nc, listed_wheel_ids(nc));
}

ContactCase hertz_wheel_case(const ContactCase& placed, const noise::HertzWheel& w) {
  ContactCase c = placed;
  const double k = w.semi_axis_ratio();  // Hertz at the case's curvatures: a, b ~ N^(1/3)
  c.normal_force = placed.normal_force * w.load_ratio;
  c.a = placed.a * k;
  c.b = placed.b * k;
  c.grid.dx *= k, c.grid.dy *= k, c.grid.x_min *= k, c.grid.y_min *= k;
  c.creepage = {w.creepage(0), w.creepage(1), w.creepage(2)};
  return c;
}

bool has_hertz_wheel_states(const CurvePlacement& p, const NoiseCase& nc) {
  return nc.squeal_wheelsets && p.curve.estimated && !p.contact.profiles;
}

CurvePlacement leading_outer_placement(const CurvePlacement& p, const NoiseCase& nc) {
  const noise::BogieCurvingInput in = load_transfer_input(p.contact, nc);
  const noise::CurvingEstimate e = noise::estimate_bogie_curving(in);
  const noise::HertzWheel w = noise::hertz_wheels(in, e, {noise::WheelId::leading_outer}).front();
  CurvePlacement out = p;
  out.contact = hertz_wheel_case(p.contact, w);
  out.curve.curving = e;  // its position() is the leading outer wheel's (the conical tread)
  out.curve.position = w.position;
  return out;
}

std::vector<SquealWheelContact> hertz_squeal_wheels(const ContactCase& placed, const NoiseCase& nc,
                                                    const MeanContactOptions& o,
                                                    const MeanContact* leading_outer) {
  std::vector<SquealWheelContact> out;
  for (const noise::HertzWheel& w : hertz_curve_wheels(placed, nc)) {
    if (leading_outer && w.wheel == noise::WheelId::leading_outer)
      out.push_back({w.wheel, w.position, *leading_outer});
    else
      out.push_back({w.wheel, w.position, solve_mean_contact(hertz_wheel_case(placed, w), {}, o)});
  }
  return out;
}

}  // namespace rollnoise::pipeline
