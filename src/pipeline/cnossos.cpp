// CNOSSOS-EU transfer functions and the Directive's line source power, (C1), (2.3.2)-(2.3.10) of
// cnossos.hpp.
#include "pipeline/cnossos.hpp"

#include <cmath>
#include <stdexcept>

#include "acoustics/a_weighting.hpp"
#include "noise/roughness.hpp"
#include "pipeline/passby.hpp"

namespace rollnoise::pipeline {

namespace {

double picowatts(double level) {
  return std::isfinite(level) ? std::pow(10.0, 0.1 * level) : 0.0;
}  // pW

}  // namespace

const CnossosSpectrum& cnossos_centres() {
  static const CnossosSpectrum c = {50,   63,   80,   100,  125,  160,  200,  250,
                                    315,  400,  500,  630,  800,  1000, 1250, 1600,
                                    2000, 2500, 3150, 4000, 5000, 6300, 8000, 10000};
  return c;
}

CnossosTransfer cnossos_transfer(const SoundResult& sound,
                                 const std::vector<noise::WheelId>& wheels,
                                 const std::vector<double>& roughness) {
  if (wheels.empty() || sound.contact_power.size() < wheels.size() ||
      roughness.size() != sound.centre.size())
    throw std::invalid_argument(
        "cnossos_transfer: needs every computed wheel's powers and a roughness per band");
  const std::array<std::size_t, 4> source = bogie_sources(wheels);
  CnossosTransfer t;
  std::vector<int> at(kCnossosBands, -1);  // the case's band of each of the 24
  for (std::size_t b = 0; b < sound.centre.size(); ++b)
    for (std::size_t i = 0; i < kCnossosBands; ++i)
      if (noise::nominal_centre(sound.centre[b]) == cnossos_centres()[i])
        at[i] = static_cast<int>(b);
  for (std::size_t i = 0; i < kCnossosBands; ++i) {
    if (at[i] < 0) continue;
    const auto b = static_cast<std::size_t>(at[i]);
    double vehicle = 0.0, track = 0.0;  // per axle: the bogie's four wheels halved (pW)
    for (const std::size_t k : source) {
      vehicle += 0.5 * picowatts(sound.contact_power[k][b][0]);
      track += 0.5 * (picowatts(sound.contact_power[k][b][1]) + picowatts(sound.contact_power[k][b][2]));
    }
    t.vehicle[i] = 10.0 * std::log10(vehicle) - roughness[b];  // (C1)
    t.track[i] = 10.0 * std::log10(track) - roughness[b];
    t.roughness[i] = roughness[b];
    t.computed[i] = true;
  }
  int first = -1, last = -1;
  for (std::size_t i = 0; i < kCnossosBands; ++i)
    if (t.computed[i]) last = static_cast<int>(i), first = first < 0 ? static_cast<int>(i) : first;
  if (first < 0)
    throw std::invalid_argument("cnossos_transfer: no band of the case lies in 50 Hz - 10 kHz");
  for (std::size_t i = 0; i < kCnossosBands;
       ++i) {  // the nearest computed band (the case's are contiguous)
    if (t.computed[i]) continue;
    const auto from = static_cast<std::size_t>(static_cast<int>(i) < first ? first : last);
    t.vehicle[i] = t.vehicle[from], t.track[i] = t.track[from], t.roughness[i] = t.roughness[from];
  }
  return t;
}

CnossosLinePower cnossos_line_power(const CnossosTransfer& t, double axles, double flow,
                                    double speed) {
  if (!(axles > 0.0) || !(flow > 0.0) || !(speed > 0.0))
    throw std::invalid_argument("cnossos_line_power: needs axles, a flow and a speed > 0");
  CnossosLinePower p;
  double a = 0.0;
  for (std::size_t i = 0; i < kCnossosBands; ++i) {
    const double tr = t.roughness[i] + t.track[i] + 10.0 * std::log10(axles);     // (2.3.8)
    const double veh = t.roughness[i] + t.vehicle[i] + 10.0 * std::log10(axles);  // (2.3.9)
    const double w0 =
        10.0 * std::log10(std::pow(10.0, 0.1 * tr) + std::pow(10.0, 0.1 * veh));  // (2.3.10)
    p.band[i] = w0 + 10.0 * std::log10(flow / (1000.0 * speed));                  // (2.3.2)
    a += std::pow(10.0, 0.1 * (p.band[i] + acoustics::a_weighting(cnossos_centres()[i])));
  }
  p.total_a = 10.0 * std::log10(a);
  return p;
}

}  // namespace rollnoise::pipeline
