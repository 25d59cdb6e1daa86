#include "acoustics/piston.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "linalg/gauss_legendre.hpp"

namespace rollnoise::acoustics {

namespace {

/// Gauss-Legendre nodes and weights on [a, b], split into `panels` equal panels of n points.
struct Nodes {
  std::vector<double> x, w;
};

Nodes gauss_nodes(double a, double b, int n, int panels) {
  const linalg::GaussRule rule = linalg::gauss_legendre_01(n);
  Nodes out;
  out.x.reserve(static_cast<size_t>(n) * panels);
  out.w.reserve(static_cast<size_t>(n) * panels);
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p)
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      out.x.push_back(a + (p + rule.nodes[i]) * h);
      out.w.push_back(rule.weights[i] * h);
    }
  return out;
}

/// A rule for an analytic integrand oscillating through the phase k L on an interval: about
/// k L / 2 + 16 points (Gauss-Legendre resolves ~pi points per wavelength plus a margin), rounded
/// up to GSL's precomputed tables; panels of k L <= 400 beyond 256 points.
Nodes oscillatory_rule(double a, double b, double phase) {
  static constexpr int kTables[] = {16, 20, 32, 64, 96, 128, 256};
  const int panels = std::max(1, static_cast<int>(std::ceil(phase / 400.0)));
  const double need = 0.5 * phase / panels + 16.0;
  int n = 256;
  for (int t : kTables)
    if (t >= need) {
      n = t;
      break;
    }
  return gauss_nodes(a, b, n, panels);
}

void check_piston_size(double k, double length, const char* what) {
  if (!(k > 0.0) || !std::isfinite(k))
    throw std::invalid_argument(
        "piston: the acoustic wavenumber k must be positive and finite, got " + std::to_string(k) +
        " 1/m");
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument(std::string("piston: the ") + what +
                                " must be positive and finite, got " + std::to_string(length) +
                                " m");
}

}  // namespace

double rectangular_piston_efficiency(double k, double Lx, double Ly) {
  check_piston_size(k, Lx, "piston length Lx");
  check_piston_size(k, Ly, "piston width Ly");
  // sigma = (2k / (pi A)) Int_0^Lx Int_0^Ly (Lx - u)(Ly - v) sin(kr)/r du dv (header, Eq. 1).
  const Nodes nu = oscillatory_rule(0.0, Lx, k * Lx);
  const Nodes nv = oscillatory_rule(0.0, Ly, k * Ly);
  std::vector<double> wv(nv.x.size()), v2(nv.x.size());
  for (size_t j = 0; j < nv.x.size(); ++j) {
    wv[j] = nv.w[j] * (Ly - nv.x[j]);
    v2[j] = nv.x[j] * nv.x[j];
  }
  double sum = 0.0;
  for (size_t i = 0; i < nu.x.size(); ++i) {
    const double u2 = nu.x[i] * nu.x[i];
    double inner = 0.0;
    for (size_t j = 0; j < nv.x.size(); ++j) {
      const double r = std::sqrt(u2 + v2[j]);
      inner += wv[j] * std::sin(k * r) / r;
    }
    sum += nu.w[i] * (Lx - nu.x[i]) * inner;
  }
  return 2.0 * k * sum / (kPi * Lx * Ly);
}

double circular_piston_efficiency(double k, double radius) {
  check_piston_size(k, radius, "piston radius");
  // sigma = (2ka/pi) Int_0^{pi/2} (2 phi - sin 2phi) sin(phi) sin(2ka cos phi) dphi (header).
  const double ka = k * radius;
  const Nodes n = oscillatory_rule(0.0, 0.5 * kPi, 2.0 * ka);
  double sum = 0.0;
  for (size_t i = 0; i < n.x.size(); ++i) {
    const double phi = n.x[i];
    sum += n.w[i] * (2.0 * phi - std::sin(2.0 * phi)) * std::sin(phi) *
           std::sin(2.0 * ka * std::cos(phi));
  }
  return 2.0 * ka * sum / kPi;
}

}  // namespace rollnoise::acoustics
