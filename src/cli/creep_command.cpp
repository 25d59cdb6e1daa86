// rollnoise creep: the complex creep coefficients f_jk(f) (and the load coefficients g_j(f)) of
// the linear NSS model at the case's mean creepage (paper Eqs. 28-30), on the case's frequency
// axis: read the case, run the creep pipeline (pipeline/creep.hpp), write /creep/* and the CSV.
#include <cstdio>
#include <optional>

#include "cli/commands.hpp"
#include "pipeline/creep.hpp"
#include "io/contact_case.hpp"
#include "io/creep_output.hpp"
#include "io/frequency_axis.hpp"

namespace rollnoise::cli {
namespace {

void print_extrapolation(const pipeline::CreepExtrapolation& ex, const std::vector<double>& freq) {
  std::printf("  extrapolated from %zu grids:", ex.dx.size());
  for (size_t i = 0; i < ex.dx.size(); ++i) std::printf(" %d x %d (dx %.4g mm)", ex.nx[i], ex.ny[i], 1e3 * ex.dx[i]);
  std::printf("; order observed for %ld entries, assumed (%g) for %ld\n", ex.observed, ex.assumed_order, ex.assumed);
  const size_t mid = freq.size() / 2;
  std::printf("  at %.1f Hz: f11 +- %.2g N (order %.2f), f22 +- %.2g N (order %.2f)\n", freq[mid], ex.f_error[mid](0, 0),
              ex.f_order[mid](0, 0), ex.f_error[mid](1, 1), ex.f_order[mid](1, 1));
}

}  // namespace

int run_creep(const CommonOptions& o, const std::string& csv, bool direct, const ExtrapolationOptions& x) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::InputProblems problems;  // every problem of the case at once
  std::vector<double> freq;
  problems.check([&] { freq = io::read_frequency_axis(reader); });
  io::ContactCase cc = io::read_contact_case(reader, problems);
  problems.throw_if_any();
  const std::string freq_key = reader.has("frequency.list") ? "frequency.list" : "frequency.f_max";
  const pipeline::CreepResult r = io::within_case(reader, [&] {
    return x.on ? pipeline::run_creep_extrapolated(std::move(cc), freq, direct, freq_key, x.factors,
                                                   "--extrapolate-grids")
                : pipeline::run_creep(std::move(cc), freq, direct, freq_key);
  });
  const nss::LinearContactModel& model = *r.state.model();

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_creep(w, reader, freq, r, direct);
  std::optional<io::TemporaryFile> table;  // committed with the HDF5 file, not before
  if (!csv.empty()) table.emplace(io::write_creep_csv(csv, freq, r));
  w.commit();
  if (table) table->commit();
  std::printf("%s: linear NSS model on %d contact elements (%d adhesion, %d slip), %d unknowns\n",
              reader.name().c_str(), model.adhesion_elements() + model.slip_elements(), model.adhesion_elements(),
              model.slip_elements(), model.unknowns());
  std::printf("  mean state %.0f ms; %zu frequencies (%s) in %.0f ms; Nyquist %.0f Hz\n", 1e3 * r.seconds_state,
              freq.size(), direct ? "direct" : "fast sweep", 1e3 * r.seconds_sweep, model.nyquist_frequency());
  if (r.extrapolation) print_extrapolation(*r.extrapolation, freq);
  const size_t mid = freq.size() / 2;
  const auto& f = r.f[mid];
  const auto& g = r.g[mid];
  std::printf("  at %.1f Hz: f11 = %.4g %+.4gi N, f22 = %.4g %+.4gi N, f23 = %.4g %+.4gi N m, f32 = %.4g %+.4gi N m\n",
              freq[mid], f(0, 0).real(), f(0, 0).imag(), f(1, 1).real(), f(1, 1).imag(), f(1, 2).real(),
              f(1, 2).imag(), f(2, 1).real(), f(2, 1).imag());
  std::printf("  normal load: g(0) = (%.4g, %.4g, %.4g m) (quasi-static dF/dN), at %.1f Hz g = (%.4g %+.4gi, %.4g "
              "%+.4gi, %.4g %+.4gi m)\n",
              r.g0(0).real(), r.g0(1).real(), r.g0(2).real(), freq[mid], g(0).real(), g(0).imag(), g(1).real(),
              g(1).imag(), g(2).real(), g(2).imag());
  std::printf("wrote %s%s%s\n", out.c_str(), csv.empty() ? "" : " and ", csv.c_str());
  return 0;
}

}  // namespace rollnoise::cli
