#include "io/excitation.hpp"

#include "io/contact_case.hpp"
#include "pipeline/limits.hpp"
#include "pipeline/transient.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "io/input_file.hpp"

namespace rollnoise::io {

namespace {

// The total load N_mean + dN must stay positive: a patch without load has no contact.
void check_positive_load(const CaseReader& r, const std::string& key, double total,
                         const std::string& where) {
  if (!(total > 0.0))
    r.fail(key, "the total normal load contact.normal_force + variation is " +
                    std::to_string(total) + " N" + where + "; it must stay positive");
}

void check_phase(const CaseReader& r, const std::string& key, double phase) {
  if (std::abs(phase) <= 2.0 * M_PI) return;
  std::ostringstream s;
  s << "phases are in radians and must lie within +-2 pi (6.2832); got " << phase
    << " (if meant in degrees: " << phase * M_PI / 180.0 << " rad)";
  r.fail(key, s.str());
}

// excitation.type = "harmonic": one frequency, the creepages' amplitudes and phases and the
// normal-load variation, N_mean + dN cos(2 pi f t + phase_N) > 0 checked at its minimum.
contact::CreepageHistory harmonic_excitation(const CaseReader& r, const contact::Creepage& mean) {
  // Phases in radians (SI, as /excitation/phase is written). Any phase is expressible within
  // +-2 pi; a larger value is most likely meant in degrees (the unit of earlier versions).
  const auto ph = r.real3("excitation.phase");
  for (double p : ph) check_phase(r, "excitation.phase", p);
  const double normal_phase = r.real("excitation.normal_phase");
  check_phase(r, "excitation.normal_phase", normal_phase);
  const double dN = r.real("excitation.normal_amplitude");
  if (dN != 0.0)  // the minimum of N_mean + dN cos(.) over all times
    check_positive_load(r, "excitation.normal_amplitude",
                        r.real("contact.normal_force") - std::abs(dN), " at its minimum");
  return contact::CreepageHistory::harmonic(
      mean, r.real3("excitation.amplitude"), r.real("excitation.frequency"), ph, dN, normal_phase);
}

// excitation.type = "multiharmonic": the paper's pseudo-random creepage (Eq. 32), count
// frequencies in [f_min, f_max] with seeded random phases.
contact::CreepageHistory multiharmonic_excitation(const CaseReader& r, const contact::Creepage& mean) {
  const double f0 = r.real("excitation.f_min"), f1 = r.real("excitation.f_max");
  if (f1 < f0) r.fail("excitation.f_max", "must not be below excitation.f_min");
  // The minimum over all times is not known in closed form: checked on the time steps of a run
  // (normal_load_series).
  const long count = r.integer("excitation.count");
  // per frequency: its value and 4 phases (3 creepages, normal load)
  within_case(r, [&] {
    pipeline::check_size(read_limits(r), "excitation.count", double(count), "excitation frequencies",
                         5.0 * sizeof(double) * double(count));
  });
  return contact::CreepageHistory::multiharmonic(
      mean, r.real3("excitation.amplitude"), f0, f1, static_cast<int>(count),
      static_cast<std::uint64_t>(r.integer("excitation.seed")),
      r.real("excitation.normal_amplitude"));
}

// excitation.type = "csv": the time series t, xi_x, xi_y, phi[, dN] of excitation.file; errors
// name the key and the file's line.
contact::CreepageHistory csv_excitation(const CaseReader& r, const contact::Creepage& mean) {
  const std::filesystem::path file = excitation_file_path(r);
  std::istringstream in([&]() -> std::string {
    try {
      return read_input(file.string(), "excitation.file", "the excitation file");
    } catch (const InputError& e) {
      r.fail("excitation.file", e.what());
    }
  }());
  std::vector<double> t;
  std::vector<contact::Creepage> v;
  std::vector<double> dn;  // optional 5th column: normal-load variation (N)
  std::string line;
  int row = 0, columns = 0;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty() || line[0] == '#') continue;
    for (char& c : line)
      if (c == ',' || c == ';') c = ' ';
    std::istringstream is(line);
    double a, b, c, d, e = 0.0;
    const std::string at = file.string() + ":" + std::to_string(row) + ": ";
    if (!(is >> a >> b >> c >> d)) {
      if (t.empty() && row == 1) continue;  // header line
      r.fail("excitation.file", at + "expected t, xi_x, xi_y, phi[, dN]");
    }
    const bool fifth = static_cast<bool>(is >> e);
    if (columns == 0) columns = fifth ? 5 : 4;
    if ((columns == 5) != fifth)
      r.fail("excitation.file",
             at + "expected " + std::to_string(columns) + " columns as in the first data row");
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d) ||
        !std::isfinite(e))
      r.fail("excitation.file", at + "value not finite");
    t.push_back(a);
    v.push_back({b, c, d});
    if (fifth) {
      // linear interpolation between positive loads stays positive: the samples suffice
      check_positive_load(r, "excitation.file", r.real("contact.normal_force") + e,
                          " at " + file.string() + ":" + std::to_string(row));
      dn.push_back(e);
    }
  }
  // the series as contact::CreepageHistory::samples takes it
  if (t.size() < 2) r.fail("excitation.file", file.string() + ": a creepage time series needs at least two samples");
  for (size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      r.fail("excitation.file",
             file.string() + ": times must increase (sample " + std::to_string(i + 1) + ")");
  return contact::CreepageHistory::samples(mean, t, v, dn);
}

}  // namespace

std::string excitation_file_path(const CaseReader& r) {
  std::filesystem::path file = r.string("excitation.file");
  if (file.is_relative() && !r.folder().empty()) file = std::filesystem::path(r.folder()) / file;
  return file.string();
}

contact::CreepageHistory read_excitation(const CaseReader& r) {
  const auto m = r.real3("creepage.mean");
  const contact::Creepage mean{m[0], m[1], m[2]};
  const std::string type = r.string("excitation.type");
  if (type == "none") return contact::CreepageHistory::constant(mean);
  if (type == "harmonic") return harmonic_excitation(r, mean);
  if (type == "multiharmonic") return multiharmonic_excitation(r, mean);
  return csv_excitation(r, mean);
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
    w.write(group + "/normal_amplitude", h.normal_amplitude(), "N");
    w.write(group + "/normal_phase", h.normal_phases(), {n}, "rad");
  }
  // provenance: the seed behind the random phases, on the root group (docs/conventions.md)
  if (h.kind() == contact::CreepageHistory::Kind::multiharmonic) w.attribute("/", "seed", h.seed());
}

std::vector<double> normal_load_series(const CaseReader& r, const contact::CreepageHistory& h,
                                       double normal_mean, double dt, long steps) {
  return within_case(r, [&] { return pipeline::normal_load_series(h, normal_mean, dt, steps); });
}

}  // namespace rollnoise::io
