#include "pipeline/sound_power.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "acoustics/a_weighting.hpp"
#include "acoustics/decay_rate.hpp"
#include "acoustics/piston.hpp"
#include "core/constants.hpp"
#include "core/stopwatch.hpp"
#include "core/task_pool.hpp"
#include "dynamics/rail_model.hpp"
#include "dynamics/rail_section.hpp"
#include "linalg/gauss_legendre.hpp"
#include "noise/bands.hpp"

namespace rollnoise::pipeline {
namespace {

using cdouble = std::complex<double>;
constexpr double kPowerReference = 1e-12;  // W (dB re 1 pW)
// Sleeper spans on each side of the contacts over which (S2) and (S3) are integrated point by
// point; beyond them the tails are closed as geometric series (docs/sound.md Sec. 3.2).
constexpr int kWindowSpans = 20;

// The points along the rail: Gauss points of each span (weight > 0) and the sleepers (weight 0,
// flagged), spans numbered outward on each side for the tail closure.
struct RailPoints {
  std::vector<double> x, weight;
  std::vector<int> span;         // the span [j L, (j + 1) L] of a Gauss point; j of a sleeper
  std::vector<bool> is_sleeper;  // a sleeper at x = j L (weight 0)
  int first_span = 0, last_span = 0;
};

RailPoints rail_points(double x_min, double x_max, double spacing, int gauss) {
  RailPoints p;
  p.first_span = static_cast<int>(std::floor(x_min / spacing)) - kWindowSpans;
  p.last_span = static_cast<int>(std::floor(x_max / spacing)) + kWindowSpans;
  const linalg::GaussRule rule = gauss > 0 ? linalg::gauss_legendre_01(gauss) : linalg::GaussRule{};
  for (int j = p.first_span; j <= p.last_span; ++j) {
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      p.x.push_back((j + rule.nodes[i]) * spacing);
      p.weight.push_back(rule.weights[i] * spacing);
      p.span.push_back(j);
      p.is_sleeper.push_back(false);
    }
    p.x.push_back(j * spacing);
    p.weight.push_back(0.0);
    p.span.push_back(j);
    p.is_sleeper.push_back(true);
  }
  return p;
}

// A geometric tail beyond the window: the last block times rho/(1 - rho), rho the ratio of the
// last two blocks' traces (0 when the response does not decay there: no closure).
void close_tail(Eigen::MatrixXcd& total, const Eigen::MatrixXcd& last,
                const Eigen::MatrixXcd& before) {
  const double a = last.trace().real(), b = before.trace().real();
  if (!(a > 0.0) || !(b > 0.0)) return;
  const double rho = a / b;
  if (rho < 1.0) total += last * (rho / (1.0 - rho));
}

Eigen::MatrixXcd interpolated(const std::vector<Eigen::MatrixXcd>& m, const GridPlace& p) {
  return (1.0 - p.w) * m[p.i] + p.w * m[p.i + 1];
}
// A power matrix P_n between grid points: its diagonal in log-log (a multipole's power law
// P ~ f^(2n+2) below coincidence is then exact) and its correlation coefficients
// P_ij / sqrt(P_ii P_jj) linearly, so that the interpolated matrix stays positive semi-definite.
Eigen::MatrixXcd interpolated_power(const std::vector<Eigen::MatrixXcd>& m, const GridPlace& p) {
  const Eigen::MatrixXcd& a = m[p.i];
  const Eigen::MatrixXcd& b = m[p.i + 1];
  const Eigen::Index n = a.rows();
  // a mode that does not radiate (round-off, possibly negative): the smallest normal double
  const auto floor = [](double v) {
    return std::isfinite(v) ? std::max(v, std::numeric_limits<double>::min())
                            : std::numeric_limits<double>::min();
  };
  Eigen::VectorXd ra(n), rb(n), rd(n);  // square roots of the diagonals (no underflow in products)
  for (Eigen::Index i = 0; i < n; ++i) {
    const double da = floor(a(i, i).real()), db = floor(b(i, i).real());
    ra(i) = std::sqrt(da), rb(i) = std::sqrt(db);
    rd(i) = std::exp(0.5 * ((1.0 - p.w) * std::log(da) + p.w * std::log(db)));
  }
  const auto correlation = [](cdouble x, double ri, double rj) {
    const cdouble c = x / ri / rj;
    return std::isfinite(std::abs(c)) ? c / std::max(1.0, std::abs(c)) : cdouble(0.0);
  };
  Eigen::MatrixXcd out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      // correlations: |c| <= 1 for a positive semi-definite matrix, which round-off may break
      // where a mode does not radiate
      const cdouble c = (1.0 - p.w) * correlation(a(i, j), ra(i), ra(j)) +
                        p.w * correlation(b(i, j), rb(i), rb(j));
      out(i, j) = c * rd(i) * rd(j);
    }
  return out;
}

