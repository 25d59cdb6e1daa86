#include "io/sound_output.hpp"

#include <string>

#include "dynamics/wheel_fe.hpp"
#include "noise/wheel_contact.hpp"

namespace rollnoise::io {
namespace {

constexpr const char* kColumns = "wheel, rail, sleepers, total";

std::vector<double> flat(const pipeline::SoundBands& b) {
  std::vector<double> out;
  for (const auto& row : b) out.insert(out.end(), row.begin(), row.end());
  return out;
}

void write_bands(Hdf5Writer& w, const std::string& group, const pipeline::SoundBands& bands,
                 const std::array<double, 4>& a) {
  w.write(group + "/power", flat(bands), {bands.size(), 4},
          std::string("dB re 1 pW; [band][") + kColumns + "]");
  w.write(
      group + "/power_a", std::vector<double>(a.begin(), a.end()), {4},
      std::string("dB(A) re 1 pW (IEC 61672-1 A-weighting over the bands); [") + kColumns + "]");
}

// /sound/radiation_efficiency/{rail, wheel}: the tables the powers were made of.
void write_efficiencies(Hdf5Writer& w, const pipeline::SoundResult& s) {
  if (s.rail) {
    w.write("/sound/radiation_efficiency/rail/frequency", s.rail->frequency,
            {s.rail->frequency.size()}, "Hz");
    w.write("/sound/radiation_efficiency/rail/vertical", s.rail->sigma_vertical,
            {s.rail->sigma_vertical.size()},
            "- (sigma of the section's rigid vertical motion, 2D BEM)");
    w.write("/sound/radiation_efficiency/rail/lateral", s.rail->sigma_lateral,
            {s.rail->sigma_lateral.size()},
            "- (sigma of the section's rigid lateral motion, 2D BEM)");
    w.attribute(
        "/sound/radiation_efficiency/rail", "ground",
        s.rail->ground ? "rigid plane at the foot (sound.rail_ground = \"rigid\")" : "free field");
  }
  if (s.wheel) {
    const pipeline::WheelRadiation& wr = *s.wheel;
    const std::string g = "/sound/radiation_efficiency/wheel";
    w.write(g + "/frequency", wr.frequency, {wr.frequency.size()}, "Hz");
    std::vector<double> sigma;
    std::vector<int> n, mode;
    for (const auto& o : wr.orders)
      for (int k : o.modes) n.push_back(o.n), mode.push_back(k);
    for (std::size_t f = 0; f < wr.frequency.size(); ++f)
      for (const auto& e : wr.efficiency) sigma.push_back(e[f]);
    w.write(g + "/sigma", sigma, {wr.frequency.size(), wr.efficiency.size()},
            "- (each mode's radiation efficiency, axisymmetric BEM; [frequency][mode])");
    w.write(g + "/n", n, {n.size()}, "- (nodal diameters of each column of sigma)");
    std::vector<std::string> family;
    for (int f : wr.family)
      family.push_back(dynamics::family_name(static_cast<dynamics::ModeFamily>(f)));
    w.write(g + "/family", family, "- (each column's mode family: axial, radial, circumferential)");
    w.write(g + "/nodal_circles", wr.nodal_circles, {wr.nodal_circles.size()},
            "- (each column's nodal circles; -1 unknown)");
    w.write(g + "/mode", mode, {mode.size()},
            "- (index of the FE mode, as /wheel/modes of `rollnoise modes`)");
    w.write(g + "/surface", wr.surface,
            "m^2 (the radiating surface: the section boundary swept around)");
    w.write(g + "/elements", std::vector<int>{wr.elements}, {},
            "- (boundary elements of the section)");
  }
}

// /track/decay_rate/*: EN 15461 from the track model, and EN ISO 3095's lower limits.
void write_decay_rates(Hdf5Writer& w, const pipeline::SoundResult& s) {
  w.write("/track/decay_rate/band_centre", s.centre, {s.centre.size()}, "Hz");
  w.write("/track/decay_rate/vertical", s.decay_vertical, {s.decay_vertical.size()},
          "dB/m (EN 15461: vertical transfer receptances along the rail from a vertical force at "
          "track.position, band means)");
  w.write("/track/decay_rate/lateral", s.decay_lateral, {s.decay_lateral.size()},
          "dB/m (EN 15461: lateral transfer receptances from a lateral force)");
  w.write("/track/decay_rate/limit_vertical", s.decay_limit_vertical,
          {s.decay_limit_vertical.size()},
          "dB/m (EN ISO 3095:2013 lower limit of the vertical decay rate of a reference track; NaN "
          "outside 250 Hz - 5 kHz)");
  w.write(
      "/track/decay_rate/limit_lateral", s.decay_limit_lateral, {s.decay_limit_lateral.size()},
      "dB/m (EN ISO 3095:2013 lower limit of the lateral decay rate; NaN outside 250 Hz - 5 kHz)");
}

}  // namespace

void write_sound(Hdf5Writer& w, const pipeline::NoiseResult& r) {
  if (!r.sound) return;
  const pipeline::SoundResult& s = *r.sound;
  w.write("/noise/sound/band_centre", s.centre, {s.centre.size()}, "Hz");
  write_bands(w, "/noise/sound", s.power, s.power_a);
  w.attribute("/noise/sound", "columns", kColumns);
  w.write("/noise/sound/input_power", s.input_power, {s.input_power.size()},
          "dB re 1 pW (the mechanical power the contact forces put into the wheels and the rails "
          "per band: "
          "the bound of the radiated power)");
  w.attribute(
      "/noise/sound", "sum",
      "all the contacts of the loop: every wheel's power, each rail's power under all the contacts "
      "on it (coherently), the sleepers of both rails; power sum over the roughness sources (with "
      "noise.contact_coupling = \"none\" each source drives its own contact alone)");
  if (!s.wheel_note.empty()) w.attribute("/noise/sound", "wheel_missing", s.wheel_note);
  const char* family_units =
      "dB re 1 pW; [band][axial, radial, circumferential]: the wheel's power with one mode "
      "family's "
      "modes alone (the families' cross terms left out)";
  auto flat3 = [](const std::vector<std::array<double, 3>>& b) {
    std::vector<double> out;
    for (const auto& row : b) out.insert(out.end(), row.begin(), row.end());
    return out;
  };
  if (!s.wheel_family.empty())
    w.write("/noise/sound/wheel_by_family", flat3(s.wheel_family), {s.wheel_family.size(), 3},
            family_units);
  for (std::size_t i = 0; i < r.wheels.size() && i < s.contact_power.size(); ++i) {
    const std::string g =
        std::string("/noise/wheels/") + noise::wheel_name(r.wheels[i].wheel) + "/sound";
    write_bands(w, g, s.contact_power[i], s.contact_power_a[i]);
    if (i < s.contact_family.size())
      w.write(g + "/wheel_by_family", flat3(s.contact_family[i]), {s.contact_family[i].size(), 3},
              family_units);
    w.attribute(
        g, "columns",
        "wheel: this wheel's radiation under all its contacts' forces; rail, sleepers: its rail "
        "and sleepers under this wheel's contact forces alone (the bogie's columns are coherent "
        "sums over the contacts on each rail)");
  }
  write_efficiencies(w, s);
  write_decay_rates(w, s);
}

}  // namespace rollnoise::io
