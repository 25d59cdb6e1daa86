#include "io/validation_output.hpp"

namespace rollnoise::io {
namespace {

std::vector<double> flatten(const std::vector<Eigen::Vector3d>& s) {
  std::vector<double> out;
  for (const auto& v : s) out.insert(out.end(), {v(0), v(1), v(2)});
  return out;
}

}  // namespace

void write_linear_response(Hdf5Writer& w, const std::string& g, const nss::LinearResponse& r) {
  const std::size_t n = r.time.size();
  w.write(g + "/time", r.time, {n}, "s");
  w.write(g + "/creepage", flatten(r.creepage), {n, 3}, "-, -, rad/m");
  w.write(g + "/normal_force", r.normal_force, {n}, "N");
  w.write(g + "/force", flatten(r.recursion), {n, 3}, "N, N, N m");
  if (r.has_synthesis()) w.write(g + "/force_synthesis", flatten(r.synthesis), {n, 3}, "N, N, N m");
}

void write_validation(Hdf5Writer& w, const nss::LinearResponse& lin,
                      const std::vector<Eigen::Vector3d>& unsteady, const nss::ValidationErrors& v,
                      const std::vector<double>& fr) {
  const std::size_t n = lin.time.size();
  w.write("/validate/time", lin.time, {n}, "s");
  w.write("/validate/unsteady/force", flatten(unsteady), {n, 3}, "N, N, N m");
  w.write("/validate/errors/rms_relative",
          std::vector<double>{v.rms_relative(0), v.rms_relative(1), v.rms_relative(2)}, {3},
          "RMS(linear - unsteady) / RMS(unsteady variation), t >= analysis_start; Fx, Fy, Mz; NaN: not excited");
  w.write("/validate/errors/excited", std::vector<int>{v.excited[0], v.excited[1], v.excited[2]}, {3},
          "1 excited, 0 not excited (variation below 1e-9 of the force scale, nss/validation.hpp); Fx, Fy, Mz");
  // spectra (Hann window over t >= analysis_start)
  for (int j = 0; j < 3; ++j) {
    const nss::Spectrum &su = v.unsteady_spectrum[j], &sl = v.linear_spectrum[j];
    const char* name[] = {"Fx", "Fy", "Mz"};
    const std::string unit = j == 2 ? "N m" : "N";
    w.write(std::string("/validate/spectrum/unsteady_") + name[j], su.amplitude, {su.amplitude.size()}, unit);
    w.write(std::string("/validate/spectrum/linear_") + name[j], sl.amplitude, {sl.amplitude.size()}, unit);
    if (j == 0) w.write("/validate/spectrum/frequency", su.frequency, {su.frequency.size()}, "Hz");
  }
  w.attribute("/validate/spectrum", "window",
              "Hann over t >= transient.analysis_start, mean removed, amplitude scaled by the coherent gain");
  // amplitude and phase at each excited frequency (least-squares multisine fit), if resolvable
  if (v.fitted) {
    w.write("/validate/errors/frequency", fr, {fr.size()}, "Hz");
    w.write("/validate/errors/amplitude", v.amplitude_error, {3, fr.size()},
            "relative (linear/unsteady - 1); Fx, Fy, Mz");
    w.write("/validate/errors/phase", v.phase_error, {3, fr.size()}, "deg (linear - unsteady); Fx, Fy, Mz");
  }
}

}  // namespace rollnoise::io
