// Wheel and rail roughness: 1/3-octave wavelength spectra, conversion to frequency at the train
// speed, the wheel + rail energy sum and the contact filter (Thompson, Railway Noise and Vibration,
// 2009, chapters on roughness and wheel/rail interaction; EN 15610:2019 for the spectra;
// CNOSSOS-EU, Directive (EU) 2015/996, Annex II Sec. 2.3 and Appendix G, for the tabulated
// spectra used as defaults).
//
// A roughness level is L = 10 log10(r_rms^2 / r_0^2), r_0 = 1 um, of the roughness r(x) in one
// 1/3-octave wavelength band. A wavelength lambda passes the contact at frequency f = V / lambda,
// and a 1/3-octave band in wavelength maps onto a 1/3-octave band in frequency, so the band level
// is unchanged by the conversion: L_f(V / lambda) = L_lambda(lambda).
//
// Wheel and rail roughness are incoherent, so their mean squares add (energy sum):
//   L_total = 10 log10(10^{L_wheel/10} + 10^{L_rail/10}).
// The contact filter (roughness_filter.hpp) then gives the effective roughness
//   L_eff(f) = L_total(V/f) + 10 log10 <|H(k)|^2>_band,   k = 2 pi f / V.
//
// Spectra in CSV files are read by io/roughness_file.hpp.
#pragma once

#include <string>
#include <vector>

#include "noise/roughness_filter.hpp"

namespace rollnoise::noise {

/// A roughness spectrum in 1/3-octave wavelength bands.
struct RoughnessSpectrum {
  std::string name;
  std::vector<double> wavelength;  ///< band centre wavelengths (m), strictly decreasing
  std::vector<double> level;       ///< band levels (dB re 1 um)

  /// Level at any wavelength: linear in dB against log(wavelength) between band centres, the end
  /// values held beyond the tabulated range.
  double level_at(double wavelength) const;

  /// The contract of a usable table (>= 2 bands, wavelengths positive and strictly decreasing,
  /// levels finite): std::invalid_argument saying which fails. A reader of a spectrum maps it to
  /// its key or file (io/roughness_file.cpp).
  void validate() const;
};

/// The EN ISO 3095:2013 rail roughness limit, in the 35 bands from 2 m to 0.8 mm as tabulated by
/// CNOSSOS-EU (Appendix G, Table G-1, "EN ISO 3095:2013"); models/roughness/iso3095_2013_limit.csv.
RoughnessSpectrum iso3095_2013_rail_limit();

/// The rail roughness of an average network ("normally maintained smooth"; CNOSSOS-EU, Directive
/// (EU) 2015/996 Annex II, Appendix G, Table G-1);
/// models/roughness/rail_cnossos_average_network.csv. Against the EN ISO 3095 limit: 8-18 dB above
/// it at 1-2 m, up to 4.5 dB below at 0.1-0.4 m, up to 4.2 dB above at 2.5-4 cm (the bands 80 km/h
/// puts at 550-900 Hz).
RoughnessSpectrum rail_roughness_cnossos_average();

/// Typical tread roughness of cast-iron block-braked wheels (CNOSSOS-EU Table G-2, "cast iron
/// tread"); models/roughness/wheel_cast_iron_block.csv. Approximate, see docs/models.md.
RoughnessSpectrum wheel_roughness_cast_iron_block();

/// Typical tread roughness of disc-braked wheels without tread brakes (CNOSSOS-EU Table G-2,
/// "disc brake"); models/roughness/wheel_disc_braked.csv. Approximate, see docs/models.md.
RoughnessSpectrum wheel_roughness_disc_braked();

/// 10 log10(10^{a/10} + 10^{b/10}).
double energy_sum_db(double a, double b);

/// Index n of the base-10 1/3-octave band (exact centre 1000 * 10^{n/10} Hz) that contains f:
/// the band whose nominal centre (100, 125, ..., 4000, 5000 Hz) is nearest to f on a log scale.
int third_octave_index(double f);

/// The nominal centre (IEC 61260-1: ..., 100, 125, 160, ..., 4000, 5000, 6300, ... Hz) of the band
/// that contains f, e.g. 5000 for the exact centre 5011.9 Hz: the label of a band.
double nominal_centre(double f);

/// Exact 1/3-octave band centres 1000 * 10^{n/10} Hz (IEC 61260 base 10) from the band that
/// contains f_min to the band that contains f_max: the limits select bands by nominal centre, so
/// (100, 5000) gives the 18 bands 100 ... 5012 Hz (nominal 100 ... 5000 Hz) although the exact
/// centre 5011.9 Hz lies above 5000 Hz.
std::vector<double> third_octave_centres(double f_min, double f_max);

/// Width of the 1/3-octave band centred at f: f (10^{1/20} - 10^{-1/20}) ~= 0.2308 f.
double third_octave_bandwidth(double centre);

/// Combined wheel + rail roughness at a train speed, with the contact filter.
class ContactRoughness {
 public:
  ContactRoughness(RoughnessSpectrum wheel, RoughnessSpectrum rail, double speed,
                   ContactFilter filter);

  /// Combined roughness level without the filter in the 1/3-octave band centred at f (dB re 1 um).
  double combined_level(double frequency) const;

  /// Effective roughness level, after the contact filter, in the band centred at f (dB re 1 um).
  double level(double frequency) const;

  /// Effective levels at the given band centres (e.g. third_octave_centres()).
  std::vector<double> levels(const std::vector<double>& centres) const;

  /// One-sided power spectral density of the effective roughness at any frequency (m^2/Hz): the
  /// band mean square spread over the band, r_0^2 10^{L(f)/10} / third_octave_bandwidth(f), with
  /// L interpolated between band centres as in RoughnessSpectrum::level_at.
  double psd(double frequency) const;

  /// Amplitude of one harmonic line of a narrow-band spectrum with line spacing df:
  /// sqrt(2 psd(f) df) (m). Its mean square (amplitude^2 / 2) carries the PSD over the line.
  double line_amplitude(double frequency, double df) const;

  double speed() const { return speed_; }
  const ContactFilter& filter() const { return filter_; }

 private:
  RoughnessSpectrum wheel_, rail_;
  double speed_;
  ContactFilter filter_;
};

}  // namespace rollnoise::noise
