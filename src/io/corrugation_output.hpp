// Writing `rollnoise corrugation` (pipeline/corrugation.hpp) to HDF5 (docs/corrugation.md Sec. 6):
// /case, the mean state of the main contact (write_mean_state), and /corrugation/*.
#pragma once

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/corrugation.hpp"

namespace rollnoise::io {

void write_corrugation(Hdf5Writer& w, const CaseReader& r, const pipeline::NoiseCase& nc,
                       const pipeline::CorrugationCase& cc, const pipeline::CorrugationResult& res);

/// "outer" (+1) or "inner" (-1).
const char* rail_name(int side);

}  // namespace rollnoise::io
