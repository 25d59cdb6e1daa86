// --reference contact DIR (contact_reference_report.hpp).
#include "cli/contact_reference_report.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "io/contact_reference_output.hpp"
#include "nss/validation.hpp"

namespace rollnoise::cli {
namespace {

const char* kName[] = {"Fx", "Fy", "Mz"};
const char* kUnit[] = {"N", "N", "N m"};

/// Half a unit of CONTACT's 4th printed digit of |v|: the rounding of its printed totals.
double printed_rounding(double v) {
  return v == 0.0 ? 0.0 : 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(v))) - 3.0);
}

}  // namespace

std::optional<io::ContactReference> read_reference(const CommonOptions& o) {
  if (o.contact_reference.empty()) return std::nullopt;
  return io::read_contact_reference(o.contact_reference);
}

void report_steady_reference(io::Hdf5Writer& w, const io::ContactReference& ref,
                             const Eigen::Vector3d& steady) {
  io::write_contact_steady_reference(w, ref);
  const Eigen::Vector3d c = io::contact_steady_force(ref);
  std::printf("CONTACT (%s, %s): ", ref.out_path.c_str(),
              ref.first_tractions ? "integrated over its .mat" : "printed 4 digits");
  for (int j = 0; j < 3; ++j)
    std::printf("%s = %.7g %s (rollnoise - CONTACT: %.3g, relative %.2g)%s", kName[j], c[j],
                kUnit[j], steady[j] - c[j], c[j] != 0 ? (steady[j] - c[j]) / std::abs(c[j]) : 0.0,
                j < 2 ? "; " : "\n");
}

void report_validate_reference(io::Hdf5Writer& w, const io::ContactReference& ref,
                               const nss::LinearResponse& lin,
                               const std::vector<Eigen::Vector3d>& unsteady, double t_start,
                               const std::vector<double>& frequencies, double dt) {
  const std::size_t n = ref.time.size();
  if (ref.module != 3 || std::abs(ref.dt - dt) > 1e-9 * dt)
    throw InputError("--reference",
                     "--reference contact " + ref.folder +
                         ": a transient module-3 run with dt = dx/V = " + std::to_string(dt) +
                         " s is needed (CONTACT's DQ/VELOC = " + std::to_string(ref.dt) + " s)");
  if (n > unsteady.size())
    throw InputError("--reference", "--reference contact " + ref.folder + ": CONTACT's run has " +
                                        std::to_string(n - 1) + " steps, rollnoise's " +
                                        std::to_string(unsteady.size() - 1) +
                                        " (raise transient.duration)");
  const std::vector<double> time(lin.time.begin(), lin.time.begin() + long(n));
  const std::vector<Eigen::Vector3d> linear(lin.recursion.begin(), lin.recursion.begin() + long(n));
  nss::ValidationErrors e;
  if (nss::analysed_samples(time, t_start) >= 8)
    e = nss::compare_linear_unsteady(time, ref.force, linear, t_start, frequencies, dt);
  else
    e.rms_relative.setConstant(std::nan(""));
  io::write_contact_validation(w, ref, unsteady, linear, e);
  std::printf("CONTACT (%s): %zu cases (steady + %zu steps of %.6g s)\n", ref.out_path.c_str(), n,
              n - 1, ref.dt);
  for (int j = 0; j < 3; ++j) {
    double du = 0, dl = 0, round = 0, di = 0;
    int integrated = 0;
    for (std::size_t k = 0; k < n; ++k) {
      du = std::max(du, std::abs(unsteady[k][j] - ref.force[k][j]));
      dl = std::max(dl, std::abs(linear[k][j] - ref.force[k][j]));
      round = std::max(
          round, printed_rounding(ref.force[k][j] * (j == 2 ? 1e3 : 1.0)) * (j == 2 ? 1e-3 : 1.0));
      if (std::isfinite(ref.force_integrated[k][j])) {
        di = std::max(di, std::abs(unsteady[k][j] - ref.force_integrated[k][j]));
        ++integrated;
      }
    }
    std::printf(
        "  %s: max |unsteady - CONTACT| %.3g %s (CONTACT's printed rounding up to %.3g %s), max "
        "|linear - "
        "CONTACT| %.3g %s",
        kName[j], du, kUnit[j], round, kUnit[j], dl, kUnit[j]);
    if (integrated)
      std::printf("; against its %d .mat files: max |unsteady - CONTACT| %.3g %s", integrated, di,
                  kUnit[j]);
    if (std::isfinite(e.rms_relative(j)))
      std::printf("; linear RMS error %.3g %%", 100 * e.rms_relative(j));
    std::printf("\n");
  }
}

}  // namespace rollnoise::cli
