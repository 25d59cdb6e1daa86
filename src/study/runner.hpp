// Running the cases of a study (docs/study.md): locally with worker processes, one shard of it (a
// Slurm array task or a GNU parallel job), or one case; resuming where a run stopped.
//
// Each case is `rollnoise noise BASE --set key=value ...` run in a worker: its file case_NNNN.h5
// is written whole or not at all, so a complete file is a finished case and a rerun skips it if
// its `study_case` attribute (case_stamp) names the same parameters and the same digests of the
// case as run and of every model file it reads; a file computed from other inputs is stale and run
// again. A case that fails gets case_NNNN.error with its message; the others go on. A run holds a
// lock on each case of its shard (byte K of OUTPUT/.lock, fcntl): a second run on the same cases
// is refused, naming the process that holds them.
//
// Reuse (what a case does not need to compute again):
//   - cases that differ only in roughness.* keys share the curve state, the contact, the creep
//     sweep and the loop (stages 1-4 of pipeline/noise_pipeline.hpp): the study runs them as one
//     group in one worker, computes the loop once and adds each case's bands (the same bits as
//     computing again).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/case_reader.hpp"
#include "pipeline/study_plan.hpp"

namespace rollnoise::study {

struct RunOptions {
  int workers = 1;          ///< worker processes
  pipeline::Shard shard;    ///< the part of the study to run
  bool reuse = true;        ///< false: every case computes everything (for benchmarks)
  /// Called now and then with the cases finished (complete or failed) and the cases to run.
  std::function<void(long done, long total)> progress;
};

struct RunSummary {
  long cases = 0;      ///< in the shard
  long skipped = 0;    ///< already complete
  long completed = 0;  ///< run now, complete
  long failed = 0;
  long loops_computed = 0, loops_reused = 0;      ///< stages 1-4
  double seconds = 0.0;
  /// The cases that failed in this run, with their messages (also in their .error files).
  std::vector<std::pair<std::size_t, std::string>> failures;
};

/// Run the cases of the shard that are not complete. InputError for a study that cannot run (its
/// output folder cannot be created).
RunSummary run_study(const pipeline::StudyPlan& plan, const RunOptions& options);

/// Case `index` alone, in this process (skipped when complete): `rollnoise study STUDY --case K`,
/// the command `--list` prints for each case. InputError naming --case when out of range.
RunSummary run_one_case(const pipeline::StudyPlan& plan, std::size_t index);

/// The base case and the parameters of case `c` ("base PATH; case K: key=value, ...").
std::string case_label(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c);
/// The stamp that marks a complete case of this study in its file: case_label, then the digests
/// (io::digest) of the case as run (`reader`: base + axes, as TOML text) and of the bytes of every
/// model file it reads (io::case_input_files).
std::string case_stamp(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c, const io::CaseReader& reader);
/// The same, reading the case now; nullopt if it cannot be read (it will fail when run).
std::optional<std::string> case_stamp(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c);

enum class CaseState { kNotRun, kComplete, kStale };
/// kComplete: the case's file holds this study's stamp as of now; kStale: a file of this case
/// computed from other inputs (the base case, an axis or a model file changed since) or of another
/// study; kNotRun: no readable file.
CaseState case_state(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c);
/// case_state == kComplete.
bool is_complete(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c);

/// The groups of cases that share stages 1-4 (equal overrides but for roughness.* keys), in the
/// order of their first case.
std::vector<std::vector<std::size_t>> reuse_groups(const pipeline::StudyPlan& plan,
                                                   const std::vector<pipeline::StudyCase>& cases,
                                                   const std::vector<std::size_t>& selection);

}  // namespace rollnoise::study
