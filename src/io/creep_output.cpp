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
  const pipeline::MeanState& ms = c.state;
  write_mean_state(w, r, *ms.patch, ms.contact.creepage, ms.steady);
  std::vector<std::complex<double>> flat;
  for (const auto& m : c.f)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) flat.push_back(m(j, k));
  w.write("/creep/frequency", freq, {freq.size()}, "Hz");
  w.write("/creep/f", flat, {freq.size(), 3, 3}, kCreepUnits);
  std::vector<std::complex<double>> flat_g;
  for (const auto& v : c.g) flat_g.insert(flat_g.end(), {v(0), v(1), v(2)});
  w.write("/creep/g", flat_g, {freq.size(), 3}, kLoadUnits);
  w.write("/creep/nyquist_frequency", ms.model->nyquist_frequency(), "Hz");
  w.attribute("/creep", "method", creep_method(c, direct));
}

std::string creep_method(const pipeline::CreepResult& c, bool direct) {
  if (direct) return "complex LU per frequency (--direct)";
  // the route the fast sweep took (nss/linear_model.cpp, "Numerics of the fast sweep")
  switch (c.state.model->sweep_info().method) {
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
