// Track decay rate by EN 15461:2008+A1:2010 (Railway applications - Noise emission -
// Characterisation of the dynamic properties of track sections for pass by noise measurements),
// and the lower limits of ISO 3095:2013 for the reference track of vehicle type tests.
//
// A hammer excites the rail at positions x_n along it (in sleeper spacings from the
// accelerometer at x_0 = 0, mid-span); the transfer mobility or accelerance A(x_n) is reduced to
// band-mean squared magnitudes |A(x_n)|^2 per 1/3-octave band. If the vibration decayed as
// |A(x)| = |A(0)| e^{-beta x} (beta in Np/m), the decay rate in dB/m would be
//   DR = 20 log10(e^beta) = 8.686 beta,
// and Int_0^inf |A(x)|^2 / |A(0)|^2 dx = 1 / (2 beta) = 4.343 / DR (EN 15461 Annex A.1). The
// standard estimates that integral by a sum over the positions (Formula 1, A.3):
//   DR = 4.343 / Sum_{n=0}^{N} ( |A(x_n)|^2 / |A(x_0)|^2 ) Delta x_n   dB/m,             (1)
// 4.343 = 10 log10(e), with Delta x_n the length of rail each position stands for (A.2): from
// halfway to the previous position to halfway to the next; the first (x_0 = 0) from 0 to halfway
// to x_1; the last symmetric about itself, i.e. Delta x_N = x_N - x_{N-1}.
// (The last interval as read by the third-party transcription named below; a variant that gives
// the last position only half its distance to the previous one differs by (x_N - x_{N-1})/2 *
// |A(x_N)/A(x_0)|^2, below 0.5 % for decays >= 0.5 dB/m on the standard grid.)
// The sum is a trapezoid-like rule and is dominated by the first 10 dB of decay. A grid ending at
// x_N cannot measure rates below DR_min = 4.343 / x_N (Formula 2); a band whose rate is less than
// 2 DR_min is an upper bound only (clause 7), and the response at x_N should be 10 dB below the
// direct one (6.7).
//
// Positions (EN 15461 6.7, Figure 2), in sleeper spacings (0.6 m if the rail has no discrete
// supports): every quarter spacing to 2.5, every half spacing to 4, every spacing to 8, then
// 10, 12, 16, 20, 24, 30, 36, 42, 48, 54, 66 (29 positions). Source: the standard is not openly
// available; the list is the transcription of Figure 2 of BS EN 15461:2008+A1:2010 in the open
// acoustics library "phonometry" (J. M. Requena Plens, github.com/jmrplens/phonometry,
// src/phonometry/environment/sources/track_decay.py, TRACK_DECAY_EXCITATION_INDICES, and its test
// "the grid is the 29 points of Figure 2"), consistent with the 66 spacings the standard is known
// to reach. Not checked against the standard itself.
//
// Bias of the standard's grid for an ideal exponential decay (tests/acoustics/
// decay_rate_test.cpp, 0.6 m spacing, x_N = 39.6 m, DR_min = 0.11 dB/m): Formula 1 on the 29
// positions gives +0.1 % at 0.5 dB/m (the truncation at 39.6 m and the long last interval nearly
// cancel), -0.7 % at 1 to 5 dB/m, -1.1 % at 10 dB/m, -3.8 % at 20 dB/m and -13 % at 40 dB/m
// (the trapezoid error of gaps widening from 0.15 m to 7.2 m: relative error ~ (2 beta h)^2 / 12
// where the decay spends its first 10 dB); at 0.2 dB/m (< 2 DR_min, unsuitable by clause 7) +15 %.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace rollnoise::acoustics {

/// The EN 15461 (6.7, Figure 2) excitation positions (m) for a sleeper spacing (m): the 29
/// multiples 0, 0.25, ..., 2.5, 3, 3.5, 4, 5, 6, 7, 8, 10, 12, 16, 20, 24, 30, 36, 42, 48, 54, 66.
std::vector<double> en15461_positions(double sleeper_spacing = 0.6);

/// The lengths of rail Delta x_n (m) the positions stand for (EN 15461 A.2, header).
/// Positions: x_0 = 0, strictly increasing, at least two.
std::vector<double> decay_rate_intervals(const std::vector<double>& positions);

/// Track decay rate (dB/m) of one band by Formula (1) from the band-mean squared transfer
/// magnitudes |A(x_n)|^2 at the positions (any unit: only ratios to |A(x_0)|^2 enter).
double track_decay_rate(const std::vector<double>& positions,
                        const std::vector<double>& squared_magnitudes);

/// The same for several bands: squared_magnitudes is positions x bands; returns one rate per band.
Eigen::VectorXd track_decay_rate(const std::vector<double>& positions,
                                 const Eigen::MatrixXd& squared_magnitudes);

/// The smallest rate a grid can measure, DR_min = 4.343 / x_N (dB/m, EN 15461 Formula 2); a
/// measured rate below 2 DR_min is only an upper bound (clause 7).
double minimum_measurable_decay_rate(const std::vector<double>& positions);

/// A lower limit of the track decay rate at a 1/3-octave band (nominal centre, Hz), dB/m.
struct DecayRateLimit {
  double frequency;  ///< nominal band centre (Hz)
  double vertical;   ///< dB/m
  double lateral;    ///< dB/m
};

/// The lower limits of the track decay rates of the reference track for vehicle pass-by tests,
/// ISO 3095:2013 (EN ISO 3095:2013) Figure 3, the table printed beside the curves (also the
/// reference-track condition of the TSI Noise, Commission Regulation (EU) No 1304/2014, which
/// refers to EN ISO 3095:2013), 1/3-octave bands 250 Hz - 5 kHz. Values from the transcription of
/// that table in the open library "phonometry" (github.com/jmrplens/phonometry,
/// tests/reference_data/rolling_stock_noise.py, FIGURE_3_VERTICAL_DB_PER_M /
/// FIGURE_3_LATERAL_DB_PER_M, read from the ISO copy, folio 13); not checked against the
/// standard itself. Both curves are piecewise straight on log-log axes (e.g. 800 Hz vertical 2.19
/// = sqrt(6 x 0.8), lateral 0.94 ... 0.20 a constant ratio per band).
std::vector<DecayRateLimit> iso3095_decay_rate_limits();

}  // namespace rollnoise::acoustics
