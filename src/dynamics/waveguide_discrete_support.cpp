#include "dynamics/waveguide_discrete_support.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "dynamics/frequency_argument.hpp"
#include "dynamics/rail_model.hpp"
#include "dynamics/rail_section.hpp"
#include "fem/mesh.hpp"
#include "linalg/block_toeplitz_solve.hpp"

namespace rollnoise::dynamics {

FootAttachment foot_attachment(const RailWaveguide& rail) {
  // The foot: the boundary edges along the lowest z (as RailWaveguide's continuous support).
  const fem::QuadraticTriangleMesh& mesh = rail.mesh();
  double zmin = mesh.nodes.at(0).y(), zmax = zmin;
  for (const auto& p : mesh.nodes) zmin = std::min(zmin, p.y()), zmax = std::max(zmax, p.y());
  const double tol = 1e-6 * (zmax - zmin);
  std::vector<int> edges;
  double width = 0.0, first = 0.0;
  for (int i = 0; i < static_cast<int>(mesh.boundary_edges.size()); ++i) {
    const auto& e = mesh.boundary_edges[i];
    bool on_foot = true;
    for (int v : e) on_foot = on_foot && std::abs(mesh.nodes[v].y() - zmin) < tol;
    if (!on_foot) continue;
    edges.push_back(i);
    const double len = (mesh.nodes[e[2]] - mesh.nodes[e[0]]).norm();
    width += len;
    first += len * mesh.nodes[e[1]].x();  // the mid node is the edge's centre
  }
  if (edges.empty()) throw InputError("rail_section", "the rail section has no flat foot");
  const double yf = first / width;
  FootAttachment a;
  a.loads = Eigen::MatrixXd::Zero(rail.dofs(), 4);
  for (int d = 0; d < 3; ++d) a.loads.col(d) = rail.edge_traction(edges, d);
  // Int N (y - y_f) ds on each straight quadratic edge by 3-point Gauss (exact, degree 3), and
  // I_f = Int (y - y_f)^2 ds (exact for the linear y).
  const double g = std::sqrt(0.6), gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}, gx[3] = {-g, 0.0, g};
  double inertia = 0.0;
  for (int i : edges) {
    const auto& e = mesh.boundary_edges[i];
    const double y0 = mesh.nodes[e[0]].x(), y2 = mesh.nodes[e[2]].x(),
                 half = 0.5 * std::abs(y2 - y0);
    for (int q = 0; q < 3; ++q) {
      const double xi = gx[q], y = 0.5 * (y0 + y2) + 0.5 * (y2 - y0) * xi - yf;
      const double N[3] = {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
      for (int k = 0; k < 3; ++k)
        a.loads(RailWaveguide::dof(e[k], 2), 3) += gw[q] * half * N[k] * y;
      inertia += gw[q] * half * y * y;
    }
  }
  a.loads.col(3) /= inertia;
  a.roll_arm_squared = inertia / width;
  return a;
}

DiscretelySupportedWaveguide::DiscretelySupportedWaveguide(RailWaveguide free_rail,
                                                           FootAttachment foot,
                                                           const FootSupport& support,
                                                           int supports_each_side)
    : rail_(std::move(free_rail)),
      foot_(std::move(foot)),
      support_(support),
      n_(supports_each_side) {
  support_.vertical.validate("track.support.vertical");
  support_.lateral.validate("track.support.lateral");
  support_.longitudinal.validate("track.support.longitudinal");
  if (!(support_.sleeper_spacing > 0.0))
    throw InputError("rail_support", "sleeper spacing must be > 0");
  if (!(support_.seat_length >= 0.0) || !(support_.seat_length < support_.sleeper_spacing))
    throw InputError("rail_support", "the seat length must lie in [0, L)");
  if (n_ < 1) throw InputError("rail_support", "at least one support each side");
  if (foot_.loads.rows() != rail_.dofs() || foot_.loads.cols() != 4)
    throw InputError("rail_section", "foot attachment does not match the rail's mesh");
}

namespace {

// A distribution's wave amplitudes for both signs of x (RailWaveguide::wave_amplitudes).
using Amplitudes = WaveAmplitudes;

// Eq. (W4)'s weights -i e^{-i k_j |x|} / d_j.
Eigen::VectorXcd green_weights(const RailWaves& w, double x) {
  const cdouble I(0.0, 1.0);
  return (-I * (-I * w.wavenumbers * std::abs(x)).array().exp() / w.norms.array()).matrix();
}

// Eq. (W4) between the response amplitudes r and the load amplitudes f at x = x_r - x_l.
Eigen::MatrixXcd green(const RailWaves& w, const Amplitudes& r, const Amplitudes& f, double x) {
  const bool ahead = x >= 0.0;
  return (ahead ? r.plus : r.minus).transpose() * green_weights(w, x).asDiagonal() *
         (ahead ? f.minus : f.plus);
}

// Eq. (W4)'s weights at the points x_i = x0 + i h, i = 0 .. count - 1 (column i; h != 0, the
// sleepers' spacing): e^{-i k_j |x_i|} as powers of z_j = e^{-i k_j |h|}. The points on either side
// of x = 0 are each an arithmetic run in |x|, walked from its point nearest 0 outward
// (green_weights there, then one complex product per step instead of an exponential and a division
// per point; the rounding error grows by about an ulp per span).
Eigen::MatrixXcd green_weights_along(const RailWaves& w, double x0, double h, int count) {
  const cdouble I(0.0, 1.0);
  const Eigen::ArrayXcd z = (-I * w.wavenumbers.array() * std::abs(h)).exp();
  Eigen::MatrixXcd out(w.wavenumbers.size(), count);
  const auto x = [&](int i) { return x0 + i * h; };
  // the indices [a, b) of one side of x = 0, from the end nearest 0
  const auto walk_run = [&](int a, int b) {
    if (a >= b) return;
    const bool up = std::abs(x(a)) <= std::abs(x(b - 1));
    int i = up ? a : b - 1;
    Eigen::ArrayXcd weight = green_weights(w, x(i)).array();
    for (int k = a; k < b; ++k, i += up ? 1 : -1) {
      out.col(i) = weight.matrix();
      weight *= z;
    }
  };
  int split = 1;  // the first index on the other side of 0 from x_0 (count: none)
  while (split < count && (x(split) >= 0.0) == (x(0) >= 0.0)) ++split;
  walk_run(0, split);
  walk_run(split, count);
  return out;
}

// A seat's force spread evenly over [x_n - l/2, x_n + l/2] (l = FootSupport::seat_length): Eq.
// (W4)'s weights averaged over it. With E(k, a) = Int_0^a e^{-iku} du = (1 - e^{-ika}) / (ik):
//  - between a seat and a point, x = x_response - x_load between the point and the seat's centre:
//    the part of the seat where x_response - x_load >= 0 (Eq. W4 ahead) weighs E(k, x + l/2) / l
//    for |x| < l/2, e^{-ik(x - l/2)} E(k, l) / l for x >= l/2 (none for x <= -l/2), the other
//    part the same mirrored;
//  - two seats d L apart (d != 0, l < L): e^{-ik(|d| L - l)} E(k, l)^2 / l^2;
//  - a seat on itself: 2 (l - E(k, l)) / (ik l^2), half of it each way.
// Each times -i / d_j; as l -> 0 they tend to Eq. (W4)'s point weights, which l = 0 takes (the
// former model, its code unchanged).
cdouble integral_of_wave(cdouble k, double a) {  // E(k, a), by its series where ka is small
  const cdouble z = cdouble(0.0, -1.0) * k * a;  // -ika
  if (std::abs(z) < 1e-3) return a * (1.0 + z / 2.0 + z * z / 6.0 + z * z * z / 24.0);
  return (1.0 - std::exp(z)) / (cdouble(0.0, 1.0) * k);
}

// A seat wholly on one side of the point at distance ax >= l/2 from its centre: e^{-ik(ax - l/2)}
// E(k, l) / l times -i / d_j per wave (l = 0: Eq. W4's point weights, green_weights).
Eigen::ArrayXcd whole_seat_weights(const RailWaves& w, double ax, double l) {
  if (l == 0.0) return green_weights(w, ax).array();
  const cdouble I(0.0, 1.0);
  Eigen::ArrayXcd v(w.wavenumbers.size());
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    const cdouble k = w.wavenumbers(j);
    v(j) = -I / (w.norms(j) * l) * std::exp(-I * k * (ax - 0.5 * l)) * integral_of_wave(k, l);
  }
  return v;
}

// A seat over the point (|x| < l/2, x = x_point - x_seat): its parts behind (E(k, x + l/2) / l) and
// ahead of the point (E(k, l/2 - x) / l), times -i / d_j per wave.
void overlapping_seat_weights(const RailWaves& w, double x, double l, Eigen::ArrayXcd& behind,
                              Eigen::ArrayXcd& ahead) {
  const cdouble I(0.0, 1.0);
  behind.resize(w.wavenumbers.size());
  ahead.resize(w.wavenumbers.size());
  for (Eigen::Index j = 0; j < behind.size(); ++j) {
    const cdouble k = w.wavenumbers(j), scale = -I / (w.norms(j) * l);
    behind(j) = scale * integral_of_wave(k, x + 0.5 * l);
    ahead(j) = scale * integral_of_wave(k, 0.5 * l - x);
  }
}

// Columns i of `behind` and `ahead`: the seat's parts where x_response - x_load >= 0 and < 0, for
// x_i = x0 + i h (|h| = L > l > 0), as above. The seats wholly on one side of the point are an
// arithmetic run in |x| each, walked from its seat nearest the point outward by z_j = e^{-ik_j|h|}
// (as green_weights_along); a seat that overlaps the point is computed directly.
struct SeatWeights {
  Eigen::MatrixXcd behind, ahead;
};

SeatWeights seat_weights_along(const RailWaves& w, double x0, double h, int count, double l) {
  const cdouble I(0.0, 1.0);
  const Eigen::Index m = w.wavenumbers.size();
  SeatWeights out{Eigen::MatrixXcd::Zero(m, count), Eigen::MatrixXcd::Zero(m, count)};
  const auto x = [&](int i) { return x0 + i * h; };
  const Eigen::ArrayXcd z = (-I * w.wavenumbers.array() * std::abs(h)).exp();
  // the indices [a, b) on one side (behind: x >= l/2, into `target`), walked from the one nearest 0
  const auto walk_run = [&](int a, int b, Eigen::MatrixXcd& target) {
    if (a >= b) return;
    const bool up = std::abs(x(a)) <= std::abs(x(b - 1));
    int i = up ? a : b - 1;
    Eigen::ArrayXcd weight = whole_seat_weights(w, std::abs(x(i)), l);
    for (int k = a; k < b; ++k, i += up ? 1 : -1) {
      target.col(i) = weight.matrix();
      weight *= z;
    }
  };
  std::vector<int> behind, ahead;
  for (int i = 0; i < count; ++i) {
    if (x(i) >= 0.5 * l) {
      behind.push_back(i);
    } else if (x(i) <= -0.5 * l) {
      ahead.push_back(i);
    } else {  // the seat overlaps the point
      Eigen::ArrayXcd b, a;
      overlapping_seat_weights(w, x(i), l, b, a);
      out.behind.col(i) = b.matrix();
      out.ahead.col(i) = a.matrix();
    }
  }
  // x is monotone in i, so each side's indices are consecutive
  if (!behind.empty()) walk_run(behind.front(), behind.back() + 1, out.behind);
  if (!ahead.empty()) walk_run(ahead.front(), ahead.back() + 1, out.ahead);
  return out;
}

// One frequency's waves, the foot's amplitudes, the seats' stiffness (Eq. D1) and I + A K of Eq.
// (D2), block Toeplitz (its block (i, j) is delta_ij I + a(i - j) K with a(d) = g(d L) and a(-d) =
// g(d L)^T, d = 0..2N: the seats' spacing alone sets it), solved by the block Levinson recursion
// (linalg/block_toeplitz_solve.hpp: O(N^2) blocks instead of the dense LU's O(N^3), checked by its
// residual) and by a dense LU where that check fails.
struct Seats {
  RailWaves waves;
  Amplitudes foot;
  Eigen::Vector4cd stiffness;
  int n;
  double spacing;
  double seat_length = 0.0;                                         // FootSupport::seat_length
  std::optional<linalg::BlockToeplitzSolver> levinson;              // I + A K
  mutable std::optional<Eigen::PartialPivLU<Eigen::MatrixXcd>> lu;  // only where Levinson fails

