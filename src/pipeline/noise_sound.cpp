#include "pipeline/noise_sound.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace rollnoise::pipeline {
namespace {

// A single-contact loop as a contact set of one with one unit source.
noise::ContactSetLoopResult as_contact_set(const noise::LoopResult& l) {
  noise::ContactSetLoopResult s;
  s.frequency = l.frequency;
  for (const auto& F : l.force) s.force.push_back(Eigen::MatrixXcd(F));
  for (const auto& v : l.wheel_velocity) s.wheel_velocity.push_back(Eigen::MatrixXcd(v));
  for (const auto& v : l.rail_velocity) s.rail_velocity.push_back(Eigen::MatrixXcd(v));
  s.rho = Eigen::MatrixXd::Ones(1, 1);
  return s;
}

}  // namespace

SoundResult noise_sound(const NoiseResult& r, const NoiseCase& nc, int threads) {
  const std::vector<double>& centres = r.axis.centres;
  if (r.bogie) {
    const noise::ContactSetLoopResult& loop = r.refined ? *r.refined->bogie : *r.bogie;
    const std::vector<noise::ContactPoint> contacts = bogie_contacts(r.wheels, nc, r.patches);
    std::vector<SoundWheel> wheels(r.wheels.size());
    for (std::size_t a = 0; a < contacts.size(); ++a)  // the patches to the wheel they belong to
      for (std::size_t w = 0; w < r.wheels.size(); ++w)
        if (contacts[a].wheelset == contacts[w].wheelset && contacts[a].side == contacts[w].side)
          wheels[w].contacts.push_back(static_cast<int>(a));
    return sound_power(loop, contacts, wheels, r.source_levels, centres, *nc.rail, nc.sound,
                       threads);
  }
  // each wheel's loop alone (noise.contact_coupling = "none"), or the case's single contact
  std::vector<noise::ContactSetLoopResult> loops;
  std::vector<noise::ContactPoint> points;
  std::vector<std::vector<double>> levels;
  if (r.wheels.empty()) {
    loops.push_back(as_contact_set(r.refined ? r.refined->variants.main : r.variants.main));
    noise::ContactPoint c;
    c.position = r.mean.curve().position;
    c.rail_x = nc.rail->position();
    points.push_back(c);
    levels.push_back(contact_roughness(nc, r.mean).levels(centres));
  } else {
    const std::vector<noise::ContactPoint> all = bogie_contacts(r.wheels, nc);
    const std::vector<std::vector<double>> source =
        bogie_source_levels(r.wheels, nc, centres, {}, threads);
    for (std::size_t i = 0; i < r.wheels.size(); ++i) {
      const bool main = r.wheels[i].state.wheel == noise::WheelId::leading_outer;
      const noise::LoopResult& l =
          r.refined ? (main ? r.refined->variants.main : r.refined->wheel_loops[i])
                    : (main ? r.variants.main : r.wheels[i].loop);
      loops.push_back(as_contact_set(l));
      points.push_back(all[i]);
      levels.push_back(source[i]);
    }
  }
  SoundResult total;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const SoundResult one = sound_power(loops[i], {points[i]}, {SoundWheel{{0}}}, {levels[i]},
                                        centres, *nc.rail, nc.sound, threads);
    if (i == 0) {
      total = one;
      total.contact_power.clear();
      total.contact_power_a.clear();
      total.contact_family.clear();
    } else {
      for (std::size_t b = 0; b < total.wheel_family.size() && b < one.wheel_family.size(); ++b)
        for (std::size_t c = 0; c < 3; ++c)
          total.wheel_family[b][c] = power_sum(total.wheel_family[b][c], one.wheel_family[b][c]);
      for (std::size_t b = 0; b < centres.size(); ++b)
        for (std::size_t c = 0; c < 4; ++c)
          total.power[b][c] = power_sum(total.power[b][c], one.power[b][c]);
      for (std::size_t b = 0; b < centres.size(); ++b)
        total.input_power[b] = power_sum(total.input_power[b], one.input_power[b]);
      total.seconds += one.seconds;
    }
    total.contact_power.push_back(one.contact_power.front());
    total.contact_power_a.push_back(one.contact_power_a.front());
    if (!one.contact_family.empty()) total.contact_family.push_back(one.contact_family.front());
  }
  total.power_a = a_weighted_columns(centres, total.power);
  return total;
}

}  // namespace rollnoise::pipeline
