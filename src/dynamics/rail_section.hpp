// The rail's cross-section: the default UIC60 (60E1) outline and the section properties a beam
// model needs (area, centroid, second moments, St-Venant torsion constant, shear centre, warping
// constant), computed on a mesh of 6-node triangles.
//
// Torsion (St-Venant; Timoshenko & Goodier, Theory of Elasticity, 3rd ed. 1970, Sec. 104-105):
// with the warping function phi(y, z) about the centroid, u_x = theta' phi, u_y = -theta z,
// u_z = theta y, equilibrium and traction-free sides give
//
//   laplace(phi) = 0 in A,   d phi/dn = z n_y - y n_z on the boundary,                       (S1)
//
// solved in the weak form  Int grad(v).grad(phi) dA = Int grad(v).(z, -y) dA  (the boundary term
// integrated back by parts, div(z, -y) = 0) with the same 6-node triangles. The torsion constant is
//
//   J = Int (y^2 + z^2 + y dphi/dz - z dphi/dy) dA.                                          (S2)
//
// Shear centre P = (y_p, z_p) from the centroid (Vlasov 1961; Pilkey, Analysis and Design of
// Elastic Beams, 2002, Sec. 6.3): the warping function about P, phi_P = phi - z_p y + y_p z
// (+ const), makes the warping stresses free of bending moments, Int phi_P y dA = Int phi_P z dA
// = 0:
//
//   [ I_zz  -I_yz ] [z_p]   [Int phi y dA]         I_zz = Int y^2 dA, I_yy = Int z^2 dA,      (S3)
//   [ I_yz  -I_yy ] [y_p] = [Int phi z dA],        I_yz = Int y z dA,
//
// and the warping constant I_w = Int (phi_P - mean phi_P)^2 dA.                             (S4)
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

/// The UIC60 (60E1) rail's outline in (y, z), metres, y lateral (0 on the centre line), z up from
/// the foot's bottom; counter-clockwise, last point not repeated. Approximate: drawn from the
/// principal dimensions of EN 13674-1 (height 172 mm, foot 150 mm, head 72 mm, web 16.5 mm, head
/// crown R300/R80/R13 and foot slope as polylines, fillets as chamfers); docs/models.md Sec. 2.6
/// lists its properties against the standard's.
std::vector<Eigen::Vector2d> uic60_outline();

/// The z of a section's head underside (m) for the spin load of RailWaveguide::contact_loads: at
/// the UIC60 proportion, 133/172 of the height above the lowest point (kUic60HeadBottom for
/// uic60_outline(), to round-off). An estimate for other sections: the spin is the plane fitted to
/// u_x over the triangles above it.
double rail_head_bottom(const std::vector<Eigen::Vector2d>& outline);

/// Properties of a meshed section (SI). Coordinates of the centroid in the mesh's (y, z); the
/// second moments about the centroid; the shear centre relative to the centroid.
struct SectionProperties {
  double area = 0.0;                       ///< A (m^2)
  Eigen::Vector2d centroid{0.0, 0.0};      ///< (y_c, z_c) (m)
  double second_moment_yy = 0.0;           ///< I_yy = Int z^2 dA, vertical bending (m^4)
  double second_moment_zz = 0.0;           ///< I_zz = Int y^2 dA, lateral bending (m^4)
  double product_moment = 0.0;             ///< I_yz = Int y z dA (m^4)
  double torsion_constant = 0.0;           ///< J of Eq. (S2) (m^4)
  Eigen::Vector2d shear_centre{0.0, 0.0};  ///< (y_p, z_p) from the centroid, Eq. (S3) (m)
  double warping_constant = 0.0;           ///< I_w of Eq. (S4) (m^6)

  /// Polar moment about the centroid, I_yy + I_zz (m^4).
  double polar_moment() const { return second_moment_yy + second_moment_zz; }
};

/// One quadrature point of a 6-node triangle mapped onto the section: shape functions, their
/// derivatives in (y, z), the point and its weight (Gauss weight times det J, m^2).
struct SectionPoint {
  Eigen::Matrix<double, 6, 1> shape;
  Eigen::Matrix<double, 2, 6> gradient;  ///< rows dN/dy, dN/dz (1/m)
  Eigen::Vector2d position;
  double weight = 0.0;
};

/// The degree-5 Gauss points of triangle `t` of `mesh` (throws NumericalError on an inverted
/// element).
std::vector<SectionPoint> section_points(const fem::QuadraticTriangleMesh& mesh, int t);

/// Eqs. (S1)-(S4) on `mesh`.
SectionProperties section_properties(const fem::QuadraticTriangleMesh& mesh);

}  // namespace rollnoise::dynamics