double interpolated(const std::vector<double>& v, const GridPlace& p) {
  return (1.0 - p.w) * v[p.i] + p.w * v[p.i + 1];
}

// The forces of `which` contacts under source e at line k, stacked (4 per contact).
Eigen::VectorXcd stacked_forces(const noise::ContactSetLoopResult& loop,
                                const std::vector<int>& which, std::size_t k, int e) {
  Eigen::VectorXcd F(static_cast<Eigen::Index>(4 * which.size()));
  for (std::size_t j = 0; j < which.size(); ++j)
    F.segment<4>(static_cast<Eigen::Index>(4 * j)) = loop.force[k].block<4, 1>(4 * which[j], e);
  return F;
}

// Per source, per line: the powers (W per unit roughness amplitude) the bands are made of.
struct LinePowers {
  // [source][line]
  std::vector<std::vector<double>> wheel_total, rail_total, sleeper_total;
  // [wheel][source][line]
  std::vector<std::vector<std::vector<double>>> wheel, rail, sleepers;
  // [source][line]: the mechanical power the contact forces put into the wheels and the rails
  std::vector<std::vector<double>> input;
  // [wheel][family][source][line]: the wheel's power with the modes of one family alone
  std::vector<std::vector<std::vector<std::vector<double>>>> family;
};

// (S5): the power the contact forces put into the structures, (1/2) Re(F^H v_wheel - F^H v_rail)
// summed over the contacts, with the velocities of the loop (z, x, y, rot z of each contact's local
// frame) taken into its contact frame (T^T v; the rotations about x and y, which the loop does not
// keep, taken as zero: they carry only the spin moment's share).
double input_power(const noise::ContactSetLoopResult& loop,
                   const std::vector<noise::ContactPoint>& contacts, std::size_t k, int e) {
  if (loop.wheel_velocity.empty()) return kNaN;
  double p = 0.0;
  for (std::size_t a = 0; a < contacts.size(); ++a) {
    const Eigen::Matrix<double, 6, 4> T =
        dynamics::contact_frame(contacts[a].position.contact_angle);
    Eigen::Matrix<cdouble, 6, 1> vw = Eigen::Matrix<cdouble, 6, 1>::Zero(), vr = vw;
    for (int i = 0; i < 4; ++i) {
      vw(dynamics::kSixOfFour[i]) = loop.wheel_velocity[k](static_cast<Eigen::Index>(4 * a) + i, e);
      vr(dynamics::kSixOfFour[i]) = loop.rail_velocity[k](static_cast<Eigen::Index>(4 * a) + i, e);
    }
    const Eigen::Matrix<cdouble, 4, 1> F =
        loop.force[k].block<4, 1>(static_cast<Eigen::Index>(4 * a), e);
    const Eigen::Matrix<cdouble, 4, 1> dv = T.transpose().cast<cdouble>() * (vw - vr);
    p += 0.5 * F.dot(dv).real();
  }
  return p;
}

double band_level(const std::vector<double>& f, const std::vector<std::vector<double>>& by_source,
                  const std::vector<std::vector<double>>& source_levels, std::size_t band,
                  double centre) {
  double sum = 0.0;  // the band mean is linear: <2 W> = 2 <W>
  for (std::size_t e = 0; e < by_source.size(); ++e) {
    const double r2 = noise::kRoughnessReference * noise::kRoughnessReference *
                      std::pow(10.0, source_levels[e][band] / 10.0);
    sum += 2.0 * r2 * noise::band_mean(f, by_source[e], centre);
  }
  // a band without power (a wheel far below coincidence, at round-off): the smallest normal
  // double, so that the level stays finite (some -3000 dB) and the power sums hold
  return 10 * std::log10(std::max(sum, std::numeric_limits<double>::min()) / kPowerReference);
}

}  // namespace

std::array<double, 4> a_weighted_columns(const std::vector<double>& centres,
                                         const SoundBands& bands) {
  std::array<double, 4> out{};
  for (int c = 0; c < 4; ++c) {
    std::vector<double> levels;
    for (const auto& b : bands) levels.push_back(b[static_cast<std::size_t>(c)]);
    out[static_cast<std::size_t>(c)] = a_weighted_column(centres, levels);
  }
  return out;
}

