// rollnoise response: the linear model's force response to the case's creepage history, by the
// discrete-time recursion M0 Q_k = M1 Q_{k-1} + W_k (any history) and by harmonic synthesis
// (paper Eqs. 33-34, harmonic and multiharmonic histories): nss/linear_response.hpp.
// rollnoise validate: the same against the unsteady solver (paper Eq. 2) on the same history, with
// spectra and error figures: nss/validation.hpp.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/contact_reference_report.hpp"
#include "cli/contact_setup.hpp"
#include "cli/progress.hpp"
#include "contact/forces.hpp"
#include "contact/rolling_history.hpp"
#include "contact/transient_rolling.hpp"
#include "io/contact_case.hpp"
#include "io/contact_output.hpp"
#include "io/excitation.hpp"
#include "io/validation_output.hpp"
#include "nss/linear_response.hpp"
#include "nss/validation.hpp"
#include "pipeline/limits.hpp"
#include "pipeline/transient.hpp"

namespace rollnoise::cli {
namespace {

Eigen::Vector3d mean_force(const MeanContact& ms) {
  const auto f = contact::total_forces(ms.patch().grid, ms.steady().px, ms.steady().py);
  return {f.Fx, f.Fy, f.Mz};
}

nss::LinearResponse linear_response(const MeanContact& ms, const contact::CreepageHistory& h, long steps) {
  return nss::linear_response(*ms.model(), mean_force(ms), ms.contact().normal_force, h, steps);
}

long steps_of(const io::CaseReader& reader, double dt) {
  const double duration = reader.real("transient.duration");
  const double count = std::floor(duration / dt + 1e-9);
  io::within_case(reader, [&] {
    pipeline::check_size(io::read_limits(reader), "transient.duration", count, "time steps of dt = dx/V",
                         pipeline::transient_bytes(count));
  });
  const long steps = std::lround(count);
  if (steps < 1) reader.fail("transient.duration", "shorter than one time step dx/V");
  return steps;
}

}  // namespace

int run_response(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const contact::CreepageHistory h = io::read_excitation(reader);
  const MeanContact ms = solve_mean_contact(reader);
  io::within_case(reader, [&] { pipeline::check_excitation_nyquist(ms.contact(), h); });
  const long steps = steps_of(reader, ms.model()->time_step());
  io::normal_load_series(reader, h, ms.contact().normal_force, ms.model()->time_step(), steps);  // N_k > 0
  const auto t0 = std::chrono::steady_clock::now();
  const nss::LinearResponse r = linear_response(ms, h, steps);
  const double ms_run = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, reader, ms.patch(), ms.contact().creepage, ms.steady());
  io::write_linear_response(w, "/response", r);
  io::write_excitation(w, "/response/excitation", h);
  w.commit();
  std::printf("%s: linear response, %ld steps of %.4g s, in %.0f ms (recursion%s)\n", reader.name().c_str(),
              steps, ms.model()->time_step(), ms_run, r.has_synthesis() ? " and harmonic synthesis" : "");
  if (r.has_synthesis()) {
    const double t_start = reader.real("transient.analysis_start");
    const nss::RecursionSynthesisGap gap = nss::recursion_synthesis_gap(r, t_start);
    std::printf("  recursion vs synthesis after %.4g s: max |difference| %.3g N (variation %.3g N)\n",
                t_start, gap.difference, gap.variation);
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

int run_validate(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const auto reference = read_reference(o);  // CONTACT's run: bad files fail before any work
  const contact::CreepageHistory h = io::read_excitation(reader);
  const MeanContact ms = solve_mean_contact(reader);
  io::within_case(reader, [&] { pipeline::check_excitation_nyquist(ms.contact(), h); });
  const double dt = ms.model()->time_step();
  const long steps = steps_of(reader, dt);
  io::normal_load_series(reader, h, ms.contact().normal_force, dt, steps);  // N_k > 0, else InputError
  const double t_start = reader.real("transient.analysis_start");
  const nss::LinearResponse lin = linear_response(ms, h, steps);
  if (nss::analysed_samples(lin.time, t_start) < 8)
    reader.fail("transient.analysis_start", "leaves fewer than 8 samples to analyse");

  // the unsteady reference from the same steady state
  contact::TransientRolling rolling(ms.patch().influence, ms.patch().normal.pn, ms.contact().mu, ms.contact().speed,
                                    ms.contact().spin_offset, ms.contact().backend, ms.contact().tangential);
  rolling.set_falling_friction(ms.contact().falling);
  rolling.set_tractions(ms.steady().px, ms.steady().py);
  const bool varying_load = h.has_normal_variation();
  if (varying_load)  // the normal problem is re-solved at every step (transient_rolling.hpp)
    rolling.set_normal_problem(ms.patch().undeformed_distance, ms.contact().normal_force, ms.contact().normal);
  std::vector<Eigen::Vector3d> unsteady = {mean_force(ms)};
  const auto t0 = std::chrono::steady_clock::now();
  {
    Progress progress("unsteady solver", steps, o.quiet, "steps");
    const auto forces =
        contact::rolling_forces(rolling, ms.patch().grid, h, ms.contact().sampling, dt, steps,
                                varying_load ? lin.normal_force : std::vector<double>{},
                                [&](long k) { progress.update(k); });
    unsteady.insert(unsteady.end(), forces.begin(), forces.end());
    progress.finish();
  }
  const double ms_unsteady = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  // errors after the start transient
  const auto& fr = h.frequencies();
  const nss::ValidationErrors v = nss::compare_linear_unsteady(lin.time, unsteady, lin.recursion, t_start, fr, dt);

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, reader, ms.patch(), ms.contact().creepage, ms.steady());
  io::write_linear_response(w, "/validate/linear", lin);
  io::write_excitation(w, "/validate/excitation", h);
  io::write_validation(w, lin, unsteady, v, fr);
  if (reference) report_validate_reference(w, *reference, lin, unsteady, t_start, fr, dt);
  const char* name[] = {"Fx", "Fy", "Mz"};
  if (v.fitted && fr.size() <= 5)
    for (size_t k = 0; k < fr.size(); ++k) {
      std::printf("  %.1f Hz:", fr[k]);
      for (int j = 0; j < 2; ++j)
        if (v.excited[j])
          std::printf(" %s amplitude error %.3f %%, phase error %.3f deg;", name[j], 100 * v.amplitude_error[j * fr.size() + k],
                      v.phase_error[j * fr.size() + k]);
        else
          std::printf(" %s not excited;", name[j]);
      std::printf("\n");
    }
  w.commit();
  std::string rms;
  for (int j = 0; j < 3; ++j) {
    char buf[64];
    std::snprintf(buf, sizeof buf, v.excited[j] ? "%s %.3g %%" : "%s not excited", name[j], 100 * v.rms_relative(j));
    rms += (j ? ", " : "") + std::string(buf);
  }
  std::printf("%s: unsteady solver %ld steps in %.1f s; linear model RMS error after %.4g s (of the RMS variation): "
              "%s%s\nwrote %s\n",
              reader.name().c_str(), steps, ms_unsteady / 1e3, t_start, rms.c_str(),
              v.fitted ? "" : " (record too short for per-frequency errors)", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
