// 1/3-octave band levels of the loop's outputs (docs/noise_loop.md Sec. 5).
//
// The effective roughness in the band b has the mean square r_b^2 = r0^2 10^{L_r(b)/10}
// (r0 = 1 um, L_r from ContactRoughness::level), spread evenly over the band (the flat PSD of
// ContactRoughness::psd, Eq. R7 of docs/models.md). A transfer function H(f) = X/r of the loop
// (N/m, m/s per m, ...) then gives the band mean square of X
//
//   X_b^2 = Int_band |H|^2 S_r df = r_b^2 <|H|^2>_b,   <|H|^2>_b = (1/Delta f) Int_band |H(f)|^2
//   df,
//
//   L_X(b) = L_r(b) + 10 log10( <|H|^2>_b r0^2 / X_ref^2 )                                   (B1)
//
// with X_ref = 1 N (forces), 1 N m (Mz), 1e-9 m/s (translational velocities) and 1e-9 rad/s
// (rotational velocity about z). <|H|^2>_b, the *linear-frequency* mean over the band edges
// f_c 10^{-1/20} ... f_c 10^{1/20}, is evaluated from the narrow-band samples inside the band by
// the midpoint rule on cells: the samples split the band at the midpoints between neighbours and
// the outer cells reach the band edges (equal weights, an exact midpoint rule, for
// band_frequencies() grids). A band needs at least one sample; lightly damped resonances need many
// samples per band (band_frequencies), otherwise the mean is only as good as the sampling.
#pragma once

#include <array>
#include <vector>

#include "noise/loop.hpp"
#include "noise/roughness.hpp"

namespace rollnoise::noise {

constexpr double kRoughnessReference = 1e-6;  ///< m (dB re 1 um)
constexpr double kForceReference = 1.0;       ///< N, and N m for Mz
constexpr double kVelocityReference = 1e-9;   ///< m/s, and rad/s for the rotation

/// Lower and upper edge of the base-10 1/3-octave band centred at f_c: f_c 10^{-+1/20}.
std::array<double, 2> third_octave_edges(double centre);

/// Narrow-band frequencies: `points_per_band` equal sub-bands of each band, at their midpoints
/// (sorted, bands in the given order must not overlap).
std::vector<double> band_frequencies(const std::vector<double>& centres, int points_per_band);

/// Centres of the base-10 1/3-octave bands that contain at least `min_points` of the (increasing)
/// frequencies `f` and whose edges lie within the span of their cells.
std::vector<double> covered_centres(const std::vector<double>& f, int min_points = 1);

/// The cell-weighted linear-frequency mean of `values` (sampled at increasing `f`) over the band
/// centred at `centre`. std::invalid_argument when the band holds no sample (a contract:
/// the narrow-band axis is built from the bands, noise.points_per_band >= 4).
double band_mean(const std::vector<double>& f, const std::vector<double>& values, double centre);

/// Band levels (B1) of one transfer function H (per unit roughness): L_r + 10 log10(<|H|^2> r0^2
/// / ref^2) at each centre. `roughness_levels` are the effective roughness levels in the same bands
/// (dB re 1 um).
std::vector<double> transfer_band_levels(const std::vector<double>& f,
                                         const std::vector<cdouble>& H,
                                         const std::vector<double>& centres,
                                         const std::vector<double>& roughness_levels,
                                         double reference);

/// All band levels of a loop result.
struct BandLevels {
  std::vector<double> centre;                      ///< Hz
  std::vector<double> roughness_level;             ///< dB re 1 um (effective)
  std::vector<std::array<double, 4>> force_level;  ///< Fz, Fx, Fy (dB re 1 N), Mz (re 1 N m)
  std::vector<std::array<std::array<double, 4>, 2>> velocity_level;  ///< [wheel, rail][z, x, y, rot
                                                                     ///< z] dB re 1e-9 m/s, rad/s
  std::vector<int> samples;  ///< narrow-band samples in each band
};

/// Levels (B1) of forces and (if the result has them) velocities in the bands `centres`, with the
/// effective roughness levels in those bands (e.g. ContactRoughness::levels(centres)).
BandLevels band_levels(const LoopResult& result, const std::vector<double>& centres,
                       const std::vector<double>& roughness_levels);

/// The same with the effective roughness levels of `roughness` in those bands.
BandLevels band_levels(const LoopResult& result, const std::vector<double>& centres,
                       const ContactRoughness& roughness);

}  // namespace rollnoise::noise