  /// v = (I + A K)^{-1} B.
  Eigen::MatrixXcd solve(const Eigen::MatrixXcd& B) const {
    if (std::optional<Eigen::MatrixXcd> v = levinson->solve(B)) return std::move(*v);
    if (!lu) lu.emplace(levinson->dense());
    return lu->solve(B);
  }
};

Seats seats(const RailWaveguide& rail, const FootAttachment& attachment, const FootSupport& support,
            int n, cdouble omega) {
  Seats s;
  s.waves = rail.waves(omega);
  s.foot = wave_amplitudes(rail, s.waves, attachment.loads);
  s.n = n;
  s.spacing = support.sleeper_spacing;
  const int m = 2 * n + 1;
  const cdouble kz = support.vertical.dynamic_stiffness(omega);
  s.stiffness << support.longitudinal.dynamic_stiffness(omega),
      support.lateral.dynamic_stiffness(omega), kz, kz * attachment.roll_arm_squared;
  std::vector<Eigen::Matrix4cd> g(m);  // g(-x) = g(x)^T, reciprocity of Eq. W4
  const double l = support.seat_length;
  s.seat_length = l;
  if (l == 0.0) {
    const Eigen::MatrixXcd weights = green_weights_along(s.waves, 0.0, s.spacing, m);
    for (int d = 0; d < m; ++d)  // x = d L >= 0: Eq. (W4) ahead
      g[d] = s.foot.plus.transpose() * weights.col(d).asDiagonal() * s.foot.minus;
  } else {  // the seats spread over l (seat_weights_along's comment)
    const cdouble I(0.0, 1.0);
    const Eigen::Index nw = s.waves.wavenumbers.size();
    Eigen::VectorXcd self(nw), spread(nw);
    for (Eigen::Index j = 0; j < nw; ++j) {
      const cdouble k = s.waves.wavenumbers(j), e = integral_of_wave(k, l);
      const cdouble kl = k * l;
      // 2 (l - E) / (ik l^2), by its series 1 - ikl/3 + (ikl)^2/12 where kl is small
      self(j) = std::abs(kl) < 1e-3 ? 1.0 - I * kl / 3.0 + (I * kl) * (I * kl) / 12.0
                                    : 2.0 * (l - e) / (I * k * l * l);
      self(j) *= -I / s.waves.norms(j);
      spread(j) = -I / s.waves.norms(j) * e * e / (l * l);
    }
    const Eigen::Matrix4cd half = 0.5 * s.foot.plus.transpose() * self.asDiagonal() * s.foot.minus;
    g[0] = half + half.transpose();  // the two halves x > x', x < x' (g(-x) = g(x)^T)
    Eigen::ArrayXcd wd(nw), z(nw);   // e^{-ik(d L - l)} walked by z = e^{-ikL}
    for (Eigen::Index j = 0; j < nw; ++j) {
      const cdouble k = s.waves.wavenumbers(j);
      wd(j) = spread(j) * std::exp(-I * k * (s.spacing - l));
      z(j) = std::exp(-I * k * s.spacing);
    }
    for (int d = 1; d < m; ++d, wd *= z)
      g[d] = s.foot.plus.transpose() * wd.matrix().asDiagonal() * s.foot.minus;
  }
  std::vector<Eigen::Matrix4cd> lower(m), upper(m);  // the blocks t(d), t(-d) of I + A K
  for (int d = 0; d < m; ++d) {
    lower[d] = g[d] * s.stiffness.asDiagonal();
    upper[d] = g[d].transpose() * s.stiffness.asDiagonal();
  }
  lower[0] += Eigen::Matrix4cd::Identity();
  upper[0] = lower[0];
  s.levinson.emplace(std::move(lower), std::move(upper));
  return s;
}

// Eq. (D2) with the seats of one frequency: the seats' resultants v (4 (2N + 1) rows) under the
// load f at x_l, the seats first L, (first + 1) L, ... .
Eigen::MatrixXcd seat_resultants(const Seats& s, const Amplitudes& f, double x_l, long first) {
  const int m = 2 * s.n + 1;
  Eigen::MatrixXcd B(4 * m, f.plus.cols());
  const double from_load = first * s.spacing - x_l;  // x_i - x_l = x_first - x_l + i L
  if (s.seat_length == 0.0) {
    const Eigen::MatrixXcd to_seats = green_weights_along(s.waves, from_load, s.spacing, m);
    for (int i = 0; i < m; ++i) {
      const bool ahead = from_load + i * s.spacing >= 0.0;
      B.middleRows(4 * i, 4) = (ahead ? s.foot.plus : s.foot.minus).transpose() *
                               to_seats.col(i).asDiagonal() * (ahead ? f.minus : f.plus);
    }
  } else {
    // the seat (spread) as the response, the load at x_l
    const SeatWeights w = seat_weights_along(s.waves, from_load, s.spacing, m, s.seat_length);
    for (int i = 0; i < m; ++i)
      B.middleRows(4 * i, 4) = s.foot.plus.transpose() * w.behind.col(i).asDiagonal() * f.minus +
                               s.foot.minus.transpose() * w.ahead.col(i).asDiagonal() * f.plus;
  }
  return s.solve(B);
}

// Eqs. (D2)-(D3) with the seats of one frequency: the response r at x_r per load f at x_l for
// every (x_r, x_l) of `positions`, with one window of 2N + 1 seats for all of them (centred on the
// midpoint of the positions' extent: for one pair its midpoint, so H(x_l, x_r) = H(x_r, x_l)^T)
// and one solve of Eq. (D2) per distinct load position.
//
// The seats' part of Eq. (D3) at x_r, Sum_n G_rf(x_r - x_n) K v_n, is A_+(r)^T b(x_r) + A_-(r)^T
// a(x_r) with the wave sums over the seats behind (x_n <= x_r) and ahead of x_r,
//
//   b(x_r) = Sum_{n behind} w(x_r - x_n) P-_n,   a(x_r) = Sum_{n ahead} w(x_n - x_r) P+_n,
//
// P-+_n = A_-+(foot) K v_n, w(x) = -i e^{-i k_j x} / d_j (a point seat; a spread seat wholly on one
// side: seat_weights_along's). As w(x + L) = z w(x), z_j = e^{-i k_j L}, the sums are running ones,
// C_n = z C_{n-1} + P-_n from the first seat and D_n = z D_{n+1} + P+_n from the last, and
// b(x_r) = w(x_r - x_n*) C_n* with n* the last seat behind x_r (a(x_r) likewise): O(waves) per
// response point instead of O(waves x seats). A spread seat that overlaps x_r adds its two parts.
std::vector<Eigen::MatrixXcd> supported_transfers(
    const Seats& s, const Amplitudes& r, const Amplitudes& f,
    const std::vector<std::pair<double, double>>& positions, std::optional<double> centre = {}) {
  if (positions.empty()) return {};
  const int m = 2 * s.n + 1;
  const double L = s.spacing, l = s.seat_length;
  const cdouble I(0.0, 1.0);
  double lo = positions.front().first, hi = lo;
  for (const auto& [x_r, x_l] : positions)
    lo = std::min({lo, x_r, x_l}), hi = std::max({hi, x_r, x_l});
  const long first = std::lround(centre.value_or(0.5 * (lo + hi)) / L) - s.n;
  const auto seat_x = [&](int i) { return (first + i) * L; };
  const Eigen::Index nw = s.waves.wavenumbers.size();
  const Eigen::ArrayXcd z = (-I * s.waves.wavenumbers.array() * L).exp();
  // the pairs by load position, in order of first appearance
  std::vector<double> loads;
  std::vector<std::vector<std::size_t>> by_load;
  for (std::size_t p = 0; p < positions.size(); ++p) {
    const auto it = std::find(loads.begin(), loads.end(), positions[p].second);
    if (it == loads.end()) {
      loads.push_back(positions[p].second);
      by_load.push_back({p});
    } else {
      by_load[static_cast<std::size_t>(it - loads.begin())].push_back(p);
    }
  }
  std::vector<Eigen::MatrixXcd> out(positions.size());
  for (std::size_t g = 0; g < loads.size(); ++g) {
    const double x_l = loads[g];
    const Eigen::MatrixXcd v = seat_resultants(s, f, x_l, first);
    const Eigen::Index nc = v.cols();
    std::vector<Eigen::ArrayXXcd> Pm(m), Pp(m), C(m), D(m);
    for (int i = 0; i < m; ++i) {
      const Eigen::MatrixXcd Kv = s.stiffness.asDiagonal() * v.middleRows(4 * i, 4);
      Pm[i] = (s.foot.minus * Kv).array();
      Pp[i] = (s.foot.plus * Kv).array();
    }
    C[0] = Pm[0];
    for (int i = 1; i < m; ++i) C[i] = C[i - 1].colwise() * z + Pm[i];
    D[m - 1] = Pp[m - 1];
    for (int i = m - 2; i >= 0; --i) D[i] = D[i + 1].colwise() * z + Pp[i];
    for (std::size_t p : by_load[g]) {
      const double x_r = positions[p].first;
      // behind: x_r - x_n >= l/2; ahead: x_r - x_n <= -l/2; between them (l > 0) one overlapping
      int last_behind = static_cast<int>(std::floor((x_r - 0.5 * l) / L)) - static_cast<int>(first);
      last_behind = std::clamp(last_behind, -1, m - 1);
      while (last_behind + 1 < m && x_r - seat_x(last_behind + 1) >= 0.5 * l) ++last_behind;
      while (last_behind >= 0 && !(x_r - seat_x(last_behind) >= 0.5 * l)) --last_behind;
      int first_ahead = last_behind + 1;
      while (first_ahead < m && !(x_r - seat_x(first_ahead) <= -0.5 * l)) ++first_ahead;
      Eigen::ArrayXXcd behind = Eigen::ArrayXXcd::Zero(nw, nc), ahead = behind;
      if (last_behind >= 0)
        behind =
            C[last_behind].colwise() * whole_seat_weights(s.waves, x_r - seat_x(last_behind), l);
      if (first_ahead < m)
        ahead = D[first_ahead].colwise() * whole_seat_weights(s.waves, seat_x(first_ahead) - x_r, l);
      for (int i = last_behind + 1; i < first_ahead; ++i) {  // a spread seat over x_r
        Eigen::ArrayXcd wb, wa;
        overlapping_seat_weights(s.waves, x_r - seat_x(i), l, wb, wa);
        behind += Pm[i].colwise() * wb;
        ahead += Pp[i].colwise() * wa;
      }
      out[p] = green(s.waves, r, f, x_r - x_l) - r.plus.transpose() * behind.matrix() -
               r.minus.transpose() * ahead.matrix();
    }
  }
  return out;
}

// supported_transfers between one set of distributions (responses and loads alike), each pair
// from the side with fewer distinct positions: Eq. (D2) is solved once per distinct load position,
// and H(x_r, x_l) = H(x_l, x_r)^T for one window of seats (the response along the rail under a few
// loads: the rail's sound asks for many x_r per load).
std::vector<Eigen::MatrixXcd> reciprocal_transfers(
    const Seats& s, const Amplitudes& p, const std::vector<std::pair<double, double>>& positions) {
  std::vector<double> responses, loads;
  for (const auto& [x_r, x_l] : positions) {
    if (std::find(responses.begin(), responses.end(), x_r) == responses.end())
      responses.push_back(x_r);
    if (std::find(loads.begin(), loads.end(), x_l) == loads.end()) loads.push_back(x_l);
  }
  if (responses.size() >= loads.size()) return supported_transfers(s, p, p, positions);
  std::vector<std::pair<double, double>> swapped;  // the same extent: the same window
  for (const auto& [x_r, x_l] : positions) swapped.emplace_back(x_l, x_r);
  std::vector<Eigen::MatrixXcd> out = supported_transfers(s, p, p, swapped);
  for (Eigen::MatrixXcd& h : out) h.transposeInPlace();
  return out;
}

}  // namespace

