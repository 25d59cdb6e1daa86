// A CONTACT run as rollnoise's reference (contact_reference.hpp).
#include "io/contact_reference.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/errors.hpp"

namespace rollnoise::io {
namespace {

namespace fs = std::filesystem;

std::string find_out_file(const std::string& folder) {
  if (!fs::is_directory(folder))
    throw InputError("--reference", "--reference contact " + folder + ": not a folder");
  std::vector<std::string> outs;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file() && e.path().extension() == ".out") outs.push_back(e.path().string());
  if (outs.size() != 1)
    throw InputError("--reference", "--reference contact " + folder +
                                        ": expected one CONTACT .out file, found " +
                                        std::to_string(outs.size()));
  return outs[0];
}

/// DQ/VELOC of the first case that gives "CHI, DQ, VELOC" (s).
double time_step(const std::vector<ContactInpCase>& cases, const std::string& inp) {
  for (const auto& c : cases)
    for (const auto& l : c.lines)
      if (l.label.rfind("CHI, DQ, VELOC", 0) == 0 || l.label.rfind("DX, DS, DQREL", 0) == 0) {
        if (c.module == 3 && l.numbers.size() >= 3 && l.numbers[2] > 0)
          return l.numbers[1] / l.numbers[2];
        if (c.module == 1) return 0.0;  // module 1: steady only here
      }
  throw InputError(inp, inp + ": no line 'CHI, DQ, VELOC' gives the rolling step");
}

std::string mat_name(const std::string& stem, int number, int module) {
  char buf[32];
  std::snprintf(buf, sizeof buf, ".%04d%s.mat", number, module == 1 ? "a" : "");
  return stem + buf;
}

}  // namespace

ContactReference read_contact_reference(const std::string& folder) {
  ContactReference r;
  r.folder = folder;
  r.out_path = find_out_file(folder);
  const fs::path stem = fs::path(r.out_path).replace_extension();
  r.inp_path = stem.string() + ".inp";
  if (!fs::exists(r.inp_path))
    throw InputError("--reference", "--reference contact " + folder + ": no input " + r.inp_path +
                                        " beside " + r.out_path + " (the case times come from it)");
  const ContactOut out = read_contact_out(r.out_path);
  const std::vector<ContactInpCase> inp = read_contact_inp(r.inp_path);
  if (inp.size() != out.cases.size())
    throw InputError(r.out_path, r.out_path + ": " + std::to_string(out.cases.size()) +
                                     " cases, but " + r.inp_path + " has " +
                                     std::to_string(inp.size()) + " (a run cut short?)");
  r.module = out.cases.front().module;
  r.dt = time_step(inp, r.inp_path);
  const double sign = r.module == 1 ? -1.0 : 1.0;  // module 1: forces on the rail
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t n = 0; n < out.cases.size(); ++n) {
    const ContactOutCase& c = out.cases[n];
    if (c.module == 1 && c.patches.size() != 1)
      throw InputError(r.out_path, r.out_path + ":" + std::to_string(c.line) + ": case " +
                                       std::to_string(c.number) + " has " +
                                       std::to_string(c.patches.size()) +
                                       " contact patches; rollnoise compares one");
    const ContactOutPatch& p = c.patches.front();
    const std::string where = r.out_path + ":" + std::to_string(c.line);
    const char* fy = c.module == 1 ? "FS" : "FY";
    const char* mz = c.module == 1 ? "MN" : "MZ";
    r.time.push_back(double(n) * r.dt);
    r.force.push_back(sign *
                      Eigen::Vector3d(p.at("FX", where), p.at(fy, where), 1e-3 * p.at(mz, where)));
    r.normal_force.push_back(p.at("FN", where));
    const std::string mat = mat_name(stem.string(), c.number, c.module);
    if (fs::exists(mat)) {
      ContactMat m = read_contact_mat(mat);
      const ContactMatTotals t = integrate(m);
      r.force_integrated.push_back(sign * Eigen::Vector3d(t.Fx, t.Fy, 1e-3 * t.Mz));
      if (n == 0) r.first_tractions = std::move(m);
    } else {
      r.force_integrated.push_back(Eigen::Vector3d::Constant(nan));
    }
  }
  return r;
}

ContactTractionField traction_field(const ContactMat& m, int module) {
  ContactTractionField f;
  f.nx = m.mx();
  f.ny = m.my();
  const double dx = m.header_value("DX"), dy = m.header_value("DY");
  for (int ix = 0; ix < f.nx; ++ix) f.x.push_back(1e-3 * (m.header_value("XL") + (ix + 0.5) * dx));
  for (int iy = 0; iy < f.ny; ++iy) f.y.push_back(1e-3 * (m.header_value("YL") + (iy + 0.5) * dy));
  const std::size_t n = std::size_t(f.nx) * std::size_t(f.ny);
  f.pn.assign(n, 0.0);
  f.px.assign(n, 0.0);
  f.py.assign(n, 0.0);
  f.state.assign(n, 0);
  const double sign = module == 1 ? -1.0 : 1.0;
  const auto &I = m.column("I"), &igs = m.column("IGS"), &pn = m.column("PN"), &px = m.column("PX"),
             &py = m.column("PY");
  for (std::size_t r = 0; r < m.rows(); ++r) {
    const std::size_t k = std::size_t(std::lround(I[r])) - 1;  // = iy * MX + ix, rollnoise's layout
    f.pn[k] = 1e6 * pn[r];
    f.px[k] = sign * 1e6 * px[r];
    f.py[k] = sign * 1e6 * py[r];
    f.state[k] = int(igs[r]);
  }
  return f;
}

}  // namespace rollnoise::io
