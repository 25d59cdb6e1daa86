#include "pipeline/limits.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::pipeline {

double Limits::memory_bytes() const {
  return memory > 0.0 ? memory : default_memory_limit();
}

double default_memory_limit() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 4.0 * 1024 * 1024 * 1024;
  return 0.5 * double(pages) * double(page);
}

void check_memory(const Limits& limits, const std::string& key, const std::string& what,
                  double bytes) {
  const double limit = limits.memory_bytes();
  if (bytes <= limit) return;
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "%s need an estimated %.3g GB of memory, above limits.memory = %.3g GB (%s; "
                "docs/conventions.md, "
                "Limits; raise it with --set limits.memory=BYTES if you mean it)",
                what.c_str(), bytes * 1e-9, limit * 1e-9,
                limits.memory > 0.0 ? "as set" : "half the physical memory");
  throw InputError(key, msg);
}

void check_size(const Limits& limits, const std::string& key, double count, const std::string& what,
                double bytes) {
  if (!(count <= double(limits.steps))) {
    char msg[300];
    std::snprintf(
        msg, sizeof msg,
        "%.4g %s exceed limits.steps = %ld (docs/conventions.md, Limits; raise it with --set "
        "limits.steps=N if you mean it)",
        count, what.c_str(), limits.steps);
    throw InputError(key, msg);
  }
  char counted[200];
  std::snprintf(counted, sizeof counted, "%.4g %s", count, what.c_str());
  check_memory(limits, key, counted, bytes);
}

double contact_bytes(const ContactCase& c) {
  const double n = double(c.grid.nx) * double(c.grid.ny);
  const double dense = 16.0 * n * n;
  // The reduced unknowns r (2 per adhesion, 1 per slip element) are known only after the steady
  // solve: bounded by 2n. Dense path (solver.linear_model = "dense", or "auto" where even r = 2n
  // stays dense): 16 n^2 as measured. Otherwise the matrix-free estimate at r = 2n, and where
  // "auto" may still take the dense path (r <= nss::kDenseReducedUnknowns) that one's at its
  // largest r (nss::linear_model_bytes).
  const double r_max = 2.0 * n;
  if (!nss::uses_matrix_free(c.linear_solver, int(std::min(r_max, 1e9)))) return dense;
  const int grid = int(std::min(n, 1e9)), Lc = c.grid.nx;
  const double mf = nss::linear_model_bytes(nss::LinearSolver::matrix_free, int(std::min(r_max, 1e9)), grid, Lc);
  if (c.linear_solver == nss::LinearSolver::matrix_free) return mf;
  return std::max(mf, std::min(dense, nss::linear_model_bytes(nss::LinearSolver::dense, nss::kDenseReducedUnknowns,
                                                              grid, Lc)));
}

double transient_bytes(double steps) {
  return 20.0 * sizeof(double) * steps;
}

double sweep_bytes(const ContactCase& c, double points) {
  const double n = double(c.grid.nx) * double(c.grid.ny);
  return points * (double(sizeof(ContactCase)) + 33.0 * n);
}

double frequency_bytes(double frequencies) {
  return 4096.0 * frequencies;
}

void check_contact_size(const ContactCase& c) {
  char what[160];
  std::snprintf(what, sizeof what,
                "the contact matrices and the linear model of %d x %d grid elements (docs/conventions.md, "
                "Limits)",
                c.grid.nx, c.grid.ny);
  check_memory(c.limits, "grid.nx", what, contact_bytes(c));
}

}  // namespace rollnoise::pipeline