Eigen::MatrixXcd DiscretelySupportedWaveguide::transfer(cdouble omega,
                                                        const Eigen::MatrixXd& response,
                                                        double x_response,
                                                        const Eigen::MatrixXd& load,
                                                        double x_load) const {
  const Seats s = seats(rail_, foot_, support_, n_, omega);
  return supported_transfers(s, wave_amplitudes(rail_, s.waves, response),
                             wave_amplitudes(rail_, s.waves, load), {{x_response, x_load}})
      .front();
}

std::vector<Eigen::MatrixXcd> DiscretelySupportedWaveguide::transfers(
    cdouble omega, const Eigen::MatrixXd& points,
    const std::vector<std::pair<double, double>>& positions) const {
  const Seats s = seats(rail_, foot_, support_, n_, omega);
  const Amplitudes p = wave_amplitudes(rail_, s.waves, points);
  return reciprocal_transfers(s, p, positions);
}

std::vector<Eigen::MatrixXcd> DiscretelySupportedWaveguide::transfers(
    cdouble omega, const Eigen::MatrixXd& points,
    const std::vector<std::pair<double, double>>& positions, double centre) const {
  const Seats s = seats(rail_, foot_, support_, n_, omega);
  const Amplitudes p = wave_amplitudes(rail_, s.waves, points);
  return supported_transfers(s, p, p, positions, centre);
}

