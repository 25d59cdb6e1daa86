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
//
// Falling friction (friction_law.hpp): in slip the bound is g(l) = g r(l), r = mu(l)/mu_s, so
// s_k (l + d_k g(l)) = l b_k and l solves  phi(l) = sum_k (b_k/h_k(l))^2 - 1,  h_k = l + d_k g(l).
// phi(0) is the same as with constant friction (g(0) = g: the adhesion test uses mu_s), and phi is
// strictly decreasing, so the slip speed is unique, iff every h_k increases:
//   1 + d_k g'(l) > 0 for all l,  i.e.  d_max mu_s pn (1 - A) B < 1          (uniqueness)
// (the steepest slope is at l = 0). Beyond it phi can have several roots: the element law is
// non-unique (a negative slip compliance larger than the elastic one; docs/falling_friction.md, Sec. 3).
// The root is found by Newton safeguarded by bisection on [0, |b|] (phi(|b|) < 0 as h_k > l);
// phi need not be convex here. Differentiating u_k h_k = b_k, |u| = 1 (u = s/l):
//   dl = u'G db / (u'G H' u),  dp = -g(l) G db + (g(l) G H' u - g'(l) u) dl,
// G = diag(1/h_k), H' = diag(h_k' = 1 + d_k g'(l)); with g' = 0 this is the constant-friction
// dp/db below.
#pragma once

#include "contact/friction_law.hpp"

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

/// The same with falling friction: g = mu_s pn is the adhesion bound, the slip traction is
/// g ratio(|s|). Requires 1 + d_k g ratio_slope(l) > 0 (the caller checks it, see above).
ElementTraction solve_coulomb_element(double bx, double by, double d1, double d2, double g,
                                      const FallingFriction& law);

}  // namespace rollnoise::contact
