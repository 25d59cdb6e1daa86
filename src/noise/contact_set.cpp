#include "noise/contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "dynamics/rail_model.hpp"

namespace rollnoise::noise {
namespace {

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

ContactSetRailPairs contact_set_rail_pairs(const std::vector<ContactPoint>& contacts,
                                           const CrossCoupling& cross) {
  ContactSetRailPairs out;
  const Eigen::Index n = static_cast<Eigen::Index>(contacts.size());
  auto point = [](const ContactPoint& c) {
    return dynamics::RailContact{c.rail_x, c.position.rail_offset_y, c.position.contact_angle};
  };
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = a; b < n; ++b) {
      if (contacts[a].side != contacts[b].side || (a != b && !cross.rail)) continue;
      out.index.emplace_back(a, b);
      out.points.emplace_back(point(contacts[a]), point(contacts[b]));
    }
  return out;
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

ContactSetReceptance contact_set_receptance(const dynamics::WheelModel& wheel,
                                            const dynamics::RailModel& rail,
                                            const std::vector<ContactPoint>& contacts,
                                            double frequency, const CrossCoupling& cross) {
  validate_contacts(contacts);
  if (!(frequency > 0.0) || !std::isfinite(frequency))
    throw InputError("frequency", "rail transfer receptance needs a positive frequency");
  const ContactSetRailPairs pairs = contact_set_rail_pairs(contacts, cross);
  return contact_set_receptance(
      wheel, rail.contact_transfers({frequency}, pairs.points, false).front(), contacts,
      contact_mode_tables(wheel, contacts), frequency, cross);
}

ContactSetReceptance contact_set_receptance(const dynamics::WheelModel& wheel,
                                            const std::vector<Receptance6>& rail_pairs,
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
  // The rail between the contacts of one rail, each pair once (reciprocity: alpha_ba = alpha_ab^T).
  const ContactSetRailPairs pairs = contact_set_rail_pairs(contacts, cross);
  if (rail_pairs.size() != pairs.index.size())
    throw InputError("contacts", "one rail receptance per rail pair of the contacts is needed");
  std::vector<Receptance6> rail_block(static_cast<std::size_t>(n * n), Receptance6::Zero());
  for (std::size_t p = 0; p < pairs.index.size(); ++p) {
    const auto [a, b] = pairs.index[p];
    rail_block[a * n + b] = rail_pairs[p];
    if (b != a) rail_block[b * n + a] = rail_pairs[p].transpose();
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
      if ((self || cross.rail) && ca.side == cb.side) r = rail_block[a * n + b];
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
