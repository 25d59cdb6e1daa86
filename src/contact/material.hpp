// Elastic constants of two quasi-identical bodies (same E and nu): the normal and tangential problems
// decouple (Kalker 1990, Sec. 1.6; "Johnson's process").
#pragma once

namespace rollnoise::contact {

struct Material {
  double E = 210e9;  ///< Young's modulus of both bodies (Pa)
  double nu = 0.28;  ///< Poisson's ratio of both bodies (-)

  /// Combined shear modulus, 1/G = (1/G1 + 1/G2)/2 = 1/G1 for identical bodies (Pa).
  double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }
  /// Combined plane-strain modulus, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (Johnson 1985, Eq. 4.22) (Pa).
  double contact_modulus() const { return E / (2.0 * (1.0 - nu * nu)); }
};

}  // namespace rollnoise::contact
