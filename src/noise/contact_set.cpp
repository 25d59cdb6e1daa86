#include "noise/contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/assert.hpp"
#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

// L(d) M of (M2) applied to the columns of a 6-row M: u' = u + th x d (loop.hpp's L2).
template <class M>
void apply_lever(M& m, const Eigen::Vector3d& d) {
  for (Eigen::Index j = 0; j < m.cols(); ++j) {  // written out: Eigen's complex cross() conjugates
    const cdouble tx = m(3, j), ty = m(4, j), tz = m(5, j);
    m(0, j) += ty * d.z() - tz * d.y();
    m(1, j) += tz * d.x() - tx * d.z();
    m(2, j) += tx * d.y() - ty * d.x();
  }
}

bool same_wheel(const ContactPoint& a, const ContactPoint& b) {
  return a.wheelset == b.wheelset && a.side == b.side;
}

}  // namespace

void validate_contacts(const std::vector<ContactPoint>& contacts) {
  if (contacts.empty())
    throw InputError("contacts", "the loop with several contacts needs at least one contact");
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactPoint& c = contacts[i];
    const std::string where = "contacts[" + std::to_string(i) + "]";
    if (c.side != 1 && c.side != -1) throw InputError(where + ".side", "side must be +1 or -1");
    if (c.wheelset < 0) throw InputError(where + ".wheelset", "wheelset index must be >= 0");
    if (!std::isfinite(c.rail_x) || !std::isfinite(c.position.wheel_shift_y) ||
        !std::isfinite(c.position.rail_offset_y) || !std::isfinite(c.position.contact_angle))
      throw InputError(where, "contact position, angle and rail_x must be finite");
  }
}

Eigen::Matrix<double, 6, 6> side_reflection(int side) {
  Eigen::Matrix<double, 6, 6> P = Eigen::Matrix<double, 6, 6>::Identity();
  if (side < 0) P(1, 1) = P(3, 3) = P(5, 5) = -1.0;
  return P;
}

Receptance6 move_points(const Receptance6& alpha, const Eigen::Vector3d& d_a,
                        const Eigen::Vector3d& d_b) {
  Receptance6 left = alpha;  // L(d_a) alpha
  apply_lever(left, d_a);
  Receptance6 both = left.transpose();  // L(d_b) (L(d_a) alpha)^T, transposed back
  apply_lever(both, d_b);
  return both.transpose();
}

// ---------------------------------------------------------------------------------------------
// The rail line
// ---------------------------------------------------------------------------------------------

RailLine::RailLine(const dynamics::TrackParameters& track, dynamics::TrackSupport support)
    : track_(track),
      support_(support),
      vertical_(track.vertical, track.vertical_support, track.sleeper_spacing,
                track.supports_each_side),
      lateral_(track.lateral, track.lateral_support, track.sleeper_spacing,
               track.supports_each_side) {
  track_.validate();
}

Receptance4 RailLine::transfer(double frequency, double x_r, double x_e) const {
  return transfers(frequency, {{x_r, x_e}}).front();
}

RailLine RailLine::with_point_receptance(double x, std::vector<double> frequency,
                                         std::vector<Receptance4> receptance) const {
  RailLine out = *this;
  if (frequency.size() != receptance.size() || !std::is_sorted(frequency.begin(), frequency.end()))
    return out;  // not usable as a table: everything is solved
  out.known_ = std::make_shared<const KnownPoint>(
      KnownPoint{x, std::move(frequency), std::move(receptance)});
  return out;
}

const Receptance4* RailLine::known_point(double frequency, double x) const {
  if (!known_ || x != known_->x) return nullptr;
  const auto& f = known_->frequency;
  const auto it = std::lower_bound(f.begin(), f.end(), frequency);
  if (it == f.end() || *it != frequency) return nullptr;
  return &known_->receptance[static_cast<std::size_t>(it - f.begin())];
}

std::vector<Receptance4> RailLine::transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw InputError("frequency", "rail transfer receptance needs a positive frequency");
  std::vector<Receptance4> out(pairs.size());
  std::vector<std::pair<double, double>> unknown;  // the pairs to solve, at `slot` in out
  std::vector<std::size_t> slot;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const Receptance4* known =
        pairs[p].first == pairs[p].second ? known_point(frequency, pairs[p].first) : nullptr;
    if (known) {
      out[p] = *known;
      continue;
    }
    unknown.push_back(pairs[p]);
    slot.push_back(p);
  }
  if (unknown.empty()) return out;
  const double omega = dynamics::angular(frequency), L = track_.sleeper_spacing;
  std::vector<Eigen::Matrix2cd> Hv(unknown.size()), Hl(unknown.size());
  if (support_ == dynamics::TrackSupport::kDiscrete) {
    Hv = vertical_.transfers(frequency, unknown);
    Hl = lateral_.transfers(frequency, unknown);
  } else {
    for (std::size_t p = 0; p < unknown.size(); ++p) {
      const double dx = unknown[p].first - unknown[p].second;
      Hv[p] =
          dynamics::continuous_transfer(track_.vertical, track_.vertical_support, L, frequency, dx);
      Hl[p] =
          dynamics::continuous_transfer(track_.lateral, track_.lateral_support, L, frequency, dx);
    }
  }
  const cdouble s_x = track_.longitudinal_support.dynamic_stiffness(omega) / L;
  for (std::size_t p = 0; p < unknown.size(); ++p) {
    const cdouble rod =
        dynamics::rod_receptance(track_.vertical, omega, s_x, unknown[p].first - unknown[p].second);
    out[slot[p]] = dynamics::rail_receptance4(Hv[p], Hl[p], rod, track_.head_height);
  }
  return out;
}

