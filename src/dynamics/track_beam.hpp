// An infinite rail as a Timoshenko (or Euler-Bernoulli) beam, free or on a continuous foundation:
// its Green's function (transfer receptance) at one frequency, in closed form from the roots of the
// dispersion relation.
//
// Equations of motion for harmonic motion e^{i omega t} (Thompson, Railway Noise and Vibration,
// 2009, Ch. 3; Graff, Wave Motion in Elastic Solids, 1975, Ch. 3), deflection
// w(x), rotation of the cross-section psi(x), loads F delta(x) and M delta(x):
//
//   kGA (w'' - psi') + (m' omega^2 - s) w = -F delta(x)        (shear force balance)
//   EI psi''  + kGA (w' - psi) + rho I omega^2 psi = -M delta(x) (moment balance)
//
// with m' = rho A the mass per length, rho I = m' I / A the rotary inertia per length, k the shear
// coefficient and s(omega) the complex dynamic stiffness of the foundation per unit length (N/m^2).
// Losses of the rail itself enter as E(1 + i eta), G(1 + i eta).
//
// Fourier transform w(x) = (1/2pi) Int W(k) e^{-ikx} dk (so d/dx -> -ik) turns this into
//
//   [ kGA k^2 + s - m' omega^2        -i k kGA             ] [W  ]   [F]
//   [ i k kGA                  EI k^2 + kGA - rho I omega^2] [Psi] = [M],
//
// whose determinant is the dispersion polynomial, quadratic in k^2 (docs/models.md Eq. T3):
//
//   P(k) = EI kGA k^4 + [ (s - m' omega^2) EI - kGA rho I omega^2 ] k^2
//          + (s - m' omega^2)(kGA - rho I omega^2).
//
// Its four roots are +-k_1, +-k_2 (k_j^2 = lambda_j). The inverse transform is done by residues:
// for x > 0 the contour closes in the lower half plane, where the decaying (or outgoing, Re k > 0)
// roots lie, so for a numerator N(k) of the inverse matrix
//
//   g(x) = -i sum_{j=1,2} N(k_j) e^{-i k_j x} / P'(k_j),   P'(k_j) = 2 a k_j (lambda_j -
//   lambda_other),
//
// with a = EI kGA; numerators even in k give g(-x) = g(x), odd ones g(-x) = -g(x) and g(0) = 0
// (Knothe & Grassie, Veh. Syst. Dyn. 22, 1993; Grassie et al., J. Mech. Eng. Sci. 24, 1982).
//
// Euler-Bernoulli limit (kGA -> infinity, rho I = 0): P(k)/kGA -> EI k^4 + s - m' omega^2 with the
// numerators W/F: 1, Psi/F: -ik, W/M: ik, Psi/M: k^2.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

#include "dynamics/receptance.hpp"

namespace rollnoise::dynamics {

/// Bending (and axial) properties of a rail for one plane of bending.
struct BeamSection {
  double youngs_modulus = 210e9;   ///< E (Pa)
  double shear_modulus = 81e9;     ///< G (Pa)
  double area = 0.0;               ///< cross-section A (m^2)
  double second_moment = 0.0;      ///< I about the bending axis (m^4)
  double mass_per_length = 0.0;    ///< m' = rho A (kg/m)
  double shear_coefficient = 0.4;  ///< Timoshenko's k (-)
  double loss_factor = 0.0;        ///< rail material loss factor eta_r (-)
  bool timoshenko = true;  ///< false: Euler-Bernoulli (no shear deformation, no rotary inertia)

