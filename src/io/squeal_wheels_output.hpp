// Writing squeal per wheelset (pipeline/squeal_wheels.hpp, docs/squeal.md Sec. 8.2):
// /squeal/wheels/<wheel>/{frequency, damping_ratio, unstable, mode, share, converged} (the roots
// whose dominant wheel it is) and /squeal/wheels/unstable/{wheel, frequency, damping_ratio, mode,
// share} (every unstable root of the bogie).
#pragma once

#include <vector>

#include "io/hdf5_writer.hpp"
#include "pipeline/squeal_wheels.hpp"

namespace rollnoise::io {

void write_squeal_wheels(Hdf5Writer& w, const std::vector<pipeline::WheelsetSqueal>& s);

}  // namespace rollnoise::io
