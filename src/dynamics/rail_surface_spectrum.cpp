// The rail's surface in the wavenumber domain, Eqs. (W7) and (D4) of rail_surface_spectrum.hpp.
#include "dynamics/rail_surface_spectrum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "dynamics/rail_waveguide.hpp"
#include "linalg/gauss_legendre.hpp"

namespace rollnoise::dynamics {

namespace {

// The boundary edge of `mesh` nearest to p, and p's parameter t in [0, 1] along it (from its
// first end node to its last; the edges are straight, their mid node at t = 1/2).
std::pair<int, double> nearest_edge(const fem::QuadraticTriangleMesh& mesh,
                                    const Eigen::Vector2d& p, double& distance) {
  int best = -1;
  double best_t = 0.0;
  distance = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < mesh.boundary_edges.size(); ++e) {
    const Eigen::Vector2d a = mesh.nodes[mesh.boundary_edges[e][0]];
    const Eigen::Vector2d b = mesh.nodes[mesh.boundary_edges[e][2]];
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const double d = (a + t * ab - p).norm();
    if (d < distance) distance = d, best = static_cast<int>(e), best_t = t;
  }
  return {best, best_t};
}

}  // namespace

Eigen::MatrixXd outline_normal_distributions(const fem::QuadraticTriangleMesh& mesh,
                                             const std::vector<OutlinePiece>& pieces) {
  constexpr int kGauss = 6;  // exact for the quadratic u . n over a piece within one edge
  const linalg::GaussRule rule = linalg::gauss_legendre_01(kGauss);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(mesh.nodes.size()),
                                              static_cast<Eigen::Index>(pieces.size()));
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const OutlinePiece& piece = pieces[p];
    for (std::size_t g = 0; g < rule.nodes.size(); ++g) {
      const double s = rule.nodes[g], w = rule.weights[g];
      const Eigen::Vector2d at = piece.start + s * (piece.end - piece.start);
      double distance = 0.0;
      const auto [edge, t] = nearest_edge(mesh, at, distance);
      if (edge < 0 || distance > 1e-6)
        throw std::invalid_argument(
            "outline_normal_distributions: a piece is off the mesh's outline");
      // the quadratic line's shape functions at t: end, mid, end
      const std::array<double, 3> N{(1.0 - t) * (1.0 - 2.0 * t), 4.0 * t * (1.0 - t),
                                    t * (2.0 * t - 1.0)};
      for (int i = 0; i < 3; ++i) {
        const int node =
            mesh.boundary_edges[static_cast<std::size_t>(edge)][static_cast<std::size_t>(i)];
        out(3 * node + 1, static_cast<Eigen::Index>(p)) +=
            w * N[static_cast<std::size_t>(i)] * piece.normal.x();
        out(3 * node + 2, static_cast<Eigen::Index>(p)) +=
            w * N[static_cast<std::size_t>(i)] * piece.normal.y();
      }
    }
  }
  return out;
}

WaveAmplitudes wave_amplitudes(const RailWaveguide& rail, const RailWaves& w,
                               const Eigen::MatrixXd& d) {
  return {rail.wave_amplitudes(w, d, 1.0), rail.wave_amplitudes(w, d, -1.0)};
}

