#include "study/runner.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <new>
#include <optional>

#include "core/errors.hpp"
#include "io/input_file.hpp"
#include "io/noise_case.hpp"
#include "io/output_files.hpp"
#include "io/study_output.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::study {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr int kMaxWorkers = 256;

// Counters the workers share with the parent (anonymous shared memory: they are separate processes).
struct Shared {
  std::atomic<long> next_group{0}, done{0}, failed{0};
  std::atomic<long> loops_computed{0}, loops_reused{0};
  std::atomic<long> current[kMaxWorkers];  ///< the case each worker is running, -1: none
  /// Several worker processes share the cores: a case whose solver.threads is automatic (0) runs
  /// on one thread (its wheels one after the other) instead of one per core in every worker.
  bool one_thread_per_case = false;
};

class SharedCounters {
 public:
  explicit SharedCounters(bool across_processes) {
    void* p = across_processes ? ::mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0)
                               : ::operator new(sizeof(Shared));
    if (p == MAP_FAILED) throw NumericalError("study: cannot share memory with the worker processes");
    shared_ = new (p) Shared;
    for (auto& c : shared_->current) c = -1;
    mapped_ = across_processes;
  }
  ~SharedCounters() {
    shared_->~Shared();
    if (mapped_)
      ::munmap(shared_, sizeof(Shared));
    else
      ::operator delete(shared_);
  }
  SharedCounters(const SharedCounters&) = delete;
  SharedCounters& operator=(const SharedCounters&) = delete;
  Shared& get() { return *shared_; }

 private:
  Shared* shared_;
  bool mapped_;
};

// A case that failed: its error file (and no results file of an earlier run with other inputs).
void record_failure(const pipeline::StudyPlan& plan, std::size_t index, const std::string& message) {
  std::error_code ec;
  fs::remove(pipeline::case_output(plan, index), ec);
  try {
    io::write_case_error(pipeline::case_error(plan, index), message);
  } catch (const std::exception& e) {  // e.g. the disk is full: the failure goes to stderr instead
    std::fprintf(stderr, "study: case %zu failed (%s), and its error file could not be written: %s\n", index,
                 message.c_str(), e.what());
  }
}

// The cases of one reuse group, in this process: stages 1-4 once (when reusing), each case's bands,
// each case's file.
void run_group(const pipeline::StudyPlan& plan, const std::vector<pipeline::StudyCase>& cases,
               const std::vector<std::size_t>& group, bool reuse, Shared& shared, int slot,
               const std::function<void()>& after_case) {
  std::optional<pipeline::NoiseResult> loop;
  for (std::size_t index : group) {
    const pipeline::StudyCase& c = cases[index];
    shared.current[slot] = long(index);
    const auto t0 = Clock::now();
    try {
      const io::CaseReader reader = io::CaseReader::from_file(plan.base, pipeline::overrides(plan, c));
      io::NoiseInputs in = io::read_noise_inputs(reader);
      if (shared.one_thread_per_case && in.contact.threads == 0) in.contact.threads = 1;
      pipeline::NoiseResult r;
      if (loop) {
        r = *loop;  // the same inputs up to the roughness (reuse_groups): the same stages 1-4 and wheels
        ++shared.loops_reused;
        io::within_case(reader, [&] { pipeline::add_bands(r, in.noise); });
      } else {
        // as `rollnoise noise`: the main loop, every wheel of curve.wheels (/noise/wheels) and the bands
        r = io::within_case(reader, [&] { return pipeline::run_noise(std::move(in.contact), in.noise); });
        ++shared.loops_computed;
        if (reuse) loop = r;
      }
      io::write_study_case(pipeline::case_output(plan, index), reader, in.noise, r, case_stamp(plan, c, reader),
                           seconds_since(t0));
      std::error_code ec;
      fs::remove(pipeline::case_error(plan, index), ec);
      ++shared.done;
    } catch (const InputError& e) {
      record_failure(plan, index, std::string("input error: ") + e.what());
      ++shared.failed;
    } catch (const NumericalError& e) {
      record_failure(plan, index, std::string("numerical failure: ") + e.what());
      ++shared.failed;
    } catch (const std::exception& e) {
      record_failure(plan, index, std::string("failure: ") + e.what());
      ++shared.failed;
    }
    shared.current[slot] = -1;
    if (after_case) after_case();
  }
}

// Take groups from the shared queue until it is empty.
void work(const pipeline::StudyPlan& plan, const std::vector<pipeline::StudyCase>& cases,
          const std::vector<std::vector<std::size_t>>& groups, bool reuse, Shared& shared, int slot,
          const std::function<void()>& after_case) {
  for (long g = shared.next_group++; g < long(groups.size()); g = shared.next_group++)
    run_group(plan, cases, groups[g], reuse, shared, slot, after_case);
}