double power_sum(double a, double b) {
  if (std::isnan(a)) return b;
  if (std::isnan(b)) return a;
  return 10 * std::log10(std::pow(10.0, a / 10) + std::pow(10.0, b / 10));
}

double a_weighted_column(const std::vector<double>& centres, const std::vector<double>& levels) {
  for (double l : levels)
    if (!std::isfinite(l)) return kNaN;  // an empty column (the table wheel) stays empty
  return acoustics::a_weighted_total(centres, levels);
}

namespace {

// (S2), (S3) at one frequency from the transfers at the points `pts` (p positions a point).
void add_line_gram(const RailPoints& pts, std::size_t p,
                   const std::vector<dynamics::Receptance6>& transfers, Eigen::MatrixXcd& z,
                   Eigen::MatrixXcd& y, Eigen::MatrixXcd& sleepers) {
  const Eigen::Index n = static_cast<Eigen::Index>(6 * p);
  const std::size_t spans = static_cast<std::size_t>(pts.last_span - pts.first_span + 1);
  // per span (and per sleeper) blocks, for the tails
  std::vector<Eigen::MatrixXcd> span_z(spans, Eigen::MatrixXcd::Zero(n, n));
  std::vector<Eigen::MatrixXcd> span_y = span_z, sleeper_z = span_z;
  Eigen::RowVectorXcd az(n), ay(n);
  for (std::size_t i = 0; i < pts.x.size(); ++i) {
    for (std::size_t b = 0; b < p; ++b) {
      const dynamics::Receptance6& alpha = transfers[i * p + b];
      az.segment<6>(static_cast<Eigen::Index>(6 * b)) = alpha.row(2);
      ay.segment<6>(static_cast<Eigen::Index>(6 * b)) = alpha.row(1);
    }
    const std::size_t s = static_cast<std::size_t>(pts.span[i] - pts.first_span);
    if (pts.is_sleeper[i]) {
      sleeper_z[s].noalias() += az.adjoint() * az;
    } else {
      span_z[s].noalias() += pts.weight[i] * az.adjoint() * az;
      span_y[s].noalias() += pts.weight[i] * ay.adjoint() * ay;
    }
  }
  auto summed = [&](const std::vector<Eigen::MatrixXcd>& blocks) {
    Eigen::MatrixXcd total = Eigen::MatrixXcd::Zero(n, n);
    for (const auto& b : blocks) total += b;
    close_tail(total, blocks[0], blocks[1]);
    close_tail(total, blocks[blocks.size() - 1], blocks[blocks.size() - 2]);
    return total;
  };
  z = summed(span_z);
  y = summed(span_y);
  sleepers = summed(sleeper_z);
}

}  // namespace

RailLineGram rail_line_gram(const dynamics::RailModel& rail, const std::vector<double>& positions,
                            const std::vector<double>& grid, int gauss, int threads) {
  RailLineGram g;
  g.positions = positions;
  if (positions.empty()) return g;
  const double L = rail.track().sleeper_spacing;
  const auto [lo, hi] = std::minmax_element(positions.begin(), positions.end());
  const RailPoints pts = rail_points(*lo, *hi, L, gauss);
  const std::size_t p = positions.size();
  std::vector<dynamics::RailContactPair> pairs;
  for (double x : pts.x)
    for (double xb : positions)
      pairs.push_back({dynamics::RailContact{x, 0.0, 0.0}, dynamics::RailContact{xb, 0.0, 0.0}});
  const std::size_t nf = grid.size();
  g.z.resize(nf), g.y.resize(nf), g.sleepers.resize(nf);
  if (rail.samples_grid()) {
    // The waveguide: the whole grid in one call (its evaluations run on threads), each frequency
    // directly: on the ~630 positions' pairs the adaptive sampling's interpolation checks cost
    // more than the evaluations they save (curve_300m: 25.0 -> 14.1 s on a loaded machine, the
    // sleepers' band powers within 0.002 dB; docs/record/performance_waveguide.md Sec. 12).
    const auto transfers = rail.contact_transfers(grid, pairs, false);
    for (std::size_t k = 0; k < nf; ++k)
      add_line_gram(pts, p, transfers[k], g.z[k], g.y[k], g.sleepers[k]);
    return g;
  }
  // every frequency alone (the beams): a few at a time on the threads, without keeping them all
  constexpr std::size_t kChunk = 4;
  parallel_for((nf + kChunk - 1) / kChunk, threads, [&](std::size_t c, int) {
    const std::size_t k0 = c * kChunk, k1 = std::min(nf, k0 + kChunk);
    const std::vector<double> chunk(grid.begin() + static_cast<std::ptrdiff_t>(k0),
                                    grid.begin() + static_cast<std::ptrdiff_t>(k1));
    const auto transfers = rail.contact_transfers(chunk, pairs, true);
    for (std::size_t k = k0; k < k1; ++k)
      add_line_gram(pts, p, transfers[k - k0], g.z[k], g.y[k], g.sleepers[k]);
  });
  return g;
}

