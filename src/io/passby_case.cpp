#include "io/passby_case.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/task_pool.hpp"
#include "io/input_problems.hpp"

namespace rollnoise::io {

namespace {

// wheelbase < bogie_distance < length, and the outer axles within the vehicle
// (bogie_distance + wheelbase <= length). A [[train.vehicle]] entry's problems name train.vehicle
// and the entry (`at`: "train.vehicle[i]."); the [train] vehicle's name the key.
void check_vehicle(const CaseReader& r, const pipeline::Vehicle& v, const std::string& at) {
  const bool entry = !at.empty();
  const auto num = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m", x);
    return std::string(text);
  };
  if (!(v.wheelbase < v.bogie_distance))
    r.fail(entry ? "train.vehicle" : "train.wheelbase",
           at + "wheelbase = " + num(v.wheelbase) +
               " must be less than bogie_distance = " + num(v.bogie_distance));
  if (!(v.bogie_distance < v.length))
    r.fail(entry ? "train.vehicle" : "train.bogie_distance",
           at + "bogie_distance = " + num(v.bogie_distance) +
               " must be less than the vehicle's length = " + num(v.length));
  if (v.bogie_distance + v.wheelbase > v.length)
    r.fail(entry ? "train.vehicle" : "train.bogie_distance",
           at + "the outer axles (bogie_distance + wheelbase = " +
               num(v.bogie_distance + v.wheelbase) +
               ") lie beyond the vehicle's length = " + num(v.length));
}

// One [[train.vehicle]] entry: its count and the vehicle (fields not given: `base`'s).
void read_entry(const CaseReader& r, const std::map<std::string, double>& e, std::size_t i,
                const pipeline::Vehicle& base, std::vector<pipeline::Vehicle>& train) {
  const std::string key = "train.vehicle", at = key + "[" + std::to_string(i) + "].";
  pipeline::Vehicle v = base;
  const std::pair<const char*, double*> fields[] = {
      {"length", &v.length}, {"bogie_distance", &v.bogie_distance}, {"wheelbase", &v.wheelbase}};
  for (const auto& [name, value] : fields) {
    const auto it = e.find(name);
    if (it == e.end()) continue;
    if (!(it->second > 0.0))
      r.fail(key, at + name + " must be positive, got " + std::to_string(it->second));
    *value = it->second;
  }
  double count = 1.0;
  if (const auto it = e.find("count"); it != e.end()) count = it->second;
  if (!(count >= 1.0 && count <= 1000.0 && std::floor(count) == count))
    r.fail(key,
           at + "count must be a whole number between 1 and 1000, got " + std::to_string(count));
  check_vehicle(r, v, at);
  train.insert(train.end(), static_cast<std::size_t>(count), v);
}

// The vehicles: [[train.vehicle]] entries, or train.vehicles alike ones.
std::vector<pipeline::Vehicle> read_train(const CaseReader& r, const pipeline::NoiseCase& nc,
                                          InputProblems& p) {
  pipeline::Vehicle base;
  long vehicles = 1;
  p.check([&] { base.length = r.real("train.vehicle_length"); });
  p.check([&] { base.bogie_distance = r.real("train.bogie_distance"); });
  base.wheelbase = nc.wheelbase;
  p.check([&] {
    if (r.has("train.wheelbase")) base.wheelbase = r.real("train.wheelbase");
  });
  p.check([&] { vehicles = r.integer("train.vehicles"); });
  std::vector<pipeline::Vehicle> train;
  std::vector<std::map<std::string, double>> entries;
  p.check([&] {
    entries = r.table_list("train.vehicle", {"count", "length", "bogie_distance", "wheelbase"});
  });
  if (entries.empty()) {
    p.check([&] { check_vehicle(r, base, ""); });
    return std::vector<pipeline::Vehicle>(static_cast<std::size_t>(vehicles), base);
  }
  p.check([&] {
    if (r.has("train.vehicles"))
      r.fail("train.vehicles", "give train.vehicles or [[train.vehicle]] entries, not both");
  });
  for (std::size_t i = 0; i < entries.size(); ++i)
    p.check([&] { read_entry(r, entries[i], i, base, train); });
  p.check([&] {
    if (train.size() > 1000) r.fail("train.vehicle", "more than 1000 vehicles");
  });
  return train;
}

}  // namespace

pipeline::PassbyCase read_passby_case(const CaseReader& r, const pipeline::NoiseCase& nc) {
  InputProblems p;
  pipeline::PassbyCase pc;
  pc.train = read_train(r, nc, p);
  pc.wheel_radius = nc.wheel_radius;
  p.check([&] { pc.geometry.distance = r.real("passby.distance"); });
  p.check([&] {
    pc.geometry.height = r.real("passby.height");
    if (!(pc.geometry.height > pc.geometry.ground_level))
      r.fail("passby.height", "the receiver must stand above the ground plane at " +
                                  std::to_string(pc.geometry.ground_level) + " m, got " +
                                  std::to_string(pc.geometry.height) + " m");
  });
  p.check([&] { pc.geometry.reflection = r.string("passby.ground") == "reflecting" ? 1.0 : 0.0; });
  p.check([&] {
    const std::string d = r.string("passby.rail_directivity");
    pc.rail_directivity = d == "vertical-dipole"  ? acoustics::Directivity::kDipoleZ
                          : d == "lateral-dipole" ? acoustics::Directivity::kDipoleY
                                                  : acoustics::Directivity::kMonopole;
  });
  p.check([&] { pc.time_step = r.real("passby.time_step"); });
  p.check([&] { pc.threads = resolved_threads(static_cast<int>(r.integer("solver.threads"))); });
  p.check([&] {
    const std::string c = r.string("passby.category");
    pc.category = c == "none" ? std::string() : c;
  });
  p.throw_if_any();
  return pc;
}

}  // namespace rollnoise::io
