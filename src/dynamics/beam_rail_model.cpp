// The beam rail (beam_rail_model.hpp): the beams' centre-line transfer (Eqs. 1, 2 of track.hpp,
// the rod in x) and its rigid move to the contacts (G1 of rail_contact.hpp).
#include "dynamics/beam_rail_model.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/errors.hpp"
#include "dynamics/frequency_argument.hpp"

namespace rollnoise::dynamics {

BeamRailModel::BeamRailModel(const TrackParameters& track, TrackSupport support,
                             double contact_position)
    : RailModel(track, contact_position),
      support_(support),
      vertical_(track.vertical, track.vertical_support, track.sleeper_spacing,
                track.supports_each_side, track.discrete_solution),
      lateral_(track.lateral, track.lateral_support, track.sleeper_spacing,
               track.supports_each_side, track.discrete_solution) {}

Receptance4 BeamRailModel::receptance(double frequency) const {
  const double omega = checked_omega(frequency);
  Eigen::Matrix2cd Hv, Hl;
  if (support_ == TrackSupport::kDiscrete) {
    Hv = vertical_.point(frequency, position());
    Hl = lateral_.point(frequency, position());
  } else {
    Hv = continuous_transfer(track().vertical, track().vertical_support, track().sleeper_spacing,
                             frequency, 0.0);
    Hl = continuous_transfer(track().lateral, track().lateral_support, track().sleeper_spacing,
                             frequency, 0.0);
  }
  const cdouble s_x =
      track().longitudinal_support.dynamic_stiffness(omega) / track().sleeper_spacing;
  const cdouble rod = rod_receptance(track().vertical, omega, s_x, 0.0);
  return rail_receptance4(Hv, Hl, rod, track().head_height);
}

Receptance4 BeamRailModel::receptance_laplace(cdouble s) const {
  return line_transfer_laplace(s, position(), position());
}

std::vector<Receptance4> BeamRailModel::line_transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw InputError("frequency", "rail transfer receptance needs a positive frequency");
  std::vector<Receptance4> out(pairs.size());
  if (pairs.empty()) return out;
  const double omega = angular(frequency), L = track().sleeper_spacing;
  std::vector<Eigen::Matrix2cd> Hv(pairs.size()), Hl(pairs.size());
  if (support_ == TrackSupport::kDiscrete) {
    Hv = vertical_.transfers(frequency, pairs);
    Hl = lateral_.transfers(frequency, pairs);
  } else {
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const double dx = pairs[p].first - pairs[p].second;
      Hv[p] = continuous_transfer(track().vertical, track().vertical_support, L, frequency, dx);
      Hl[p] = continuous_transfer(track().lateral, track().lateral_support, L, frequency, dx);
    }
  }
  const cdouble s_x = track().longitudinal_support.dynamic_stiffness(omega) / L;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const cdouble rod =
        rod_receptance(track().vertical, omega, s_x, pairs[p].first - pairs[p].second);
    out[p] = rail_receptance4(Hv[p], Hl[p], rod, track().head_height);
  }
  return out;
}

Receptance4 BeamRailModel::line_transfer_laplace(cdouble s, double x_r, double x_e) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  const cdouble omega = cdouble(0.0, -1.0) * s;  // i omega = s
  const double wr = omega.real(), L = track().sleeper_spacing;
  Eigen::Matrix2cd Hv, Hl;
  if (support_ == TrackSupport::kDiscrete) {
    Hv = vertical_.transfer_at(omega, x_r, x_e);
    Hl = lateral_.transfer_at(omega, x_r, x_e);
  } else {
    auto beam = [&](const BeamSection& b, const Support& sup) {
      return InfiniteBeam(b, omega, sup.dynamic_stiffness(omega) / L, sup.dynamic_stiffness(wr) / L)
          .transfer(x_r - x_e);
    };
    Hv = beam(track().vertical, track().vertical_support);
    Hl = beam(track().lateral, track().lateral_support);
  }
  const Support& lon = track().longitudinal_support;
  const cdouble rod = rod_receptance(track().vertical, omega, lon.dynamic_stiffness(omega) / L,
                                     x_r - x_e, lon.dynamic_stiffness(wr) / L);
  return rail_receptance4(Hv, Hl, rod, track().head_height);
}

namespace {

// (G1) of the header: the centre-line transfer moved to the two contacts' offsets.
Receptance6 at_offsets(const Receptance4& line, const RailContactPair& pair) {
  const Receptance6 r = embed(line);
  const double oa = pair.first.offset_y, ob = pair.second.offset_y;
  if (oa == 0.0 && ob == 0.0) return r;
  return move_points(r, Eigen::Vector3d(0.0, oa, 0.0), Eigen::Vector3d(0.0, ob, 0.0));
}

// The distinct (x_a, x_b) of the pairs, and which of them each pair has: both rails are the same
// track, so a pair of positions met before (on the other rail) is solved once, the same bits.
std::vector<std::pair<double, double>> distinct_positions(const std::vector<RailContactPair>& pairs,
                                                          std::vector<std::size_t>& which) {
  std::vector<std::pair<double, double>> out;
  which.assign(pairs.size(), 0);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const std::pair<double, double> x(pairs[p].first.x, pairs[p].second.x);
    const auto earlier = std::find(out.begin(), out.end(), x);
    which[p] = static_cast<std::size_t>(earlier - out.begin());
    if (earlier == out.end()) out.push_back(x);
  }
  return out;
}

}  // namespace

std::vector<std::vector<Receptance6>> BeamRailModel::contact_transfers(
    const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs, bool) const {
  std::vector<std::size_t> which;
  const std::vector<std::pair<double, double>> positions = distinct_positions(pairs, which);
  std::vector<std::vector<Receptance6>> out;
  out.reserve(frequencies.size());
  for (double f : frequencies) {
    const std::vector<Receptance4> line = line_transfers(f, positions);
    std::vector<Receptance6> at(pairs.size());
    for (std::size_t p = 0; p < pairs.size(); ++p) at[p] = at_offsets(line[which[p]], pairs[p]);
    out.push_back(std::move(at));
  }
  return out;
}

RailModel::LaplaceTransfers BeamRailModel::laplace_transfers(
    const std::vector<RailContactPair>& pairs) const {
  auto which = std::make_shared<std::vector<std::size_t>>();
  const std::vector<std::pair<double, double>> positions = distinct_positions(pairs, *which);
  return [this, pairs, which, positions](cdouble s) {
    std::vector<Receptance4> line;
    for (const auto& [xa, xb] : positions) line.push_back(line_transfer_laplace(s, xa, xb));
    std::vector<Receptance6> out(pairs.size());
    for (std::size_t p = 0; p < pairs.size(); ++p) out[p] = at_offsets(line[(*which)[p]], pairs[p]);
    return out;
  };
}

}  // namespace rollnoise::dynamics
