// rollnoise bench --sweep-cost NX,...: time and peak memory of the linear model's 1000-frequency
// sweep (f and g at 10 Hz - 10 kHz, clipped to the grid's Nyquist limit; model set-up included)
// per grid, on the dense path (Cholesky of K0) and the matrix-free path (PCG). Each run
// is a child process (fork), so that its peak resident memory (VmHWM of /proc/self/status) is its
// own; the dense path is skipped where its factor alone (8 r^2) would exceed 4 GB.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "io/contact_case.hpp"
#include "pipeline/grid_study.hpp"

namespace rollnoise::cli {

pipeline::GridStudyCase bench_study_case(const io::CaseReader& reader, const io::ContactCase& base);

namespace {

struct SweepCost {
  int ny = 0, contact = 0, r = 0, block_steps = 0, threads = 0;
  double t_steady = 0, t_sweep = 0, peak_mb = 0, its_per_solve = 0;
  bool ok = false;
};

double vm_hwm_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;  // kB
  return NAN;
}

SweepCost measure(const pipeline::GridStudyCase& c, int nx, nss::LinearSolver solver, int threads) {
  using Clock = std::chrono::steady_clock;
  auto secs = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  SweepCost out;
  const contact::Grid g = pipeline::study_grid(c, nx, &out.ny);
  const contact::HertzContact hz = contact::hertz_from_semi_axes(c.a, c.b, c.normal_force, c.material);
  auto t = Clock::now();
  const contact::ContactPatch patch =
      contact::solve_patch(g, c.material, contact::quadratic_distance(g, hz.A, hz.B), c.normal_force);
  const auto steady = contact::solve_steady_rolling(patch.influence, patch.normal.pn, c.steady, c.tangential);
  out.t_steady = secs(t);
  out.contact = patch.normal.contact_elements();
  t = Clock::now();
  nss::LinearModelInput in{c.steady.mu, c.steady.speed, c.steady.spin_offset, c.steady.falling, solver};
  in.threads = threads;
  const nss::LinearContactModel m(patch, steady, in);
  out.r = m.reduced_unknowns();
  out.threads = m.threads();
  if (!m.matrix_free() && 8.0 * out.r * out.r > 4e9) return out;  // dense factor alone above 4 GB
  std::vector<double> f;
  for (int i = 0; i < 1000; ++i) f.push_back(std::min(10.0 * std::pow(1000.0, i / 999.0), m.nyquist_frequency()));
  m.creep_coefficients(f);
  m.normal_load_coefficients(f);
  out.t_sweep = secs(t);
  out.block_steps = m.sweep_info().block_steps;
  out.its_per_solve = m.inner_solves() > 0 ? double(m.inner_iterations()) / m.inner_solves() : 0.0;
  out.peak_mb = vm_hwm_mb();
  out.ok = true;
  return out;
}

// measure() in a child process; the result comes back through a pipe.
SweepCost measure_in_child(const pipeline::GridStudyCase& c, int nx, nss::LinearSolver solver, int threads) {
  int fd[2];
  SweepCost res;
  if (pipe(fd) != 0) return res;
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    SweepCost s;
    try {
      s = measure(c, nx, solver, threads);
    } catch (...) {
      s.ok = false;
    }
    const ssize_t w = write(fd[1], &s, sizeof s);
    _exit(w == ssize_t(sizeof s) ? 0 : 1);
  }
  close(fd[1]);
  if (pid > 0 && read(fd[0], &res, sizeof res) != ssize_t(sizeof res)) res = SweepCost{};
  close(fd[0]);
  if (pid > 0) waitpid(pid, nullptr, 0);
  return res;
}

}  // namespace

int run_sweep_cost(const CommonOptions& o, const std::vector<int>& grids) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const io::ContactCase base = io::read_contact_case(reader);
  if (base.geometry != "hertz") reader.fail("contact.geometry", "bench needs a Hertzian case");
  const pipeline::GridStudyCase study = bench_study_case(reader, base);
  const contact::Creepage& mc = study.steady.creepage;
  std::printf(
      "%s: cost of the 1000-frequency sweep (f and g, 10 Hz - 10 kHz, model set-up included) at the mean "
      "creepage (%g, %g, %g rad/m); each run a child process, peak = its VmHWM\n",
      reader.name().c_str(), mc.xi_x, mc.xi_y, mc.phi);
  std::printf("%5s %5s %7s %7s %12s %9s %9s %10s %6s %9s %7s\n", "nx", "ny", "contact", "r", "path", "steady[s]",
              "sweep[s]", "peak[MB]", "steps", "PCG its", "threads");
  for (int nx : grids)
    for (nss::LinearSolver s : {nss::LinearSolver::dense, nss::LinearSolver::matrix_free}) {
      const SweepCost r = measure_in_child(study, nx, s, base.threads);
      const char* path = s == nss::LinearSolver::dense ? "dense" : "matrix-free";
      if (!r.ok) {
        std::printf("%5d %5d %7d %7d %12s   (skipped: dense factor above 4 GB, or failed)\n", nx, r.ny, r.contact,
                    r.r, path);
        continue;
      }
      std::printf("%5d %5d %7d %7d %12s %9.2f %9.3f %10.0f %6d %9.1f %7d\n", nx, r.ny, r.contact, r.r, path,
                  r.t_steady, r.t_sweep, r.peak_mb, r.block_steps, r.its_per_solve, r.threads);
    }
  return 0;
}

}  // namespace rollnoise::cli