std::vector<Eigen::MatrixXcd> DiscreteWaveguideRailModel::HeadStation::transfers(
    cdouble omega, const std::vector<std::pair<double, double>>& positions,
    std::size_t keep_up_to) const {
  if (positions.size() > keep_up_to) return rail.transfers(omega, loads, positions);
  using Key = std::tuple<double, double, double, double>;
  const auto key = [&](const std::pair<double, double>& x) {
    return Key(omega.real(), omega.imag(), x.first, x.second);
  };
  std::vector<Eigen::MatrixXcd> out(positions.size());
  std::vector<std::pair<double, double>> missing;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (std::size_t p = 0; p < positions.size(); ++p) {
      const auto it = kept.find(key(positions[p]));
      if (it != kept.end())
        out[p] = it->second;
      else
        missing.push_back(positions[p]);
    }
  }
  if (missing.empty()) return out;
  const std::vector<Eigen::MatrixXcd> computed = rail.transfers(omega, loads, missing, centre);
  const std::lock_guard<std::mutex> lock(mutex);
  for (std::size_t q = 0; q < missing.size(); ++q) kept.emplace(key(missing[q]), computed[q]);
  for (std::size_t p = 0; p < positions.size(); ++p)
    if (out[p].size() == 0) out[p] = kept.at(key(positions[p]));
  return out;
}

