// The FE wheel (wheel_fe.hpp) at its contacts: the mode shapes at a contact's actual position s on
// the tread resolved into that contact's frame, the point and cross receptances of contacts on the
// same wheel, modal damping by family, the +-n Omega split of a rotating wheel, and the
// contact-point mode table of WheelModel (wheel.hpp) (docs/models.md Sec. 3.4).
//
// Frame. A contact at the bottom of the wheel (theta = 0) at lateral position s on the tread (m,
// the section's z, positive towards the field side = +y for a wheel at +y). The wheel's cylindrical
// frame (r, theta, axial) is right-handed about +y, so at the bottom e_r = -z, e_theta = -x,
// e_axial = +y (x forward, y lateral, z up). Per mode of order n with tread shape (U_r, U_theta,
// U_z) at s and tread radius r(s), the two partners of the pair at theta = 0 are
//   cos set (W1):               (x, y, z) = (0, U_z, -U_r),   rot z = 0
//   sin set (W1 turned by pi/2n, u_r = U_r sin, u_theta = -U_theta cos, u_z = U_z sin):
//                               (x, y, z) = (U_theta, 0, 0),  rot z = du_y/dx = -(1/r) du_z/dtheta
//                                                                    = -n U_z / r
// (n = 0: one mode, (x, y, z) = (-U_theta, U_z, -U_r)). Rotations about x and y are not taken from
// the modes (the table's convention, Sec. 3.2). The contact frame of contact angle gamma is that of
// noise/loop.hpp: n = (0, -sin g, cos g), t_x = x, t_y = (0, cos g, sin g), spin about n:
//   psi = (n, x, y, rot n) = (-sin g u_y + cos g u_z, u_x, cos g u_y + sin g u_z, cos g rot_z).
//
// Receptance (unit modal masses, mass-normalised shapes), response at contact a, force at b:
//   H_ab(omega) = sum_modes sum_sets psi_a psi_b^T R_k(omega),
//   R_k = 1 / (omega_k^2 - omega^2 + 2 i zeta_k omega_k omega).
// Rotation (Thompson, Railway Noise and Vibration, 2009, Ch. 5; Thompson & Jones, JSV 231 (2000)
// 519-536): a wheel spinning at Omega = V / r0 carries each n >= 1 pair as a forward and a
// backward travelling wave; the fixed contact sees them at omega_k +- n Omega, each with half the
// pair's participation:
//   R_k -> (R(omega_k + n Omega) + R(omega_k - n Omega)) / 2   (Coriolis terms neglected).
// The exact fixed-frame response also carries an antisymmetric coupling i/2 (psi_c psi_s^T - psi_s
// psi_c^T)(R_+ - R_-) between the cos-set and sin-set components (rotation breaks reciprocity); it
// is omitted here, so the split receptance stays symmetric (documented in docs/models.md Sec. 3.4).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/receptance.hpp"
#include "dynamics/wheel.hpp"

