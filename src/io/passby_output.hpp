// Writing a pass-by (pipeline/passby.hpp, docs/sound.md Sec. 6) to HDF5: /passby/* with units
// (docs/interface.md), after the noise run's own output (io/noise_output.hpp).
#pragma once

#include "io/hdf5_writer.hpp"
#include "pipeline/passby.hpp"

namespace rollnoise::io {

void write_passby(Hdf5Writer& w, const pipeline::PassbyResult& r, const pipeline::PassbyCase& pc);

}  // namespace rollnoise::io
