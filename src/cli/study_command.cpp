// rollnoise study / collect: a parameter study of noise cases (docs/study.md). Read the study
// file, run its cases (study/runner.hpp) or merge them (study/collect.hpp), print a summary.
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "io/output_files.hpp"
#include "io/study_file.hpp"
#include "study/collect.hpp"
#include "study/runner.hpp"

namespace rollnoise::cli {
namespace {

// This program, absolute, for the commands --list prints.
std::string program_path() {
  char buf[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  return n > 0 ? std::string(buf, std::size_t(n)) : std::string("rollnoise");
}

}  // namespace

int run_study(const StudyOptions& o) {
  const pipeline::StudyPlan plan = io::read_study_file(o.study_file);
  const pipeline::Shard shard = o.shard.empty() ? pipeline::shard_from_environment() : pipeline::parse_shard(o.shard);
  const std::vector<pipeline::StudyCase> cases = pipeline::expand(plan);

  if (o.list) {  // one self-contained command per case, for GNU parallel or HyperQueue
    const std::string program = io::shell_quote({program_path()}), file = io::shell_quote({plan.file});
    for (const auto& c : cases)
      if (shard.contains(c.index) &&
          (std::printf("%s study %s --case %zu -q\n", program.c_str(), file.c_str(), c.index) < 0 ||
           std::ferror(stdout)))
        break;  // stdout lost (a full disk): main's check (finish_process) reports it, exit 1
    return 0;
  }
  if (o.case_index >= 0) {
    const study::RunSummary s = study::run_one_case(plan, std::size_t(o.case_index));
    if (!o.quiet)
      std::printf("%s: case %ld %s (%.2f s)\n", plan.file.c_str(), o.case_index,
                  s.skipped ? "already complete" : s.failed ? "failed (see its .error file)" : "complete", s.seconds);
    return s.failed > 0 ? 1 : 0;
  }

  study::RunOptions ro;
  ro.workers = o.workers > 0 ? o.workers : int(std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN)));
  ro.shard = shard;
  ro.reuse = !o.no_reuse;
  std::optional<Progress> progress;  // once the cases to run are known
  ro.progress = [&](long done, long total) {
    if (!progress) progress.emplace("study", total, o.quiet, "cases");
    progress->update(done);
  };
  const study::RunSummary s = study::run_study(plan, ro);
  if (progress) progress->finish();
  std::printf("study %s: %ld cases%s: %ld complete now, %ld already complete, %ld failed; %d workers, %.1f s, %.2f "
              "cases/s; loops computed %ld, reused %ld; output %s\n",
              plan.file.c_str(), s.cases,
              shard.count > 1 ? (" in shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count)).c_str()
                              : "",
              s.completed, s.skipped, s.failed, ro.workers, s.seconds,
              s.seconds > 0 ? double(s.completed + s.failed) / s.seconds : 0.0, s.loops_computed, s.loops_reused,
              plan.output.c_str());
  if (!s.failures.empty()) {  // the log of failures (also in OUTPUT/case_NNNN.error and the collected table)
    std::fprintf(stderr, "%zu cases failed:\n", s.failures.size());
    for (const auto& [index, message] : s.failures)
      std::fprintf(stderr, "  case %zu (%s): %s\n", index, pipeline::describe(plan, cases[index]).c_str(), message.c_str());
  }
  return s.failed > 0 ? 1 : 0;  // a study with a failed case is not a success (the log above names them)
}

int run_collect(const StudyOptions& o) {
  const pipeline::StudyPlan plan = io::read_study_file(o.study_file);
  const study::CollectSummary s = study::collect(plan);
  std::printf("collect %s: %ld complete, %ld failed, %ld missing, %ld stale%s\nwrote %s\nwrote %s\n", plan.file.c_str(),
              s.complete, s.failed, s.missing, s.stale,
              s.stale ? " (computed from other inputs: run the study again)" : "", s.h5.c_str(), s.csv.c_str());
  return 0;
}

}  // namespace rollnoise::cli
