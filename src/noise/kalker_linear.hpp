// Kalker's linear theory of steady rolling contact (full adhesion, vanishing creepage) for elliptic
// contact areas: creep coefficients for the noise loop and the curving estimate
// (docs/conventions.md Secs. 1-2; docs/noise_loop.md Sec. 3).
//
// Forces on the wheel (body 1), opposing the creepage, c = sqrt(a b), G the combined shear modulus:
//
//   Fx = -G c^2 C11 xi_x
//   Fy = -G c^2 C22 xi_y - G c^3 C23 phi
//   Mz =  G c^3 C23 xi_y - G c^4 C33 phi
//
// i.e. F = -f xi with the creep matrix (rows Fx, Fy, Mz; columns xi_x, xi_y, phi)
//
//         [ G c^2 C11        0            0       ]
//   f  =  [     0        G c^2 C22    G c^3 C23   ]      f23 = -f32 = G c^3 C23.
//         [     0       -G c^3 C23    G c^4 C33   ]
//
// The coefficients C_ij(a/b, nu) are Kalker's table (Kalker, Three-Dimensional Elastic Bodies in
// Rolling Contact, Kluwer 1990, Table E.3; first published in Kalker's thesis, Delft 1967),
// embedded below as constants for a/b = 0.1 ... 1 and b/a = 0.9 ... 0.1, nu = 0, 0.25, 0.5. C11,
// C22 and C23 are identical to tests/data/kalker/kalker_linear_theory.csv (a test checks every
// entry). C33 is not in that file: it is transcribed from the same table as reproduced in the
// textbooks (Johnson, Contact Mechanics 1985, Ch. 8; Knothe & Stichel, Rail Vehicle Dynamics 2017;
// Iwnicki (ed.), Handbook of Railway Vehicle Dynamics 2006, chapter on wheel-rail contact). The
// transcription could not be compared with a printed copy here; a test checks C33 against the
// project's own CONTACT solver in the full-adhesion limit (tests/noise/kalker_linear_test.cpp,
// within a few per cent).
//
// Interpolation (the usual practice, see tests/data/kalker/README.md): linear in g = a/b for
// a <= b and in g = b/a for a >= b (the two halves meet at the circle), and quadratic (Lagrange
// through nu = 0, 0.25, 0.5) in 1/C for the Poisson ratio. The table range is a/b in [0.1, 10].
#pragma once

#include <Eigen/Core>

#include "contact/material.hpp"

namespace rollnoise::noise {

/// Kalker's dimensionless creep coefficients.
struct KalkerCoefficients {
  double C11 = 0.0, C22 = 0.0, C23 = 0.0, C33 = 0.0;
};

/// One row of Kalker's table as embedded in the library.
struct KalkerTableRow {
  double a_over_b;  ///< a/b of the row (a along the rolling direction)
  double nu;        ///< Poisson's ratio: 0, 0.25 or 0.5
  KalkerCoefficients c;
};

/// The 57 embedded rows (19 aspect ratios x 3 Poisson ratios), ordered by a/b then nu.
const KalkerTableRow* kalker_table(int* rows);

/// C_ij at any a/b in [0.1, 10] and nu in [0, 0.5] (interpolated as above).
/// InputError("a_over_b") outside the table (a/b comes from the patch); std::invalid_argument for
/// nu outside [0, 0.5] (a contract: material.nu is checked where read).
KalkerCoefficients kalker_coefficients(double a_over_b, double nu);

/// The creep matrix f (F = -f xi) for semi-axes a (rolling direction), b (lateral), the combined
/// shear modulus G and Poisson's ratio nu. Units: f11, f22 (N), f23, f32 (N m), f33 (N m^2).
Eigen::Matrix3d kalker_creep_matrix(double a, double b, double shear_modulus, double nu);

/// The same for a patch of semi-axes a, b between two bodies of `material` (its combined shear
/// modulus and Poisson's ratio): the one place a case's patch and material give Kalker's matrix.
Eigen::Matrix3d kalker_creep_matrix(double a, double b, const contact::Material& material);

}  // namespace rollnoise::noise