RailGram rail_gram(const RailLineGram& line, const std::vector<noise::ContactPoint>& contacts,
                   int side) {
  RailGram g;
  for (std::size_t a = 0; a < contacts.size(); ++a)
    if (contacts[a].side == side) g.contacts.push_back(static_cast<int>(a));
  if (g.contacts.empty()) return g;
  // M: contact forces (4 per contact, its frame) -> the centre-line loads (6 per position):
  // (G1) with the response on the centre line, alpha L(d_b)^T, L(d)^T = [[I, 0], [S(d), I]],
  // d_b = (0, offset_b, 0); then the contact frame T_b (G2).
  const Eigen::Index n = static_cast<Eigen::Index>(6 * line.positions.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(4 * g.contacts.size()));
  for (std::size_t j = 0; j < g.contacts.size(); ++j) {
    const noise::ContactPoint& c = contacts[static_cast<std::size_t>(g.contacts[j])];
    std::size_t p = 0;
    while (p < line.positions.size() && std::abs(line.positions[p] - c.rail_x) > 1e-12) ++p;
    if (p == line.positions.size())
      throw std::invalid_argument("rail_gram: a contact's position is not among the line Gram's");
    Eigen::Matrix<double, 6, 6> Lt = Eigen::Matrix<double, 6, 6>::Identity();
    Lt.block<3, 3>(3, 0) =
        dynamics::cross_matrix(Eigen::Vector3d(0.0, c.position.rail_offset_y, 0.0));
    M.block(static_cast<Eigen::Index>(6 * p), static_cast<Eigen::Index>(4 * j), 6, 4) =
        Lt * dynamics::contact_frame(c.position.contact_angle);
  }
  const Eigen::MatrixXcd Mc = M.cast<cdouble>();
  for (std::size_t k = 0; k < line.z.size(); ++k) {
    g.z.push_back(Mc.adjoint() * line.z[k] * Mc);
    g.y.push_back(Mc.adjoint() * line.y[k] * Mc);
    g.sleepers.push_back(Mc.adjoint() * line.sleepers[k] * Mc);
  }
  return g;
}

