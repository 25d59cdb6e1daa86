#include "dynamics/wheel.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "dynamics/rail_contact.hpp"  // the 6-dof order kSixOfFour, the lever arm cross_matrix

namespace rollnoise::dynamics {

// ---------------------------------------------------------------------------------------------
// Rigid wheelset
// ---------------------------------------------------------------------------------------------

void RigidWheelset::validate(const std::string& prefix) const {
  auto positive = [&](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw InputError(prefix + "." + name,
                       prefix + "." + name + " must be positive, got " + std::to_string(v));
  };
  positive(mass, "mass");
  positive(roll_inertia, "roll_inertia");
  positive(spin_inertia, "spin_inertia");
  positive(yaw_inertia, "yaw_inertia");
  positive(wheel_radius, "wheel_radius");
  if (!std::isfinite(contact_offset_y))
    throw InputError(prefix + ".contact_offset_y", prefix + ".contact_offset_y must be finite");
}

Receptance4 RigidWheelset::receptance(double frequency) const {
  const double omega = angular(frequency);
  if (!(omega > 0.0))
    throw InputError("frequency", "rigid wheelset receptance needs a positive frequency");
  const Eigen::Vector3d r(0.0, contact_offset_y, -wheel_radius);
  const Eigen::Matrix3d S = cross_matrix(r);
  const Eigen::Matrix3d Jinv =
      Eigen::Vector3d(1.0 / roll_inertia, 1.0 / spin_inertia, 1.0 / yaw_inertia).asDiagonal();
  Eigen::Matrix<double, 6, 6> C;  // -omega^2 times the receptance
  C.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() / mass - S * Jinv * S;
  C.topRightCorner<3, 3>() = -S * Jinv;
  C.bottomLeftCorner<3, 3>() = Jinv * S;
  C.bottomRightCorner<3, 3>() = Jinv;
  Receptance4 R;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) R(i, j) = -C(kSixOfFour[i], kSixOfFour[j]) / (omega * omega);
  return R;
}

// ---------------------------------------------------------------------------------------------
// Modes
// ---------------------------------------------------------------------------------------------

void validate_mode(const WheelMode& m, const std::string& where) {
  auto fail = [&](const char* field, const std::string& why) {
    throw InputError(where + ":" + field, where + ": field '" + field + "' " + why);
  };
  if (!std::isfinite(m.frequency) || !(m.frequency > 0.0))
    fail("frequency_Hz", "must be a positive frequency, got " + std::to_string(m.frequency));
  if (!std::isfinite(m.damping_ratio) || m.damping_ratio < 0.0 || m.damping_ratio >= 1.0)
    fail("damping_ratio", "must be in [0, 1), got " + std::to_string(m.damping_ratio));
  if (!std::isfinite(m.modal_mass) || !(m.modal_mass > 0.0))
    fail("modal_mass_kg", "must be positive, got " + std::to_string(m.modal_mass));
  for (int j = 0; j < 4; ++j)
    if (!std::isfinite(m.shape[j])) fail(kWheelModeFields[3 + j], "must be a finite number");
  if (m.shape.cwiseAbs().maxCoeff() == 0.0)
    fail("phi_z", "and phi_x, phi_y, phi_rz are all zero: the mode is not excited at the contact");
}

// ---------------------------------------------------------------------------------------------
// Wheel model
// ---------------------------------------------------------------------------------------------

namespace {

void validate_modes(const std::vector<WheelMode>& modes) {
  for (std::size_t n = 0; n < modes.size(); ++n)
    validate_mode(modes[n], "wheel.modes[" + std::to_string(n) + "]");
}

}  // namespace

WheelModel::WheelModel(const RigidWheelset& wheelset, std::vector<WheelMode> modes)
    : wheelset_(wheelset) {
  wheelset_.validate("wheelset");
  validate_modes(modes);
  std::promise<std::vector<WheelMode>> ready;
  ready.set_value(std::move(modes));
  modes_ = ready.get_future().share();
}

WheelModel::WheelModel(const RigidWheelset& wheelset, std::vector<WheelMode> modes, ModesAlongTread along_tread)
    : WheelModel(wheelset, std::move(modes)) {
  along_tread_ = std::move(along_tread);
}

WheelModel::WheelModel(const RigidWheelset& wheelset,
                       std::shared_future<std::vector<WheelMode>> later,
                       ModesAlongTread along_tread)
    : wheelset_(wheelset), along_tread_(std::move(along_tread)) {
  wheelset_.validate("wheelset");
  // deferred: run once, by the first thread that asks for the modes (the others wait for it)
  modes_ = std::async(std::launch::deferred, [later = std::move(later)] {
             std::vector<WheelMode> modes = later.get();
             validate_modes(modes);
             return modes;
           }).share();
}

std::vector<WheelMode> WheelModel::modes_at(double shift_y) const {
  if (!along_tread_ || shift_y == 0.0) return modes();
  std::vector<WheelMode> at = along_tread_(shift_y);
  if (at.size() != modes().size())
    throw NumericalError("the wheel's mode table along the tread changed its size");
  for (WheelMode& m : at) m.shape(1) += shift_y * m.shape(3);  // undone by the loop's lever arm
  return at;
}

// sum_k phi_k(a) phi_k(b)^T / (m_k (omega_k^2 - omega^2 + 2 i zeta_k omega_k omega)): the response
// at a to a force at b; `a` and `b` hold the same modes (frequency, damping, mass) in the same order,
// their shapes at the two points (a == b: the point receptance).
Receptance4 modal_sum(const std::vector<WheelMode>& a, const std::vector<WheelMode>& b,
                      double frequency) {
  ROLLNOISE_ASSERT(a.size() == b.size(), "the same modes at both points");
  const double omega = angular(frequency);
  Receptance4 H = Receptance4::Zero();
  for (std::size_t k = 0; k < a.size(); ++k) {
    const WheelMode& m = a[k];
    const double wn = angular(m.frequency);
    // 1 / (m d), d = wn^2 - w^2 + 2 i zeta wn w, as conj(d) / (m |d|^2): the library's complex
    // division guards against overflow and NaN (C99 Annex G), which these finite values never need.
    const double re = wn * wn - omega * omega, im = 2.0 * m.damping_ratio * wn * omega;
    const double s = 1.0 / (m.modal_mass * (re * re + im * im));
    const cdouble q(re * s, -im * s);
    H += (m.shape * b[k].shape.transpose()).cast<cdouble>() * q;
  }
  return H;
}

Receptance4 WheelModel::modal_receptance(double frequency) const {
  const std::vector<WheelMode>& modes = this->modes();
  return modal_sum(modes, modes, frequency);
}

Receptance4 WheelModel::modal_receptance(double frequency, double shift_y) const {
  const std::vector<WheelMode> at = modes_at(shift_y);
  return modal_sum(at, at, frequency);
}

Receptance4 WheelModel::modal_cross_receptance(double frequency, double shift_a,
                                               double shift_b) const {
  return modal_sum(modes_at(shift_a), modes_at(shift_b), frequency);
}

Receptance4 WheelModel::receptance(double frequency) const {
  return wheelset_.receptance(frequency) + modal_receptance(frequency);
}

}  // namespace rollnoise::dynamics