SurfaceSpectrum DiscretelySupportedWaveguide::surface_spectrum(
    double omega, const Eigen::MatrixXd& response, const Eigen::MatrixXd& load,
    const std::vector<double>& load_x) const {
  if (static_cast<Eigen::Index>(load_x.size()) != load.cols())
    throw std::invalid_argument("surface_spectrum: one position per load column");
  Seats s = seats(rail_, foot_, support_, n_, omega);
  SpectrumTerms t;
  t.load = wave_amplitudes(rail_, s.waves, load);
  t.response = wave_amplitudes(rail_, s.waves, response);
  t.load_x = load_x;
  t.spacing = s.spacing;
  t.seat_length = s.seat_length;
  t.seat_forces.resize(4 * (2 * n_ + 1), load.cols());
  // Eq. (D2) per load column, the 2N + 1 seats nearest the load (the columns at one x together)
  for (Eigen::Index b = 0; b < load.cols(); ++b) {
    const double x = load_x[static_cast<std::size_t>(b)];
    const long first = std::lround(x / s.spacing) - n_;
    t.first_seat_x.push_back(first * s.spacing);
    if (b > 0 && load_x[static_cast<std::size_t>(b - 1)] == x) continue;
    Eigen::Index e = b;
    while (e < load.cols() && load_x[static_cast<std::size_t>(e)] == x) ++e;
    const Amplitudes f{t.load.plus.middleCols(b, e - b), t.load.minus.middleCols(b, e - b)};
    const Eigen::MatrixXcd v = seat_resultants(s, f, x, first);
    for (int i = 0; i < 2 * n_ + 1; ++i)
      t.seat_forces.block(4 * i, b, 4, e - b) = s.stiffness.asDiagonal() * v.middleRows(4 * i, 4);
  }
  t.foot = std::move(s.foot);
  t.wavenumbers = s.waves.wavenumbers;
  t.norms = s.waves.norms;
  return spectrum_of(std::move(t));
}

