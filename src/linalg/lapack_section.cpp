#include "linalg/lapack_section.hpp"

#include <dlfcn.h>

namespace rollnoise::linalg {

namespace {

// OpenBLAS exports openblas_get_parallel(): 0 built single-threaded, 1 with pthreads, 2 with
// OpenMP. Any other library (no such symbol) is taken as reentrant.
bool loaded_lapack_reentrant() {
  using Parallel = int (*)();
  void* symbol = dlsym(RTLD_DEFAULT, "openblas_get_parallel");
  if (symbol == nullptr) return true;
  return reinterpret_cast<Parallel>(symbol)() != 0;
}

std::mutex& lapack_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

bool lapack_reentrant() {
  static const bool reentrant = loaded_lapack_reentrant();
  return reentrant;
}

LapackSection::LapackSection() : lock_(lapack_mutex(), std::defer_lock) {
  if (!lapack_reentrant()) lock_.lock();
}

}  // namespace rollnoise::linalg
