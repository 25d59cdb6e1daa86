#include "io/excitation.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::io {

contact::CreepageHistory read_excitation(const CaseReader& r) {
  const auto m = r.real3("creepage.mean");
  const contact::Creepage mean{m[0], m[1], m[2]};
  const std::string type = r.string("excitation.type");
  if (type == "none") return contact::CreepageHistory::constant(mean);
  if (type == "harmonic") {
    const auto ph = r.real3("excitation.phase");
    return contact::CreepageHistory::harmonic(mean, r.real3("excitation.amplitude"),
                                              r.real("excitation.frequency"),
                                              {ph[0] * M_PI / 180, ph[1] * M_PI / 180, ph[2] * M_PI / 180});
  }
  if (type == "multiharmonic") {
    const double f0 = r.real("excitation.f_min"), f1 = r.real("excitation.f_max");
    if (f1 < f0) r.fail("excitation.f_max", "must not be below excitation.f_min");
    return contact::CreepageHistory::multiharmonic(
        mean, r.real3("excitation.amplitude"), f0, f1, static_cast<int>(r.integer("excitation.count")),
        static_cast<std::uint64_t>(r.integer("excitation.seed")));
  }
  // csv
  std::filesystem::path file = r.string("excitation.file");
  if (file.is_relative() && !r.folder().empty()) file = std::filesystem::path(r.folder()) / file;
  std::ifstream in(file);
  if (!in) r.fail("excitation.file", "cannot open " + file.string());
  std::vector<double> t;
  std::vector<contact::Creepage> v;
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty() || line[0] == '#') continue;
    for (char& c : line)
      if (c == ',' || c == ';') c = ' ';
    std::istringstream is(line);
    double a, b, c, d;
    if (!(is >> a >> b >> c >> d)) {
      if (t.empty() && row == 1) continue;  // header line
      r.fail("excitation.file", file.string() + ":" + std::to_string(row) + ": expected t, xi_x, xi_y, phi");
    }
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d))
      r.fail("excitation.file", file.string() + ":" + std::to_string(row) + ": value not finite");
    t.push_back(a);
    v.push_back({b, c, d});
  }
  try {
    return contact::CreepageHistory::samples(mean, t, v);
  } catch (const InputError& e) {
    r.fail("excitation.file", file.string() + ": " + e.what());
  }
}

void write_excitation(Hdf5Writer& w, const std::string& group, const contact::CreepageHistory& h) {
  static const char* kinds[] = {"none", "harmonic", "multiharmonic", "csv"};
  w.attribute(group, "type", kinds[static_cast<int>(h.kind())]);
  const auto& m = h.mean();
  w.write(group + "/mean", std::vector<double>{m.xi_x, m.xi_y, m.phi}, {3}, "-, -, rad/m");
  if (h.kind() == contact::CreepageHistory::Kind::harmonic ||
      h.kind() == contact::CreepageHistory::Kind::multiharmonic) {
    const auto& a = h.amplitude();
    const std::size_t n = h.frequencies().size();
    w.write(group + "/amplitude", std::vector<double>{a[0], a[1], a[2]}, {3}, "-, -, rad/m");
    w.write(group + "/frequency", h.frequencies(), {n}, "Hz");
    std::vector<double> ph;
    for (int j = 0; j < 3; ++j) ph.insert(ph.end(), h.phases()[j].begin(), h.phases()[j].end());
    w.write(group + "/phase", ph, {3, n}, "rad");
  }
}

}  // namespace rollnoise::io
