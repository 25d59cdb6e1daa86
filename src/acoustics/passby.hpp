// The sound of a train passing a receiver: moving incoherent sources of known band powers, the
// squared pressure at the receiver against time, and the levels a pass-by is judged by
// (EN ISO 3095:2013, Railway applications - Acoustics - Measurement of noise emitted by
// railbound vehicles: L_pAeq,Tp, TEL, L_pAFmax).
//
// Geometry (the measurement position of EN ISO 3095:2013 Sec. 6: 7.5 m from the track centre,
// 1.2 m above the top of the rail): x along the track, y lateral from the track centre (positive
// towards the receiver), z up from the top of the rail. The receiver sits at (0, d, h). Every
// source moves with the train, x(t) = x_0 + V t, so that a source at x_0 = 0 passes the receiver
// at t = 0.
//
// A point source of power W (W) and directivity D(u) (the ratio of its intensity in direction u
// to that of a monopole of the same power: the mean of D over the sphere is 1), at distance r in
// direction u, gives the free-field mean-square pressure
//   p^2 = rho c W D(u) / (4 pi r^2)                                                       (P1)
// (Kinsler et al., Fundamentals of Acoustics, 4th ed. 2000, Sec. 7.4: I = W / (4 pi r^2) and
// p^2 = rho c I in the far field). The ground is a plane at z = ground_level; its reflection is
// an image source mirrored in it, added in energy with the factor Q (1: a reflecting ground, the
// default; 0: absorbing), which is what band levels of broadband sources see (the interference
// of the direct and reflected paths averages out over a band):
//   p^2 = rho c W / (4 pi) [D(u) / r^2 + Q D(u') / r'^2].                                  (P2)
//
// Directivities (the radiating motions they stand for):
//   monopole:          D = 1 (the sleepers, the wheel's radial and circumferential motion);
//   dipole along a:    D = 3 (u . a)^2 (a wheel's axial motion along the axle, a = y; the rail's
//                      vertical motion, a = z, and lateral, a = y), the point dipole's pattern
//                      (Kinsler et al. Sec. 7.5), the mean of 3 cos^2 over the sphere being 1.
//
// A line source stands for a rail under one wheel: the rail's vibration decays away from the
// contact at the track decay rate Delta (dB/m), so its power per length is
//   w(s) = W beta e^{-2 beta |s|},  beta = Delta / (20 log10 e) = Delta / 8.686 (Np/m),       (L1)
// s along the rail from the contact, Int w ds = W (EN 15461 Annex A.1's exponential decay,
// acoustics/decay_rate.hpp). Its p^2 is (P2) integrated over s, which depends on the source's
// place X = x_0 + V t only: it is tabulated once per line shape (decay and direction) on a grid
// of X and read by linear interpolation.
//
// Levels (p_0 = 20 uPa), from the A-weighted squared pressure p_A^2(t) = Sum_b p_b^2(t)
// 10^{A(f_b)/10} (IEC 61672-1, acoustics/a_weighting.hpp):
//   L_pAeq,T = 10 lg[ (1/T) Int_T p_A^2 dt / p_0^2 ]                                        (E1)
// over the pass-by time T_p (EN ISO 3095:2013 3.5: from the front of the train passing the
// receiver's position to its rear, T_p = l / V); the transit exposure level
//   TEL = 10 lg[ (1/T_p) Int_T p_A^2 dt / p_0^2 ]                                            (E2)
// over a time T that holds the whole event (EN ISO 3095:2013 3.7); and the F-time-weighted level
//   L_pAF(t) = 10 lg[ (1/tau) Int_{-inf}^t p_A^2(xi) e^{-(t - xi)/tau} dxi / p_0^2 ],
//   tau = 0.125 s (IEC 61672-1:2013 5.8),                                                    (E3)
// and its maximum L_pAFmax. On a uniform time grid (E3) is the exact response of the exponential
// to p_A^2 held constant over each step; (E1), (E2) are the rectangle sums of the grid.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "acoustics/fluid.hpp"

namespace rollnoise::acoustics {

/// The directivity D(u) of (P1): a monopole, or a dipole along y (the axle, the rail's lateral
/// motion) or z (the rail's vertical motion).
enum class Directivity { kMonopole, kDipoleY, kDipoleZ };

/// D(u) for a unit vector u (x, y, z).
double directivity(Directivity d, const Eigen::Vector3d& u);

/// The receiver and the ground (m): EN ISO 3095's position by default.
struct PassbyGeometry {
  double distance = 7.5;      ///< d: the receiver's distance from the track centre (m)
  double height = 1.2;        ///< h: the receiver's height above the top of the rail (m)
  double ground_level = -0.3; ///< z of the reflecting plane (m; the ballast's top, assumed)
  double reflection = 1.0;    ///< Q of (P2): 1 reflecting, 0 absorbing
};

/// A point source moving with the train.
struct MovingPointSource {
  Eigen::Vector3d at{0.0, 0.0, 0.0};  ///< (x_0, y, z) at t = 0 (m)
  Directivity directivity = Directivity::kMonopole;
  std::vector<double> power;  ///< per band (W)
};

/// A rail's sound under one wheel, (L1): centred on the contact, moving with it.
struct MovingLineSource {
  Eigen::Vector3d at{0.0, 0.0, 0.0};  ///< the contact's (x_0, y, z) at t = 0 (m)
  Directivity directivity = Directivity::kMonopole;
  std::vector<double> power;  ///< per band, the whole line's (W)
  std::vector<double> decay;  ///< per band, the vibration's decay rate Delta (dB/m, > 0)
};

/// p^2(t) at the receiver per band: time (s) x band (Pa^2).
struct PassbyHistory {
  std::vector<double> time;     ///< uniform, ascending (s)
  Eigen::MatrixXd mean_square;  ///< rows: times; columns: bands (Pa^2)
};

/// (P2) of each point source and (L1)'s integral of each line source at the receiver, summed,
/// at the times t_0 + k dt, k = 0 .. steps - 1, for the train's speed V (m/s). The lines' bands
/// on `threads` threads (the same result for any number).
PassbyHistory passby_history(const std::vector<MovingPointSource>& points,
                             const std::vector<MovingLineSource>& lines,
                             const PassbyGeometry& geometry, double speed, double t0, double dt,
                             int steps, const Fluid& fluid = Fluid{}, int threads = 1);

/// p_A^2(t) (Pa^2): the bands of `history` A-weighted at their centres (Hz) and summed.
std::vector<double> a_weighted_mean_square(const PassbyHistory& history,
                                           const std::vector<double>& band_centres);

/// (E3) on the uniform grid of step dt (s): the F-time-weighted mean square (Pa^2) at each step,
/// from 0 before the first.
std::vector<double> time_weighted(const std::vector<double>& mean_square, double dt,
                                  double tau = 0.125);

/// 10 lg(p^2 / p_0^2), p_0 = 20 uPa.
double pressure_level(double mean_square);

/// (1/T) Int p^2 dt over the steps whose times lie in [t_1, t_2), as a level (dB re 20 uPa): (E1)
/// with T = t_2 - t_1, or (E2) with `over` = T_p in place of T.
double equivalent_level(const std::vector<double>& time, const std::vector<double>& mean_square,
                        double t1, double t2, double over = 0.0);

}  // namespace rollnoise::acoustics
