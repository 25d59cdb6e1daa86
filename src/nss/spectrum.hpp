// Amplitude spectra of sampled force histories (FFTW), for comparing the linear model with the
// unsteady solver in the frequency domain (paper Figs. 7, 9, 10, 15).
//
// Window: Hann, w_k = 0.5 (1 - cos(2 pi k / n)), over the analysed record. The one-sided amplitude
// is scaled by the window's coherent gain, |X_m| = 2 |sum_k w_k x_k e^{-2 pi i k m/n}| / sum_k w_k,
// so that a sinusoid of amplitude A on a bin reads A. The mean is removed first.
#pragma once

#include <complex>
#include <vector>

namespace rollnoise::nss {

struct Spectrum {
  std::vector<double> frequency;                 ///< Hz, bins 0 .. n/2
  std::vector<std::complex<double>> amplitude;   ///< complex amplitude per bin (see header)
};

Spectrum amplitude_spectrum(const std::vector<double>& signal, double dt);

}  // namespace rollnoise::nss
