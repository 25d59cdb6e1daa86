// rollnoise transient: unsteady rolling (paper Eq. 2) under the case's creepage and normal-load
// history, from the steady state at the mean creepage (and mean load) or from zero tractions.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "contact/forces.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "core/errors.hpp"
#include "io/contact_case.hpp"
#include "io/contact_output.hpp"
#include "io/excitation.hpp"

namespace rollnoise::cli {

int run_transient(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::ContactCase cc = io::read_contact_case(reader);
  const contact::CreepageHistory history = io::read_excitation(reader);
  const double duration = reader.real("transient.duration");
  const bool from_steady = reader.string("transient.start") == "steady";
  const std::vector<double> snapshots = reader.real_list("transient.snapshots");
  io::within_case(reader, [&] { pipeline::place_contact(cc); });
  const contact::ContactPatch patch = io::within_case(reader, [&] { return pipeline::solve_patch(cc); });
  cc.grid = patch.grid;  // profiles: the grid may have been enlarged
  const double dt = cc.grid.dx / cc.speed;
  const long steps = std::lround(std::floor(duration / dt + 1e-9));
  if (steps < 1) reader.fail("transient.duration", "shorter than one time step dx/V = " + std::to_string(dt) + " s");
  for (double t : snapshots)
    if (t < 0 || t > duration) reader.fail("transient.snapshots", "times must lie in [0, duration]");

  // total normal load of every step (checked positive); the normal problem is re-solved per step
  // only when the load varies (transient_rolling.hpp)
  const std::vector<double> load =
      io::normal_load_series(reader, history, cc.normal_force, dt, steps);
  const bool varying_load = history.has_normal_variation();
  if (varying_load) {  // the contact area at the largest load must fit the grid: check before
                       // running
    const double n_max = *std::max_element(load.begin(), load.end());
    try {
      contact::solve_patch(cc.grid, cc.material, patch.undeformed_distance, n_max, cc.backend,
                           cc.normal);
    } catch (const InputError& e) {
      reader.fail(history.kind() == contact::CreepageHistory::Kind::samples
                      ? "excitation.file"
                      : "excitation.normal_amplitude",
                  "at the largest normal load " + std::to_string(n_max) + " N: " + e.what());
    }
  }

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_case(w, reader);
  io::write_patch(w, patch);
  const contact::Grid& g = cc.grid;

  contact::TransientRolling rolling(patch.influence, patch.normal.pn, cc.mu, cc.speed, cc.spin_offset,
                                    cc.backend, cc.tangential);
  if (varying_load)
    rolling.set_normal_problem(patch.undeformed_distance, cc.normal_force, cc.normal);
  contact::TangentialSolution state;
  if (from_steady) {
    state = contact::solve_steady_rolling(patch.influence, patch.normal.pn, cc.steady_input(), cc.tangential);
    rolling.set_tractions(state.px, state.py);
  } else {
    state.px.assign(g.size(), 0.0);
    state.py.assign(g.size(), 0.0);
    state.sx = state.px, state.sy = state.px;
    state.state.assign(g.size(), 0);
    for (int k = 0; k < g.size(); ++k)
      if (patch.normal.pn[k] > 0) state.state[k] = 1;
  }
  std::printf("%s: transient rolling, %ld steps of dt = dx/V = %.6g s on %d x %d elements (%d in "
              "contact), start: %s\n",
              reader.name().c_str(), steps, dt, g.nx, g.ny, patch.normal.contact_elements(),
              from_steady ? "steady state at the mean creepage" : "zero tractions");
  if (varying_load) {
    const auto [lo, hi] = std::minmax_element(load.begin(), load.end());
    std::printf(
        "  normal load %.6g N varies in [%.6g, %.6g] N: the normal problem is solved at every "
        "step\n",
        cc.normal_force, *lo, *hi);
  }

  std::vector<double> time, creep, force;
  std::vector<int> n_adh, n_slip;
  std::vector<long> snap_step;
  for (double t : snapshots) snap_step.push_back(std::lround(t / dt));
  auto record = [&](long k, const contact::Creepage& c, const contact::TangentialSolution& s) {
    const auto f = contact::total_forces(g, s.px, s.py);
    time.push_back(k * dt);
    creep.insert(creep.end(), {c.xi_x, c.xi_y, c.phi});
    force.insert(force.end(), {f.Fx, f.Fy, f.Mz});
    n_adh.push_back(s.count(contact::ElementState::adhesion));
    n_slip.push_back(s.count(contact::ElementState::slip));
    for (size_t i = 0; i < snap_step.size(); ++i)
      if (snap_step[i] == k) {
        const std::string grp = "/transient/snapshots/" + std::to_string(i);
        io::write_tangential(w, grp, g, c, s);
        w.write(grp + "/time", k * dt, "s");
      }
  };
  record(0, history.at(0.0), state);
  const auto t0 = std::chrono::steady_clock::now();
  Progress progress("transient", steps, o.quiet);
  int newton = 0, factorisations = 0, gmres = 0;
  for (long k = 1; k <= steps; ++k) {
    const contact::Creepage c = history.at(k * dt);  // creepage of step k at t_k = k dt
    const auto& s = varying_load ? rolling.step(c, load[k]) : rolling.step(c);
    newton += s.iterations;
    factorisations += s.factorisations;
    gmres += s.linear_iterations;
    record(k, c, s);
    progress.update(k);
  }
  progress.finish();
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const std::size_t nt = time.size();
  w.write("/transient/time", time, {nt}, "s");
  w.write("/transient/creepage", creep, {nt, 3}, "-, -, rad/m");
  w.write("/transient/force", force, {nt, 3}, "N, N, N m");
  w.write("/transient/n_adhesion", n_adh, {nt}, "-");
  w.write("/transient/n_slip", n_slip, {nt}, "-");
  w.write("/transient/normal_force", load, {nt}, "N");
  io::write_excitation(w, "/transient/excitation", history);
  w.commit();
  const std::size_t e = 3 * (nt - 1);
  std::printf(
      "  final: Fx = %.6g N, Fy = %.6g N, Mz = %.6g N m; %.2f ms per step, %.1f Newton "
      "and %.1f GMRES iterations per step\n",
      force[e], force[e + 1], force[e + 2], ms / steps, double(newton) / steps,
      double(gmres) / steps);
  if (varying_load)
    std::printf(
        "  normal problem: %d solves, %.1f Polonsky-Keer iterations and %.2f ms per solve "
        "(included "
        "above); %d LU factorisations of the tangential Jacobian\n",
        rolling.normal_solves(),
        rolling.normal_solves() ? double(rolling.normal_iterations()) / rolling.normal_solves()
                                : 0.0,
        rolling.normal_solves() ? 1e3 * rolling.normal_seconds() / rolling.normal_solves() : 0.0,
        factorisations);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