namespace {

// What the lines' powers need, prepared once a run: the rails' Gram matrices, each wheel's modal
// participation and where its modes sit in the radiation table, the sleepers' piston efficiency.
struct SoundSetup {
  std::vector<double> grid;                         // the rail's radiation grid
  std::vector<RailGram> rails;                      // side +1, side -1
  std::vector<dynamics::ModalParticipation> modal;  // per wheel
  std::vector<Eigen::MatrixXcd> psi_cos, psi_sin;   // their rows, complex
  // per order of the radiation table, per mode: its row in ModalParticipation (-1: none) and its
  // family (0 axial, 1 radial, 2 circumferential)
  std::vector<std::vector<int>> order_rows, order_family;
  std::vector<double> piston;  // sigma of a sleeper on the grid
};

// (S2), (S3): the Gram matrices of both rails, from the cache where io gives one. Gauss points a
// span from the bending wavelength at the top of the grid (12 a span up to 5 kHz: 2.4 wavelengths
// of |u|^2 in a 0.6 m span); none where the section deforms: that rail radiates by (R2)
// (add_rail_radiation), the line is its sleepers' alone (1/13 of the points).
std::vector<RailGram> rail_grams(const dynamics::RailModel& rail,
                                 const std::vector<noise::ContactPoint>& contacts,
                                 const std::vector<double>& grid, const SoundCase& sound,
                                 int threads) {
  const int gauss =
      rail.section_deforms()
          ? 0
          : std::max(12, static_cast<int>(std::ceil(12 * std::sqrt(grid.back() / 5000.0))));
  std::vector<double> positions;
  for (const noise::ContactPoint& c : contacts)
    if (std::none_of(positions.begin(), positions.end(),
                     [&](double x) { return std::abs(x - c.rail_x) <= 1e-12; }))
      positions.push_back(c.rail_x);
  const std::shared_ptr<const RailLineGram> line =
      sound.rail_line_table ? sound.rail_line_table(rail, positions, grid, gauss, threads)
                            : std::make_shared<const RailLineGram>(
                                  rail_line_gram(rail, positions, grid, gauss, threads));
  std::vector<RailGram> rails;
  for (int side : {1, -1}) rails.push_back(rail_gram(*line, contacts, side));
  return rails;
}

// The rail's section: the case's, else the built-in UIC60.
std::vector<Eigen::Vector2d> rail_outline(const SoundCase& sound) {
  return sound.rail_section.empty() ? dynamics::uic60_outline() : sound.rail_section;
}

// (S2)'s radiation of each rail on the grid: the rigid section's P_v z + P_l y, or, where the
// rail's section deforms (the waveguide), the wavenumber integral (R2) of its loads
// (rail_section_sound).
void add_rail_radiation(std::vector<RailGram>& rails, const dynamics::RailModel& rail,
                        const std::vector<noise::ContactPoint>& contacts,
                        const RailRadiation& rigid, const std::vector<double>& grid,
                        const SoundCase& sound, int threads) {
  std::shared_ptr<const SectionRadiationTable> table;
  if (rail.section_deforms()) {
    const double max_k = 2 * kPi * grid.back() / sound.fluid.sound_speed;
    table = sound.section_table
                ? sound.section_table(max_k)
                : std::make_shared<const SectionRadiationTable>(section_radiation_table(
                      rail_outline(sound), sound.rail_ground, max_k, sound.fluid, threads));
  }
  for (RailGram& g : rails) {
    if (g.contacts.empty()) continue;
    if (!table) {
      for (std::size_t k = 0; k < grid.size(); ++k)
        g.radiated.push_back(rigid.vertical[k] * g.z[k] + rigid.lateral[k] * g.y[k]);
      continue;
    }
    std::vector<dynamics::RailLoadPoint> points;
    for (int a : g.contacts) {
      const noise::ContactPoint& c = contacts[static_cast<std::size_t>(a)];
      points.push_back({c.position.rail_offset_y, c.position.contact_angle, c.rail_x});
    }
    g.radiated = sound.section_gram_table
                     ? sound.section_gram_table(rail, points, *table, grid, sound.fluid, threads)
                     : section_grams(rail, points, *table, grid, sound.fluid, threads);
  }
}

// (W2) of each wheel at its contacts, and where its modes sit in the radiation table's orders.
void add_modal_setup(SoundSetup& s, const dynamics::WheelFeModes& tread,
                     const WheelRadiation& table, const std::vector<noise::ContactPoint>& contacts,
                     const std::vector<SoundWheel>& wheels, const SoundCase& sound) {
  for (const SoundWheel& w : wheels) {
    std::vector<dynamics::TreadContact> at;
    for (int a : w.contacts) {
      const noise::ContactPoint& c = contacts[static_cast<std::size_t>(a)];
      at.push_back({c.position.wheel_shift_y, c.position.contact_angle});
    }
    s.modal.push_back(dynamics::modal_participation(tread, sound.wheel_options, at));
    s.psi_cos.push_back(s.modal.back().cos_set.cast<cdouble>());
    s.psi_sin.push_back(s.modal.back().sin_set.cast<cdouble>());
  }
  if (s.modal.empty()) return;
  const std::vector<int>& participating = s.modal.front().modes;
  for (const auto& order : table.orders) {
    std::vector<int> rows, families;
    for (int k : order.modes) {
      families.push_back(static_cast<int>(tread.modes[static_cast<std::size_t>(k)].family));
      const auto it = std::find(participating.begin(), participating.end(), k);
      rows.push_back(it == participating.end() ? -1 : static_cast<int>(it - participating.begin()));
    }
    s.order_rows.push_back(rows);
    s.order_family.push_back(families);
  }
}

// The structures' values at one line, interpolated from the grids.
struct LineStructures {
  double w2 = 0.0;                       // omega^2
  double sleeper = 0.0;                  // (S3)'s factor |tau|^2 (rho c / 2) sigma_p A_s
  std::vector<Eigen::MatrixXcd> gr, gs;  // each rail's radiation and sleepers' Gram matrices
  std::vector<Eigen::MatrixXcd> pw;      // the wheel's P_n
  std::vector<Eigen::VectorXcd> R;       // each wheel's modal responses
};

LineStructures line_structures(double f, const SoundSetup& s, const SoundResult& r,
                               const dynamics::Support& seat, const SoundCase& sound) {
  LineStructures l;
  const double omega = dynamics::angular(f);
  l.w2 = omega * omega;
  const GridPlace at = grid_place(s.grid, f);
  const double tau2 = std::norm(seat.sleeper_transfer(omega));  // Eq. (1)'s seat
  l.sleeper = tau2 * 0.5 * sound.fluid.impedance() * interpolated(s.piston, at) *
              sound.sleeper_length * sound.sleeper_width;
  for (const RailGram& g : s.rails) {
    const bool any = !g.contacts.empty();
    l.gr.push_back(any ? interpolated(g.radiated, at) : Eigen::MatrixXcd());
    l.gs.push_back(any ? interpolated(g.sleepers, at) : Eigen::MatrixXcd());
  }
  if (r.wheel) {
    const GridPlace on_wheel = grid_place(r.wheel->frequency, f);
    for (const auto& order : r.wheel->orders)
      l.pw.push_back(interpolated_power(order.power, on_wheel));
  }
  for (const auto& m : s.modal) l.R.push_back(dynamics::modal_responses(m, f));
  return l;
}

// (S2), (S3) of the forces F on rail s: the rail's and its sleepers' power.
std::pair<double, double> rail_power(const LineStructures& l, std::size_t s,
                                     const Eigen::VectorXcd& F) {
  // a section whose radiation is far below its noise level (bem2d's P_2D is not positive to
  // round-off) radiates nothing, not a negative power
  return {std::max(l.w2 * F.dot(l.gr[s] * F).real(), 0.0),
          l.w2 * l.sleeper * F.dot(l.gs[s] * F).real()};
}

// (S1) of wheel w under its contacts' forces F, in one pass over each order's P_n: [0] all its
// modes, [1 + f] family f's alone (their cross terms within an order kept, the other families'
// left out).
std::array<double, 4> wheel_power(const LineStructures& l, const SoundSetup& s, std::size_t w,
                                  const Eigen::VectorXcd& F) {
  const Eigen::VectorXcd qc = l.R[w].cwiseProduct(s.psi_cos[w] * F);
  const Eigen::VectorXcd qs = l.R[w].cwiseProduct(s.psi_sin[w] * F);
  std::array<double, 4> power{};
  for (std::size_t o = 0; o < l.pw.size(); ++o) {
    const std::vector<int>& rows = s.order_rows[o];
    const Eigen::MatrixXcd& P = l.pw[o];
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i] < 0) continue;
      for (std::size_t j = 0; j < rows.size(); ++j) {
        if (rows[j] < 0) continue;
        const cdouble p = P(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        // conj(v_i) P_ij v_j of both sets (the cos and the sin set radiate alike, without cross
        // power)
        const double term =
            (std::conj(qc(rows[i])) * p * qc(rows[j]) + std::conj(qs(rows[i])) * p * qs(rows[j]))
                .real();
        power[0] += term;
        if (s.order_family[o][i] == s.order_family[o][j])
          power[1 + static_cast<std::size_t>(s.order_family[o][i])] += term;
      }
    }
  }
  // a mode far below coincidence (sigma < 1e-13) radiates at round-off, which may come out
  // negative through the cross terms: no power
  for (double& p : power) p = std::max(l.w2 * p, 0.0);
  return power;
}