namespace rollnoise::dynamics {

struct WheelFeModes;
struct WheelFeMode;
enum class ModeFamily;

/// Modal damping ratios: by n for n = 0, 1 and by family for n >= 2. Defaults: Thompson's typical
/// values for solid wheels (Railway Noise and Vibration, 2009, Ch. 5), those of the mode table
/// (docs/models.md Sec. 3.2).
struct WheelModalDamping {
  double n0 = 1e-3;               ///< n = 0
  double n1 = 1e-2;               ///< n = 1 (axle coupling)
  double axial = 1e-4;            ///< n >= 2, axial family
  double radial = 1e-4;           ///< n >= 2, radial family
  double circumferential = 1e-4;  ///< n >= 2, circumferential family
  double ratio(int n, ModeFamily family) const;
  /// The mode's own ratio when it has one (an imported mode), else ratio(n, family).
  double ratio(const WheelFeMode& mode) const;
};

/// How the FE modes enter a contact receptance.
struct WheelFeContactOptions {
  int n_min = 2;  ///< lowest order kept (2: n = 0, 1 from the rigid wheelset)
  WheelModalDamping damping;
  double spin_speed = 0.0;  ///< Omega (rad/s) of the +-n Omega split; 0: the wheel at rest
};

/// A contact on the wheel's running surface: lateral position s (m) and contact angle gamma (rad).
struct TreadContact {
  double s = 0.0;
  double contact_angle = 0.0;
};

/// Radius of the tread at s (linear between samples); throws InputError off the tread.
double tread_radius_at(const WheelFeModes& w, double s);

/// The shapes of one mode at a contact, in its frame (n, x, y, rot n): the cos set and the sin set
/// (zero for n = 0).
struct ContactShapes {
  Eigen::Vector4d cos_set = Eigen::Vector4d::Zero();
  Eigen::Vector4d sin_set = Eigen::Vector4d::Zero();
};
ContactShapes contact_shapes(const WheelFeModes& w, const WheelFeMode& mode, const TreadContact& c);

/// The flexible wheel's receptance between two contacts of the same wheel: the response at `a` (in
/// a's frame) to a unit force or moment at `b` (in b's frame), m/N, rad/N, m/(N m), rad/(N m).
/// a == b gives the point receptance. Reciprocal: H_ab = H_ba^T.
Receptance4 fe_cross_receptance(const WheelFeModes& w, const WheelFeContactOptions& options,
                                const TreadContact& a, const TreadContact& b, double frequency);

/// The FE modes with n >= n_min as the contact-point mode table of WheelModel (wheel.hpp) at
/// lateral position s, contact angle 0 (the table's z, x, y, rot z): per mode the cos partner and,
/// for n >= 1, the sin partner; with a spin speed each n >= 1 partner becomes two entries at
/// f +- n Omega / 2 pi with shapes / sqrt 2. Modal mass 1 kg (mass-normalised shapes).
std::vector<WheelMode> contact_mode_table(const WheelFeModes& w, double s,
                                          const WheelFeContactOptions& options = {});

/// The modes' participation at the contacts of one wheel, for the wheel's modal response to the
/// loop's contact forces (the sound power, docs/sound.md Sec. 2): for every mode with n >= n_min,
/// the rows psi^T of its cos set and its sin set at each contact (4 columns per contact, its frame),
/// so that the modal coordinates under forces F (4 per contact, on the wheel) are
///   q_cos = R_k(omega) psi_cos^T F,   q_sin = R_k(omega) psi_sin^T F                      (W2)
/// with R_k of the header (unit modal masses; the +-n Omega split as in the receptance). The
/// wheel's displacement field is then sum_k q_cos,k Phi_k cos(n theta) + q_sin,k Phi_k sin(n theta)
/// (Phi_k the mode's section shape, wheel_fe.hpp): the rotating wheel's fixed-frame response as
/// fe_cross_receptance has it (the antisymmetric Coriolis coupling left out there too).
struct ModalParticipation {
  std::vector<int> modes;    ///< index into WheelFeModes::modes
  Eigen::MatrixXd cos_set;   ///< modes x 4 contacts: psi^T of each mode's cos set
  Eigen::MatrixXd sin_set;   ///< the same for the sin sets (zero rows for n = 0)
  std::vector<double> omega; ///< omega_k (rad/s)
  std::vector<double> zeta;  ///< damping ratio
  std::vector<int> n;        ///< nodal diameters
  double spin_speed = 0.0;   ///< Omega (rad/s)
};
ModalParticipation modal_participation(const WheelFeModes& w, const WheelFeContactOptions& options,
                                       const std::vector<TreadContact>& contacts);
/// R_k(omega) of every mode of `p` at `frequency` (Hz), unit modal mass (m/N per unit modal force).
Eigen::VectorXcd modal_responses(const ModalParticipation& p, double frequency);

}  // namespace rollnoise::dynamics