  /// Throws InputError naming `prefix`.field for a non-physical value.
  void validate(const std::string& prefix) const;
};

/// Green's function of an infinite beam on a continuous foundation at one angular frequency.
class InfiniteBeam {
 public:
  /// `foundation` is the complex dynamic stiffness per unit length s (N/m^2); 0 for a free beam.
  InfiniteBeam(const BeamSection& section, double omega, cdouble foundation);
  /// The same at a complex angular frequency omega = -i s (s the Laplace variable, 1/s): the
  /// closed form continued analytically (docs/squeal.md Sec. 2). The loss factors stay constants
  /// E(1 + i eta). For Im omega <= 0 (Re s >= 0) the roots are chosen by the same rule (Im k < 0),
  /// the analytic continuation there; for Im omega > 0 (decaying s) each root is the one of +-k
  /// nearest to the physical root at the real frequency Re omega (with `foundation_at_real`, the
  /// foundation stiffness there), i.e. continued along the vertical path from the real axis,
  /// across the real k axis if need be (where the rule Im k < 0 would jump to another sheet).
  InfiniteBeam(const BeamSection& section, cdouble omega, cdouble foundation, cdouble foundation_at_real);

  /// (w(x), psi(x)) per (F, M) applied at 0: [[w/F, w/M], [psi/F, psi/M]] (m/N, m/(N m), rad/N,
  /// rad/(N m)). Reciprocity: transfer(x)^T = transfer(-x).
  Eigen::Matrix2cd transfer(double x) const;

  /// The first row of transfer(x), (w/F, w/M), at the equally spaced x_n = x0 + n step,
  /// n = 0 .. count-1, as rows of a count x 2 matrix. The exponentials e^{-i k_j |x_n|} by the
  /// recurrence e^{-i k (|x| + step)} = e^{-i k |x|} e^{-i k step} on each side of x = 0 (two
  /// exponentials per side and root instead of one per point); equal to transfer() to a few
  /// count x round-off (|e^{-i k step}| <= 1).
  Eigen::MatrixX2cd deflection_rows(double x0, double step, int count) const;

  /// The amplitudes of the two waves in the deflection row of transfer(x), x != 0:
  ///   g_wF(x) = sum_j wF[j] e^{-i k_j |x|},   g_wM(x) = sgn(x) sum_j wM[j] e^{-i k_j |x|},
  /// wF_j = -i (d2 k_j^2 + d0) / P'(k_j), wM_j = g k_j / P'(k_j) (the residues above; g_psiF =
  /// -g_wM by reciprocity). wM[0] + wM[1] = 0 (g_wM is continuous at 0). Used by the periodic
  /// rail's lattice sums (track_periodic.hpp).
  struct WaveAmplitudes {
    std::array<cdouble, 2> wF, wM;
  };
  WaveAmplitudes wave_amplitudes() const;

  /// Point receptance w/F at the load.
  cdouble point_receptance() const { return transfer(0.0)(0, 0); }

  /// The two roots k_1, k_2 of the dispersion relation with Im k < 0 (decaying towards +x), or
  /// Re k > 0 for a propagating wave without damping (rad/m).
  const std::array<cdouble, 2>& wavenumbers() const { return k_; }

 private:
  std::array<cdouble, 2> k_;       // roots in the lower half plane
  std::array<cdouble, 2> inv_dp_;  // 1 / P'(k_j)
  cdouble d2_, d0_, e2_, e0_, g_;  // numerators: W/F = d2 k^2 + d0, Psi/M = e2 k^2 + e0, odd: g k
  void init_complex(const BeamSection& section, cdouble omega, cdouble foundation, const InfiniteBeam* reference);
};

/// Longitudinal receptance u/F of an infinite rod (axial stiffness EA(1 + i eta), mass m') on a
/// continuous foundation of stiffness s per length, at distance x from the load:
///   u(x) = -i e^{-i k0 |x|} / (2 EA k0),  k0^2 = (m' omega^2 - s) / EA,  Im k0 < 0
/// (Graff 1975, Ch. 2, for the free rod; the foundation only shifts k0^2).
cdouble rod_receptance(const BeamSection& section, double omega, cdouble foundation, double x);
/// The same at a complex angular frequency omega = -i s (root continued as in InfiniteBeam).
cdouble rod_receptance(const BeamSection& section, cdouble omega, cdouble foundation, double x,
                       cdouble foundation_at_real);

}  // namespace rollnoise::dynamics