SurfaceSpectrum spectrum_of(SpectrumTerms terms) {
  SurfaceSpectrum out;
  out.columns = static_cast<int>(terms.load.plus.cols());
  out.wavenumbers = terms.wavenumbers;
  // the seats' forces as seats x (4 c): row n holds K v_n of every column (r + 4 b), so that
  // Eq. (D4)'s sums over the seats at all wavenumbers of a call are one matrix product
  const Eigen::Index c = terms.load.plus.cols();
  const Eigen::Index seats = terms.seat_forces.rows() / 4;
  auto by_seat = std::make_shared<Eigen::MatrixXcd>(seats, 4 * c);
  for (Eigen::Index n = 0; n < seats; ++n)
    for (Eigen::Index b = 0; b < c; ++b)
      by_seat->block(n, 4 * b, 1, 4) = terms.seat_forces.block(4 * n, b, 4, 1).transpose();
  auto t = std::make_shared<const SpectrumTerms>(std::move(terms));
  // the response side transposed once: pieces x waves
  auto rp = std::make_shared<const Eigen::MatrixXcd>(t->response.plus.transpose());
  auto rm = std::make_shared<const Eigen::MatrixXcd>(t->response.minus.transpose());
  out.at = [t, rp, rm, by_seat, c, seats](const std::vector<double>& kappas) {
    const cdouble I(0.0, 1.0);
    const Eigen::Index m = t->wavenumbers.size();
    const Eigen::Index nq = static_cast<Eigen::Index>(kappas.size());
    const bool discrete = seats > 0;
    // Eq. (D4): S(kappa) = Sum_n K v_n e^{i kappa x_n}, x_n = first + n L per column:
    // e^{i kappa first} (E W)(kappa), E_qn = e^{i kappa_q n L}
    Eigen::MatrixXcd sums;
    if (discrete) {
      Eigen::MatrixXcd E(nq, seats);
      for (Eigen::Index q = 0; q < nq; ++q) {
        const cdouble step = std::exp(I * kappas[static_cast<std::size_t>(q)] * t->spacing);
        cdouble z = 1.0;
        for (Eigen::Index n = 0; n < seats; ++n, z *= step) E(q, n) = z;
      }
      sums = E * (*by_seat);
    }
    Eigen::MatrixXcd xp(m, c * nq), xm(m, c * nq);
    for (Eigen::Index q = 0; q < nq; ++q) {
      const double kappa = kappas[static_cast<std::size_t>(q)];
      Eigen::VectorXcd phase(c);
      for (Eigen::Index b = 0; b < c; ++b)
        phase(b) = std::exp(I * kappa * t->load_x[static_cast<std::size_t>(b)]);
      Eigen::MatrixXcd lp = t->load.minus * phase.asDiagonal();
      Eigen::MatrixXcd lm = t->load.plus * phase.asDiagonal();
      if (discrete) {
        Eigen::MatrixXcd S(4, c);
        for (Eigen::Index b = 0; b < c; ++b)
          S.col(b) = std::exp(I * kappa * t->first_seat_x[static_cast<std::size_t>(b)]) *
                     sums.block(q, 4 * b, 1, 4).transpose();
        if (t->seat_length > 0.0 && kappa != 0.0)  // spread over l: times sin(kl/2) / (kl/2)
          S *= std::sin(0.5 * kappa * t->seat_length) / (0.5 * kappa * t->seat_length);
        lp -= t->foot.minus * S;
        lm -= t->foot.plus * S;
      }
      const Eigen::ArrayXcd dm = (t->norms.array() * (kappa - t->wavenumbers.array())).inverse();
      const Eigen::ArrayXcd dp = (t->norms.array() * (kappa + t->wavenumbers.array())).inverse();
      xp.middleCols(c * q, c) = dm.matrix().asDiagonal() * lp;
      xm.middleCols(c * q, c) = dp.matrix().asDiagonal() * lm;
    }
    Eigen::MatrixXcd U = (*rp) * xp;  // Eq. (W7)
    U.noalias() -= (*rm) * xm;
    return U;
  };
  return out;
}

SurfaceSpectrum combined(SurfaceSpectrum basis, Eigen::MatrixXd combination) {
  if (combination.rows() != basis.columns)
    throw std::invalid_argument("combined: one row of the combination per column of the basis");
  SurfaceSpectrum out;
  out.columns = static_cast<int>(combination.cols());
  out.wavenumbers = basis.wavenumbers;
  out.at = [at = std::move(basis.at), C = combination.cast<cdouble>().eval(),
            b = basis.columns](const std::vector<double>& kappas) {
    const Eigen::MatrixXcd U = at(kappas);
    Eigen::MatrixXcd out(U.rows(), C.cols() * static_cast<Eigen::Index>(kappas.size()));
    for (Eigen::Index q = 0; q < static_cast<Eigen::Index>(kappas.size()); ++q)
      out.middleCols(q * C.cols(), C.cols()).noalias() = U.middleCols(q * b, b) * C;
    return out;
  };
  return out;
}

SurfaceSpectra combined(SurfaceSpectra basis, Eigen::MatrixXd combination) {
  return [basis = std::move(basis), C = std::move(combination)](double frequency) {
    return combined(basis(frequency), C);
  };
}

PlacedLoads placed_at(const Eigen::MatrixXd& distributions, const std::vector<double>& x) {
  const Eigen::Index c = distributions.cols();
  PlacedLoads out{Eigen::MatrixXd(distributions.rows(), c * Eigen::Index(x.size())), {}};
  for (std::size_t i = 0; i < x.size(); ++i) {
    out.load.middleCols(c * Eigen::Index(i), c) = distributions;
    out.x.insert(out.x.end(), static_cast<std::size_t>(c), x[i]);
  }
  return out;
}

SurfaceSpectrum surface_spectrum(const RailWaveguide& rail, double omega,
                                 const Eigen::MatrixXd& response, const Eigen::MatrixXd& load,
                                 const std::vector<double>& load_x) {
  if (static_cast<Eigen::Index>(load_x.size()) != load.cols())
    throw std::invalid_argument("surface_spectrum: one position per load column");
  const RailWaves w = rail.waves(omega);
  SpectrumTerms t;
  t.wavenumbers = w.wavenumbers;
  t.norms = w.norms;
  t.response = wave_amplitudes(rail, w, response);
  t.load = wave_amplitudes(rail, w, load);
  t.load_x = load_x;
  return spectrum_of(std::move(t));
}

}  // namespace rollnoise::dynamics
