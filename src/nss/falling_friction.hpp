// Falling friction in full slip: the point-contact (rigid) limit of the creep coefficients and the
// classical single-mode squeal criterion (docs/falling_friction.md, Sec. 4).
//
// Full slip, rigid bodies: F = -mu(v) N s^, v = V |xi| the slip speed, s^ = xi/|xi| (xi = (xi_x,
// xi_y), no spin). With the paper's F~ = -f xi~ (Eqs. 28-30), f = -dF/dxi:
//   f = N [ V mu'(v) s^ s^' + (mu(v)/|xi|) t t' ],   t perpendicular to s^,                  (S1)
// along the slip direction f_par = N V mu'(v) (< 0 for falling friction: negative damping),
// across it N mu(v)/|xi| (the rotation of the force, paper Eq. 9). The NSS model's f tends to (S1)
// at low frequency in full slip up to the elastic slip of the patch (second order at w = 0, see
// docs/falling_friction.md; tests/nss/falling_friction_test.cpp measures it).
//
// One wheel mode (modal mass m, natural frequency w_n, damping ratio zeta, mode shape psi at the
// contact in the slip direction) on a rigid rail: the wheel velocity psi q' adds psi q'/V to the
// creepage, the force -f_par psi q'/V acts on the mode, so
//   m q'' + (2 zeta w_n m + f_par psi^2 / V) q' + m w_n^2 q = 0,
// unstable when 2 zeta w_n m + f_par psi^2/V < 0; with (S1): 2 zeta w_n m + N mu'(v) psi^2 < 0,
// i.e. zeta < zeta_crit = -N mu'(v) psi^2 / (2 m w_n).                                      (S2)
// With a frequency-dependent f_par(w) (the NSS model) Re f_par(w_n) takes its place (Im f_par
// shifts the frequency).
#pragma once

#include <Eigen/Dense>

#include "contact/friction_law.hpp"

namespace rollnoise::nss {

/// (S1): the 2 x 2 (xi_x, xi_y) creep coefficients (N) of a rigid point contact in full slip at
/// the creepage (xi_x, xi_y) != 0, normal load N (N), speed V (m/s).
Eigen::Matrix2d full_slip_creep_coefficients(double normal_force, double speed, double xi_x, double xi_y,
                                             const contact::FrictionLaw& law);

/// (S2): the modal damping ratio below which one mode goes unstable, from the along-slip creep
/// coefficient f_par (N; e.g. N V mu'(v) or Re f_par(w_n)), speed V (m/s), mode shape psi at the
/// contact (1/sqrt(kg) for mass-normalised modes with modal_mass 1), modal mass (kg) and natural
/// frequency w_n (rad/s). Negative (never unstable) when f_par > 0.
double critical_damping_ratio(double along_slip_coefficient, double speed, double psi, double modal_mass,
                              double omega_n);

}  // namespace rollnoise::nss
