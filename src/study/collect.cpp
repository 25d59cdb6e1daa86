#include "study/collect.hpp"

#include <filesystem>

#include "core/errors.hpp"
#include "study/runner.hpp"

namespace rollnoise::study {

std::vector<io::StudyRow> collect_rows(const pipeline::StudyPlan& plan) {
  std::vector<io::StudyRow> rows;
  for (const pipeline::StudyCase& c : pipeline::expand(plan)) {
    io::StudyRow row;
    row.parameters = c;
    const auto record = is_complete(plan, c) ? io::read_case_record(pipeline::case_output(plan, c.index)) : std::nullopt;
    if (record) {
      row.status = io::CaseStatus::kComplete;
      row.record = *record;
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
  const std::vector<io::StudyRow> rows = collect_rows(plan);
  CollectSummary s;
  for (const auto& r : rows) {
    s.complete += r.status == io::CaseStatus::kComplete;
    s.failed += r.status == io::CaseStatus::kFailed;
    s.missing += r.status == io::CaseStatus::kMissing;
  }
  s.h5 = plan.output + "/study.h5";
  s.csv = plan.output + "/study.csv";
  io::write_study_table(s.h5, s.csv, plan, rows);
  return s;
}

}  // namespace rollnoise::study