// The forces of rail g's contacts that belong to `wheel` (the others zero), or an empty vector.
Eigen::VectorXcd own_forces(const noise::ContactSetLoopResult& loop, const RailGram& g,
                            const SoundWheel& wheel, std::size_t k, int e) {
  Eigen::VectorXcd F = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(4 * g.contacts.size()));
  bool any = false;
  for (std::size_t j = 0; j < g.contacts.size(); ++j)
    if (std::find(wheel.contacts.begin(), wheel.contacts.end(), g.contacts[j]) !=
        wheel.contacts.end()) {
      F.segment<4>(static_cast<Eigen::Index>(4 * j)) =
          loop.force[k].block<4, 1>(4 * g.contacts[j], e);
      any = true;
    }
  return any ? F : Eigen::VectorXcd();
}

LinePowers line_powers(const noise::ContactSetLoopResult& loop,
                       const std::vector<noise::ContactPoint>& contacts,
                       const std::vector<SoundWheel>& wheels, const SoundSetup& s,
                       const SoundResult& r, const dynamics::RailModel& rail,
                       const SoundCase& sound, int threads) {
  const std::size_t nl = loop.frequency.size(), ne = static_cast<std::size_t>(loop.sources());
  const std::size_t nw = wheels.size();
  LinePowers lp;
  lp.wheel_total.assign(ne, std::vector<double>(nl, 0.0));
  lp.rail_total = lp.sleeper_total = lp.input = lp.wheel_total;
  lp.wheel.assign(nw, lp.wheel_total);
  lp.rail = lp.sleepers = lp.wheel;
  lp.family.assign(nw, std::vector<std::vector<std::vector<double>>>(3, lp.wheel_total));
  parallel_for(nl, threads, [&](std::size_t k, int) {
    const LineStructures l =
        line_structures(loop.frequency[k], s, r, rail.track().vertical_support, sound);
    for (std::size_t e = 0; e < ne; ++e) {
      const int src = static_cast<int>(e);
      lp.input[e][k] = input_power(loop, contacts, k, src);
      for (std::size_t side = 0; side < s.rails.size(); ++side) {  // each rail coherently
        if (s.rails[side].contacts.empty()) continue;
        const auto [rail_w, sleeper_w] =
            rail_power(l, side, stacked_forces(loop, s.rails[side].contacts, k, src));
        lp.rail_total[e][k] += rail_w;
        lp.sleeper_total[e][k] += sleeper_w;
      }
      for (std::size_t w = 0; w < nw; ++w) {
        for (std::size_t side = 0; side < s.rails.size(); ++side) {  // under its own forces alone
          const Eigen::VectorXcd F = own_forces(loop, s.rails[side], wheels[w], k, src);
          if (F.size() == 0) continue;
          const auto [rail_w, sleeper_w] = rail_power(l, side, F);
          lp.rail[w][e][k] += rail_w;
          lp.sleepers[w][e][k] += sleeper_w;
        }
        if (!r.wheel) continue;
        const Eigen::VectorXcd F = stacked_forces(loop, wheels[w].contacts, k, src);
        const std::array<double, 4> power = wheel_power(l, s, w, F);
        lp.wheel[w][e][k] = power[0];
        lp.wheel_total[e][k] += lp.wheel[w][e][k];
        for (int fam = 0; fam < 3; ++fam)
          lp.family[w][static_cast<std::size_t>(fam)][e][k] =
              power[1 + static_cast<std::size_t>(fam)];
      }
    }
  });
  return lp;
}

