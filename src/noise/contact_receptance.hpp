// The contact receptance of the rolling-noise loop (docs/noise_loop.md; docs/noise_loop.md
// Sec. 2): a 4x4 complex matrix in the contact frame, order (n, x, y, rotation about n) =
// (z, x, y, rot z) of dynamics::Receptance4 when the contact angle is zero.
//
// Sign convention. F is the contact force on the wheel (Fz up = compressive increment; Fx, Fy, Mz
// the tangential force and spin moment on the wheel, as in the creep law F = -f xi of the contact
// model). The contact is a spring element between the wheel and the rail; its extension is the
// displacement of the wheel's contact point relative to the rail's, e = u_wheel - u_rail, and
//
//   e = -alpha_c F - r e_z                                                                  (C1)
//
// (r the roughness, see loop.hpp for its sign), i.e. alpha_c is a compliance with the usual sign
// (a static spring has alpha_c = 1/k > 0).
//
//  * Normal: the linearised Hertz spring, alpha_c,zz = 1/k_H, k_H = dN/d(approach) = 3N/(2 delta)
//    (contact::HertzContact::normal_stiffness(); Johnson 1985, Ch. 4).
//  * Tangential and spin: a creepage variation is the relative velocity of the contact points over
//    the rolling speed, xi~ = (xi_x, xi_y, phi)~ = i omega (e_x, e_y, e_rotz) / V. With the creep
//    law F~t = -f(omega) xi~ (rows Fx, Fy, Mz; columns xi_x, xi_y, phi):
//
//      F~t = -(i omega / V) f e_t   =>   e_t = -(V / (i omega)) f^{-1} F~t,
//      alpha_c,t = (V / (i omega)) f(omega)^{-1}          (3x3 block for x, y, rot z)        (C2)
//
//    Kalker's steady coefficients (real f) make alpha_c,t a pure damper (creep damping f/V); the
//    linear NSS model adds the elasticity of the contact, |f| ~ 1/omega at high frequency, so that
//    alpha_c,t tends to a spring.
//  * Normal -> tangential coupling (friction). The linear contact model may also respond to the
//    normal-load variation N~: F~t = -f(omega) xi~ + g(omega) N~ (nss::LinearContactModel::
//    normal_load_coefficients; g = (g_x, g_y, g_z) in (-, -, m)). N~ is the normal contact force
//    variation, compressive positive, which is Fz of this file (the force on the wheel, up =
//    compressive increment): N~ = Fz. With xi~ = (i omega / V) e_t,
//
//      F~t = -(i omega / V) f e_t + g Fz   =>   e_t = -(V / (i omega)) f^{-1} F~t
//                                                      + (V / (i omega)) f^{-1} g Fz,
//      and with (C1), e_t = -alpha_c,tt F~t - alpha_c,tn Fz:
//      alpha_c,tn = -(V / (i omega)) f^{-1} g = -alpha_c,tt g   (3x1 block: rows x, y, rot z;
//                                                                   column n)            (C3)
//
//    alpha_c,nt stays 0 (the tangential forces do not change the normal approach: quasi-identical
//    bodies), so alpha_c is not symmetric when g != 0 (no reciprocity: friction is not a
//    potential force). g = 0 gives (C2) exactly. In a saturated contact at low frequency
//    g ~ F_mean / N_mean and f is small (the tangential contact is nearly free), so the loop gives
//    F~t ~ g Fz: the tangential forces follow the mu-scaled normal force (docs/noise_loop.md
//    Sec. 2.1).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "dynamics/receptance.hpp"

