#include "io/passby_output.hpp"

#include <cmath>
#include <string>

namespace rollnoise::io {

namespace {

// /passby/train/*: the axles and the train's geometry.
void write_train(Hdf5Writer& w, const pipeline::PassbyResult& r, const pipeline::PassbyCase& pc) {
  std::vector<double> at;
  std::vector<int> leading;
  for (const pipeline::Axle& a : r.axles)
    at.push_back(a.from_front), leading.push_back(a.leading ? 1 : 0);
  w.write("/passby/train/axle_position", at, {at.size()}, "m (behind the train's front)");
  w.write("/passby/train/axle_leading", leading, {leading.size()},
          "- (1: the leading axle of its bogie)");
  std::vector<double> length, bogie, base;
  for (const pipeline::Vehicle& v : pc.train)
    length.push_back(v.length), bogie.push_back(v.bogie_distance), base.push_back(v.wheelbase);
  w.write("/passby/train/vehicle_length", length, {length.size()}, "m");
  w.write("/passby/train/bogie_distance", bogie, {bogie.size()}, "m");
  w.write("/passby/train/wheelbase", base, {base.size()}, "m");
  w.write("/passby/train/length", r.length, "m");
  std::string took;
  for (std::size_t i = 0; i < 4; ++i)
    took += std::string(i ? "; " : "") + noise::wheel_name(static_cast<noise::WheelId>(i)) +
            " <- " + noise::wheel_name(r.source_wheel[i]);
  w.attribute("/passby/train", "source_wheels", took);
}

}  // namespace

void write_passby(Hdf5Writer& w, const pipeline::PassbyResult& r, const pipeline::PassbyCase& pc) {
  const std::string tp = "over the pass-by time T_p = " + std::to_string(r.passage_time) + " s";
  w.write("/passby/time", r.time, {r.time.size()},
          "s (the train's front passes the receiver at 0)");
  w.write("/passby/level_a", r.level_a, {r.level_a.size()},
          "dB(A) re 20 uPa (F time weighting, tau = 0.125 s)");
  w.write("/passby/leq_a", r.leq_a, "dB(A) re 20 uPa (L_pAeq,Tp, " + tp + ")");
  w.write("/passby/tel", r.tel,
          "dB(A) re 20 uPa (transit exposure level: the whole history over T_p)");
  w.write("/passby/lmax_a", r.lmax_a, "dB(A) re 20 uPa (L_pAFmax)");
  w.write("/passby/passage_time", r.passage_time, "s");
  w.write("/passby/speed", r.speed, "m/s");
  w.write("/passby/band_centre", r.centre, {r.centre.size()}, "Hz");
  std::vector<double> s;
  for (const auto& row : r.spectrum) s.insert(s.end(), row.begin(), row.end());
  w.write("/passby/spectrum", s, {r.spectrum.size(), 4},
          "dB re 20 uPa (L_eq per 1/3-octave band, unweighted, " + tp +
              "); [band][wheel, rail, sleepers, total]");
  w.write("/passby/leq_a_80", r.leq_a_80,
          "dB(A) re 20 uPa (L_pAeq,Tp normalised to 80 km/h: - 30 lg(v / 80 km/h), Regulation (EU) "
          "No 1304/2014 "
          "Annex 6.2.2.3)");
  if (std::isfinite(r.limit_a)) {
    w.write("/passby/limit_a", r.limit_a,
            "dB(A) re 20 uPa (TSI Noise limit of L_pAeq,Tp(80 km/h), Regulation (EU) No 1304/2014 "
            "Annex 4.2.3 "
            "Table 4)");
    w.attribute("/passby/limit_a", "category", pc.category);
  }
  w.write("/passby/receiver", std::vector<double>{pc.geometry.distance, pc.geometry.height}, {2},
          "m (distance from the track centre, height above the top of rail)");
  w.attribute("/passby", "ground",
              pc.geometry.reflection > 0.0 ? "reflecting (Q = 1)" : "absorbing (Q = 0)");
  w.attribute(
      "/passby", "sources",
      std::string("wheel: point at its centre, ") +
          (r.wheel_split ? "the axial modes' share a dipole along the axle, the rest a monopole"
                         : "a monopole") +
          "; rail: line of the vertical decay rate, monopole; sleepers: line of the same decay, "
          "monopole "
          "into the half space (docs/sound.md Sec. 6)");
  write_train(w, r, pc);
}

}  // namespace rollnoise::io
