// Writing `rollnoise squeal` (pipeline/squeal.hpp) to HDF5 (docs/squeal.md Sec. 5): /squeal/* after
// /case, the patch and the steady state of the mean contact (write_mean_state) and the contact
// state the loop ran on (/squeal/contact/*, as /noise/contact/*).
#pragma once

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/squeal.hpp"

namespace rollnoise::io {

void write_squeal(Hdf5Writer& w, const CaseReader& r, const pipeline::NoiseCase& nc, const pipeline::SquealResult& res);

}  // namespace rollnoise::io
