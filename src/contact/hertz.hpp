// Hertz's solution for two quasi-identical elastic bodies with an elliptic contact
// (Johnson 1985, Contact Mechanics, Sec. 4.2, Eqs. 4.39-4.41; docs/conventions.md Secs. 1-2).
//
// With semi-axes a (along x) and b (along y), eccentricity e^2 = 1 - (minor/major)^2 and the complete
// elliptic integrals K(e), E(e) (GSL), the undeformed distance h = A x^2 + B y^2 and the load N give,
// for a >= b,
//   p0 = 3N / (2 pi a b),
//   A  = p0 b / (E* a^2 e^2) [K(e) - E(e)],
//   B  = p0 b / (E* a^2 e^2) [(a/b)^2 E(e) - K(e)],
//   approach delta = p0 b K(e) / E*,
// and the same with x and y exchanged for a < b. E* is Material::contact_modulus().
#pragma once

#include "contact/material.hpp"

namespace rollnoise::contact {

struct HertzContact {
  double a = 0.0;         ///< semi-axis in x, rolling direction (m)
  double b = 0.0;         ///< semi-axis in y (m)
  double A = 0.0;         ///< curvature coefficient of h in x (1/m): h = A x^2 + B y^2
  double B = 0.0;         ///< curvature coefficient of h in y (1/m)
  double p0 = 0.0;        ///< peak pressure (Pa)
  double approach = 0.0;  ///< rigid approach of the bodies (m)
  double normal_force = 0.0;  ///< N (N)

  /// Linearised normal contact stiffness dN/d(approach) = 3N / (2 approach) (N/m).
  double normal_stiffness() const { return 1.5 * normal_force / approach; }
};

/// Hertz's solution given the semi-axes and load (CONTACT's IPOTCN = -3 input).
HertzContact hertz_from_semi_axes(double a, double b, double normal_force, const Material& m);

/// Hertz's solution given the curvature coefficients A, B of h = A x^2 + B y^2 and the load.
HertzContact hertz_from_curvatures(double A, double B, double normal_force, const Material& m);

}  // namespace rollnoise::contact