Receptance4 RailLine::transfer_laplace(cdouble s, double x_r, double x_e) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency",
                     "rail transfer receptance needs a finite, non-zero Laplace variable s");
  const cdouble omega = cdouble(0.0, -1.0) * s;  // i omega = s
  const double wr = omega.real(), L = track_.sleeper_spacing;
  Eigen::Matrix2cd Hv, Hl;
  if (support_ == dynamics::TrackSupport::kDiscrete) {
    Hv = vertical_.transfer_at(omega, x_r, x_e);
    Hl = lateral_.transfer_at(omega, x_r, x_e);
  } else {
    auto beam = [&](const dynamics::BeamSection& b, const dynamics::Support& sup) {
      return dynamics::InfiniteBeam(b, omega, sup.dynamic_stiffness(omega) / L,
                                    sup.dynamic_stiffness(wr) / L)
          .transfer(x_r - x_e);
    };
    Hv = beam(track_.vertical, track_.vertical_support);
    Hl = beam(track_.lateral, track_.lateral_support);
  }
  const dynamics::Support& lon = track_.longitudinal_support;
  const cdouble rod =
      dynamics::rod_receptance(track_.vertical, omega, lon.dynamic_stiffness(omega) / L, x_r - x_e,
                               lon.dynamic_stiffness(wr) / L);
  return dynamics::rail_receptance4(Hv, Hl, rod, track_.head_height);
}

// ---------------------------------------------------------------------------------------------
// The pieces between two contacts
// ---------------------------------------------------------------------------------------------

Eigen::Vector3d wheelset_arm(const dynamics::RigidWheelset& w, const ContactPoint& c) {
  return {0.0, c.side * (w.contact_offset_y + c.position.wheel_shift_y), -w.wheel_radius};
}

Eigen::Matrix<double, 6, 6> rigid_flexibility6(const dynamics::RigidWheelset& w,
                                               const ContactPoint& a, const ContactPoint& b) {
  if (a.wheelset != b.wheelset) return Eigen::Matrix<double, 6, 6>::Zero();
  // the centre flexibility: wheelset_centre_receptance at omega = 1 is -C
  const Receptance6 centre = -wheelset_centre_receptance(w, 1.0 / (2.0 * M_PI));
  const Eigen::Matrix<double, 6, 6> C =
      move_points(centre, wheelset_arm(w, a), wheelset_arm(w, b)).real();  // (M2)
  return side_reflection(a.side) * C * side_reflection(b.side);
}

Receptance6 wheel_modal_cross(const Receptance4& modal, const ContactPoint& a,
                              const ContactPoint& b) {
  if (!same_wheel(a, b)) return Receptance6::Zero();
  // Both points in the wheel's own (local) frame: the reference point's modal receptance moved by
  // each contact's shift (loop.hpp's wheel_receptance6 for a = b).
  const Receptance6 m = embed(modal);
  const double sa = a.position.wheel_shift_y, sb = b.position.wheel_shift_y;
  if (sa == 0.0 && sb == 0.0) return m;
  return move_points(m, Eigen::Vector3d(0.0, sa, 0.0), Eigen::Vector3d(0.0, sb, 0.0));
}

Receptance6 rail_cross(const Receptance4& transfer, const ContactPoint& a, const ContactPoint& b) {
  if (a.side != b.side) return Receptance6::Zero();
  const Receptance6 r = embed(transfer);
  const double oa = a.position.rail_offset_y, ob = b.position.rail_offset_y;
  if (oa == 0.0 && ob == 0.0) return r;
  return move_points(r, Eigen::Vector3d(0.0, oa, 0.0), Eigen::Vector3d(0.0, ob, 0.0));
}

// ---------------------------------------------------------------------------------------------
// The assembly at one frequency
// ---------------------------------------------------------------------------------------------

