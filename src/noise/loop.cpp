#include "noise/loop.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "dynamics/rail_model.hpp"

namespace rollnoise::noise {
namespace {

void check_frequency(double f) {
  if (!(f > 0.0) || !std::isfinite(f))
    throw InputError("frequency", "the noise loop needs positive frequencies");
}

}  // namespace

Receptance4 reduce(const Receptance6& a) {
  Receptance4 out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out(i, j) = a(kSixOfFour[i], kSixOfFour[j]);
  return out;
}

Receptance4 to_contact_frame(const Receptance6& a, double gamma) {
  const Eigen::Matrix<cdouble, 6, 4> T = contact_frame(gamma).cast<cdouble>();
  return T.transpose() * a * T;
}

Receptance6 wheelset_centre_receptance(const dynamics::RigidWheelset& w, double frequency) {
  check_frequency(frequency);
  const double omega = dynamics::angular(frequency);
  Receptance6 a = Receptance6::Zero();
  const double inv[6] = {1.0 / w.mass,         1.0 / w.mass,         1.0 / w.mass,
                         1.0 / w.roll_inertia, 1.0 / w.spin_inertia, 1.0 / w.yaw_inertia};
  for (int i = 0; i < 6; ++i) a(i, i) = -inv[i] / (omega * omega);  // free mass: -1/(m omega^2)
  return a;
}

namespace {

// The wheel at the contact point: the rigid wheelset moved from its centre, plus the modal part
// (given at the reference point) moved by the contact's lateral shift.
Receptance6 wheel_receptance6(const dynamics::WheelModel& wheel, double frequency, const Receptance4& modal_at_reference,
                              double shift_y) {
  const dynamics::RigidWheelset& w = wheel.wheelset();
  const Receptance6 rigid =
      move_point(wheelset_centre_receptance(w, frequency),
                 Eigen::Vector3d(0.0, w.contact_offset_y + shift_y, -w.wheel_radius));
  Receptance6 modal = embed(modal_at_reference);
  if (shift_y != 0.0) modal = move_point(modal, Eigen::Vector3d(0.0, shift_y, 0.0));
  return rigid + modal;
}

}  // namespace

Receptance6 wheel_receptance6(const dynamics::WheelModel& wheel, double frequency, double shift_y) {
  return wheel_receptance6(wheel, frequency, wheel.modal_receptance(frequency, shift_y), shift_y);
}

dynamics::RailContact rail_contact(const dynamics::RailModel& rail, const ContactPosition& p) {
  return {rail.position(), p.rail_offset_y, p.contact_angle};
}

Receptance6 rail_receptance6(const dynamics::RailModel& rail, double frequency,
                             const ContactPosition& p) {
  check_frequency(frequency);
  const dynamics::RailContact c = rail_contact(rail, p);
  return rail.contact_transfers({frequency}, {{c, c}}, false).front().front();
}

Receptance4 rail_contact_receptance(const dynamics::RailModel& rail, double frequency,
                                    const ContactPosition& p) {
  return to_contact_frame(rail_receptance6(rail, frequency, p), p.contact_angle);
}

std::vector<Receptance4> rail_contact_receptances(const dynamics::RailModel& rail,
                                                  const std::vector<double>& frequencies,
                                                  const ContactPosition& p) {
  for (double f : frequencies) check_frequency(f);
  const dynamics::RailContact c = rail_contact(rail, p);
  std::vector<Receptance4> out;
  for (const auto& r : rail.contact_transfers(frequencies, {{c, c}}, false))
    out.push_back(to_contact_frame(r.front(), p.contact_angle));
  return out;
}

Receptance6 from_contact_frame(const Receptance4& a, double contact_angle) {
  const Eigen::Matrix<cdouble, 6, 4> T = contact_frame(contact_angle).cast<cdouble>();
  return T * a * T.transpose();
}

StructureSpectra structure_spectra(const dynamics::WheelModel& wheel,
                                   const std::vector<double>& frequencies) {
  StructureSpectra s;
  s.frequency = frequencies;
  for (double f : frequencies) {
    check_frequency(f);
    s.wheel_modal.push_back(wheel.modal_receptance(f));
  }
  return s;
}

StructuralReceptances structural_receptances(const dynamics::WheelModel& wheel,
                                             const dynamics::RailModel& rail,
                                             const StructureSpectra& spectra,
                                             const ContactPosition& position) {
  const dynamics::RailContact c = rail_contact(rail, position);
  const std::vector<std::vector<Receptance6>> at_contact =
      rail.contact_transfers(spectra.frequency, {{c, c}});
  StructuralReceptances s;
  s.frequency = spectra.frequency;
  s.position = position;
  // a wheel that follows the contact (the FE wheel) has its modal part at the contact's position:
  // its modes' table there once, the modal sum per frequency
  const std::vector<dynamics::WheelMode> at =
      wheel.follows_contact() ? wheel.modes_at(position.wheel_shift_y) : std::vector<dynamics::WheelMode>{};
  for (std::size_t k = 0; k < spectra.frequency.size(); ++k) {
    const Receptance4 modal =
        wheel.follows_contact() ? dynamics::modal_sum(at, at, spectra.frequency[k]) : spectra.wheel_modal[k];
    s.wheel.push_back(wheel_receptance6(wheel, spectra.frequency[k], modal, position.wheel_shift_y));
    s.rail.push_back(at_contact[k].front());
    s.wheel_contact.push_back(to_contact_frame(s.wheel.back(), position.contact_angle));
    s.rail_contact.push_back(to_contact_frame(s.rail.back(), position.contact_angle));
  }
  return s;
}

StructuralReceptances structural_receptances(const dynamics::WheelModel& wheel,
                                             const dynamics::RailModel& rail,
                                             const ContactPosition& position,
                                             const std::vector<double>& frequencies) {
  return structural_receptances(wheel, rail, structure_spectra(wheel, frequencies), position);
}

StructuralReceptances structural_receptances(const std::vector<double>& frequencies,
                                             const std::vector<Receptance4>& wheel,
                                             const std::vector<Receptance4>& rail,
                                             double contact_angle) {
  ROLLNOISE_ASSERT(wheel.size() == frequencies.size() && rail.size() == frequencies.size(),
                   "one wheel and one rail receptance per frequency are needed");
  StructuralReceptances s;
  s.frequency = frequencies;
  s.position.contact_angle = contact_angle;
  for (std::size_t k = 0; k < frequencies.size(); ++k) {
    check_frequency(frequencies[k]);
    s.wheel.push_back(embed(wheel[k]));
    s.rail.push_back(embed(rail[k]));
    s.wheel_contact.push_back(to_contact_frame(s.wheel.back(), contact_angle));
    s.rail_contact.push_back(to_contact_frame(s.rail.back(), contact_angle));
  }
  return s;
}

Vector4c solve_contact_forces(const Receptance4& wheel, const Receptance4& rail,
                              const Receptance4& contact, const LoopOptions& options) {
  Vector4c F = Vector4c::Zero();
  if (options.coupling == Coupling::kVerticalOnly) {
    // The classic vertical loop: Fz = -r / (alpha_w + alpha_r + alpha_c)_zz.
    F(0) = -options.roughness / (wheel(0, 0) + rail(0, 0) + contact(0, 0));
    return F;
  }
  const Receptance4 A = wheel + rail + contact;
  // Diagonal equilibration D A D (D_i = |A_ii|^{-1/2}): the entries mix m/N, rad/N and
  // rad/(N m) over several decades; the scaled system is solved by a pivoted LU.
  Eigen::Vector4d d;
  for (int i = 0; i < 4; ++i) {
    const double m = std::abs(A(i, i));
    d(i) = m > 0.0 && std::isfinite(m) ? 1.0 / std::sqrt(m) : 1.0;
  }
  const Receptance4 As = d.cast<cdouble>().asDiagonal() * A * d.cast<cdouble>().asDiagonal();
  Vector4c rhs = Vector4c::Zero();
  rhs(0) = -options.roughness * d(0);
  const Eigen::FullPivLU<Receptance4> lu(As);
  if (!lu.isInvertible() || !As.allFinite()) {
    std::ostringstream s;
    s << "noise loop: the total receptance matrix is singular or not finite:\n" << A;
    throw NumericalError(s.str());
  }
  F = d.cast<cdouble>().asDiagonal() * lu.solve(rhs);
  return F;
}

LoopResult solve_loop(const StructuralReceptances& s, const std::vector<Receptance4>& contact,
                      const LoopOptions& options) {
  const std::size_t n = s.frequency.size();
  ROLLNOISE_ASSERT(contact.size() == n, "noise loop: one contact receptance per frequency is needed");
  const Eigen::Matrix<cdouble, 6, 4> T = contact_frame(s.position.contact_angle).cast<cdouble>();
  LoopResult r;
  r.frequency = s.frequency;
  r.force.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vector4c F =
        solve_contact_forces(s.wheel_contact[k], s.rail_contact[k], contact[k], options);
    r.force.push_back(F);
    if (!options.velocities) continue;
    const cdouble iw(0.0, dynamics::angular(s.frequency[k]));
    const Eigen::Matrix<cdouble, 6, 1> load = T * F;  // global force and moment on the wheel
    const Eigen::Matrix<cdouble, 6, 1> vw = iw * (s.wheel[k] * load);
    const Eigen::Matrix<cdouble, 6, 1> vr = iw * (s.rail[k] * (-load));
    Vector4c w4, r4;
    for (int i = 0; i < 4; ++i) {
      w4(i) = vw(kSixOfFour[i]);
      r4(i) = vr(kSixOfFour[i]);
    }
    r.wheel_velocity.push_back(w4);
    r.rail_velocity.push_back(r4);
  }
  return r;
}

}  // namespace rollnoise::noise
