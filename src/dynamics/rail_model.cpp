// RailModel's transfers between points along the rail and between contact points (track.hpp):
// the beams' centre-line transfer (Eqs. 1, 2 of track.hpp, the rod in x) and its rigid move to
// the contacts (G1 of rail_contact.hpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/errors.hpp"
#include "dynamics/track.hpp"

namespace rollnoise::dynamics {

std::vector<Receptance4> RailModel::line_transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw InputError("frequency", "rail transfer receptance needs a positive frequency");
  std::vector<Receptance4> out(pairs.size());
  if (pairs.empty()) return out;
  const double omega = angular(frequency), L = track_.sleeper_spacing;
  std::vector<Eigen::Matrix2cd> Hv(pairs.size()), Hl(pairs.size());
  if (support_ == TrackSupport::kDiscrete) {
    Hv = vertical_.transfers(frequency, pairs);
    Hl = lateral_.transfers(frequency, pairs);
  } else {
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const double dx = pairs[p].first - pairs[p].second;
      Hv[p] = continuous_transfer(track_.vertical, track_.vertical_support, L, frequency, dx);
      Hl[p] = continuous_transfer(track_.lateral, track_.lateral_support, L, frequency, dx);
    }
  }
  const cdouble s_x = track_.longitudinal_support.dynamic_stiffness(omega) / L;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const cdouble rod =
        rod_receptance(track_.vertical, omega, s_x, pairs[p].first - pairs[p].second);
    out[p] = rail_receptance4(Hv[p], Hl[p], rod, track_.head_height);
  }
  return out;
}

Receptance4 RailModel::line_transfer_laplace(cdouble s, double x_r, double x_e) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  const cdouble omega = cdouble(0.0, -1.0) * s;  // i omega = s
  const double wr = omega.real(), L = track_.sleeper_spacing;
  Eigen::Matrix2cd Hv, Hl;
  if (support_ == TrackSupport::kDiscrete) {
    Hv = vertical_.transfer_at(omega, x_r, x_e);
    Hl = lateral_.transfer_at(omega, x_r, x_e);
  } else {
    auto beam = [&](const BeamSection& b, const Support& sup) {
      return InfiniteBeam(b, omega, sup.dynamic_stiffness(omega) / L, sup.dynamic_stiffness(wr) / L)
          .transfer(x_r - x_e);
    };
    Hv = beam(track_.vertical, track_.vertical_support);
    Hl = beam(track_.lateral, track_.lateral_support);
  }
  const Support& lon = track_.longitudinal_support;
  const cdouble rod = rod_receptance(track_.vertical, omega, lon.dynamic_stiffness(omega) / L,
                                     x_r - x_e, lon.dynamic_stiffness(wr) / L);
  return rail_receptance4(Hv, Hl, rod, track_.head_height);
}

Receptance6 RailModel::at_offsets(const Receptance4& line, const RailContactPair& pair) {
  const Receptance6 r = embed(line);
  const double oa = pair.first.offset_y, ob = pair.second.offset_y;
  if (oa == 0.0 && ob == 0.0) return r;
  return move_points(r, Eigen::Vector3d(0.0, oa, 0.0), Eigen::Vector3d(0.0, ob, 0.0));
}

namespace {

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

std::vector<std::vector<Receptance6>> RailModel::contact_transfers(
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

RailModel::LaplaceTransfers RailModel::laplace_transfers(
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
