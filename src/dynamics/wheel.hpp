// Wheel model: a rigid wheelset plus the flexible modes of the wheel, as receptances at the
// wheel/rail contact point (Thompson, Railway Noise and Vibration, 2009, chapter on wheel
// vibration; Thompson, JSV 161, 1993, "Wheel-rail noise generation, part II: wheel vibration").
//
// Flexible modes n with natural frequency omega_n, damping ratio zeta_n, modal mass m_n and mode
// shape phi_n at the contact point (one entry per contact degree of freedom z, x, y, rot z; the
// normalisation is free as long as m_n matches it):
//
//   H_jk(omega) = sum_n phi_{j,n} phi_{k,n} / ( m_n (omega_n^2 - omega^2 + 2 i zeta_n omega_n
//   omega) ).
//
// Rigid wheelset: mass M and principal moments of inertia J = diag(I_xx roll, I_yy spin about the
// axle, I_zz yaw) about its centre, contact point at r = (0, y_c, -R) from the centre (x forward,
// y lateral towards this wheel, z up, R the rolling radius). A force F and moment M at the contact
// give, with S the cross-product matrix of r (S v = r x v) and the free-body accelerations
// -omega^2 (u, theta),
//
//   theta = -(1/omega^2) J^{-1} (S F + M),   u_contact = u_centre + theta x r
//         = -(1/omega^2) [ (1/M - S J^{-1} S) F - S J^{-1} M ],
//
// a symmetric 6x6 receptance of which the rows and columns z, x, y, rot z are kept. The mass-line
// asymptote of the translational receptances is -1/(M_eff omega^2); vertically the roll adds to the
// bounce (M_eff = M / (1 + M y_c^2 / I_xx), about half the wheelset mass for I_xx ~ M y_c^2).
// The wheel's rotation about the axle is free (no drive or brake torque).
//
// The wheelset parameter file and the mode table are read by io/wheel_file.hpp.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <future>
#include <string>
#include <vector>

#include "dynamics/receptance.hpp"

namespace rollnoise::dynamics {

/// One flexible mode of the wheel.
struct WheelMode {
  double frequency = 0.0;      ///< natural frequency (Hz)
  double damping_ratio = 0.0;  ///< zeta (-)
  double modal_mass = 0.0;     ///< m_n for the normalisation of `shape` (kg)
  Eigen::Vector4d shape =
      Eigen::Vector4d::Zero();  ///< phi at the contact: z, x, y (-), rot z (1/m)
  std::string label;            ///< e.g. "axial n=2"
};

/// The rigid wheelset.
struct RigidWheelset {
  double mass = 0.0;              ///< M (kg)
  double roll_inertia = 0.0;      ///< I_xx about the longitudinal axis (kg m^2)
  double spin_inertia = 0.0;      ///< I_yy about the axle (kg m^2)
  double yaw_inertia = 0.0;       ///< I_zz about the vertical axis (kg m^2)
  double contact_offset_y = 0.0;  ///< y_c, lateral position of the contact from the centre (m)
  double wheel_radius = 0.0;      ///< R (m)

  void validate(const std::string& prefix) const;

  /// The 4x4 rigid-body receptance at the contact point (z, x, y, rot z); omega > 0.
  Receptance4 receptance(double frequency) const;
};

/// The fields of a mode as named in messages: the columns of a mode table (io/wheel_file.hpp).
inline constexpr const char* kWheelModeFields[7] = {
    "frequency_Hz", "damping_ratio", "modal_mass_kg", "phi_z", "phi_x", "phi_y", "phi_rz"};

/// Checks the values of one mode; throws InputError(`where`:field, ...).
void validate_mode(const WheelMode& mode, const std::string& where);

/// The modal sum between two points from the tables of the same modes at each (as
/// WheelModel::modes_at gives them): sum_k phi_k(a) phi_k(b)^T / (m_k (w_k^2 - w^2 + 2 i zeta_k w_k
/// w)); `at_a` = `at_b` gives the point receptance. The contact set builds the tables once per
/// contact and sums them per frequency (noise/contact_set.hpp).
Receptance4 modal_sum(const std::vector<WheelMode>& at_a, const std::vector<WheelMode>& at_b,
                      double frequency);

/// Rigid wheelset plus flexible modes.
class WheelModel {
 public:
  WheelModel(const RigidWheelset& wheelset, std::vector<WheelMode> modes);

  /// Rigid + modal receptance at the contact point.
  Receptance4 receptance(double frequency) const;

  /// The modal sum alone.
  Receptance4 modal_receptance(double frequency) const;

  /// A wheel whose mode shapes are known along the tread (the FE wheel, wheel_fe_contact.hpp):
  /// `along_tread(shift_y)` gives the table at the contact shifted by shift_y (m) from the reference
  /// point (same modes, same order as `modes`, the shapes at the shifted point).
  using ModesAlongTread = std::function<std::vector<WheelMode>(double shift_y)>;
  WheelModel(const RigidWheelset& wheelset, std::vector<WheelMode> modes, ModesAlongTread along_tread);
  /// The same with the table at the reference point arriving later: `later` is being computed on
  /// another thread (the FE wheel's modes while the case's contact is solved, io/wheel_fe_case.hpp)
  /// and is waited for, and its modes checked, at the first use of the modes (modes(), the
  /// receptances, modes_at); an error of its computation is thrown there.
  WheelModel(const RigidWheelset& wheelset, std::shared_future<std::vector<WheelMode>> later,
             ModesAlongTread along_tread);
  bool follows_contact() const { return static_cast<bool>(along_tread_); }

  /// The table for a contact shifted by shift_y, in the form the loop expects (noise/loop.hpp moves
  /// the modal part from the reference point by the lever arm (0, shift_y, 0), u_x -> u_x - shift_y
  /// rot_z): for a wheel that follows the contact the shapes at the contact itself with
  /// phi_x + shift_y phi_rz, so that the lever arm gives back the shape at the contact; otherwise
  /// `modes()` (the reference-point table moved as a rigid rim).
  std::vector<WheelMode> modes_at(double shift_y) const;
  /// The modal sum of modes_at(shift_y).
  Receptance4 modal_receptance(double frequency, double shift_y) const;
  /// The modal sum between two contacts of the same wheel, shifted by shift_a and shift_b:
  /// sum_k phi_k(shift_a) phi_k(shift_b)^T / (m_k (w_k^2 - w^2 + 2 i zeta_k w_k w)) with the tables
  /// of modes_at (response at a to a force at b; shift_a = shift_b gives modal_receptance).
  Receptance4 modal_cross_receptance(double frequency, double shift_a, double shift_b) const;

  const RigidWheelset& wheelset() const { return wheelset_; }
  const std::vector<WheelMode>& modes() const { return modes_.get(); }

 private:
  RigidWheelset wheelset_;
  std::shared_future<std::vector<WheelMode>> modes_;  // ready, or computed later (see above)
  ModesAlongTread along_tread_;
};

}  // namespace rollnoise::dynamics
