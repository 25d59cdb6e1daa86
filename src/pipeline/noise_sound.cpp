#include "pipeline/noise_sound.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace rollnoise::pipeline {
SoundResult noise_sound(const NoiseResult& r, const NoiseCase& nc, int threads) {
  const noise::ContactSetLoopResult& loop = r.band_loops().main;
  const std::vector<noise::ContactPoint> contacts = bogie_contacts(r.wheels, nc, r.patches);
  std::vector<SoundWheel> wheels(r.wheels.size());
  for (std::size_t a = 0; a < contacts.size(); ++a)  // the patches to the wheel they belong to
    for (std::size_t w = 0; w < r.wheels.size(); ++w)
      if (contacts[a].wheelset == contacts[w].wheelset && contacts[a].side == contacts[w].side)
        wheels[w].contacts.push_back(static_cast<int>(a));
  return sound_power(loop, contacts, wheels, r.source_levels, r.axis.centres, *nc.rail, nc.sound,
                     threads);
}

}  // namespace rollnoise::pipeline
