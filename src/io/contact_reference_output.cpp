// CONTACT's run in rollnoise's result files (contact_reference_output.hpp).
#include "io/contact_reference_output.hpp"

#include <cmath>

namespace rollnoise::io {
namespace {

std::vector<double> flatten(const std::vector<Eigen::Vector3d>& v, std::size_t n) {
  std::vector<double> out;
  for (std::size_t k = 0; k < n; ++k) out.insert(out.end(), {v[k][0], v[k][1], v[k][2]});
  return out;
}

std::vector<double> differences(const std::vector<Eigen::Vector3d>& a,
                                const std::vector<Eigen::Vector3d>& b, std::size_t n) {
  std::vector<Eigen::Vector3d> d;
  for (std::size_t k = 0; k < n; ++k) d.push_back(a[k] - b[k]);
  return flatten(d, n);
}

const char* kForceConvention =
    "rollnoise's conventions: forces on the wheel (module 1: minus CONTACT's forces on the rail), "
    "Mz in N m";

}  // namespace

Eigen::Vector3d contact_steady_force(const ContactReference& ref) {
  const Eigen::Vector3d& integrated = ref.force_integrated.front();
  return integrated.allFinite() ? integrated : ref.force.front();
}

void write_contact_steady_reference(Hdf5Writer& w, const ContactReference& ref) {
  const Eigen::Vector3d f = contact_steady_force(ref);
  w.write("/reference/contact/force", std::vector<double>{f[0], f[1], f[2]}, {3}, "N, N, N m");
  w.attribute("/reference/contact/force", "source",
              ref.first_tractions ? "integrated over " + ref.first_tractions->path
                                  : "printed in " + ref.out_path);
  const Eigen::Vector3d& p = ref.force.front();
  w.write("/reference/contact/force_printed", std::vector<double>{p[0], p[1], p[2]}, {3},
          "N, N, N m (4 digits)");
  w.write("/reference/contact/normal_force", ref.normal_force.front(), "N");
  w.attribute("/reference/contact", "out_file", ref.out_path);
  w.attribute("/reference/contact", "conventions", kForceConvention);
  if (!ref.first_tractions) return;
  const ContactTractionField t = traction_field(*ref.first_tractions, ref.module);
  const std::size_t nx = std::size_t(t.nx), ny = std::size_t(t.ny);
  w.write("/reference/contact/x", t.x, {nx}, "m");
  w.write("/reference/contact/y", t.y, {ny}, "m");
  w.write("/reference/contact/pn", t.pn, {ny, nx}, "Pa");
  w.write("/reference/contact/px", t.px, {ny, nx}, "Pa");
  w.write("/reference/contact/py", t.py, {ny, nx}, "Pa");
  w.write("/reference/contact/state", t.state, {ny, nx}, "0 exterior, 1 adhesion, 2 slip");
}

void write_contact_validation(Hdf5Writer& w, const ContactReference& ref,
                              const std::vector<Eigen::Vector3d>& unsteady,
                              const std::vector<Eigen::Vector3d>& linear,
                              const nss::ValidationErrors& e) {
  const std::size_t n = ref.time.size();
  w.write("/validate/contact/time", ref.time, {n}, "s");
  w.write("/validate/contact/force", flatten(ref.force, n), {n, 3},
          "N, N, N m (CONTACT's 4 printed digits)");
  w.write("/validate/contact/force_integrated", flatten(ref.force_integrated, n), {n, 3},
          "N, N, N m (integrated over the .mat files; NaN where absent)");
  w.write("/validate/contact/normal_force", ref.normal_force, {n}, "N");
  w.write("/validate/contact/unsteady_minus_contact", differences(unsteady, ref.force, n), {n, 3},
          "N, N, N m");
  w.write("/validate/contact/linear_minus_contact", differences(linear, ref.force, n), {n, 3},
          "N, N, N m");
  w.attribute("/validate/contact", "out_file", ref.out_path);
  w.attribute("/validate/contact", "conventions", kForceConvention);
  w.write("/validate/contact/errors/rms_relative",
          std::vector<double>{e.rms_relative(0), e.rms_relative(1), e.rms_relative(2)}, {3},
          "RMS(linear - CONTACT) / RMS(CONTACT variation), t >= analysis_start; Fx, Fy, Mz; NaN: "
          "not excited");
  if (e.fitted) {
    const std::size_t nf = e.amplitude_error.size() / 3;
    w.write("/validate/contact/errors/amplitude", e.amplitude_error, {3, nf},
            "relative (linear/CONTACT - 1); Fx, Fy, Mz");
    w.write("/validate/contact/errors/phase", e.phase_error, {3, nf},
            "deg (linear - CONTACT); Fx, Fy, Mz");
  }
}

}  // namespace rollnoise::io
