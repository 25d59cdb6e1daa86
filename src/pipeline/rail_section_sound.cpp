// The sound of a rail whose section deforms, Eqs. (R1), (R2) of rail_section_sound.hpp.
#include "pipeline/rail_section_sound.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "acoustics/bem2d.hpp"
#include "core/constants.hpp"
#include "core/task_pool.hpp"
#include "dynamics/rail_model.hpp"
#include "linalg/gauss_kronrod.hpp"
#include "pipeline/sound_radiation.hpp"

namespace rollnoise::pipeline {

namespace {

using cdouble = std::complex<double>;
constexpr int kMaxDepth = 24;  // halvings of a starting panel

// (R2)'s integrand k U^H P_2D(k cos theta) U over a panel [a, b] by the 21-point Kronrod rule, and
// the same by its 10 Gauss nodes alone (the error estimate of the Gauss value, which the Kronrod
// value far undercuts).
struct PanelValue {
  Eigen::MatrixXcd kronrod, gauss;
};

// PanelValues of the panels [a_i, b_i], one spectrum call for all of them.
std::vector<PanelValue> panel_values(const dynamics::SurfaceSpectrum& spectrum,
                                     const SectionRadiationTable& table, double k,
                                     const std::vector<std::pair<double, double>>& panels) {
  static const linalg::GaussKronrod21 rule = linalg::gauss_kronrod_21_01();
  std::vector<double> kappas;
  for (const auto& [a, b] : panels)
    for (double t : rule.nodes) kappas.push_back(k * std::sin(a + t * (b - a)));
  const Eigen::MatrixXcd U = spectrum.at(kappas);
  const Eigen::Index c = spectrum.columns;
  std::vector<PanelValue> out;
  Eigen::Index q = 0;
  for (const auto& [a, b] : panels) {
    PanelValue v{Eigen::MatrixXcd::Zero(c, c), Eigen::MatrixXcd::Zero(c, c)};
    for (std::size_t i = 0; i < rule.nodes.size(); ++i, ++q) {
      const double theta = a + rule.nodes[i] * (b - a);
      const auto Uq = U.middleCols(c * q, c);
      const Eigen::MatrixXcd f =
          ((b - a) * k) * (Uq.adjoint() * (table.at(k * std::cos(theta)) * Uq));
      v.kronrod += rule.kronrod[i] * f;
      if (rule.gauss[i] != 0.0) v.gauss += rule.gauss[i] * f;
    }
    out.push_back(std::move(v));
  }
  return out;
}

// The starting panels: [-pi/2, pi/2] cut at the poles +-Re k_j inside (-k, k) of the waves that
// decay slowly (|Im k_j| < k / 2), each piece into panels no wider than `widest`.
std::vector<std::pair<double, double>> starting_panels(const Eigen::VectorXcd& poles, double k,
                                                       double widest) {
  std::vector<double> cuts{-0.5 * kPi, 0.5 * kPi};
  for (const cdouble& p : poles)
    if (std::abs(p.real()) < k && std::abs(p.imag()) < 0.5 * k)
      for (double s : {1.0, -1.0}) cuts.push_back(std::asin(s * p.real() / k));
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    if (!(b - a > 1e-12)) continue;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / widest)));
    for (int j = 0; j < n; ++j) out.emplace_back(a + j * (b - a) / n, a + (j + 1) * (b - a) / n);
  }
  return out;
}

}  // namespace

