// Writing the results of the noise pipeline (pipeline/noise_pipeline.hpp) to HDF5: /noise/* of
// `rollnoise noise` and /receptance/* of `rollnoise receptance` (docs/noise_loop.md Sec. 6), each
// after /case, the patch and the steady state of the mean contact.
#pragma once

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::io {

/// The case as run: when the curve stage set the creepages, creepage.mean records them.
CaseReader case_as_run(const CaseReader& r, const pipeline::ContactCase& c, const pipeline::CurveSetup& curve);

void write_noise(Hdf5Writer& w, const CaseReader& r, const pipeline::NoiseCase& nc, const pipeline::NoiseResult& res);

void write_receptance(Hdf5Writer& w, const CaseReader& r, const pipeline::ReceptanceResult& res);

}  // namespace rollnoise::io
