// The train and the receiver of `rollnoise passby` ([train], [[train.vehicle]], [passby];
// docs/interface.md) read into pipeline::PassbyCase, every value checked.
#pragma once

#include "io/case_reader.hpp"
#include "pipeline/noise_case.hpp"
#include "pipeline/passby.hpp"

namespace rollnoise::io {

/// Read and check the pass-by keys of a case (`nc`: the noise case read from it, whose
/// curve.wheelbase and curve.wheel_radius are the bogie's); one InputError with every problem,
/// each naming its key (a vehicle entry's as train.vehicle[i].field).
pipeline::PassbyCase read_passby_case(const CaseReader& r, const pipeline::NoiseCase& nc);

}  // namespace rollnoise::io
