#include "io/study_output.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "io/case_schema.hpp"
#include "io/hdf5_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "io/noise_output.hpp"
#include "io/output_files.hpp"
#include "noise/roughness.hpp"

namespace rollnoise::io {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string number(double v) {
  if (std::isnan(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

const char* status_name(CaseStatus s) {
  return s == CaseStatus::kComplete ? "complete"
         : s == CaseStatus::kFailed ? "failed"
         : s == CaseStatus::kStale  ? "stale"
                                    : "missing";
}

}  // namespace

void write_study_case(const std::string& path, const CaseReader& reader, const pipeline::NoiseCase& nc,
                      const pipeline::NoiseResult& r, const std::string& stamp, double seconds) {
  Hdf5Writer w(path);
  write_noise(w, reader, nc, r);
  w.attribute("/", "study_case", stamp);
  char t[48];
  std::snprintf(t, sizeof t, "%.6f s", seconds);
  w.attribute("/", "run_time", t);
  w.commit();
}

std::optional<std::string> read_case_stamp(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) return std::nullopt;
  return Hdf5Reader(path).attribute("/", "study_case");
}

void write_case_error(const std::string& path, const std::string& message) {
  write_text_file(path, "output", [&](std::ostream& out) { out << message << "\n"; }).commit();
}

std::optional<std::string> read_case_error(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

std::optional<CaseRecord> read_case_record(const std::string& path) {
  const Hdf5Reader h(path);
  if (!h.ok()) return std::nullopt;
  CaseRecord c;
  const auto creepage = h.numbers("/noise/contact/creepage"), angle = h.numbers("/noise/contact/angle"),
             normal = h.numbers("/noise/contact/normal_force"), state = h.numbers("/steady/state"),
             centre = h.numbers("/noise/bands/centre"), force = h.numbers("/noise/bands/force_level"),
             velocity = h.numbers("/noise/bands/velocity_level");
  if (!creepage || creepage->size() != 3 || !angle || !normal || !state || !centre || !force || !velocity ||
      force->size() != 4 * centre->size() || velocity->size() != 8 * centre->size())
    return std::nullopt;
  c.creepage = {(*creepage)[0], (*creepage)[1], (*creepage)[2]};
  c.contact_angle = angle->front();
  c.normal_force = normal->front();
  for (double s : *state) {
    c.adhesion_elements += s == 1.0;
    c.slip_elements += s == 2.0;
  }
  c.band_centre = *centre;
  c.force_level = *force;
  c.velocity_level = *velocity;
  const auto t = h.attribute("/", "run_time");
  c.run_time = t ? std::strtod(t->c_str(), nullptr) : kNaN;
  return c;
}

void write_study_table(const std::string& h5_path, const std::string& csv_path, const pipeline::StudyPlan& plan,
                       const std::vector<StudyRow>& rows) {
  const std::size_t n = rows.size(), na = plan.axes.size();
  // the band centres: those of the first complete case
  std::vector<double> centres;
  for (const auto& r : rows)
    if (r.status == CaseStatus::kComplete) {
      centres = r.record.band_centre;
      break;
    }
  const std::size_t nb = centres.size();
  auto band_of = [&](const StudyRow& r, std::size_t b) -> long {  // index of centre b in the row's bands
    if (r.status != CaseStatus::kComplete) return -1;
    for (std::size_t k = 0; k < r.record.band_centre.size(); ++k)
      if (std::abs(r.record.band_centre[k] - centres[b]) <= 1e-9 * centres[b]) return long(k);
    return -1;
  };

  std::vector<double> run_time(n, kNaN), creepage(3 * n, kNaN), angle(n, kNaN), normal(n, kNaN),
      adhesion(n, kNaN), slip(n, kNaN), force(n * nb * 4, kNaN), velocity(n * nb * 8, kNaN);
  std::vector<int> index(n), status(n);
  std::vector<std::string> message(n);
  for (std::size_t i = 0; i < n; ++i) {
    const StudyRow& r = rows[i];
    index[i] = int(r.parameters.index);
    status[i] = int(r.status);
    message[i] = r.message;
    if (r.status != CaseStatus::kComplete) continue;
    const CaseRecord& c = r.record;
    run_time[i] = c.run_time;
    for (int k = 0; k < 3; ++k) creepage[3 * i + k] = c.creepage[k];
    angle[i] = c.contact_angle;
    normal[i] = c.normal_force;
    adhesion[i] = double(c.adhesion_elements);
    slip[i] = double(c.slip_elements);
    for (std::size_t b = 0; b < nb; ++b) {
      const long k = band_of(r, b);
      if (k < 0) continue;
      for (int j = 0; j < 4; ++j) force[(i * nb + b) * 4 + j] = c.force_level[k * 4 + j];
      for (int j = 0; j < 8; ++j) velocity[(i * nb + b) * 8 + j] = c.velocity_level[k * 8 + j];
    }
  }

  auto units_of = [](const std::string& key) {
    const KeySpec* s = find_key(key);
    return s && !s->units.empty() ? s->units : std::string("-");
  };

  {
    Hdf5Writer w(h5_path);
    w.write("/study/case", index, {n}, "-");
    for (std::size_t a = 0; a < na; ++a) {
      const std::string& key = plan.axes[a].key;
      bool numeric = true;
      std::vector<double> v(n);
      std::vector<std::string> text(n);
      for (std::size_t i = 0; i < n; ++i) {
        v[i] = rows[i].parameters.values[a].number;
        text[i] = rows[i].parameters.values[a].toml;
        numeric = numeric && !std::isnan(v[i]);
      }
      if (numeric)
        w.write("/study/parameters/" + key, v, {n}, units_of(key));
      else
        w.write("/study/parameters/" + key, text, units_of(key) + " (TOML text)");
    }
    w.write("/study/status", status, {n}, "0 complete, 1 failed, 2 missing, 3 stale");
    w.write("/study/message", message, "-");
    w.write("/study/run_time", run_time, {n}, "s");
    w.write("/study/creepage", creepage, {n, 3}, "-, -, rad/m");
    w.write("/study/contact_angle", angle, {n}, "rad");
    w.write("/study/normal_force", normal, {n}, "N");
    w.write("/study/adhesion_elements", adhesion, {n}, "-");
    w.write("/study/slip_elements", slip, {n}, "-");
    w.write("/study/band_centre", centres, {nb}, "Hz");
    w.write("/study/force_level", force, {n, nb, 4}, "dB re 1 N (Fz, Fx, Fy), re 1 N m (Mz)");
    w.write("/study/velocity_level", velocity, {n, nb, 2, 4},
            "dB re 1e-9 m/s (z, x, y), re 1e-9 rad/s (rot z); [wheel, rail]");
    w.attribute("/study", "base", plan.base);
    w.attribute("/study", "combine", plan.combine == pipeline::Combine::kZip ? "zip" : "product");
    w.commit();
  }

  write_text_file(csv_path, "output", [&](std::ostream& csv) {
    csv << "case";
    for (const auto& a : plan.axes) csv << "," << csv_cell(a.key + " [" + units_of(a.key) + "]");
    csv << ",status,run_time [s],xi_x [-],xi_y [-],phi [rad/m],contact_angle [rad],normal_force [N],"
           "adhesion_elements [-],slip_elements [-]";
    const char* force_names[4] = {"Fz", "Fx", "Fy", "Mz"};
    const char* force_ref[4] = {"dB re 1 N", "dB re 1 N", "dB re 1 N", "dB re 1 N m"};
    const char* velocity_names[4] = {"vz", "vx", "vy", "wz"};
    const char* velocity_ref[4] = {"dB re 1e-9 m/s", "dB re 1e-9 m/s", "dB re 1e-9 m/s", "dB re 1e-9 rad/s"};
    for (std::size_t b = 0; b < nb; ++b)
      for (int j = 0; j < 4; ++j) csv << "," << force_names[j] << "_" << number(noise::nominal_centre(centres[b])) << "Hz [" << force_ref[j] << "]";
    for (int side = 0; side < 2; ++side)
      for (std::size_t b = 0; b < nb; ++b)
        for (int j = 0; j < 4; ++j)
          csv << "," << (side ? "rail_" : "wheel_") << velocity_names[j] << "_" << number(noise::nominal_centre(centres[b])) << "Hz ["
              << velocity_ref[j] << "]";
    csv << ",message\n";
    for (std::size_t i = 0; i < n; ++i) {
      const StudyRow& r = rows[i];
      csv << r.parameters.index;
      for (const auto& v : r.parameters.values) csv << "," << csv_cell(v.toml);
      csv << "," << status_name(r.status) << "," << number(run_time[i]);
      for (int k = 0; k < 3; ++k) csv << "," << number(creepage[3 * i + k]);
      csv << "," << number(angle[i]) << "," << number(normal[i]) << "," << number(adhesion[i]) << "," << number(slip[i]);
      for (std::size_t b = 0; b < nb; ++b)
        for (int j = 0; j < 4; ++j) csv << "," << number(force[(i * nb + b) * 4 + j]);
      for (int side = 0; side < 2; ++side)
        for (std::size_t b = 0; b < nb; ++b)
          for (int j = 0; j < 4; ++j) csv << "," << number(velocity[(i * nb + b) * 8 + side * 4 + j]);
      csv << "," << csv_cell(r.message) << "\n";
    }
  }).commit();
}

}  // namespace rollnoise::io
