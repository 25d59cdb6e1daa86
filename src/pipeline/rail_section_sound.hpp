// The sound of a rail whose section deforms (the waveguide rail), wavenumber by wavenumber
// (docs/sound.md Sec. 3.3).
//
// The rail's surface normal velocity v_n(x, s) = i omega u_n(x, s) (s along the outline) has along
// the rail the spectrum V(kappa, s) = i omega U(kappa, s) (dynamics/rail_surface_spectrum.hpp). A
// wave V(s) e^{-i kappa x} radiates per unit length as the 2D section at the radial wavenumber
// k_r = sqrt(k^2 - kappa^2) driven at omega (acoustics/bem2d.hpp, axial_wave_efficiency):
//
//   W'(kappa) = V^H P_3D(kappa) V,   P_3D(kappa) = (k / k_r) P_2D(k_r)   for |kappa| < k,    (R1)
//
// and nothing for |kappa| >= k (a wave subsonic along the rail has no far field; Nilsson, Jones,
// Thompson & Ryue, JSV 321 (2009) 813-836, Sec. 3; Thompson, Railway Noise and Vibration, 2009,
// Sec. 6.5). Waves of different kappa are orthogonal over the infinite rail (Parseval), so the
// rail radiates
//
//   W = (1/2 pi) Int_{-k}^{k} V(kappa)^H P_3D(kappa) V(kappa) dkappa = omega^2 F^H G F,
//   G = (k / 2 pi) Int_{-pi/2}^{pi/2} U(theta)^H P_2D(k cos theta) U(theta) dtheta,           (R2)
//
// with kappa = k sin theta (dkappa = k_r dtheta: the factor k / k_r cancels, and the integrand
// stays finite at kappa -> +-k), F the forces of the loads (4 per contact, its frame). The section
// moving rigidly in a wave much longer than the acoustic one (kappa << k) gives back the 2D
// efficiency of the rigid section that the beams use (sound_power.hpp, (S2)).
//
// P_2D(k_r): the section's boundary elements' power matrix (bem2d radiated_power_matrix_2d with
// unit patterns, W' = a^H P a for the elements' normal velocity amplitudes a), tabulated at
// k_r = 0, h, 2h, ... up to the top of the grid's k, interpolated by cubic (Catmull-Rom) splines.
// Reduction: P_2D has few large eigenvalues (the section's radiation modes, about 2 k a + 1 of
// them); the table keeps P_2D on the span W of the patterns that radiate at any of its k_r (a
// real orthonormal basis, r of about 40 for 112 elements up to 5 kHz), and the rail's spectrum
// is asked for those patterns only (RailModel::surface_spectra), which cuts the cost of (R2) by
// about (elements / r)^2 where it is dominated by P_2D.
//
// Quadrature of (R2): adaptive Gauss-Kronrod on panels of theta. The starting panels end at the
// poles of U near the real axis (the waves with |Re k_j| < k) and are no wider than one period of
// the loads' relative phase e^{i kappa dx}; a panel's 21-point Kronrod value is accepted when the
// 10-point Gauss value of its own nodes agrees with it within `tolerance` times the integral's norm
// times the panel's share of the interval (the Gauss value's error, which the Kronrod value's is
// far below), else its halves are refined in turn, all panels of a level in one spectrum call.
// (Before, each 10-point panel was checked against its two halves: 30 wavenumbers a panel
// accepted at once, against 21 now.)
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "acoustics/fluid.hpp"
#include "dynamics/rail_model.hpp"
#include "dynamics/rail_surface_spectrum.hpp"
#include "dynamics/track.hpp"

namespace rollnoise::pipeline {

/// P_2D(k_r) of a section's boundary elements on the grid k_r = i step (i = 0, 1, ...).
struct SectionRadiationTable {
  std::vector<dynamics::OutlinePiece> pieces;  ///< the boundary elements (y, z in m)
  /// The patterns that radiate (pieces x r, orthonormal columns; header comment): the powers are
  /// W^T P_2D W, and a velocity a over the pieces enters as W^T a.
  Eigen::MatrixXd patterns;
  double step = 1.0;                    ///< h (rad/m)
  std::vector<Eigen::MatrixXcd> power;  ///< per k_r, r x r (W/m per (m/s)^2)
  bool ground = false;                  ///< over a rigid plane at the foot
  /// P_2D at k_r in [0, (power.size() - 1) step] (cubic interpolation).
  Eigen::MatrixXcd at(double k_r) const;
  double max_wavenumber() const { return step * static_cast<double>(power.size() - 1); }
};

/// The table of `outline` (y, z in m; closed polygon) up to k_r = max_k (1/m), steps of 1 rad/m,
/// 10 elements a wavelength at max_k (at least 40), on `threads` threads.
SectionRadiationTable section_radiation_table(const std::vector<Eigen::Vector2d>& outline,
                                              bool ground, double max_k,
                                              const acoustics::Fluid& fluid, int threads = 1);

/// (R2) at one frequency (Hz): G (columns x columns of `spectrum`), W = omega^2 F^H G F.
/// `spread`: the largest distance between the loads along the rail (m).
Eigen::MatrixXcd section_gram(const dynamics::SurfaceSpectrum& spectrum,
                              const SectionRadiationTable& table, double frequency, double spread,
                              const acoustics::Fluid& fluid, double tolerance = 1e-3);

/// (R2) of the distributions of `rail`'s load basis at the positions `x` (m along the rail;
/// RailModel::basis_surface_spectra, per_position columns a position) at every frequency of
/// `grid` (Hz): G_D, shared by every set of contacts at those positions. Empty where the rail has
/// no load basis.
std::vector<Eigen::MatrixXcd> basis_section_grams(const dynamics::RailModel& rail,
                                                  const std::vector<double>& x,
                                                  const SectionRadiationTable& table,
                                                  const std::vector<double>& grid,
                                                  const acoustics::Fluid& fluid, int threads = 1);

/// The Gram matrices of loads made of the basis' distributions, G = C^T G_D C (C real: the
/// loads' combination, RailLoadBasis::combination, or some of its columns), per frequency.
std::vector<Eigen::MatrixXcd> combined_grams(const std::vector<Eigen::MatrixXcd>& basis_grams,
                                             const Eigen::MatrixXd& combination);

/// basis_section_grams at the positions x, from a cache where the caller keeps one.
using BasisGrams = std::function<std::vector<Eigen::MatrixXcd>(const std::vector<double>& x)>;

/// (R2) of `rail` under loads at `points` at every frequency of `grid` (Hz): by the rail's load
/// basis where it has one (combined_grams of `basis_grams`, or of basis_section_grams where that
/// is null), else from the points' own spectra; empty where the rail has no section
/// (RailModel::surface_spectra null: the beams).
std::vector<Eigen::MatrixXcd> section_grams(const dynamics::RailModel& rail,
                                            const std::vector<dynamics::RailLoadPoint>& points,
                                            const SectionRadiationTable& table,
                                            const std::vector<double>& grid,
                                            const acoustics::Fluid& fluid, int threads = 1,
                                            const BasisGrams& basis_grams = nullptr);

}  // namespace rollnoise::pipeline
