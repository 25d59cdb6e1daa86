// The sound stage of the noise pipeline (docs/sound.md): the loop the case asked for (the bogie's
// contact set, or each wheel's loop alone) handed to sound_power with its contacts, its wheels and
// its sources' roughness levels.
#pragma once

#include <memory>

#include "pipeline/noise_pipeline.hpp"
#include "pipeline/sound_power.hpp"

namespace rollnoise::pipeline {

/// The sound powers of a noise run (after add_bands; the refined lines where the run has them).
/// Without the bogie loop each wheel's loop alone is a contact set of one, its own rail under it;
/// the bogie's columns are then the power sums of the wheels'.
SoundResult noise_sound(const NoiseResult& r, const NoiseCase& nc, int threads = 1);

}  // namespace rollnoise::pipeline
