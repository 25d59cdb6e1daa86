#include "pipeline/bogie_noise.hpp"

#include "core/errors.hpp"
#include "noise/roughness.hpp"

namespace rollnoise::pipeline {

std::vector<noise::ContactPoint> bogie_contacts(const std::vector<WheelNoise>& wheels,
                                                const NoiseCase& nc) {
  std::vector<noise::ContactPoint> out;
  for (const WheelNoise& w : wheels) {
    noise::ContactPoint c;
    const bool leading = noise::is_leading(w.state.wheel);
    c.wheelset = leading ? 0 : 1;
    c.side = noise::is_outer(w.state.wheel) ? 1 : -1;
    c.position = w.position;  // its own frame (mirrored for an inner wheel), as its loop alone
    c.rail_x = nc.rail_position + (leading ? 0.0 : nc.wheelbase);
    out.push_back(c);
  }
  return out;
}

noise::ContactSetLoopResult bogie_loop(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                       const std::vector<double>& frequency,
                                       const noise::CrossCoupling& cross) {
  if (!nc.rail_track)
    throw InputError(
        "noise.contact_coupling",
        "the wheels' contacts are coupled through the beam rail only (track.model = \"beam\"); "
        "set noise.contact_coupling = \"none\" for the waveguide rail");
  const noise::RailLine rail(*nc.rail_track, nc.rail_support);
  const noise::ContactSetStructures s =
      noise::contact_set_structures(*nc.wheel, rail, bogie_contacts(wheels, nc), frequency, cross);
  std::vector<std::vector<noise::Receptance4>> alpha;
  for (const WheelNoise& w : wheels) alpha.push_back(w.contact_receptance);
  // every wheel a tread contact with its own roughness (Sec. 5.2: uncorrelated sources)
  return noise::solve_contact_set_loop(
      s, alpha, noise::independent_sources(std::vector<bool>(wheels.size(), true)));
}

std::vector<noise::BandLevels> bogie_bands(const noise::ContactSetLoopResult& loop,
                                           const std::vector<WheelNoise>& wheels,
                                           const NoiseCase& nc,
                                           const std::vector<double>& centres) {
  std::vector<std::vector<double>> levels;  // source e = wheel e, with its patch's contact filter
  for (const WheelNoise& w : wheels) {
    noise::ContactFilter filter;
    filter.model = nc.filter;
    filter.a = w.mean.contact().a;
    filter.b = w.mean.contact().b;
    levels.push_back(
        noise::ContactRoughness(nc.wheel_roughness, nc.rail_roughness, w.mean.contact().speed, filter)
            .levels(centres));
  }
  std::vector<noise::BandLevels> out;
  for (int a = 0; a < static_cast<int>(wheels.size()); ++a)
    out.push_back(noise::contact_band_levels(loop, a, centres, levels));
  return out;
}

}  // namespace rollnoise::pipeline
