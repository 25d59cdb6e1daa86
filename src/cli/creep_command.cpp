// rollnoise creep: the complex creep coefficients f_jk(f) of the linear NSS model at the case's
// mean creepage (paper Eqs. 28-30), on the case's frequency axis.
#include <chrono>
#include <cstdio>
#include <fstream>

#include "cli/commands.hpp"
#include "cli/contact_setup.hpp"
#include "core/errors.hpp"
#include "io/contact_output.hpp"
#include "io/frequency_axis.hpp"

namespace rollnoise::cli {

const char* kCreepUnits =
    "f_jk with F~ = -f xi~; rows Fx [N], Fy [N], Mz [N m]; columns xi_x [-], xi_y [-], phi [rad/m]: "
    "f11..f22 in N, f13, f23, f31, f32 in N m, f33 in N m^2";

const char* kLoadUnits =
    "g_j with F~ = -f xi~ + g N~ (N~ the normal-load variation): g1 = dFx/dN [-], g2 = dFy/dN [-], "
    "g3 = dMz/dN [m]";

int run_creep(const CommonOptions& o, const std::string& csv, bool direct) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const std::vector<double> freq = io::read_frequency_axis(reader);
  const auto t0 = std::chrono::steady_clock::now();
  MeanState ms = solve_mean_state(reader, true);
  const nss::LinearContactModel& model = *ms.model;
  for (double f : freq)
    if (f > model.nyquist_frequency() * (1 + 1e-12))
      reader.fail(reader.has("frequency.list") ? "frequency.list" : "frequency.f_max",
                  std::to_string(f) + " Hz is above the grid's Nyquist limit V/(2 dx) = " +
                      std::to_string(model.nyquist_frequency()) + " Hz: refine grid.nx or lower it");
  const auto t1 = std::chrono::steady_clock::now();
  std::vector<nss::CreepMatrix> f;
  std::vector<nss::LoadVector> g;
  if (direct) {
    for (double fr : freq) f.push_back(model.creep_coefficients_direct(fr));
    for (double fr : freq) g.push_back(model.normal_load_coefficients_direct(fr));
  } else {
    f = model.creep_coefficients(freq);
    g = model.normal_load_coefficients(freq);  // the same Markov parameters (one more column)
  }
  const auto t2 = std::chrono::steady_clock::now();
  auto ms_ = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, reader, *ms.patch, ms.contact.creepage, ms.steady);
  std::vector<std::complex<double>> flat;
  for (const auto& m : f)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) flat.push_back(m(j, k));
  w.write("/creep/frequency", freq, {freq.size()}, "Hz");
  w.write("/creep/f", flat, {freq.size(), 3, 3}, kCreepUnits);
  std::vector<std::complex<double>> flat_g;
  for (const auto& v : g) flat_g.insert(flat_g.end(), {v(0), v(1), v(2)});
  w.write("/creep/g", flat_g, {freq.size(), 3}, kLoadUnits);
  w.write("/creep/nyquist_frequency", model.nyquist_frequency(), "Hz");
  w.attribute("/creep", "method", direct ? "direct complex LU per frequency" : "Markov parameters (impulse response)");
  if (!csv.empty()) {
    std::ofstream c(csv);
    if (!c) throw InputError("--csv", "cannot write " + csv);
    c << "# creep coefficients f_jk (F~ = -f xi~ + g N~), " << kCreepUnits << "; " << kLoadUnits
      << "\nfrequency_Hz";
    for (int j = 1; j <= 3; ++j)
      for (int k = 1; k <= 3; ++k) c << ",re_f" << j << k << ",im_f" << j << k;
    for (int j = 1; j <= 3; ++j) c << ",re_g" << j << ",im_g" << j;
    c << "\n";
    c.precision(10);
    for (size_t i = 0; i < freq.size(); ++i) {
      c << freq[i];
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) c << "," << f[i](j, k).real() << "," << f[i](j, k).imag();
      for (int j = 0; j < 3; ++j) c << "," << g[i](j).real() << "," << g[i](j).imag();
      c << "\n";
    }
  }
  w.commit();
  std::printf("%s: linear NSS model on %d contact elements (%d adhesion, %d slip), %d unknowns\n",
              reader.name().c_str(), ms.steady.count(contact::ElementState::adhesion) +
                                         ms.steady.count(contact::ElementState::slip),
              model.adhesion_elements(), model.slip_elements(), model.unknowns());
  std::printf("  mean state %.0f ms; %zu frequencies (%s) in %.0f ms; Nyquist %.0f Hz\n", ms_(t0, t1),
              freq.size(), direct ? "direct" : "fast sweep", ms_(t1, t2), model.nyquist_frequency());
  const size_t mid = freq.size() / 2;
  std::printf("  at %.1f Hz: f11 = %.4g %+.4gi N, f22 = %.4g %+.4gi N, f23 = %.4g %+.4gi N m, f32 = %.4g %+.4gi N m\n",
              freq[mid], f[mid](0, 0).real(), f[mid](0, 0).imag(), f[mid](1, 1).real(), f[mid](1, 1).imag(),
              f[mid](1, 2).real(), f[mid](1, 2).imag(), f[mid](2, 1).real(), f[mid](2, 1).imag());
  // g(0) by the same method as the sweep (one more LU with --direct; else the same Markov parameters)
  const nss::LoadVector g0 = direct ? model.normal_load_coefficients_direct(0.0)
                                    : model.normal_load_coefficients(std::vector<double>{0.0})[0];
  std::printf("  normal load: g(0) = (%.4g, %.4g, %.4g m) (quasi-static dF/dN), at %.1f Hz g = (%.4g %+.4gi, %.4g "
              "%+.4gi, %.4g %+.4gi m)\n",
              g0(0).real(), g0(1).real(), g0(2).real(), freq[mid], g[mid](0).real(), g[mid](0).imag(),
              g[mid](1).real(), g[mid](1).imag(), g[mid](2).real(), g[mid](2).imag());
  std::printf("wrote %s%s%s\n", out.c_str(), csv.empty() ? "" : " and ", csv.c_str());
  return 0;
}

}  // namespace rollnoise::cli
