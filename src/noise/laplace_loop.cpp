// The loop at complex s (stability.hpp, (S1)): the wheels' modes and the rigid wheelsets in the
// contact frames, the rails at complex s, the contacts' f(s), g(s), and
// A(s) = R(s) + sum_k Psi_k Psi_k^T / (m_k D_k(s)).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "dynamics/rail_model.hpp"
#include "noise/stability.hpp"

namespace rollnoise::noise {
namespace {

// The wheel's mode k at contact c in its frame: T^T L(0, shift, 0) (phi_x, phi_y, phi_z, 0, 0,
// phi_rz) (the vector form of the rank-one modal term of loop.hpp's wheel_receptance6).
Eigen::Vector4d contact_shape(const dynamics::WheelMode& mode, const ContactPoint& c) {
  Eigen::Matrix<double, 6, 1> phi = Eigen::Matrix<double, 6, 1>::Zero();
  for (int i = 0; i < 4; ++i) phi(kSixOfFour[i]) = mode.shape(i);
  // the lever arm (L2) on the shape: u' = u + th x d, d = (0, shift, 0)
  const Eigen::Vector3d th = phi.tail<3>(), d(0.0, c.position.wheel_shift_y, 0.0);
  phi.head<3>() += th.cross(d);
  return contact_frame(c.position.contact_angle).transpose() * phi;
}

}  // namespace

Eigen::MatrixXcd LaplaceLoop::matrix(cdouble s) const {
  Eigen::MatrixXcd a = rest(s);
  for (const LoopMode& m : modes)
    a += (m.shape * m.shape.transpose()).cast<cdouble>() / modal_denominator(m, s);
  return a;
}

LaplaceLoop LaplaceLoop::one_contact(std::vector<LoopMode> modes,
                                     std::function<Eigen::MatrixXcd(cdouble s)> rest) {
  LaplaceLoop loop;
  for (LoopMode& m : modes) {
    ROLLNOISE_ASSERT(m.shape.size() == 4, "a loop of one contact needs 4-vector mode shapes");
    m.wheel = 0;
  }
  loop.modes = std::move(modes);
  loop.wheels = {{0, 1}};
  loop.contact_wheel = {0};
  loop.rest = std::move(rest);
  return loop;
}

LoopModes loop_modes(const dynamics::WheelModel& wheel, const std::vector<ContactPoint>& points) {
  const Eigen::Index n = static_cast<Eigen::Index>(points.size());
  LoopModes out;
  for (const ContactPoint& p : points) {
    const std::pair<int, int> w{p.wheelset, p.side};
    auto it = std::find(out.wheels.begin(), out.wheels.end(), w);
    out.contact_wheel.push_back(static_cast<int>(it - out.wheels.begin()));
    if (it == out.wheels.end()) out.wheels.push_back(w);
  }
  // each contact's mode shapes at its own position on the tread (the FE wheel follows the contact;
  // the table wheel has one table): the same frequencies and damping at every position
  std::vector<std::vector<dynamics::WheelMode>> at_contact;
  for (const ContactPoint& p : points)
    at_contact.push_back(wheel.modes_at(p.position.wheel_shift_y));
  for (std::size_t w = 0; w < out.wheels.size(); ++w)
    for (std::size_t k = 0; k < wheel.modes().size(); ++k) {
      const dynamics::WheelMode& wm = wheel.modes()[k];
      LoopMode m{wm.frequency,       wm.damping_ratio,
                 wm.modal_mass,      Eigen::VectorXd::Zero(4 * n),
                 wm.label,           k,
                 static_cast<int>(w)};
      for (Eigen::Index a = 0; a < n; ++a)
        if (out.contact_wheel[a] == static_cast<int>(w))
          m.shape.segment<4>(4 * a) = contact_shape(at_contact[a][k], points[a]);
      out.modes.push_back(m);
    }
  return out;
}

Eigen::MatrixXd rigid_flexibility(const dynamics::RigidWheelset& ws,
                                  const std::vector<ContactPoint>& points,
                                  const CrossCoupling& cross) {
  return contact_frame_blocks(points,
                              [&](Eigen::Index a, Eigen::Index b) -> Receptance6 {
                                if (a != b && !cross.wheelset) return Receptance6::Zero();
                                return rigid_flexibility6(ws, points[a], points[b]).cast<cdouble>();
                              })
      .real();
}

LaplaceLoop laplace_loop(const dynamics::WheelModel& wheel, const dynamics::RailModel& rail,
                         const std::vector<SquealContact>& contacts, double speed,
                         bool normal_coupling, const CrossCoupling& cross) {
  const Eigen::Index n = static_cast<Eigen::Index>(contacts.size());
  if (n == 0) throw InputError("contacts", "squeal needs at least one contact");
  std::vector<ContactPoint> points;
  for (const SquealContact& c : contacts) {
    if (!c.transfer)
      throw InputError("contacts", "squeal: every contact needs its contact transfer");
    points.push_back(c.point);
  }
  validate_contacts(points);
  LoopModes m = loop_modes(wheel, points);
  LaplaceLoop loop;
  loop.modes = std::move(m.modes);
  loop.wheels = std::move(m.wheels);
  loop.contact_wheel = std::move(m.contact_wheel);
  // The rigid wheelsets' flexibility in the contact frames (constant: alpha = C / s^2).
  const Eigen::MatrixXcd C = rigid_flexibility(wheel.wheelset(), points, cross).cast<cdouble>();
  // the rails between the contact points as a function of s, set up once
  // (RailModel::laplace_transfers; alpha_ba = alpha_ab^T)
  const ContactSetRailPairs pairs = contact_set_rail_pairs(points, cross);
  const dynamics::RailModel::LaplaceTransfers rail_at = rail.laplace_transfers(pairs.points);
  loop.rest = [=](cdouble s) -> Eigen::MatrixXcd {
    Eigen::MatrixXcd A = C / (s * s);
    const std::vector<Receptance6> r = rail_at(s);
    std::vector<Receptance6> block(static_cast<std::size_t>(n * n), Receptance6::Zero());
    for (std::size_t p = 0; p < pairs.index.size(); ++p) {
      const auto [a, b] = pairs.index[p];
      block[a * n + b] = r[p];
      if (b != a) block[b * n + a] = r[p].transpose();
    }
    A += contact_frame_blocks(points,
                              [&](Eigen::Index a, Eigen::Index b) { return block[a * n + b]; });
    for (Eigen::Index a = 0; a < n; ++a) {
      const ContactTransfer& t = *contacts[a].transfer;
      const auto [f, g] = normal_coupling
                              ? t.creep_and_load(s)
                              : std::make_pair(t.creep(s), Eigen::Vector3cd::Zero().eval());
      A.block<4, 4>(4 * a, 4 * a) +=
          contact_receptance_laplace(s, contacts[a].normal_stiffness, speed, f, g);
    }
    return A;
  };
  return loop;
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
