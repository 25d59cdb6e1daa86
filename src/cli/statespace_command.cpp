// rollnoise statespace: the linearised contact as a state-space model (docs/statespace.md): read
// the case, run the state-space pipeline (pipeline/statespace.hpp: creep sweep, vector fit, ERA),
// write /creep/*, /statespace/* and the CSV matrices, print a summary.
#include <cstdio>

#include "cli/commands.hpp"
#include "io/contact_case.hpp"
#include "io/frequency_axis.hpp"
#include "io/output_files.hpp"
#include "io/statespace_output.hpp"

namespace rollnoise::cli {

int run_statespace(const CommonOptions& o, const std::string& csv_prefix) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const std::string out = output_path(o, reader.name());
  if (!csv_prefix.empty()) {  // every output before any computation (main checked -o alone)
    std::vector<io::OutputFile> outputs = {{"-o", out}};
    for (const auto& p : io::statespace_csv_paths(csv_prefix)) outputs.push_back({"--csv", p});
    io::check_outputs(outputs, io::case_input_files(reader));
  }
  io::InputProblems problems;
  std::vector<double> freq;
  pipeline::StateSpaceOptions opt;
  problems.check([&] { freq = io::read_frequency_axis(reader); });
  problems.check([&] { opt = io::read_statespace_options(reader); });
  io::ContactCase cc = io::read_contact_case(reader, problems);
  problems.throw_if_any();
  const std::string freq_key = reader.has("frequency.list") ? "frequency.list" : "frequency.f_max";
  const pipeline::StateSpaceResult r = io::within_case(
      reader, [&] { return pipeline::run_statespace(std::move(cc), freq, opt, freq_key); });

  io::Hdf5Writer w(out);
  io::write_statespace(w, reader, r);
  std::vector<io::TemporaryFile> tables;  // committed with the HDF5 file, not before
  if (!csv_prefix.empty()) tables = io::write_statespace_csv(csv_prefix, r);
  w.commit();
  for (auto& t : tables) t.commit();

  const nss::LinearContactModel& model = *r.creep.state.model();
  std::printf(
      "%s: linear NSS model on %d contact elements (%d adhesion, %d slip); f, g at %zu frequencies "
      "(0 Hz and the band %.6g-%.6g Hz) in %.0f ms\n",
      reader.name().c_str(), model.adhesion_elements() + model.slip_elements(),
      model.adhesion_elements(), model.slip_elements(), r.frequency.size(), r.band_min, r.band_max,
      1e3 * (r.creep.seconds_state + r.creep.seconds_sweep));
  std::printf(
      "  continuous: order %d (%zu poles), fit error %.3g (target %.3g %s; worst at %.6g Hz), "
      "entry error "
      "%.3g, %d poles flipped; %.0f ms\n",
      r.fit.model.order(), r.fit.poles.size(), r.fit.error, opt.tolerance,
      r.fit.reached_target ? "met" : "NOT met", r.fit.worst_frequency, r.fit.element_error,
      r.fit.flipped, 1e3 * r.seconds_fit);
  std::printf(
      "  discrete: dt = %.6g s, order %d (the recursion's %d from %d Markov parameters, Markov "
      "error %.3g, and 3 x %d of the %s sampling filter, error %.3g), response error %.3g; %.0f "
      "ms\n",
      r.dt, r.discrete.order(), r.recursion.model.order(), r.markov_count, r.recursion.markov_error,
      r.sampling_filter.order(), contact::sampling_name(r.input_sampling), r.sampling_filter_error,
      r.discrete_error, 1e3 * r.seconds_discrete);
  if (!r.fit.reached_target)
    std::fprintf(stderr,
                 "warning: the fit error %.3g is above statespace.tolerance = %.3g (raise "
                 "statespace.max_poles)\n",
                 r.fit.error, opt.tolerance);
  if (r.sampling_filter_peak_gain > 2.0)
    std::printf(
        "  note: above the band the sampling filter amplifies up to %.3g times (the exact factor "
        "is "
        "at most 1): keep a coupled code's creepages within the band, or feed "
        "/statespace/discrete/recursion the step creepages (docs/statespace.md Sec. 3)\n",
        r.sampling_filter_peak_gain);
  if (r.sampling_filter_error > opt.tolerance)
    std::fprintf(
        stderr,
        "warning: the sampling filter's error %.3g is above statespace.tolerance = %.3g: the "
        "band reaches too close to the Nyquist limit for a rational filter of the step's "
        "creepage (docs/statespace.md Sec. 3; lower frequency.f_max or refine the grid)\n",
        r.sampling_filter_error, opt.tolerance);
  std::printf("wrote %s", out.c_str());
  if (!csv_prefix.empty()) std::printf(" and %s_{A,B,C,D,Ad,Bd,Cd,Dd}.csv", csv_prefix.c_str());
  std::printf("\n");
  return 0;
}

}  // namespace rollnoise::cli
