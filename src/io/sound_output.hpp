// Writing the sound powers of a noise run (pipeline/sound_power.hpp, docs/sound.md) to HDF5:
// /noise/sound/*, /noise/wheels/<wheel>/sound/*, /sound/radiation_efficiency/* and
// /track/decay_rate/* (docs/interface.md).
#pragma once

#include "io/hdf5_writer.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::io {

void write_sound(Hdf5Writer& w, const pipeline::NoiseResult& r);

}  // namespace rollnoise::io