namespace rollnoise::noise {

using dynamics::cdouble;
using dynamics::Receptance4;

/// Creep coefficients f(omega), F~ = -f xi~, rows Fx, Fy, Mz, columns xi_x, xi_y, phi; the
/// argument is the frequency in Hz. The NSS model or Kalker's steady theory plug in here.
using CreepFunction = std::function<Eigen::Matrix3cd(double frequency_hz)>;

/// Normal-load coefficients g = (g_x, g_y, g_z) (-, -, m): F~t = -f xi~ + g Fz (Eq. C3).
using LoadCoefficients = Eigen::Vector3cd;

/// alpha_c (Eqs. C1-C2) at one frequency (Hz, > 0), for the normal stiffness k_H (N/m), the
/// rolling speed V (m/s) and the creep matrix f at that frequency. NumericalError if f is singular.
Receptance4 contact_receptance(double frequency, double normal_stiffness, double speed,
                               const Eigen::Matrix3cd& creep);

/// alpha_c with the normal -> tangential coupling g (Eqs. C1-C3); g = 0 gives the overload above.
Receptance4 contact_receptance(double frequency, double normal_stiffness, double speed,
                               const Eigen::Matrix3cd& creep, const LoadCoefficients& load);

/// alpha_c (C1-C3) at the Laplace variable s = sigma + i omega (1/s, s != 0): i omega -> s in (C2),
/// alpha_c,t = (V/s) f^{-1}, with f and g evaluated at s by the caller (docs/squeal.md Sec. 2).
/// contact_receptance(frequency, ...) is this at s = i omega (to round-off).
Receptance4 contact_receptance_laplace(cdouble s, double normal_stiffness, double speed,
                                       const Eigen::Matrix3cd& creep, const LoadCoefficients& load);

/// alpha_c at many frequencies from a creep function (evaluated once per frequency).
std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                             double normal_stiffness, double speed,
                                             const CreepFunction& creep);

/// alpha_c at many frequencies from precomputed creep matrices (e.g. one sweep of the NSS model).
std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                             double normal_stiffness, double speed,
                                             const std::vector<Eigen::Matrix3cd>& creep);

/// alpha_c with the coupling (C3) from precomputed f and g (one of each per frequency).
std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                             double normal_stiffness, double speed,
                                             const std::vector<Eigen::Matrix3cd>& creep,
                                             const std::vector<LoadCoefficients>& load);

/// The normal part alone, 1/k_H at (z, z) and zeros elsewhere: for the vertical-only loop, which
/// reads nothing but alpha_c,zz.
Receptance4 normal_contact_receptance(double normal_stiffness);

/// Frequency-independent creep coefficients (e.g. Kalker's steady linear theory).
CreepFunction steady_creep(const Eigen::Matrix3d& f);

/// Tangential contact stiffness of an elliptic contact in full adhesion, diag(K_x, K_y, K_rot),
/// approximated by the circular contact of radius c = sqrt(a b) (Mindlin; Johnson 1985, Ch. 7:
/// compliance (2 - nu1)/(8 G1 a) + (2 - nu2)/(8 G2 a); Lubkin's torsion of the stuck circular
/// contact, Johnson 1985, Ch. 7: M = (16/3) G1 a^3 beta1 per body). For two identical bodies
/// with the combined G:  K_x = K_y = 4 G c / (2 - nu),  K_rot = 8 G c^3 / 3.  Approximate (the
/// elliptic shape and the x-y difference are neglected).
Eigen::Matrix3d tangential_contact_stiffness(double a, double b, double shear_modulus, double nu);

/// A simple frequency-dependent creep law: the steady creep damper f_s/V in series with the
/// tangential contact spring K,
///
///   alpha_c,t = (V/(i omega)) f_s^{-1} + K^{-1}   <=>   f(omega) = (f_s^{-1} + (i omega / V)
///   K^{-1})^{-1},
///
/// which tends to f_s as omega -> 0 and to (V/(i omega)) K (a spring, |f| ~ 1/omega, phase -90 deg)
/// at high frequency; the corner lies near omega ~ V K / f_s, i.e. a few hundred Hz for a
/// wheel-rail contact at 100 km/h. Used by the tests as a stand-in for the NSS model.
CreepFunction creep_with_tangential_stiffness(const Eigen::Matrix3d& steady,
                                              const Eigen::Matrix3d& stiffness, double speed);

}  // namespace rollnoise::noise