DiscreteWaveguideRailModel::Parts DiscreteWaveguideRailModel::build(const TrackParameters& track,
                                                                    const WaveguideRailOptions& o,
                                                                    double contact_position) {
  std::vector<Eigen::Vector2d> outline = o.outline.empty() ? uic60_outline() : o.outline;
  RailWaveguide full(fem::mesh_polygon(outline, o.mesh_size), rail_material(track, o.poisson_ratio),
                     std::nullopt);
  RailReductionModes modes = full.reduction_modes(o.contact_reduction);
  double top = full.mesh().nodes.at(0).y();
  for (const auto& p : full.mesh().nodes) top = std::max(top, p.y());
  Eigen::MatrixXd crown =
      contact_loads_at(full, o, Eigen::Vector2d(0.0, top), Eigen::Vector2d(0.0, 1.0));
  FootAttachment foot = foot_attachment(full);
  const FootSupport support{track.vertical_support, track.lateral_support,
                            track.longitudinal_support, track.sleeper_spacing, o.seat_length};
  // the crown's basis: the head's six distributions (head loads), else the crown's patch
  const Eigen::MatrixXd ends = o.head_load ? full.head_body(o.head_bottom).loads : crown;
  Eigen::MatrixXd loads(full.dofs(), ends.cols() + 4);
  loads << ends, foot.loads;
  auto rail = std::make_shared<const DiscretelySupportedWaveguide>(
      full.reduced(o.contact_reduction, loads, modes), std::move(foot), support,
      track.supports_each_side);
  std::shared_ptr<const HeadStation> head;
  if (o.head_load) head = std::make_shared<const HeadStation>(*rail, ends, contact_position);
  return Parts{o,
               std::move(outline),
               std::move(full),
               std::move(modes),
               std::move(crown),
               std::move(head),
               std::move(rail)};
}

