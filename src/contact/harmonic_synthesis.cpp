#include "contact/harmonic_synthesis.hpp"

#include <cmath>
#include <complex>

#include <stdexcept>

namespace rollnoise::contact {

std::vector<Eigen::Vector3d> harmonic_synthesis(const CreepageHistory& h,
                                                const std::vector<Eigen::Matrix3cd>& f,
                                                const std::vector<Eigen::Vector3cd>& g,
                                                const Eigen::Vector3d& mean_force, double dt,
                                                long steps) {
  const std::vector<double>& freq = h.frequencies();
  const bool load = h.has_normal_variation();
  if (f.size() != freq.size() || (load && g.size() != freq.size()))
    throw std::invalid_argument("harmonic_synthesis: one coefficient per frequency is needed");
  // fx_n = f(w_n) xi^_n - g(w_n) N^_n
  std::vector<Eigen::Vector3cd> fx(f.size());
  for (size_t n = 0; n < f.size(); ++n) {
    Eigen::Vector3cd x;
    for (int j = 0; j < 3; ++j) x(j) = h.amplitude()[j] * std::polar(1.0, h.phases()[j][n]);
    fx[n] = f[n] * x;
    if (load) fx[n] -= g[n] * h.normal_amplitude() * std::polar(1.0, h.normal_phases()[n]);
  }
  std::vector<Eigen::Vector3d> out;
  out.reserve(steps + 1);
  for (long k = 0; k <= steps; ++k) {
    Eigen::Vector3d F = mean_force;
    for (size_t n = 0; n < f.size(); ++n)
      F -= (fx[n] * std::polar(1.0, 2 * M_PI * freq[n] * k * dt)).real();
    out.push_back(F);
  }
  return out;
}

}  // namespace rollnoise::contact
