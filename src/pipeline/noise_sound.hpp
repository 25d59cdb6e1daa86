// The sound stage of the noise pipeline (docs/sound.md): the loop of the case's contacts (coupled
// in the bogie, or each alone) handed to sound_power with its contacts, its wheels and its
// sources' roughness levels.
#pragma once

#include <memory>

#include "pipeline/noise_pipeline.hpp"
#include "pipeline/sound_power.hpp"

namespace rollnoise::pipeline {

/// The sound powers of a noise run (after add_bands; the refined lines where the run has them).
SoundResult noise_sound(const NoiseResult& r, const NoiseCase& nc, int threads = 1);

}  // namespace rollnoise::pipeline
