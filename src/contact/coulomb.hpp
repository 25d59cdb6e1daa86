// Coulomb's law at one element, solved exactly (the element step of Kalker's and Vollebregt's
// Gauss-Seidel solvers; Kalker 1990, Sec. 5.5; Vollebregt, CONTACT user guide, "ConvexGS").
//
// With the tractions of all other elements fixed, the slip velocity of element I is affine in its own
// traction: s = b + D p, D = diag(d1, d2) > 0 (the diagonal block of the slip operator; its
// off-diagonal term vanishes by symmetry). Coulomb's law with the traction bound g = mu pn:
//   adhesion  s = 0, |p| <= g        ->  p = -D^{-1} b   if that satisfies the bound;
//   slip      |p| = g, p = -g s/|s|  ->  p = -g (b1/(d1 g + l), b2/(d2 g + l)), s = l (p / -g),
// where l = |s| > 0 is the root of  phi(l) = (b1/(d1 g + l))^2 + (b2/(d2 g + l))^2 - 1.
// phi is convex and decreasing with phi(0) > 0 in the slip case, so Newton's method from l = 0
// converges monotonically.
#pragma once

namespace rollnoise::contact {

struct ElementTraction {
  double px = 0.0, py = 0.0;  ///< traction (Pa)
  double sx = 0.0, sy = 0.0;  ///< slip velocity (m/s)
  bool slip = false;
  /// Derivative dp/db of the solution (row-major 2x2): -D^{-1} in adhesion; in slip, with
  /// u = -p/g and G = diag(1/(d1 g + l), 1/(d2 g + l)),  dp/db = -g (G - G u u'G / (u'G u)).
  double dp_db[4] = {0.0, 0.0, 0.0, 0.0};
};

ElementTraction solve_coulomb_element(double bx, double by, double d1, double d2, double g);

}  // namespace rollnoise::contact