// (S4) of every column, the wheels', the families' and the input's.
void add_band_levels(SoundResult& r, const LinePowers& lp, const std::vector<double>& f,
                     bool velocities, const std::vector<std::vector<double>>& source_levels) {
  const std::vector<double>& centres = r.centre;
  const std::size_t nw = lp.wheel.size();
  auto level = [&](const std::vector<std::vector<double>>& x, std::size_t b) {
    return band_level(f, x, source_levels, b, centres[b]);
  };
  auto row = [](double wheel, double rail, double sleepers) {
    return std::array<double, 4>{wheel, rail, sleepers,
                                 power_sum(power_sum(wheel, rail), sleepers)};
  };
  r.power.resize(centres.size());
  r.contact_power.assign(nw, SoundBands(centres.size()));
  for (std::size_t b = 0; b < centres.size(); ++b) {
    r.power[b] = row(r.wheel ? level(lp.wheel_total, b) : kNaN, level(lp.rail_total, b),
                     level(lp.sleeper_total, b));
    for (std::size_t w = 0; w < nw; ++w)
      r.contact_power[w][b] = row(r.wheel ? level(lp.wheel[w], b) : kNaN, level(lp.rail[w], b),
                                  level(lp.sleepers[w], b));
    r.input_power.push_back(velocities ? level(lp.input, b) : kNaN);
  }
  if (r.wheel) {  // each family's band levels, per wheel and summed over the wheels
    r.wheel_family.assign(centres.size(), {0.0, 0.0, 0.0});
    r.contact_family.assign(nw, std::vector<std::array<double, 3>>(centres.size()));
    for (std::size_t b = 0; b < centres.size(); ++b)
      for (std::size_t fam = 0; fam < 3; ++fam) {
        double sum = 0.0;
        for (std::size_t w = 0; w < nw; ++w) {
          r.contact_family[w][b][fam] = level(lp.family[w][fam], b);
          sum += std::pow(10.0, r.contact_family[w][b][fam] / 10);
        }
        r.wheel_family[b][fam] = 10 * std::log10(sum);
      }
  }
  r.power_a = a_weighted_columns(centres, r.power);
  for (const SoundBands& c : r.contact_power)
    r.contact_power_a.push_back(a_weighted_columns(centres, c));
}

