#include "io/creep_output.hpp"


#include "io/contact_output.hpp"

namespace rollnoise::io {
namespace {

const char* kCreepUnits =
    "f_jk with F~ = -f xi~; rows Fx [N], Fy [N], Mz [N m]; columns xi_x [-], xi_y [-], phi [rad/m]: "
    "f11..f22 in N, f13, f23, f31, f32 in N m, f33 in N m^2";

const char* kLoadUnits =
    "g_j with F~ = -f xi~ + g N~ (N~ the normal-load variation): g1 = dFx/dN [-], g2 = dFy/dN [-], "
    "g3 = dMz/dN [m]";

}  // namespace

void write_creep(Hdf5Writer& w, const CaseReader& r, const std::vector<double>& freq, const pipeline::CreepResult& c,
                 bool direct) {
  const pipeline::MeanContact& ms = c.state;
  write_mean_state(w, r, ms.patch(), ms.contact().creepage, ms.steady());
  std::vector<std::complex<double>> flat;
  for (const auto& m : c.f)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) flat.push_back(m(j, k));
  w.write("/creep/frequency", freq, {freq.size()}, "Hz");
  w.write("/creep/f", flat, {freq.size(), 3, 3}, kCreepUnits);
  std::vector<std::complex<double>> flat_g;
  for (const auto& v : c.g) flat_g.insert(flat_g.end(), {v(0), v(1), v(2)});
  w.write("/creep/g", flat_g, {freq.size(), 3}, kLoadUnits);
  w.write("/creep/nyquist_frequency", ms.model()->nyquist_frequency(), "Hz");
  w.attribute("/creep", "method", creep_method(c, direct));
  w.attribute("/creep", "creepage_sampling", contact::sampling_name(ms.contact().sampling));
  if (c.extrapolation) write_extrapolation(w, freq, *c.extrapolation);
}

void write_extrapolation(Hdf5Writer& w, const std::vector<double>& freq, const pipeline::CreepExtrapolation& ex) {
  const std::size_t nf = freq.size(), ng = ex.dx.size();
  std::vector<double> fe, fo, ge, go;
  for (std::size_t n = 0; n < nf; ++n) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) fe.push_back(ex.f_error[n](j, k)), fo.push_back(ex.f_order[n](j, k));
      ge.push_back(ex.g_error[n](j)), go.push_back(ex.g_order[n](j));
    }
  }
  const std::string error_units = " (estimated error of the extrapolated value: Roache's grid convergence index)";
  w.write("/creep/f_error", fe, {nf, 3, 3}, std::string(kCreepUnits) + error_units);
  w.write("/creep/g_error", ge, {nf, 3}, std::string(kLoadUnits) + error_units);
  std::vector<std::complex<double>> fg, gg;
  for (std::size_t i = 0; i < ng; ++i)
    for (std::size_t n = 0; n < nf; ++n) {
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) fg.push_back(ex.f[i][n](j, k));
      for (int j = 0; j < 3; ++j) gg.push_back(ex.g[i][n](j));
    }
  const std::string e = "/creep/extrapolation/";
  w.write(e + "factors", ex.factors, {ng}, "- (nx, ny of the case's grid scaled by these)");
  w.write(e + "nx", ex.nx, {ng}, "-");
  w.write(e + "ny", ex.ny, {ng}, "-");
  w.write(e + "dx", ex.dx, {ng}, "m");
  w.write(e + "f_grids", fg, {ng, nf, 3, 3}, std::string(kCreepUnits) + " (per grid, coarse to fine)");
  w.write(e + "g_grids", gg, {ng, nf, 3}, std::string(kLoadUnits) + " (per grid, coarse to fine)");
  w.write(e + "f_order", fo, {nf, 3, 3}, "- (order of convergence used per entry: observed, or assumed)");
  w.write(e + "g_order", go, {nf, 3}, "- (order of convergence used per entry: observed, or assumed)");
  w.write(e + "assumed_order", ex.assumed_order, "- (two grids, and where the observed order is unusable)");
  w.attribute("/creep/extrapolation", "method",
              "Richardson with the observed order on three grids (within [0.5, 4], monotone), else the assumed "
              "order on the two finest; error = 1.25 (observed) or 3 (assumed) times |f* - f_finest|");
  w.attribute("/creep/extrapolation", "observed_entries", static_cast<std::uint64_t>(ex.observed));
  w.attribute("/creep/extrapolation", "assumed_entries", static_cast<std::uint64_t>(ex.assumed));
}

std::string creep_method(const pipeline::CreepResult& c, bool direct) {
  if (direct) return "complex LU per frequency (--direct)";
  // the route the fast sweep took (nss/markov_sweep.cpp)
  switch (c.state.model()->sweep_info().method) {
    case nss::SweepInfo::Method::krylov:
      return "block Krylov reduced model (Markov parameters, Horner per frequency)";
    case nss::SweepInfo::Method::markov:
      return "exact Markov parameters by recursion (Horner per frequency; the block Krylov model failed its check)";
    case nss::SweepInfo::Method::hessenberg:
      return "Hessenberg form of M0^-1 M1, one solve per frequency (the Markov routes failed)";
    case nss::SweepInfo::Method::none:
      break;
  }
  return "unknown";
}

TemporaryFile write_creep_csv(const std::string& path, const std::vector<double>& freq,
                              const pipeline::CreepResult& r) {
  return write_text_file(path, "--csv", [&](std::ostream& c) {
    c << "# creep coefficients f_jk (F~ = -f xi~ + g N~), " << kCreepUnits << "; " << kLoadUnits << "\nfrequency_Hz";
    for (int j = 1; j <= 3; ++j)
      for (int k = 1; k <= 3; ++k) c << ",re_f" << j << k << ",im_f" << j << k;
    for (int j = 1; j <= 3; ++j) c << ",re_g" << j << ",im_g" << j;
    c << "\n";
    c.precision(10);
    for (size_t i = 0; i < freq.size(); ++i) {
      c << freq[i];
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) c << "," << r.f[i](j, k).real() << "," << r.f[i](j, k).imag();
      for (int j = 0; j < 3; ++j) c << "," << r.g[i](j).real() << "," << r.g[i](j).imag();
      c << "\n";
    }
  });
}

}  // namespace rollnoise::io
