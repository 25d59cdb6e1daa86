// The loop at complex s (stability.hpp, (S1)): the wheel's modes and the rigid wheelset in the
// contact frame, the rail at complex s, and A(s) = R(s) + sum_k psi_k psi_k^T / (m_k D_k(s)).
// The contact at complex s is contact_receptance_laplace (contact_receptance.hpp) with f(s), g(s)
// of a ContactTransfer (contact_transfer.hpp).
#include <cmath>

#include "noise/stability.hpp"

namespace rollnoise::noise {

namespace {

Receptance4 modal_term(const LoopMode& m, cdouble s) {
  return (m.shape * m.shape.transpose()).cast<cdouble>() / modal_denominator(m, s);
}

}  // namespace

Receptance4 LaplaceLoop::matrix(cdouble s) const {
  Receptance4 a = rest(s);
  for (const LoopMode& m : modes) a += modal_term(m, s);
  return a;
}

std::vector<LoopMode> contact_frame_modes(const dynamics::WheelModel& wheel,
                                          const ContactPosition& p) {
  std::vector<LoopMode> out;
  const std::vector<dynamics::WheelMode> table = wheel.modes_at(p.wheel_shift_y);  // the FE wheel follows the contact
  for (std::size_t n = 0; n < table.size(); ++n) {
    const dynamics::WheelMode& w = table[n];
    // psi psi^T = T^T L embed(phi phi^T) L^T T (the wheel's modal part in wheel_receptance6 and
    // to_contact_frame, for one mode); psi from the rank-one matrix.
    Receptance6 r = embed((w.shape * w.shape.transpose()).cast<cdouble>());
    if (p.wheel_shift_y != 0.0) r = move_point(r, Eigen::Vector3d(0.0, p.wheel_shift_y, 0.0));
    const Eigen::Matrix4d M = to_contact_frame(r, p.contact_angle).real();
    Eigen::Index i = 0;
    M.diagonal().maxCoeff(&i);
    LoopMode m;
    m.frequency = w.frequency;
    m.damping_ratio = w.damping_ratio;
    m.modal_mass = w.modal_mass;
    m.shape =
        M(i, i) > 0.0 ? Eigen::Vector4d(M.col(i) / std::sqrt(M(i, i))) : Eigen::Vector4d::Zero();
    m.label = w.label;
    m.index = n;
    out.push_back(m);
  }
  return out;
}

Eigen::Matrix4d rigid_flexibility(const dynamics::RigidWheelset& w, const ContactPosition& p) {
  // wheelset_centre_receptance at omega = 1 is -C; alpha(s) = -C/omega^2 = C/s^2.
  Receptance6 centre = Receptance6::Zero();
  const double inv[6] = {1.0 / w.mass,         1.0 / w.mass,         1.0 / w.mass,
                         1.0 / w.roll_inertia, 1.0 / w.spin_inertia, 1.0 / w.yaw_inertia};
  for (int i = 0; i < 6; ++i) centre(i, i) = inv[i];
  const Receptance6 moved = move_point(
      centre, Eigen::Vector3d(0.0, w.contact_offset_y + p.wheel_shift_y, -w.wheel_radius));
  return to_contact_frame(moved, p.contact_angle).real();
}

std::function<Receptance4(cdouble s)> rail_laplace_at_contact(const dynamics::RailModel& rail,
                                                             const ContactPosition& p) {
  const dynamics::RailContact c = rail_contact(rail, p);
  const dynamics::RailModel::LaplaceTransfers at = rail.laplace_transfers({{c, c}});
  const double angle = p.contact_angle;
  return [at, angle](cdouble s) { return to_contact_frame(at(s).front(), angle); };
}

Receptance4 rail_receptance_laplace(const dynamics::RailModel& rail, cdouble s,
                                    const ContactPosition& p) {
  return rail_laplace_at_contact(rail, p)(s);
}

}  // namespace rollnoise::noise