ContactModeTables contact_mode_tables(const dynamics::WheelModel& wheel,
                                      const std::vector<ContactPoint>& contacts) {
  ContactModeTables tables;
  tables.reserve(contacts.size());
  for (const ContactPoint& c : contacts) tables.push_back(wheel.modes_at(c.position.wheel_shift_y));
  return tables;
}

ContactSetReceptance contact_set_receptance(const dynamics::WheelModel& wheel, const RailLine& rail,
                                            const std::vector<ContactPoint>& contacts,
                                            double frequency, const CrossCoupling& cross) {
  validate_contacts(contacts);
  return contact_set_receptance(wheel, rail, contacts, contact_mode_tables(wheel, contacts),
                                frequency, cross);
}

ContactSetReceptance contact_set_receptance(const dynamics::WheelModel& wheel, const RailLine& rail,
                                            const std::vector<ContactPoint>& contacts,
                                            const ContactModeTables& tables, double frequency,
                                            const CrossCoupling& cross) {
  validate_contacts(contacts);
  ROLLNOISE_ASSERT(tables.size() == contacts.size(), "one mode table per contact");
  const Eigen::Index n = static_cast<Eigen::Index>(contacts.size());
  const double omega = dynamics::angular(frequency);
  ContactSetReceptance out;
  out.wheel6 = Eigen::MatrixXcd::Zero(6 * n, 4 * n);
  out.rail6 = Eigen::MatrixXcd::Zero(6 * n, 4 * n);
  // Rail transfers between positions on one rail, each pair once (reciprocity: H(b, a) = H(a,
  // b)^T). Both rails are the same track: a pair of positions met on the other rail (the inner
  // wheels at the outer wheels' x) reuses that rail's result, the same bits. The distinct pairs
  // are solved together: one Toeplitz recursion per frequency and beam (RailLine::transfers).
  std::vector<std::pair<double, double>> positions;  // (x_a, x_b) of each distinct pair
  std::vector<std::size_t> which(static_cast<std::size_t>(n * n), 0);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = a; b < n; ++b) {
      if (contacts[a].side != contacts[b].side || (a != b && !cross.rail)) continue;
      const std::pair<double, double> xy(contacts[a].rail_x, contacts[b].rail_x);
      const auto earlier = std::find(positions.begin(), positions.end(), xy);
      which[a * n + b] = static_cast<std::size_t>(earlier - positions.begin());
      if (earlier == positions.end()) positions.push_back(xy);
    }
  const std::vector<Receptance4> solved =
      positions.empty() ? std::vector<Receptance4>{} : rail.transfers(frequency, positions);
  std::vector<Receptance4> transfer(static_cast<std::size_t>(n * n));
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = a; b < n; ++b) {
      if (contacts[a].side != contacts[b].side || (a != b && !cross.rail)) continue;
      transfer[a * n + b] = solved[which[a * n + b]];
      if (b != a) transfer[b * n + a] = transfer[a * n + b].transpose();
    }
  for (Eigen::Index a = 0; a < n; ++a) {
    for (Eigen::Index b = 0; b < n; ++b) {
      const ContactPoint &ca = contacts[a], &cb = contacts[b];
      const bool self = a == b;
      Receptance6 w = Receptance6::Zero(), r = Receptance6::Zero();
      if (self || cross.wheelset)
        w += rigid_flexibility6(wheel.wheelset(), ca, cb).cast<cdouble>() / (-omega * omega);
      // the point receptance at the contact's own position on the tread (the FE wheel's shapes
      // there, as the single-contact loop; the table wheel: its one table); between two patches of
      // one wheel the shapes at both positions (the table wheel: its one table moved rigidly)
      if (self)
        w += wheel_modal_cross(dynamics::modal_sum(tables[a], tables[a], frequency), ca, ca);
      else if (cross.wheel && same_wheel(ca, cb))
        w += wheel_modal_cross(dynamics::modal_sum(tables[a], tables[b], frequency), ca, cb);
      if ((self || cross.rail) && ca.side == cb.side) r = rail_cross(transfer[a * n + b], ca, cb);
      const Eigen::Matrix<cdouble, 6, 4> Tb =
          contact_frame(cb.position.contact_angle).cast<cdouble>();
      out.wheel6.block<6, 4>(6 * a, 4 * b) = w * Tb;
      out.rail6.block<6, 4>(6 * a, 4 * b) = r * Tb;
    }
  }
  out.wheel = Eigen::MatrixXcd(4 * n, 4 * n);
  out.rail = Eigen::MatrixXcd(4 * n, 4 * n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Eigen::Matrix<cdouble, 4, 6> Ta =
        contact_frame(contacts[a].position.contact_angle).cast<cdouble>().transpose();
    out.wheel.middleRows(4 * a, 4) = Ta * out.wheel6.middleRows(6 * a, 6);
    out.rail.middleRows(4 * a, 4) = Ta * out.rail6.middleRows(6 * a, 6);
  }
  return out;
}

}  // namespace rollnoise::noise
