// `rollnoise collect`: the cases of a study in one table (docs/study.md): per case its parameters,
// status (complete, failed with its message, missing, or stale: computed from other inputs), run time, mean contact state and band
// levels, written to OUTPUT/study.h5 and OUTPUT/study.csv.
#pragma once

#include <string>
#include <vector>

#include "io/study_output.hpp"
#include "pipeline/study_plan.hpp"

namespace rollnoise::study {

/// One row per case of the study, in case order.
std::vector<io::StudyRow> collect_rows(const pipeline::StudyPlan& plan);

struct CollectSummary {
  long complete = 0, failed = 0, missing = 0, stale = 0;
  std::string h5, csv;
};
/// collect_rows, written to the output folder.
CollectSummary collect(const pipeline::StudyPlan& plan);

}  // namespace rollnoise::study