Eigen::MatrixXcd SectionRadiationTable::at(double k_r) const {
  const int n = static_cast<int>(power.size());
  if (n < 2 || !(k_r >= 0.0) || k_r > max_wavenumber() * (1.0 + 1e-12))
    throw std::invalid_argument("SectionRadiationTable: k_r outside the table");
  const int i = std::min(static_cast<int>(k_r / step), n - 2);
  const double t = k_r / step - i;
  // Catmull-Rom on the uniform grid, the weights of p_{i-1} .. p_{i+2}; a neighbour beyond an end
  // is extrapolated linearly (p_{-1} = 2 p_0 - p_1, p_n = 2 p_{n-1} - p_{n-2}), its weight folded
  // onto the two it is made of
  std::array<double, 4> w{0.5 * t * (-1.0 + t * (2.0 - t)), 1.0 + 0.5 * t * t * (-5.0 + 3.0 * t),
                          0.5 * t * (1.0 + t * (4.0 - 3.0 * t)), 0.5 * t * t * (t - 1.0)};
  if (i == 0) w[1] += 2.0 * w[0], w[2] -= w[0], w[0] = 0.0;
  if (i + 2 == n) w[2] += 2.0 * w[3], w[1] -= w[3], w[3] = 0.0;
  Eigen::MatrixXcd out = Eigen::MatrixXcd::Zero(power[0].rows(), power[0].cols());
  for (int j = 0; j < 4; ++j)
    if (w[static_cast<std::size_t>(j)] != 0.0)
      out += w[static_cast<std::size_t>(j)] * power[static_cast<std::size_t>(i - 1 + j)];
  return out;
}

