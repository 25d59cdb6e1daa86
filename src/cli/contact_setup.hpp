// The mean state of a case file, for the commands that start from it (creep, response, validate,
// bench): the case read by io, the mean state solved by the pipeline (pipeline/mean_state.hpp).
#pragma once

#include "io/case_reader.hpp"
#include "pipeline/mean_state.hpp"

namespace rollnoise::cli {

using pipeline::MeanState;

/// Read the contact part of the case and solve its mean state (and linear model when asked).
MeanState solve_mean_state(const io::CaseReader& r, bool with_model);

}  // namespace rollnoise::cli
