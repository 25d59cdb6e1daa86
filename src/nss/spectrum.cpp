#include "nss/spectrum.hpp"

#include <cmath>
#include <numeric>

#include "linalg/fft.hpp"

namespace rollnoise::nss {

Spectrum amplitude_spectrum(const std::vector<double>& x, double dt) {
  const int n = static_cast<int>(x.size());
  Spectrum s;
  if (n < 2) return s;
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const linalg::RealFft fft(n);
  double* in = fft.real();
  double wsum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double w = 0.5 * (1.0 - std::cos(2.0 * M_PI * k / n));
    in[k] = w * (x[k] - mean);
    wsum += w;
  }
  const int nc = n / 2 + 1;
  fft.forward();
  const std::complex<double>* out = fft.spectrum();
  s.frequency.resize(nc);
  s.amplitude.resize(nc);
  for (int m = 0; m < nc; ++m) {
    s.frequency[m] = m / (n * dt);
    s.amplitude[m] = (m == 0 ? 1.0 : 2.0) * out[m] / wsum;
  }
  return s;
}

}  // namespace rollnoise::nss
