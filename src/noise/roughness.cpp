#include "noise/roughness.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

// The 35 nominal 1/3-octave wavelength band centres of CNOSSOS-EU Appendix G, 2000 mm to 0.8 mm
// (exact centres 2000 mm * 10^{-i/10}; the nominal values are what the tables print).
constexpr double kBandsMm[35] = {2000, 1600, 1250, 1000, 800,  630, 500,  400, 315,  250, 200,  160,
                                 125,  100,  80,   63,   50,   40,  31.5, 25,  20,   16,  12.5, 10,
                                 8,    6.3,  5,    4,    3.15, 2.5, 2,    1.6, 1.25, 1,   0.8};

RoughnessSpectrum table(const char* name, const double (&levels)[35]) {
  RoughnessSpectrum s;
  s.name = name;
  for (int i = 0; i < 35; ++i) {
    s.wavelength.push_back(kBandsMm[i] * 1e-3);
    s.level.push_back(levels[i]);
  }
  return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Spectra
// ---------------------------------------------------------------------------------------------

double RoughnessSpectrum::level_at(double lambda) const {
  // wavelength is strictly decreasing: find the bracketing bands in log(lambda).
  if (lambda >= wavelength.front()) return level.front();
  if (lambda <= wavelength.back()) return level.back();
  const auto it = std::lower_bound(wavelength.begin(), wavelength.end(), lambda,
                                   [](double w, double l) { return w > l; });
  const std::size_t j =
      static_cast<std::size_t>(it - wavelength.begin());  // wavelength[j] <= lambda
  const std::size_t i = j - 1;
  const double t = std::log(lambda / wavelength[i]) / std::log(wavelength[j] / wavelength[i]);
  return level[i] + t * (level[j] - level[i]);
}

void RoughnessSpectrum::validate() const {
  if (wavelength.size() != level.size())
    throw std::invalid_argument("wavelength and level columns differ in length");
  if (wavelength.size() < 2) throw std::invalid_argument("a spectrum needs at least two bands");
  for (std::size_t i = 0; i < wavelength.size(); ++i) {
    if (!(wavelength[i] > 0.0) || !std::isfinite(wavelength[i]))
      throw std::invalid_argument("wavelength must be positive, got " + std::to_string(wavelength[i]));
    if (!std::isfinite(level[i]))
      throw std::invalid_argument("level must be a finite number (dB re 1 um)");
    if (i > 0 && !(wavelength[i] < wavelength[i - 1]))
      throw std::invalid_argument("wavelengths must be distinct (band " +
                                  std::to_string(wavelength[i]) + " m repeated)");
  }
}

RoughnessSpectrum iso3095_2013_rail_limit() {
  // dB re 1 um; 2000 mm ... 0.8 mm. Flat at 17.1 dB above 400 mm and at -14.0 dB below 1 mm as in
  // the CNOSSOS-EU table.
  static constexpr double kLevels[35] = {
      17.1, 17.1, 17.1, 17.1,  17.1,  17.1,  17.1,  17.1,  15.0,  13.0,  11.0, 9.0,
      7.0,  4.9,  2.9,  0.9,   -1.1,  -3.2,  -5.0,  -5.6,  -6.2,  -6.8,  -7.4, -8.0,
      -8.6, -9.2, -9.8, -10.4, -11.0, -11.6, -12.2, -12.8, -13.4, -14.0, -14.0};
  return table("EN ISO 3095:2013 rail roughness limit", kLevels);
}

RoughnessSpectrum rail_roughness_cnossos_average() {
  static constexpr double kLevels[35] = {
      35.0,  31.0,  28.0,  25.0,  23.0,  20.0,  17.0,  13.5,  10.5,  9.0,   6.5,  5.5,
      5.0,   3.5,   2.0,   0.1,   -0.2,  -0.3,  -0.8,  -3.0,  -5.0,  -7.0,  -8.0, -9.0,
      -10.0, -12.0, -13.0, -14.0, -15.0, -16.0, -17.0, -18.0, -19.0, -19.0, -19.0};
  return table("rail roughness, CNOSSOS-EU average network", kLevels);
}

RoughnessSpectrum wheel_roughness_cast_iron_block() {
  static constexpr double kLevels[35] = {
      2.2, 2.2, 2.2, 2.2, 2.2, 2.2, 2.2,  2.2,  2.2,  2.2, 2.2, 2.4, 0.6, 2.6, 5.8, 8.8, 11.1, 11.0,
      9.8, 7.5, 5.1, 3.0, 1.3, 0.2, -0.7, -1.2, -1.0, 0.3, 0.2, 1.3, 3.1, 3.1, 3.1, 3.1, 3.1};
  return table("wheel roughness, cast-iron block-braked tread", kLevels);
}

RoughnessSpectrum wheel_roughness_disc_braked() {
  static constexpr double kLevels[35] = {-5.9,  -5.9, -5.9, -5.9, -5.9, -5.9,  -5.9,  -5.9,  -5.9,
                                         2.3,   2.8,  2.6,  1.2,  2.1,  0.9,   -0.3,  -1.6,  -2.9,
                                         -4.9,  -7.0, -8.6, -9.3, -9.5, -10.1, -10.3, -10.3, -10.8,
                                         -10.9, -9.5, -9.5, -9.5, -9.5, -9.5,  -9.5,  -9.5};
  return table("wheel roughness, disc-braked tread", kLevels);
}

// ---------------------------------------------------------------------------------------------
// Bands and sums
// ---------------------------------------------------------------------------------------------

double energy_sum_db(double a, double b) {
  const double m = std::max(a, b);  // factor out the larger term against overflow
  return m + 10.0 * std::log10(std::pow(10.0, (a - m) / 10.0) + std::pow(10.0, (b - m) / 10.0));
}

int third_octave_index(double f) {
  // The band n holds f_c 10^{-1/20} <= f < f_c 10^{1/20}, f_c = 1000 10^{n/10} (IEC 61260-1 base
  // 10): n = round(10 log10(f / 1000)). So a nominal frequency names its own band: 5000 Hz is the
  // band of exact centre 5011.9 Hz, 400 Hz that of 398.1 Hz.
  return static_cast<int>(std::floor(10.0 * std::log10(f / 1000.0) + 0.5));
}

double nominal_centre(double f) {
  // IEC 61260-1 Annex E: the nominal mid-band frequencies of one decade, 1000 ... 8000 Hz
  static const double kDecade[10] = {1000, 1250, 1600, 2000, 2500, 3150, 4000, 5000, 6300, 8000};
  const int n = third_octave_index(f);
  const int decade = static_cast<int>(std::floor(n / 10.0));
  return kDecade[n - 10 * decade] * std::pow(10.0, decade);
}

std::vector<double> third_octave_centres(double f_min, double f_max) {
  if (!(f_min > 0.0) || !(f_max >= f_min))
    throw std::invalid_argument("third-octave bands need 0 < f_min <= f_max");
  std::vector<double> out;
  const int n0 = third_octave_index(f_min), n1 = third_octave_index(f_max);
  for (int n = n0; n <= n1; ++n) out.push_back(1000.0 * std::pow(10.0, n / 10.0));
  return out;
}

double third_octave_bandwidth(double centre) {
  return centre * (std::pow(10.0, 0.05) - std::pow(10.0, -0.05));
}

// ---------------------------------------------------------------------------------------------
// Combined roughness at speed V
// ---------------------------------------------------------------------------------------------

ContactRoughness::ContactRoughness(RoughnessSpectrum wheel, RoughnessSpectrum rail, double speed,
                                   ContactFilter filter)
    : wheel_(std::move(wheel)), rail_(std::move(rail)), speed_(speed), filter_(filter) {
  wheel_.validate();
  rail_.validate();
  if (!(speed_ > 0.0) || !std::isfinite(speed_))
    throw std::invalid_argument("roughness: speed must be positive, got " + std::to_string(speed_));
  filter_.validate();
}

double ContactRoughness::combined_level(double f) const {
  if (!(f > 0.0)) throw std::invalid_argument("roughness: frequency must be positive");
  const double lambda = speed_ / f;  // f = V / lambda
  return energy_sum_db(wheel_.level_at(lambda), rail_.level_at(lambda));
}

double ContactRoughness::level(double f) const {
  const double k = 2.0 * M_PI * f / speed_;
  return combined_level(f) + filter_.band_db(k);
}

std::vector<double> ContactRoughness::levels(const std::vector<double>& centres) const {
  std::vector<double> out;
  out.reserve(centres.size());
  for (double f : centres) out.push_back(level(f));
  return out;
}

double ContactRoughness::psd(double f) const {
  const double r0 = 1e-6;
  return r0 * r0 * std::pow(10.0, level(f) / 10.0) / third_octave_bandwidth(f);
}

double ContactRoughness::line_amplitude(double f, double df) const {
  if (!(df > 0.0)) throw std::invalid_argument("roughness: line spacing must be positive");
  return std::sqrt(2.0 * psd(f) * df);
}

}  // namespace rollnoise::noise