// A worker process in `slot`: the queue's groups, or group `only` alone (>= 0); it dies with the
// parent (a killed study leaves no orphans).
pid_t start_worker(const pipeline::StudyPlan& plan, const std::vector<pipeline::StudyCase>& cases,
                   const std::vector<std::vector<std::size_t>>& groups, bool reuse, Shared& shared,
                   int slot, long only = -1) {
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw NumericalError("study: cannot start a worker process");
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() == 1) ::_exit(1);  // the parent is already gone
    if (only >= 0)
      run_group(plan, cases, groups[std::size_t(only)], reuse, shared, slot, {});
    else
      work(plan, cases, groups, reuse, shared, slot, {});
    std::fflush(nullptr);
    ::_exit(0);
  }
  return pid;
}

// `workers` worker processes (group `only` alone in one of them where >= 0), until they are done;
// one that dies inside a case fails that case and, while the queue has groups, is replaced.
void run_workers(const pipeline::StudyPlan& plan, const std::vector<pipeline::StudyCase>& cases,
                 const std::vector<std::vector<std::size_t>>& groups, bool reuse, Shared& shared,
                 int workers, long only, const std::function<void()>& report) {
  std::map<pid_t, int> slot_of;
  for (int k = 0; k < workers; ++k)
    slot_of[start_worker(plan, cases, groups, reuse, shared, k, only)] = k;
  while (!slot_of.empty()) {
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid > 0 && slot_of.count(pid)) {
      const int slot = slot_of[pid];
      slot_of.erase(pid);
      const long index = shared.current[slot];
      if (index >= 0 && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
        // the worker died inside a case (a crash, or killed): that case failed, the queue goes on
        record_failure(plan, std::size_t(index),
                       WIFSIGNALED(status)
                           ? "failure: the worker process died of signal " +
                                 std::to_string(WTERMSIG(status)) + " while running this case"
                           : "failure: the worker process stopped while running this case");
        ++shared.failed;
        shared.current[slot] = -1;
        if (only < 0 && shared.next_group < long(groups.size()))
          slot_of[start_worker(plan, cases, groups, reuse, shared, slot)] = slot;
      }
    } else if (pid < 0) {
      break;
    } else {
      report();
      ::usleep(100000);
    }
  }
}

void add_counts(RunSummary& s, const Shared& shared) {
  s.completed = shared.done;
  s.failed = shared.failed;
  s.loops_computed = shared.loops_computed;
  s.loops_reused = shared.loops_reused;
}

// Byte K of OUTPUT/.lock locked (fcntl, exclusive, released when the run ends however it ends) for
// every case K this run may compute: a second run on any of them is refused, naming the first.
class CaseLocks {
 public:
  CaseLocks(const pipeline::StudyPlan& plan, const std::vector<std::size_t>& indices) {
    const std::string path = plan.output + "/.lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd_ < 0)
      throw InputError("output", plan.file + ": output: cannot open the lock file " + path + ": " + std::strerror(errno));
    for (std::size_t i = 0; i < indices.size();) {  // contiguous cases as one range
      std::size_t j = i + 1;
      while (j < indices.size() && indices[j] == indices[j - 1] + 1) ++j;
      struct flock range {};
      range.l_type = F_WRLCK;
      range.l_whence = SEEK_SET;
      range.l_start = off_t(indices[i]);
      range.l_len = off_t(indices[j - 1] - indices[i] + 1);
      if (::fcntl(fd_, F_SETLK, &range) != 0) {
        if (errno != EACCES && errno != EAGAIN) {  // no locks on this file system (ENOLCK): run unlocked
          std::fprintf(stderr, "study: warning: cannot lock %s (%s); concurrent runs are not detected\n",
                       path.c_str(), std::strerror(errno));
          return;
        }
        struct flock holder = range;
        const bool known = ::fcntl(fd_, F_GETLK, &holder) == 0 && holder.l_type != F_UNLCK;
        ::close(fd_);
        throw InputError("output", plan.file + ": output " + plan.output + ": another rollnoise study" +
                                       (known ? " (process " + std::to_string(holder.l_pid) + ")" : std::string()) +
                                       " is running cases of this study in this folder (from case " +
                                       std::to_string(known ? std::size_t(holder.l_start) : indices[i]) +
                                       "); wait for it to end, or give each run its own --shard");
      }
      i = j;
    }
  }
  ~CaseLocks() {
    if (fd_ >= 0) ::close(fd_);
  }
  CaseLocks(const CaseLocks&) = delete;
  CaseLocks& operator=(const CaseLocks&) = delete;

 private:
  int fd_ = -1;
};

void prepare_output(const pipeline::StudyPlan& plan) {
  std::error_code ec;
  fs::create_directories(plan.output, ec);
  if (ec || !fs::is_directory(plan.output))
    throw InputError("output", plan.file + ": output: cannot create the folder " + plan.output);
}

}  // namespace

