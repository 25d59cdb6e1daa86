// The 6-node (quadratic, Lagrange) triangle: shape functions and their derivatives in the reference
// coordinates (xi, eta), a Gauss rule exact to degree 5, and the Jacobian at a point. What both
// element formulations (axisymmetric wheel section, rail cross-section) need.
//
// Reference triangle: corners (0, 0), (1, 0), (0, 1); mid-side nodes 3 (0-1), 4 (1-2), 5 (2-0).
// With L1 = 1 - xi - eta, L2 = xi, L3 = eta (area coordinates), the shape functions are
//   N_i = L_i (2 L_i - 1) at the corners, N_3 = 4 L1 L2, N_4 = 4 L2 L3, N_5 = 4 L3 L1
// (Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and Fundamentals, 7th ed. 2013,
// Sec. 6.6, Eq. 6.33).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace rollnoise::fem {

/// One point of a quadrature rule on the reference triangle; the weights sum to 1/2 (its area).
struct TrianglePoint {
  double xi, eta, weight;
};

/// The 7-point rule exact for polynomials of degree 5 (Dunavant 1985, Int. J. Numer. Methods Eng.
/// 21, 1129-1148, Table: degree 5; also Strang & Fix). Consistent mass of the quadratic triangle
/// needs degree 4, the axisymmetric stiffness with the 1/r terms is integrated approximately.
const std::vector<TrianglePoint>& triangle_gauss_degree5();

/// Shape functions N_0..N_5 at (xi, eta).
Eigen::Matrix<double, 6, 1> triangle6_shape(double xi, double eta);

/// Derivatives: row 0 dN/dxi, row 1 dN/deta.
Eigen::Matrix<double, 2, 6> triangle6_shape_derivatives(double xi, double eta);

/// The Jacobian J = [dx/dxi dy/dxi; dx/deta dy/deta] of the map from (xi, eta) to the element's
/// nodes `xy` (columns = nodes 0..5) at a point with derivatives `dN`.
Eigen::Matrix2d triangle6_jacobian(const Eigen::Matrix<double, 2, 6>& dN,
                                   const Eigen::Matrix<double, 2, 6>& xy);

/// The element's node coordinates as the columns of a 2x6 matrix.
Eigen::Matrix<double, 2, 6> triangle6_coordinates(const std::vector<Eigen::Vector2d>& nodes,
                                                  const std::array<int, 6>& triangle);

}  // namespace rollnoise::fem
