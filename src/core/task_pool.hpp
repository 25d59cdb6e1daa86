// A few independent tasks on a small pool of std::threads (the further wheels of a noise run, the
// orders n of the FE wheel): task(i, worker) for i = 0 .. n-1, each index exactly once, taken in
// increasing order by whichever thread is free. `worker` (0 .. workers-1) names the thread, for
// per-thread scratch (a solver with its own factorisation); 0 is the caller's. A task writes its
// result by index, so the results do not depend on the number of threads.
//
// The background threads start at construction; the caller may do other work and then calls
// finish(), which takes the remaining tasks on the caller's thread, joins the others and rethrows
// the exception of the LOWEST index that threw (the one a serial loop would have thrown first).
// A caller that has work of its own before finish() (Caller::busy) is one of the `workers` only
// from then on: the pool starts workers - 1 background threads even for fewer tasks than workers
// (one further wheel beside the main one runs at once, not after it), at most one per task.
// The destructor without finish() (the caller's own work threw) lets no further task start and
// joins.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

namespace rollnoise {

/// Threads for a `solver.threads` value: itself when > 0, else the hardware's; 1 to `most`.
inline int resolved_threads(int threads, int most = 4) {
  const int t = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(t, 1, most);
}

class TaskPool {
 public:
  using Task = std::function<void(std::size_t index, int worker)>;
  /// Whether the caller takes tasks from the start (ready: it calls finish() at once, e.g.
  /// parallel_for) or has work of its own first (busy).
  enum class Caller { ready, busy };

  /// Starts min(workers, n) - 1 background threads (ready), min(workers - 1, n) (busy); none for
  /// workers <= 1: all on finish().
  TaskPool(std::size_t n, int workers, Task task, Caller caller = Caller::ready)
      : n_(n), task_(std::move(task)), errors_(n) {
    const std::size_t most = static_cast<std::size_t>(std::max(workers, 1)) - 1;
    const std::size_t background = caller == Caller::busy
                                       ? std::min(most, n)
                                       : std::min(most + 1, std::max<std::size_t>(n, 1)) - 1;
    for (std::size_t w = 1; w <= background; ++w)
      threads_.emplace_back([this, w] { run(static_cast<int>(w)); });
  }
  ~TaskPool() {
    stop_ = true;
    join();
  }
  TaskPool(const TaskPool&) = delete;
  TaskPool& operator=(const TaskPool&) = delete;

  /// The remaining tasks on the caller's thread (worker 0), then the join; rethrows.
  void finish() {
    run(0);
    join();
    for (const std::exception_ptr& e : errors_)
      if (e) std::rethrow_exception(e);
  }

 private:
  void run(int worker) {
    for (std::size_t i = next_++; i < n_ && !stop_; i = next_++) {
      try {
        task_(i, worker);
      } catch (...) {
        errors_[i] = std::current_exception();
      }
    }
  }
  void join() {
    for (std::thread& t : threads_)
      if (t.joinable()) t.join();
  }

  std::size_t n_;
  Task task_;
  std::vector<std::exception_ptr> errors_;
  std::atomic<std::size_t> next_{0};
  std::atomic<bool> stop_{false};
  std::vector<std::thread> threads_;
};

/// task(i, worker) for i = 0 .. n-1 on `workers` threads (the caller's one of them); rethrows as
/// TaskPool::finish.
inline void parallel_for(std::size_t n, int workers, const TaskPool::Task& task) {
  TaskPool(n, workers, task).finish();
}

/// f(slice, lo, hi) for contiguous slices [lo, hi) of n items (a frequency grid's lines), one
/// slice per thread on up to `threads` threads and at least `min_items` items a slice (a slice's
/// start costs about as much as a few items; fewer, larger slices). Slice i is
/// [n i / slices, n (i + 1) / slices); returns the number of slices (0 for n = 0). Whether a result
/// may depend on the slicing is the caller's to rule out (each item computed on its own).
template <class F>
std::size_t for_slices(std::size_t n, int threads, const F& f, std::size_t min_items = 64) {
  if (n == 0) return 0;
  const std::size_t slices = std::clamp<std::size_t>(
      (n + min_items - 1) / min_items, 1, static_cast<std::size_t>(std::max(threads, 1)));
  parallel_for(slices, static_cast<int>(slices),
               [&](std::size_t i, int) { f(i, n * i / slices, n * (i + 1) / slices); });
  return slices;
}

}  // namespace rollnoise