std::string case_stamp(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c, const io::CaseReader& reader) {
  // the case as run (base + axes, as TOML) and the bytes of every model file it reads
  std::string inputs = "case " + io::digest(reader.toml_text());
  for (const io::InputFile& f : io::case_input_files(reader))
    if (f.what != "the case file") inputs += ", " + f.what + " " + io::digest(io::read_input(f.path, f.what, f.what));
  return case_label(plan, c) + "; inputs " + inputs;
}

std::string case_label(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c) {
  return "base " + plan.base + "; case " + std::to_string(c.index) + ": " + pipeline::describe(plan, c);
}

std::optional<std::string> case_stamp(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c) {
  try {
    return case_stamp(plan, c, io::CaseReader::from_file(plan.base, pipeline::overrides(plan, c)));
  } catch (const InputError&) {
    return std::nullopt;  // a case that cannot be read is never complete (it fails when run)
  }
}

CaseState case_state(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c) {
  const auto stamp = io::read_case_stamp(pipeline::case_output(plan, c.index));
  if (!stamp) return CaseState::kNotRun;
  const auto now = case_stamp(plan, c);
  if (now && *stamp == *now) return CaseState::kComplete;
  return CaseState::kStale;
}

bool is_complete(const pipeline::StudyPlan& plan, const pipeline::StudyCase& c) {
  return case_state(plan, c) == CaseState::kComplete;
}

std::vector<std::vector<std::size_t>> reuse_groups(const pipeline::StudyPlan& plan,
                                                   const std::vector<pipeline::StudyCase>& cases,
                                                   const std::vector<std::size_t>& selection) {
  // The key: the values of every axis but the roughness.* ones (only stage 5 reads those).
  std::map<std::string, std::size_t> group_of;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t index : selection) {
    std::string key;
    for (std::size_t a = 0; a < plan.axes.size(); ++a)
      if (plan.axes[a].key.rfind("roughness.", 0) != 0) key += plan.axes[a].key + "=" + cases[index].values[a].toml + "\n";
    const auto [it, added] = group_of.emplace(key, groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(index);
  }
  return groups;
}

RunSummary run_study(const pipeline::StudyPlan& plan, const RunOptions& o) {
  const auto t0 = Clock::now();
  const std::vector<pipeline::StudyCase> cases = pipeline::expand(plan);
  prepare_output(plan);
  std::vector<std::size_t> shard;
  for (const auto& c : cases)
    if (o.shard.contains(c.index)) shard.push_back(c.index);
  const CaseLocks locks(plan, shard);
  RunSummary s;
  std::vector<std::size_t> selection;
  for (std::size_t index : shard) {
    const pipeline::StudyCase& c = cases[index];
    ++s.cases;
    if (is_complete(plan, c))
      ++s.skipped;
    else
      selection.push_back(c.index);
  }
  std::vector<std::vector<std::size_t>> groups;
  if (o.reuse) {
    groups = reuse_groups(plan, cases, selection);
  } else {
    for (std::size_t i : selection) groups.push_back({i});
  }
  const long total = long(selection.size());
  const int workers = int(std::min<long>({long(std::max(1, o.workers)), long(groups.size()), long(kMaxWorkers)}));

  SharedCounters shared(workers > 1);
  auto report = [&] {
    if (o.progress) o.progress(shared.get().done + shared.get().failed, total);
  };
  if (workers <= 1) {
    work(plan, cases, groups, o.reuse, shared.get(), 0, report);
  } else {
    // The first group alone first, on every thread: it fills the cache folder with what the cases
    // share (the wheel's modes and radiation, the rail's samplings and section grams), which
    // workers started together would each compute; then the workers, one thread a case.
    shared.get().next_group = 1;
    run_workers(plan, cases, groups, o.reuse, shared.get(), 1, 0, report);
    shared.get().one_thread_per_case = true;
    run_workers(plan, cases, groups, o.reuse, shared.get(), workers, -1, report);
  }
  report();
  add_counts(s, shared.get());
  for (std::size_t index : selection)
    if (const auto message = io::read_case_error(pipeline::case_error(plan, index))) s.failures.push_back({index, *message});
  s.seconds = seconds_since(t0);
  return s;
}

RunSummary run_one_case(const pipeline::StudyPlan& plan, std::size_t index) {
  const auto t0 = Clock::now();
  const std::vector<pipeline::StudyCase> cases = pipeline::expand(plan);
  if (index >= cases.size())
    throw InputError("--case", "the study has cases 0 to " + std::to_string(cases.size() - 1) + ", not " +
                                   std::to_string(index));
  prepare_output(plan);
  const CaseLocks locks(plan, {index});
  RunSummary s;
  s.cases = 1;
  if (is_complete(plan, cases[index])) {
    s.skipped = 1;
  } else {
    SharedCounters shared(false);
    work(plan, cases, {{index}}, false, shared.get(), 0, {});
    add_counts(s, shared.get());
  }
  s.seconds = seconds_since(t0);
  return s;
}

}  // namespace rollnoise::study
