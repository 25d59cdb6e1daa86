#include "io/study_output.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <utility>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "io/case_schema.hpp"
#include "io/hdf5_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "io/noise_output.hpp"
#include "io/output_files.hpp"
#include "noise/roughness.hpp"
#include "noise/wheel_contact.hpp"

namespace rollnoise::io {
namespace {


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

constexpr noise::WheelId kWheels[4] = {noise::WheelId::leading_outer, noise::WheelId::leading_inner,
                                       noise::WheelId::trailing_outer,
                                       noise::WheelId::trailing_inner};

const char* status_name(CaseStatus s) {
  return s == CaseStatus::kComplete ? "complete"
         : s == CaseStatus::kFailed ? "failed"
         : s == CaseStatus::kStale  ? "stale"
                                    : "missing";
}

// /noise/wheels/<wheel> of a case file: the wheels whose contact state and bands are all there.
std::vector<WheelRecord> read_wheel_records(const Hdf5Reader& h, std::size_t nb) {
  std::vector<WheelRecord> out;
  for (noise::WheelId id : kWheels) {
    const std::string g = std::string("/noise/wheels/") + noise::wheel_name(id);
    const auto creepage = h.numbers(g + "/contact/creepage"),
               angle = h.numbers(g + "/contact/angle"),
               normal = h.numbers(g + "/contact/normal_force"),
               force = h.numbers(g + "/bands/force_level"),
               velocity = h.numbers(g + "/bands/velocity_level");
    if (!creepage || creepage->size() != 3 || !angle || angle->empty() || !normal ||
        normal->empty() || !force || !velocity || force->size() != 4 * nb ||
        velocity->size() != 8 * nb)
      continue;
    WheelRecord w;
    w.name = noise::wheel_name(id);
    w.creepage = {(*creepage)[0], (*creepage)[1], (*creepage)[2]};
    w.contact_angle = angle->front();
    w.normal_force = normal->front();
    w.force_level = *force;
    w.velocity_level = *velocity;
    if (const auto v = h.numbers(g + "/contact/wheelset_lateral"); v && v->size() == 1) w.wheelset_lateral = v->front();
    if (const auto v = h.numbers(g + "/contact/wheelset_yaw"); v && v->size() == 1) w.wheelset_yaw = v->front();
    if (const auto v = h.numbers(g + "/contact/two_point"); v && v->size() == 1) w.two_point = v->front();
    out.push_back(std::move(w));
  }
  return out;
}

// Band levels of every row on the study's band centres (NaN where a row has none): n x nb x 4
// forces and n x nb x 8 velocities. `levels(i)` gives row i's record (its band centres) and the
// levels to take (a case's own, or one wheel's), or nulls.
struct BandTable {
  std::vector<double> force, velocity;
};
using RowLevels =
    std::function<std::pair<const CaseRecord*, const std::vector<double>*>(std::size_t, bool)>;

BandTable band_table(std::size_t n, const std::vector<double>& centres, const RowLevels& levels) {
  const std::size_t nb = centres.size();
  BandTable t{std::vector<double>(n * nb * 4, kNaN), std::vector<double>(n * nb * 8, kNaN)};
  for (std::size_t i = 0; i < n; ++i) {
    const auto [record, force] = levels(i, false);
    if (!record || !force) continue;
    const std::vector<double>& velocity = *levels(i, true).second;
    for (std::size_t b = 0; b < nb; ++b)  // index of centre b in the row's bands
      for (std::size_t k = 0; k < record->band_centre.size(); ++k) {
        if (std::abs(record->band_centre[k] - centres[b]) > 1e-9 * centres[b]) continue;
        for (int j = 0; j < 4; ++j) t.force[(i * nb + b) * 4 + j] = (*force)[k * 4 + j];
        for (int j = 0; j < 8; ++j) t.velocity[(i * nb + b) * 8 + j] = velocity[k * 8 + j];
        break;
      }
  }
  return t;
}

// The CSV header of a band table: Fz_1000Hz [dB re 1 N], ..., wheel_vz_1000Hz, ..., rail_wz_...,
// each name after `prefix` ("" for the case's own levels, "leading_inner." for a wheel's).
void band_header(std::ostream& csv, const std::string& prefix, const std::vector<double>& centres) {
  const char* force_names[4] = {"Fz", "Fx", "Fy", "Mz"};
  const char* force_ref[4] = {"dB re 1 N", "dB re 1 N", "dB re 1 N", "dB re 1 N m"};
  const char* velocity_names[4] = {"vz", "vx", "vy", "wz"};
  const char* velocity_ref[4] = {"dB re 1e-9 m/s", "dB re 1e-9 m/s", "dB re 1e-9 m/s",
                                 "dB re 1e-9 rad/s"};
  for (double c : centres)
    for (int j = 0; j < 4; ++j)
      csv << "," << prefix << force_names[j] << "_" << number(noise::nominal_centre(c)) << "Hz ["
          << force_ref[j] << "]";
  for (int side = 0; side < 2; ++side)
    for (double c : centres)
      for (int j = 0; j < 4; ++j)
        csv << "," << prefix << (side ? "rail_" : "wheel_") << velocity_names[j] << "_"
            << number(noise::nominal_centre(c)) << "Hz [" << velocity_ref[j] << "]";
}

void band_cells(std::ostream& csv, const BandTable& t, std::size_t i, std::size_t nb) {
  for (std::size_t b = 0; b < nb; ++b)
    for (int j = 0; j < 4; ++j) csv << "," << number(t.force[(i * nb + b) * 4 + j]);
  for (int side = 0; side < 2; ++side)
    for (std::size_t b = 0; b < nb; ++b)
      for (int j = 0; j < 4; ++j) csv << "," << number(t.velocity[(i * nb + b) * 8 + side * 4 + j]);
}

// One wheel's columns of the study: its contact state and band levels per row (NaN where a row
// lacks the wheel).
struct WheelColumns {
  std::string name;
  std::vector<double> creepage, angle, normal;  // n x 3, n, n
  std::vector<double> lateral, yaw, two_point;  // n each: the wheel's axle and its flange contact
  BandTable bands;
};

const WheelRecord* find_wheel(const StudyRow& r, const std::string& name) {
  if (r.status != CaseStatus::kComplete) return nullptr;
  for (const WheelRecord& w : r.record.wheels)
    if (w.name == name) return &w;
  return nullptr;
}

// The wheels any complete case has, in the order leading_outer ... trailing_inner.
std::vector<WheelColumns> wheel_columns(const std::vector<StudyRow>& rows,
                                        const std::vector<double>& centres) {
  const std::size_t n = rows.size();
  std::vector<WheelColumns> out;
  for (noise::WheelId id : kWheels) {
    const std::string name = noise::wheel_name(id);
    bool any = false;
    for (const StudyRow& r : rows) any = any || find_wheel(r, name);
    if (!any) continue;
    WheelColumns c{name,
                   std::vector<double>(3 * n, kNaN),
                   std::vector<double>(n, kNaN),
                   std::vector<double>(n, kNaN),
                   std::vector<double>(n, kNaN),
                   std::vector<double>(n, kNaN),
                   std::vector<double>(n, kNaN),
                   {}};
    for (std::size_t i = 0; i < n; ++i)
      if (const WheelRecord* w = find_wheel(rows[i], name)) {
        for (int k = 0; k < 3; ++k) c.creepage[3 * i + k] = w->creepage[k];
        c.angle[i] = w->contact_angle;
        c.normal[i] = w->normal_force;
        c.lateral[i] = w->wheelset_lateral;
        c.yaw[i] = w->wheelset_yaw;
        c.two_point[i] = w->two_point;
      }
    c.bands = band_table(n, centres, [&](std::size_t i, bool velocity) {
      const WheelRecord* w = find_wheel(rows[i], name);
      return std::make_pair(w ? &rows[i].record : nullptr,
                            w ? (velocity ? &w->velocity_level : &w->force_level) : nullptr);
    });
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

void write_study_case(const std::string& path, const CaseReader& reader,
                      const pipeline::NoiseCase& nc, const pipeline::NoiseResult& r,
                      const std::string& stamp, double seconds) {
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
  const auto creepage = h.numbers("/noise/contact/creepage"),
             angle = h.numbers("/noise/contact/angle"),
             normal = h.numbers("/noise/contact/normal_force"), state = h.numbers("/steady/state"),
             centre = h.numbers("/noise/bands/centre"),
             force = h.numbers("/noise/bands/force_level"),
             velocity = h.numbers("/noise/bands/velocity_level");
  if (!creepage || creepage->size() != 3 || !angle || !normal || !state || !centre || !force ||
      !velocity || force->size() != 4 * centre->size() || velocity->size() != 8 * centre->size())
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
  c.wheels = read_wheel_records(h, centre->size());
  if (const auto a = h.numbers("/noise/sound/power_a"); a && a->size() == 4)
    c.sound_power_a = {(*a)[0], (*a)[1], (*a)[2], (*a)[3]};
  const auto t = h.attribute("/", "run_time");
  c.run_time = t ? std::strtod(t->c_str(), nullptr) : kNaN;
  return c;
}

namespace {

// Everything study.h5 and study.csv hold, per row (NaN where a row has no value).
struct StudyColumns {
  std::vector<double> centres;  // the band centres: those of the first complete case
  BandTable bands;
  std::vector<WheelColumns> wheels;
  std::vector<double> run_time, creepage, angle, normal, adhesion, slip;
  std::vector<double> sound_a;  // n x 4: wheel, rail, sleepers, total (dB(A) re 1 pW)
  std::vector<int> index, status;
  std::vector<std::string> message;
};

StudyColumns study_columns(const std::vector<StudyRow>& rows) {
  const std::size_t n = rows.size();
  StudyColumns t;
  for (const auto& r : rows)
    if (r.status == CaseStatus::kComplete) {
      t.centres = r.record.band_centre;
      break;
    }
  t.bands = band_table(n, t.centres, [&](std::size_t i, bool velocity) {
    const bool complete = rows[i].status == CaseStatus::kComplete;
    const CaseRecord& c = rows[i].record;
    return std::make_pair(complete ? &c : nullptr,
                          complete ? (velocity ? &c.velocity_level : &c.force_level) : nullptr);
  });
  t.wheels = wheel_columns(rows, t.centres);
  t.run_time.assign(n, kNaN);
  t.creepage.assign(3 * n, kNaN);
  t.angle.assign(n, kNaN);
  t.normal.assign(n, kNaN);
  t.adhesion.assign(n, kNaN);
  t.slip.assign(n, kNaN);
  t.sound_a.assign(4 * n, kNaN);
  t.index.resize(n);
  t.status.resize(n);
  t.message.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const StudyRow& r = rows[i];
    t.index[i] = int(r.parameters.index);
    t.status[i] = int(r.status);
    t.message[i] = r.message;
    if (r.status != CaseStatus::kComplete) continue;
    const CaseRecord& c = r.record;
    t.run_time[i] = c.run_time;
    for (int k = 0; k < 3; ++k) t.creepage[3 * i + k] = c.creepage[k];
    t.angle[i] = c.contact_angle;
    t.normal[i] = c.normal_force;
    t.adhesion[i] = double(c.adhesion_elements);
    t.slip[i] = double(c.slip_elements);
    for (int k = 0; k < 4; ++k) t.sound_a[4 * i + k] = c.sound_power_a[static_cast<std::size_t>(k)];
  }
  return t;
}

std::string units_of(const std::string& key) {
  const KeySpec* s = find_key(key);
  return s && !s->units.empty() ? s->units : std::string("-");
}

const char* const kForceUnits = "dB re 1 N (Fz, Fx, Fy), re 1 N m (Mz)";
const char* const kVelocityUnits = "dB re 1e-9 m/s (z, x, y), re 1e-9 rad/s (rot z); [wheel, rail]";

void write_study_h5(const std::string& h5_path, const pipeline::StudyPlan& plan,
                    const std::vector<StudyRow>& rows, const StudyColumns& t) {
  const std::size_t n = rows.size(), na = plan.axes.size(), nb = t.centres.size();
  Hdf5Writer w(h5_path);
  w.write("/study/case", t.index, {n}, "-");
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
  w.write("/study/status", t.status, {n}, "0 complete, 1 failed, 2 missing, 3 stale");
  w.write("/study/message", t.message, "-");
  w.write("/study/run_time", t.run_time, {n}, "s");
  w.write("/study/creepage", t.creepage, {n, 3}, "-, -, rad/m");
  w.write("/study/contact_angle", t.angle, {n}, "rad");
  w.write("/study/normal_force", t.normal, {n}, "N");
  w.write("/study/adhesion_elements", t.adhesion, {n}, "-");
  w.write("/study/slip_elements", t.slip, {n}, "-");
  w.write("/study/sound_power_a", t.sound_a, {n, 4},
          "dB(A) re 1 pW (A-weighted sound power: wheel, rail, sleepers, total; docs/sound.md)");
  w.write("/study/band_centre", t.centres, {nb}, "Hz");
  w.write("/study/force_level", t.bands.force, {n, nb, 4}, kForceUnits);
  w.write("/study/velocity_level", t.bands.velocity, {n, nb, 2, 4}, kVelocityUnits);
  for (const WheelColumns& c : t.wheels) {  // as /noise/wheels/<wheel> of the cases
    const std::string g = "/study/wheels/" + c.name + "/";
    w.write(g + "creepage", c.creepage, {n, 3}, "-, -, rad/m (the wheel's own contact frame)");
    w.write(g + "contact_angle", c.angle, {n}, "rad");
    w.write(g + "normal_force", c.normal, {n}, "N");
    w.write(g + "wheelset_lateral", c.lateral, {n}, "m (the wheel's axle, towards the outer rail)");
    w.write(g + "wheelset_yaw", c.yaw, {n}, "rad (the wheel's axle)");
    w.write(g + "two_point", c.two_point, {n}, "- (1: flange contact on this wheel's side, 0: none)");
    w.write(g + "force_level", c.bands.force, {n, nb, 4}, kForceUnits);
    w.write(g + "velocity_level", c.bands.velocity, {n, nb, 2, 4}, kVelocityUnits);
  }
  w.attribute("/study", "base", plan.base);
  w.attribute("/study", "combine", plan.combine == pipeline::Combine::kZip ? "zip" : "product");
  w.commit();
}

void write_study_csv(const std::string& csv_path, const pipeline::StudyPlan& plan,
                     const std::vector<StudyRow>& rows, const StudyColumns& t) {
  const std::size_t n = rows.size(), nb = t.centres.size();
  write_text_file(csv_path, "output", [&](std::ostream& csv) {
    csv << "case";
    for (const auto& a : plan.axes) csv << "," << csv_cell(a.key + " [" + units_of(a.key) + "]");
    csv << ",status,run_time [s],xi_x [-],xi_y [-],phi [rad/m],contact_angle [rad],normal_force "
           "[N],"
           "adhesion_elements [-],slip_elements [-],"
           "LwA_wheel [dB(A) re 1 pW],LwA_rail [dB(A) re 1 pW],LwA_sleepers [dB(A) re 1 pW],"
           "LwA_total [dB(A) re 1 pW]";
    band_header(csv, "", t.centres);
    for (const WheelColumns& c : t.wheels) {
      const std::string p = "," + c.name + ".";
      csv << p << "xi_x [-]" << p << "xi_y [-]" << p << "phi [rad/m]" << p << "contact_angle [rad]"
          << p << "normal_force [N]" << p << "wheelset_lateral [m]" << p << "wheelset_yaw [rad]" << p
          << "two_point [-]";
      band_header(csv, c.name + ".", t.centres);
    }
    csv << ",message\n";
    for (std::size_t i = 0; i < n; ++i) {
      const StudyRow& r = rows[i];
      csv << r.parameters.index;
      for (const auto& v : r.parameters.values) csv << "," << csv_cell(v.toml);
      csv << "," << status_name(r.status) << "," << number(t.run_time[i]);
      for (int k = 0; k < 3; ++k) csv << "," << number(t.creepage[3 * i + k]);
      csv << "," << number(t.angle[i]) << "," << number(t.normal[i]) << "," << number(t.adhesion[i])
          << "," << number(t.slip[i]);
      for (int k = 0; k < 4; ++k) csv << "," << number(t.sound_a[4 * i + k]);
      band_cells(csv, t.bands, i, nb);
      for (const WheelColumns& c : t.wheels) {
        for (int k = 0; k < 3; ++k) csv << "," << number(c.creepage[3 * i + k]);
        csv << "," << number(c.angle[i]) << "," << number(c.normal[i]) << "," << number(c.lateral[i]) << ","
            << number(c.yaw[i]) << "," << number(c.two_point[i]);
        band_cells(csv, c.bands, i, nb);
      }
      csv << "," << csv_cell(r.message) << "\n";
    }
  }).commit();
}

}  // namespace

void write_study_table(const std::string& h5_path, const std::string& csv_path,
                       const pipeline::StudyPlan& plan, const std::vector<StudyRow>& rows) {
  const StudyColumns t = study_columns(rows);
  write_study_h5(h5_path, plan, rows, t);
  write_study_csv(csv_path, plan, rows, t);
}

}  // namespace rollnoise::io
