// rollnoise steady: the normal problem and steady rolling at the mean creepage, or a sweep of
// steady solutions over any case key (--sweep).
#include <chrono>
#include <memory>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/contact_reference_report.hpp"
#include "cli/progress.hpp"
#include "contact/forces.hpp"
#include "contact/steady_rolling.hpp"
#include "core/errors.hpp"
#include "io/contact_case.hpp"
#include "io/contact_output.hpp"
#include "io/sweep.hpp"
#include "pipeline/steady_sweep.hpp"

namespace rollnoise::cli {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

void print_solution(const contact::Grid& g, const contact::TangentialSolution& s, double ms) {
  const auto f = contact::total_forces(g, s.px, s.py);
  std::printf("  Fx = %.6g N   Fy = %.6g N   Mz = %.6g N m\n", f.Fx, f.Fy, f.Mz);
  std::printf(
      "  adhesion %d, slip %d elements; %d Newton iterations (%d GMRES, %d LU), residual %.2g; "
      "%.1f ms\n",
      s.count(contact::ElementState::adhesion), s.count(contact::ElementState::slip), s.iterations,
      s.linear_iterations, s.factorisations, s.residual, ms);
}

}  // namespace

int run_steady(const CommonOptions& o, const std::vector<std::string>& sweeps) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::ContactCase cc = io::read_contact_case(reader);
  io::within_case(reader, [&] { cc = pipeline::placed_contact(std::move(cc)); });
  if (sweeps.size() > 1) throw InputError("--sweep", "one --sweep per run");
  if (!sweeps.empty() && !o.contact_reference.empty())
    throw InputError("--reference", "--reference compares the steady solution; not with --sweep");
  const auto reference = read_reference(o);  // CONTACT's run: bad files fail before any work
  // Read every sweep point before any work, so that bad input fails early.
  std::vector<double> values;
  std::vector<io::ContactCase> point_cases;  // the points' readers are not kept (memory)
  if (!sweeps.empty())
    for (const auto& kv : io::expand_sweep(sweeps[0], reader, cc, values)) {
      const io::CaseReader point = reader.with(kv);
      point_cases.push_back(io::read_contact_case(point));
      io::within_case(point, [&] { point_cases.back() = pipeline::placed_contact(std::move(point_cases.back())); });
    }
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_case(w, reader);

  auto t0 = Clock::now();
  const contact::ContactPatch patch = io::within_case(reader, [&] { return pipeline::solve_patch(cc); });
  cc.grid = patch.grid;  // profiles: the grid may have been enlarged
  std::printf("%s: normal problem on %d x %d elements (dx = %.4g mm, dy = %.4g mm)\n",
              reader.name().c_str(), cc.grid.nx, cc.grid.ny, cc.grid.dx * 1e3, cc.grid.dy * 1e3);
  std::printf("  N = %.6g N, %d elements in contact, p_max = %.6g MPa, approach = %.6g mm; %d "
              "iterations, %.1f ms\n",
              patch.normal.force, patch.normal.contact_elements(), patch.normal.max_pressure() * 1e-6,
              patch.normal.approach * 1e3, patch.normal.iterations, ms_since(t0));
  io::write_patch(w, patch);

  if (sweeps.empty()) {
    t0 = Clock::now();
    const auto s = contact::solve_steady_rolling(patch.influence, patch.normal.pn, cc.steady_input(),
                                                 cc.tangential);
    std::printf("steady rolling at creepage (%g, %g, %g rad/m), mu = %g, V = %g m/s:\n",
                cc.creepage.xi_x, cc.creepage.xi_y, cc.creepage.phi, cc.mu, cc.speed);
    print_solution(cc.grid, s, ms_since(t0));
    io::write_tangential(w, "/steady", cc.grid, cc.creepage, s);
    if (reference) {
      const auto f = contact::total_forces(cc.grid, s.px, s.py);
      report_steady_reference(w, *reference, {f.Fx, f.Fy, f.Mz});
    }
  } else {
    std::vector<double> force, creep;
    std::vector<int> n_adh, n_slip, iters;
    std::printf("sweep %s (%zu points):\n%12s %12s %12s %12s %8s %8s\n", sweeps[0].c_str(),
                point_cases.size(), "value", "Fx [N]", "Fy [N]", "Mz [N m]", "adhesion", "slip");
    Progress progress("sweep", long(point_cases.size()), o.quiet, "points");
    io::within_case(reader, [&] {
      return pipeline::steady_sweep(cc, patch, point_cases, [&](std::size_t i, const io::ContactCase& pc,
                                                                const contact::TangentialSolution& s) {
        progress.update(long(i) + 1);
        const auto f = contact::total_forces(pc.grid, s.px, s.py);
        std::printf("%12.6g %12.6g %12.6g %12.6g %8d %8d\n", values[i], f.Fx, f.Fy, f.Mz,
                    s.count(contact::ElementState::adhesion), s.count(contact::ElementState::slip));
        force.insert(force.end(), {f.Fx, f.Fy, f.Mz});
        creep.insert(creep.end(), {pc.creepage.xi_x, pc.creepage.xi_y, pc.creepage.phi});
        n_adh.push_back(s.count(contact::ElementState::adhesion));
        n_slip.push_back(s.count(contact::ElementState::slip));
        iters.push_back(s.iterations);
      });
    });
    progress.finish();
    const std::size_t n = point_cases.size();
    w.attribute("/sweep", "spec", sweeps[0]);
    w.write("/sweep/value", values, {n}, "as the swept key (index for TOML-array sweeps)");
    w.write("/sweep/creepage", creep, {n, 3}, "-, -, rad/m");
    w.write("/sweep/force", force, {n, 3}, "N, N, N m");
    w.write("/sweep/n_adhesion", n_adh, {n}, "-");
    w.write("/sweep/n_slip", n_slip, {n}, "-");
    w.write("/sweep/iterations", iters, {n}, "-");
  }
  w.commit();
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