DiscreteWaveguideRailModel::DiscreteWaveguideRailModel(const TrackParameters& track,
                                                       const WaveguideRailOptions& options,
                                                       double contact_position)
    : GridSamplingRail(track, contact_position, options.archive,
                       "waveguide, discrete support\n" + options.archive_identity),
      options_(options),
      parts_(
          [track, options, contact_position] { return build(track, options, contact_position); }),
      head_([options] { return section_head_body(options); }),
      x_(contact_position) {
  if (!std::isfinite(x_) || x_ < 0.0)
    throw InputError("track.position", "contact position along the rail must be >= 0");
  check_waveguide_inputs(track, options);  // the seats' values as the continuous support's
  if (track.supports_each_side < 1)
    throw InputError("rail_support", "at least one support each side");
}

std::shared_ptr<const DiscreteWaveguideRailModel::Station> DiscreteWaveguideRailModel::station(
    const std::vector<std::pair<double, double>>& points) const {
  const Parts& parts = parts_.get();
  const Eigen::MatrixXd contacts =
      contact_point_loads(parts.section, parts.outline, parts.options, points);
  if (parts.head) {  // the points' loads on the head's distributions (exactly in their span)
    Eigen::MatrixXd coefficients = parts.head->loads.colPivHouseholderQr().solve(contacts);
    return std::make_shared<const Station>(
        Station{parts.rail, contacts, parts.head, std::move(coefficients)});
  }
  // the points' loads and the foot's in one Ritz basis of the free rail (as build()'s crown)
  const DiscretelySupportedWaveguide& crown = *parts.rail;
  Eigen::MatrixXd loads(parts.section.dofs(), contacts.cols() + 4);
  loads << contacts, crown.foot().loads;
  return std::make_shared<const Station>(
      Station{std::make_shared<const DiscretelySupportedWaveguide>(
                  parts.section.reduced(parts.options.contact_reduction, loads, parts.modes),
                  crown.foot(), crown.support(), crown.supports_each_side()),
              contacts,
              nullptr,
              {}});
}

std::vector<Receptance4> DiscreteWaveguideRailModel::between(
    const Station& s, cdouble omega,
    const std::vector<std::tuple<int, int, double, double>>& pairs) {
  std::vector<std::pair<double, double>> positions;  // distinct (x_a, x_b)
  std::vector<std::size_t> which;
  for (const auto& [a, b, xa, xb] : pairs) {
    const std::pair<double, double> x(xa, xb);
    const auto it = std::find(positions.begin(), positions.end(), x);
    which.push_back(static_cast<std::size_t>(it - positions.begin()));
    if (it == positions.end()) positions.push_back(x);
  }
  std::vector<Receptance4> out;
  if (s.head) {  // the head's 6 x 6 (kept for the few positions of the loop's queries), projected
    constexpr std::size_t kKeepUpTo = 8;
    const std::vector<Eigen::MatrixXcd> H = s.head->transfers(omega, positions, kKeepUpTo);
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const auto Ca = s.coefficients.middleCols(4 * std::get<0>(pairs[p]), 4).cast<cdouble>();
      const auto Cb = s.coefficients.middleCols(4 * std::get<1>(pairs[p]), 4).cast<cdouble>();
      out.push_back(Ca.transpose() * H[which[p]] * Cb);
    }
    return out;
  }
  const std::vector<Eigen::MatrixXcd> H = s.rail->transfers(omega, s.loads, positions);
  for (std::size_t p = 0; p < pairs.size(); ++p)
    out.push_back(H[which[p]].block<4, 4>(4 * std::get<0>(pairs[p]), 4 * std::get<1>(pairs[p])));
  return out;
}

namespace {

// The pairs of set k of `sets` as (point a, point b, x_a, x_b), and their indices in `pairs`.
std::vector<std::tuple<int, int, double, double>> pairs_of_set(
    const RailPointSets& sets, const std::vector<RailContactPair>& pairs, int k,
    std::vector<std::size_t>& which) {
  std::vector<std::tuple<int, int, double, double>> out;
  which.clear();
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (sets.set[p] != k) continue;
    out.emplace_back(std::get<0>(sets.within[p]), std::get<1>(sets.within[p]), pairs[p].first.x,
                     pairs[p].second.x);
    which.push_back(p);
  }
  return out;
}

}  // namespace

GridSamplingRail::Evaluator DiscreteWaveguideRailModel::evaluator(const Points& points,
                                                                  const SetPairs& pairs) const {
  // The points' basis on the first direct evaluation (none where a kept sampling serves all; the
  // sampling may evaluate on several threads).
  const Lazy<std::shared_ptr<const Station>> st([this, points] { return station(points); });
  return [pairs, st](double f) { return between(*st.get(), checked_complex_omega(f), pairs); };
}

