// A-frequency weighting of IEC 61672-1:2013 (Electroacoustics - Sound level meters - Part 1),
// Annex E, and the A-weighted total of band levels.
//
// The weighting is the analytic response of Eq. (E.6),
//   A(f) = 20 lg[ f_4^2 f^4 / ((f^2 + f_1^2) (f^2 + f_2^2)^{1/2} (f^2 + f_3^2)^{1/2} (f^2 + f_4^2))
//   ]
//          - A_1000,
// with the pole frequencies of Eqs. (E.1)-(E.5): f_r = 1000 Hz, f_L = 10^1.5 Hz, f_H = 10^3.9 Hz,
// D = sqrt(1/2), b = [f_r^2 + f_L^2 f_H^2 / f_r^2 - D (f_L^2 + f_H^2)] / (1 - D), c = f_L^2 f_H^2,
//   f_1 = ((-b - sqrt(b^2 - 4c)) / 2)^{1/2} = 20.60 Hz,  f_4 = ((-b + sqrt(b^2 - 4c)) / 2)^{1/2}
//   = 12194 Hz,  f_A = 10^2.45 Hz,  f_2 = (3 - sqrt 5)/2 f_A = 107.7 Hz,  f_3 = (3 + sqrt 5)/2 f_A
//   = 737.9 Hz,
// and the normalisation constant A_1000 = -2.000 dB (the gain that makes A(1 kHz) = 0 dB).
// The standard's Table 3 lists these values rounded to 0.1 dB at the nominal 1/3-octave
// frequencies (computed at the exact base-10 frequencies 1000 x 10^{n/10} Hz).
//
// A-weighted total of band levels (IEC 61672-1 weighting applied per band, energetic sum):
//   L_A = 10 lg sum_b 10^{(L_b + A(f_b)) / 10}.
#pragma once

#include <vector>

namespace rollnoise::acoustics {

/// A(f) in dB at frequency f > 0 (Hz), IEC 61672-1:2013 Eq. (E.6).
double a_weighting(double frequency);

/// L_A = 10 lg sum 10^{(L_b + A(f_b))/10} (dB) of band levels L_b (dB) at band centres f_b (Hz).
double a_weighted_total(const std::vector<double>& band_centres,
                        const std::vector<double>& band_levels);

}  // namespace rollnoise::acoustics