// The decay rates (EN 15461) from a force at the centre line at track.position, band means of
// |A(x)|^2 on the grid, with EN ISO 3095:2013's lower limits where a band has one.
void add_decay_rates(SoundResult& r, const dynamics::RailModel& rail,
                     const std::vector<double>& grid) {
  const std::vector<double> measured_at =
      acoustics::en15461_positions(rail.track().sleeper_spacing);
  std::vector<dynamics::RailContactPair> pairs;
  const double x0 = rail.position();
  for (double d : measured_at)
    pairs.push_back({dynamics::RailContact{x0 + d, 0.0, 0.0}, dynamics::RailContact{x0, 0.0, 0.0}});
  const auto along = rail.contact_transfers(grid, pairs, true);
  for (double centre : r.centre) {
    const auto [lo, hi] = noise::third_octave_edges(centre);
    std::vector<double> az(measured_at.size(), 0.0), ay(measured_at.size(), 0.0);
    int count = 0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
      if (grid[k] < lo || grid[k] > hi) continue;
      ++count;
      for (std::size_t p = 0; p < measured_at.size(); ++p) {
        az[p] += std::norm(along[k][p](2, 2));
        ay[p] += std::norm(along[k][p](1, 1));
      }
    }
    r.decay_vertical.push_back(count ? acoustics::track_decay_rate(measured_at, az) : kNaN);
    r.decay_lateral.push_back(count ? acoustics::track_decay_rate(measured_at, ay) : kNaN);
    double lv = kNaN, ll = kNaN;
    for (const acoustics::DecayRateLimit& l : acoustics::iso3095_decay_rate_limits())
      if (std::abs(l.frequency / noise::nominal_centre(centre) - 1.0) < 1e-3)
        lv = l.vertical, ll = l.lateral;
    r.decay_limit_vertical.push_back(lv);
    r.decay_limit_lateral.push_back(ll);
  }
}

}  // namespace

SoundResult sound_power(const noise::ContactSetLoopResult& loop,
                        const std::vector<noise::ContactPoint>& contacts,
                        const std::vector<SoundWheel>& wheels,
                        const std::vector<std::vector<double>>& source_levels,
                        const std::vector<double>& centres, const dynamics::RailModel& rail,
                        const SoundCase& sound, int threads) {
  const Clock::time_point t0 = Clock::now();
  auto lap = [t = t0](double& part) mutable {  // the part's seconds since the last lap
    part = seconds_since(t);
    t = Clock::now();
  };
  SoundResult r;
  r.centre = centres;
  SoundSetup s;
  s.grid = radiation_grid(centres, kRailGridPerBand);
  // the radiation tables (from the cache where io gives one)
  const std::shared_ptr<const dynamics::WheelFeModes> tread =
      sound.wheel_tread ? sound.wheel_tread() : nullptr;
  if (tread && sound.wheel_table)
    r.wheel = sound.wheel_table(radiation_grid(centres, kWheelGridPerBand));
  r.wheel_note = r.wheel ? "" : sound.wheel_missing;
  r.rail = sound.rail_table
               ? sound.rail_table(s.grid)
               : std::make_shared<const RailRadiation>(rail_radiation(
                     rail_outline(sound), sound.rail_ground, s.grid, sound.fluid, threads));
  lap(r.parts.tables);
  s.rails = rail_grams(rail, contacts, s.grid, sound, threads);
  lap(r.parts.rail_line);
  add_rail_radiation(s.rails, rail, contacts, *r.rail, s.grid, sound, threads);
  lap(r.parts.rail_section);
  if (r.wheel) add_modal_setup(s, *tread, *r.wheel, contacts, wheels, sound);
  for (double fg : s.grid)  // the sleepers' piston efficiency, smooth in f
    s.piston.push_back(acoustics::rectangular_piston_efficiency(
        2 * kPi * fg / sound.fluid.sound_speed, sound.sleeper_length, sound.sleeper_width));
  const LinePowers lp = line_powers(loop, contacts, wheels, s, r, rail, sound, threads);
  add_band_levels(r, lp, loop.frequency, !loop.wheel_velocity.empty(), source_levels);
  lap(r.parts.lines);
  add_decay_rates(r, rail, s.grid);
  lap(r.parts.decay);
  r.seconds = seconds_since(t0);
  return r;
}

}  // namespace rollnoise::pipeline