SectionRadiationTable section_radiation_table(const std::vector<Eigen::Vector2d>& outline,
                                              bool ground, double max_k,
                                              const acoustics::Fluid& fluid, int threads) {
  if (!(max_k > 0.0) || !std::isfinite(max_k))
    throw std::invalid_argument("section_radiation_table: max_k must be > 0");
  acoustics::Section2d section;
  section.outline = outline;
  // the elements of the grid's top (as rail_radiation's there)
  const acoustics::Bem2dOptions options = rail_bem_options(outline, ground, max_k);
  SectionRadiationTable out;
  out.ground = ground;
  for (const acoustics::BoundaryElement2d& e : acoustics::boundary_elements_2d(section, options))
    out.pieces.push_back({e.start, e.end, e.normal});
  const int n = static_cast<int>(std::ceil(max_k / out.step)) + 1;
  out.power.resize(static_cast<std::size_t>(n));
  const Eigen::Index m = static_cast<Eigen::Index>(out.pieces.size());
  out.power[0] = Eigen::MatrixXcd::Zero(m, m);  // no radiation at k_r = 0
  const Eigen::MatrixXd unit = Eigen::MatrixXd::Identity(m, m);
  parallel_for(static_cast<std::size_t>(n - 1), threads, [&](std::size_t i, int) {
    out.power[i + 1] = acoustics::radiated_power_matrix_2d(section, out.step * double(i + 1), unit,
                                                           fluid, options);
  });
  // The patterns that radiate: the eigenvectors of S = sum_i (Re P_i Re P_i^T + Im P_i Im P_i^T) /
  // |P_i|^2 (each k_r weighted alike) above 1e-14 of its largest eigenvalue, so that
  // P_i = W (W^T P_i W) W^T up to ~1e-7 |P_i| for every i.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, m);
  for (std::size_t i = 1; i < out.power.size(); ++i) {
    const Eigen::MatrixXcd& P = out.power[i];
    S += (P.real() * P.real().transpose() + P.imag() * P.imag().transpose()) / P.squaredNorm();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(S);
  const Eigen::VectorXd& lambda = eigen.eigenvalues();  // ascending
  Eigen::Index r = 0;
  while (r < m && lambda(m - 1 - r) > 1e-8 * lambda(m - 1)) ++r;
  out.patterns = eigen.eigenvectors().rightCols(r);
  for (Eigen::MatrixXcd& P : out.power) P = out.patterns.transpose() * P * out.patterns;
  return out;
}

Eigen::MatrixXcd section_gram(const dynamics::SurfaceSpectrum& spectrum,
                              const SectionRadiationTable& table, double frequency, double spread,
                              const acoustics::Fluid& fluid, double tolerance) {
  const double k = 2 * kPi * frequency / fluid.sound_speed;
  if (k > table.max_wavenumber() * (1.0 + 1e-12))
    throw std::invalid_argument("section_gram: frequency above the radiation table");
  // a period of e^{i kappa dx} in theta near theta = 0, 2 pi / (k dx): 10 Gauss points integrate
  // it to ~1e-9
  const double widest = std::min(kPi / 8.0, 2 * kPi / std::max(k * spread, 1.0));
  // each panel by Gauss-Kronrod: accepted where its Gauss and Kronrod values agree within
  // `tolerance` times the integral's norm times its share of the interval, else halved
  std::vector<std::pair<double, double>> todo = starting_panels(spectrum.wavenumbers, k, widest);
  std::vector<PanelValue> values = panel_values(spectrum, table, k, todo);
  Eigen::MatrixXcd coarse_total = Eigen::MatrixXcd::Zero(spectrum.columns, spectrum.columns);
  for (const PanelValue& v : values) coarse_total += v.kronrod;
  const double scale = std::max(coarse_total.norm(), 1e-300);
  Eigen::MatrixXcd total = Eigen::MatrixXcd::Zero(spectrum.columns, spectrum.columns);
  for (int depth = 0; !todo.empty(); ++depth) {
    std::vector<std::pair<double, double>> halves;
    for (std::size_t i = 0; i < todo.size(); ++i) {
      const auto [a, b] = todo[i];
      if ((values[i].kronrod - values[i].gauss).norm() <= tolerance * scale * (b - a) / kPi ||
          depth >= kMaxDepth) {
        total += values[i].kronrod;
        continue;
      }
      const double mid = 0.5 * (a + b);
      halves.emplace_back(a, mid);
      halves.emplace_back(mid, b);
    }
    todo = std::move(halves);
    values = todo.empty() ? std::vector<PanelValue>{} : panel_values(spectrum, table, k, todo);
  }
  return total / (2 * kPi);
}

namespace {

// (R2) of `spectra` on the grid; `spread`: the largest distance between the loads (m).
std::vector<Eigen::MatrixXcd> grams_on_grid(const dynamics::SurfaceSpectra& spectra,
                                            const SectionRadiationTable& table,
                                            const std::vector<double>& grid, double spread,
                                            const acoustics::Fluid& fluid, int threads) {
  std::vector<Eigen::MatrixXcd> out(grid.size());
  parallel_for(grid.size(), threads, [&](std::size_t i, int) {
    out[i] = section_gram(spectra(grid[i]), table, grid[i], spread, fluid);
  });
  return out;
}

// The largest distance between the loads' positions (m).
double spread(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return x.empty() ? 0.0 : *hi - *lo;
}

}  // namespace

std::vector<Eigen::MatrixXcd> basis_section_grams(const dynamics::RailModel& rail,
                                                  const std::vector<double>& x,
                                                  const SectionRadiationTable& table,
                                                  const std::vector<double>& grid,
                                                  const acoustics::Fluid& fluid, int threads) {
  const dynamics::SurfaceSpectra spectra =
      rail.basis_surface_spectra(x, table.pieces, table.patterns);
  if (!spectra || x.empty()) return {};
  return grams_on_grid(spectra, table, grid, spread(x), fluid, threads);
}

std::vector<Eigen::MatrixXcd> combined_grams(const std::vector<Eigen::MatrixXcd>& basis_grams,
                                             const Eigen::MatrixXd& combination) {
  const Eigen::MatrixXcd C = combination.cast<cdouble>();
  std::vector<Eigen::MatrixXcd> out;
  out.reserve(basis_grams.size());
  for (const Eigen::MatrixXcd& G : basis_grams) out.push_back(C.adjoint() * G * C);
  return out;
}

std::vector<Eigen::MatrixXcd> section_grams(const dynamics::RailModel& rail,
                                            const std::vector<dynamics::RailLoadPoint>& points,
                                            const SectionRadiationTable& table,
                                            const std::vector<double>& grid,
                                            const acoustics::Fluid& fluid, int threads,
                                            const BasisGrams& basis_grams) {
  if (points.empty()) return {};
  if (const std::optional<dynamics::RailLoadBasis> basis = rail.load_basis(points))
    return combined_grams(basis_grams
                              ? basis_grams(basis->x)
                              : basis_section_grams(rail, basis->x, table, grid, fluid, threads),
                          basis->combination);
  const dynamics::SurfaceSpectra spectra =
      rail.surface_spectra(points, table.pieces, table.patterns);
  if (!spectra) return {};
  std::vector<double> x;
  for (const dynamics::RailLoadPoint& p : points) x.push_back(p.x);
  return grams_on_grid(spectra, table, grid, spread(x), fluid, threads);
}

}  // namespace rollnoise::pipeline