RailModel::LaplaceTransfers DiscreteWaveguideRailModel::direct_laplace_transfers(
    const std::vector<RailContactPair>& pairs) const {
  const RailPointSets sets = rail_point_sets(pairs);
  std::vector<std::shared_ptr<const Station>> stations;
  std::vector<std::vector<std::tuple<int, int, double, double>>> within;
  std::vector<std::vector<std::size_t>> which(sets.points.size());
  for (std::size_t k = 0; k < sets.points.size(); ++k) {
    stations.push_back(station(sets.points[k]));
    within.push_back(pairs_of_set(sets, pairs, static_cast<int>(k), which[k]));
  }
  return [pairs, stations, within, which](cdouble s) {
    const cdouble omega = checked_laplace(s);
    std::vector<Receptance6> out(pairs.size());
    for (std::size_t k = 0; k < stations.size(); ++k) {
      const std::vector<Receptance4> r = between(*stations[k], omega, within[k]);
      for (std::size_t j = 0; j < which[k].size(); ++j) {
        const RailContactPair& pair = pairs[which[k][j]];
        out[which[k][j]] =
            from_contact_frames(r[j], pair.first.contact_angle, pair.second.contact_angle);
      }
    }
    return out;
  };
}

Receptance4 DiscreteWaveguideRailModel::contact_transfer(double frequency, double offset_a,
                                                         double angle_a, double x_a,
                                                         double offset_b, double angle_b,
                                                         double x_b) const {
  const std::pair<double, double> a(offset_a, angle_a), b(offset_b, angle_b);
  if (a == b)
    return between(*station({a}), checked_complex_omega(frequency), {{0, 0, x_a, x_b}}).front();
  const bool ordered = a < b;  // the points sorted, as rail_point_sets gives them
  const std::shared_ptr<const Station> st =
      station(ordered ? std::vector{a, b} : std::vector{b, a});
  return between(*st, checked_complex_omega(frequency),
                 {{ordered ? 0 : 1, ordered ? 1 : 0, x_a, x_b}})
      .front();
}

std::optional<SpanningPoints> DiscreteWaveguideRailModel::spanning_points(
    const Points& points) const {
  return head_spanning_points(
      head_.get(), options_.outline.empty() ? uic60_outline() : options_.outline, options_, points);
}

std::optional<RailLoadBasis> DiscreteWaveguideRailModel::load_basis(
    const std::vector<RailLoadPoint>& points) const {
  const std::vector<Eigen::Vector2d> outline =
      options_.outline.empty() ? uic60_outline() : options_.outline;
  return head_load_basis(head_.get(), outline, options_, points);
}

SurfaceSpectra DiscreteWaveguideRailModel::basis_surface_spectra(
    const std::vector<double>& x, const std::vector<OutlinePiece>& pieces,
    const Eigen::MatrixXd& patterns) const {
  if (!options_.head_load) return nullptr;
  const Parts& parts = parts_.get();
  const std::shared_ptr<const HeadStation> head = parts.head;
  auto response = std::make_shared<const Eigen::MatrixXd>(
      outline_normal_distributions(parts.section.mesh(), pieces) * patterns);
  auto placed = std::make_shared<const PlacedLoads>(placed_at(head->loads, x));
  return [head, response, placed](double frequency) {
    return head->rail.surface_spectrum(angular(frequency), *response, placed->load, placed->x);
  };
}

SurfaceSpectra DiscreteWaveguideRailModel::surface_spectra(const std::vector<RailLoadPoint>& points,
                                                           const std::vector<OutlinePiece>& pieces,
                                                           const Eigen::MatrixXd& patterns) const {
  if (std::optional<RailLoadBasis> basis = load_basis(points))
    return combined(basis_surface_spectra(basis->x, pieces, patterns),
                    std::move(basis->combination));
  const LoadPointColumns at = load_point_columns(points);
  const std::shared_ptr<const Station> st = station(at.distinct);
  auto response = std::make_shared<const Eigen::MatrixXd>(
      outline_normal_distributions(st->rail->free_rail().mesh(), pieces) * patterns);
  auto load = std::make_shared<const Eigen::MatrixXd>(at.columns(st->loads));
  return [st, response, load, x = at.x](double frequency) {
    return st->rail->surface_spectrum(angular(frequency), *response, *load, x);
  };
}

Receptance4 DiscreteWaveguideRailModel::at(cdouble omega) const {
  const Parts& parts = parts_.get();
  return parts.rail->transfer(omega, parts.crown, x_, parts.crown, x_);
}

Receptance4 DiscreteWaveguideRailModel::receptance(double frequency) const {
  return at(checked_complex_omega(frequency));
}

Receptance4 DiscreteWaveguideRailModel::receptance_laplace(cdouble s) const {
  return at(checked_laplace(s));
}

Receptance4 DiscreteWaveguideRailModel::transfer(double frequency, double x_response,
                                                 double x_load) const {
  return line_transfer(frequency, x_response, x_load);
}

std::vector<Receptance4> DiscreteWaveguideRailModel::line_transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  std::vector<Receptance4> out;
  for (const Eigen::MatrixXcd& h :
       rail().transfers(checked_complex_omega(frequency), crown_loads(), pairs))
    out.push_back(h);
  return out;
}

Receptance4 DiscreteWaveguideRailModel::line_transfer_laplace(cdouble s, double x_response,
                                                              double x_load) const {
  return rail().transfer(checked_laplace(s), crown_loads(), x_response, crown_loads(), x_load);
}

}  // namespace rollnoise::dynamics
