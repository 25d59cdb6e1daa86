// Entering the system's LAPACK from several threads at once.
//
// The waveguide rail (rail_waveguide.cpp: zgeev, dstevx; rail_waveguide_point.cpp: zhseqr) calls
// LAPACK once per frequency, and its frequencies run on up to solver.threads threads at once. That
// is safe with the LAPACK and BLAS Debian installs by default (the reference libraries, built with
// -frecursive: no static work arrays) and with OpenBLAS built for threads (libopenblas0-pthread,
// -openmp), which locks its shared buffers. It is NOT safe with OpenBLAS built single-threaded
// without its locking option (USE_LOCKING; OpenBLAS issues #1761, #2126, PR #2136), which is what
// Debian 12's libopenblas0-serial is: once that package is installed it becomes the system's LAPACK
// (update-alternatives), and concurrent calls then share its memory buffers and return wrong
// values. Measured on this project's waveguide: one frequency in a hundred off by O(1) on two
// threads, none on one (docs/record/performance_waveguide.md Sec. 7).
//
// So every LAPACK call holds a LapackSection: a process-wide lock where the loaded library is
// OpenBLAS built single-threaded (openblas_get_parallel() == 0, found by the dynamic linker),
// nothing otherwise. The lock costs that library the overlap of the LAPACK part of the
// frequencies; the results then equal a single thread's, as with the other libraries.
#pragma once

#include <mutex>

namespace rollnoise::linalg {

/// Whether the LAPACK loaded in this process may be entered from several threads at once (false
/// for an OpenBLAS built single-threaded; decided once per process).
bool lapack_reentrant();

/// Held (as a scope) around each LAPACK call: the process-wide lock of the LAPACK calls where
/// lapack_reentrant() is false, nothing otherwise.
class LapackSection {
 public:
  LapackSection();

 private:
  std::unique_lock<std::mutex> lock_;
};

}  // namespace rollnoise::linalg
