// The keys of `rollnoise corrugation` ([corrugation], [wear]; docs/corrugation.md Sec. 5) read
// into pipeline::CorrugationCase, every value checked.
#pragma once

#include "io/case_reader.hpp"
#include "pipeline/corrugation.hpp"

namespace rollnoise::io {

/// One InputError with every problem, each naming its key (e.g. "wear.coefficient must be > 0").
pipeline::CorrugationCase read_corrugation_case(const CaseReader& r);

}  // namespace rollnoise::io
