// Radiation efficiency of flat rigid pistons in a rigid baffle (the sleepers: each sleeper, per
// rail half a sleeper, radiates as a baffled piston; Thompson, Railway Noise and Vibration, 2009,
// Sec. 6.7).
//
// Rayleigh integral (e^{+i omega t}, fluid.hpp): a plane surface S in a rigid baffle with normal
// velocity amplitude v(y) produces on itself the pressure
//   p(x) = (i omega rho / (2 pi)) Int_S v(y) e^{-i k R} / R dS_y,   R = |x - y|.
// The time-averaged power W = (1/2) Re Int_S p v^* dS; for a uniform (rigid) velocity v,
//   W = (|v|^2 / 2) Re Z,  Re Z = (rho c k / (2 pi)) Int_S Int_S sin(k R) / R dS dS'
// (Re of i e^{-ikR} = sin kR; the cos kR / R part is reactive), and with sigma = W / (rho c A
// |v|^2/2),
//   sigma = (k / (2 pi A)) Int_S Int_S sin(k |x - y|) / |x - y| dS_x dS_y.
// Substituting u = x - y (for each u the pairs (x, y) fill the overlap of S with S shifted by u,
// of area C(u), the autocorrelation of the piston's indicator function):
//   sigma = (k / (2 pi A)) Int_{R^2} C(u) sin(k |u|) / |u| d^2u.                            (1)
// Checks: Int C d^2u = A^2 and sin(k|u|)/|u| -> k give sigma -> k^2 A / (2 pi) as k -> 0; at high
// k, Int sin(k|u|)/|u| d^2u = 2 pi Int_0^inf sin(kR) dR = 2 pi / k (Abel sense) weights
// C(0) = A, so sigma -> 1.
//
// Rectangle Lx x Ly: C(u, v) = (Lx - |u|)(Ly - |v|) on |u| < Lx, |v| < Ly; by symmetry
//   sigma = (2 k / (pi A)) Int_0^Lx Int_0^Ly (Lx - u)(Ly - v) sin(k r) / r du dv,  r = |(u, v)|.
// sin(kr)/r = k sinc(kr) is an entire function of r^2 = u^2 + v^2, so the integrand is smooth
// (analytic) on the closed rectangle and a tensor Gauss-Legendre rule converges exponentially;
// it needs about k L / 2 + 16 points per side L (GSL's precomputed tables 16 ... 256; longer sides
// in panels of k L <= 400; converged to 1e-13 against twice the points up to k L = 1500). Cost
// ~ (k Lx / 2 + 16)(k Ly / 2 + 16) sines: for half a sleeper (1.3 m x 0.25 m) 5 us at 100 Hz,
// 8 us at 1 kHz, 40 us at 5 kHz.
//
// Disc of radius a: C(R) = 2 a^2 acos(R / 2a) - (R / 2) sqrt(4 a^2 - R^2), R < 2a, and (1) becomes
//   sigma = (k / A) Int_0^{2a} C(R) sin(k R) dR.
// C has a (2a - R)^{3/2} end point; the substitution R = 2 a cos(phi) removes it:
// C = a^2 (2 phi - sin 2 phi), dR = -2 a sin(phi) dphi,
//   sigma = (2 k a / pi) Int_0^{pi/2} (2 phi - sin 2 phi) sin(phi) sin(2 k a cos phi) dphi,
// an analytic integrand (Gauss-Legendre, k a + 16 points). Closed form for the test:
// sigma = 1 - J_1(2ka) / (ka) (Kinsler et al., Fundamentals of Acoustics, Sec. 7.5).
#pragma once

namespace rollnoise::acoustics {

/// Radiation efficiency (-) of a rigid rectangular piston Lx x Ly (m) in a rigid baffle at
/// wavenumber k = omega / c (1/m), by Eq. (1). ~k^2 Lx Ly / (2 pi) at low k, -> 1 at high k.
double rectangular_piston_efficiency(double k, double Lx, double Ly);

/// Radiation efficiency (-) of a rigid circular piston of radius a (m) in a rigid baffle, by
/// Eq. (1) (quadrature; equals 1 - J_1(2ka)/(ka)).
double circular_piston_efficiency(double k, double radius);

}  // namespace rollnoise::acoustics
