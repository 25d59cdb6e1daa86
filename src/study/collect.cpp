#include "study/collect.hpp"

#include <filesystem>

#include "core/errors.hpp"
#include "io/output_files.hpp"
#include "study/runner.hpp"

namespace rollnoise::study {

std::vector<io::StudyRow> collect_rows(const pipeline::StudyPlan& plan) {
  std::vector<io::StudyRow> rows;
  for (const pipeline::StudyCase& c : pipeline::expand(plan)) {
    io::StudyRow row;
    row.parameters = c;
    const CaseState state = case_state(plan, c);
    const auto record =
        state == CaseState::kComplete ? io::read_case_record(pipeline::case_output(plan, c.index)) : std::nullopt;
    if (record) {
      row.status = io::CaseStatus::kComplete;
      row.record = *record;
    } else if (state == CaseState::kStale) {
      row.status = io::CaseStatus::kStale;
      row.message = "stale: computed from other inputs (the base case, an axis value or a model file changed "
                    "since); run the study again";
    } else if (const auto error = io::read_case_error(pipeline::case_error(plan, c.index))) {
      row.status = io::CaseStatus::kFailed;
      row.message = *error;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

CollectSummary collect(const pipeline::StudyPlan& plan) {
  if (!std::filesystem::is_directory(plan.output))
    throw InputError("output", plan.file + ": output: no folder " + plan.output + " (run the study first)");
  CollectSummary s;
  s.h5 = plan.output + "/study.h5";
  s.csv = plan.output + "/study.csv";
  // the outputs checked before any case is read (a folder named study.h5 is refused up front)
  io::check_outputs({{"output", s.h5}, {"output", s.csv}}, {{"the study file", plan.file}});
  const std::vector<io::StudyRow> rows = collect_rows(plan);
  for (const auto& r : rows) {
    s.complete += r.status == io::CaseStatus::kComplete;
    s.failed += r.status == io::CaseStatus::kFailed;
    s.missing += r.status == io::CaseStatus::kMissing;
    s.stale += r.status == io::CaseStatus::kStale;
  }
  io::write_study_table(s.h5, s.csv, plan, rows);
  return s;
}

}  // namespace rollnoise::study
