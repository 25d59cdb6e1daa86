// rollnoise transient: unsteady rolling (paper Eq. 2) under the case's creepage and normal-load
// history, from the steady state at the mean creepage (and mean load) or from zero tractions.
// Read the case, run the transient pipeline (pipeline/transient.hpp), write /transient/*.
#include <algorithm>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "io/contact_case.hpp"
#include "io/contact_output.hpp"
#include "io/excitation.hpp"
#include "pipeline/transient.hpp"

namespace rollnoise::cli {

int run_transient(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::ContactCase cc = io::read_contact_case(reader);
  pipeline::TransientInput in{io::read_excitation(reader), reader.real("transient.duration"),
                              reader.string("transient.start") == "steady", reader.real_list("transient.snapshots")};
  io::within_case(reader, [&] {
    cc = pipeline::placed_contact(std::move(cc));
    pipeline::check_transient(cc, in);  // before any solve
  });
  const std::string out = output_path(o, reader.name());

  Progress progress("transient", pipeline::transient_steps(cc, in.duration, cc.grid.dx), o.quiet, "steps");
  const pipeline::TransientResult r =
      io::within_case(reader, [&] { return pipeline::run_transient(cc, in, [&](long k) { progress.update(k); }); });
  progress.finish();

  io::Hdf5Writer w(out);
  io::write_case(w, reader);
  io::write_patch(w, *r.patch);
  const contact::Grid& g = r.patch->grid;
  for (const auto& s : r.snapshots) {
    const std::string grp = "/transient/snapshots/" + std::to_string(s.index);
    io::write_tangential(w, grp, g, s.creepage, s.solution);
    w.write(grp + "/time", s.time, "s");
  }
  const std::size_t nt = r.time.size();
  w.write("/transient/time", r.time, {nt}, "s");
  w.write("/transient/creepage", r.creepage, {nt, 3}, "-, -, rad/m");
  w.write("/transient/force", r.force, {nt, 3}, "N, N, N m");
  w.write("/transient/n_adhesion", r.n_adhesion, {nt}, "-");
  w.write("/transient/n_slip", r.n_slip, {nt}, "-");
  w.write("/transient/normal_force", r.load, {nt}, "N");
  io::write_excitation(w, "/transient/excitation", in.history);
  w.commit();

  std::printf("%s: transient rolling, %ld steps of dt = dx/V = %.6g s on %d x %d elements (%d in "
              "contact), start: %s\n",
              reader.name().c_str(), r.steps, r.dt, g.nx, g.ny, r.patch->normal.contact_elements(),
              in.from_steady ? "steady state at the mean creepage" : "zero tractions");
  if (r.varying_load) {
    const auto [lo, hi] = std::minmax_element(r.load.begin(), r.load.end());
    std::printf("  normal load %.6g N varies in [%.6g, %.6g] N: the normal problem is solved at every step\n",
                cc.normal_force, *lo, *hi);
  }
  const std::size_t e = 3 * (nt - 1);
  const double steps = static_cast<double>(r.steps);
  std::printf("  final: Fx = %.6g N, Fy = %.6g N, Mz = %.6g N m; %.2f ms per step, %.1f Newton "
              "and %.1f GMRES iterations per step\n",
              r.force[e], r.force[e + 1], r.force[e + 2], 1e3 * r.seconds / steps, r.newton / steps, r.gmres / steps);
  if (r.varying_load && r.normal_solves)
    std::printf("  normal problem: %d solves, %.1f Polonsky-Keer iterations and %.2f ms per solve (included above); "
                "%ld LU factorisations of the tangential Jacobian\n",
                r.normal_solves, r.normal_iterations / r.normal_solves, 1e3 * r.normal_seconds / r.normal_solves,
                r.factorisations);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
