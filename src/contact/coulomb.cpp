#include "contact/coulomb.hpp"

#include <cmath>

namespace rollnoise::contact {

namespace {

// The adhesion trial p = -D^{-1} b: true (and e set) if it satisfies the bound g (the static one).
bool adhesion_trial(double bx, double by, double d1, double d2, double g, ElementTraction& e) {
  const double qx = -bx / d1, qy = -by / d2;
  if (!(qx * qx + qy * qy <= g * g)) return false;
  e.px = qx;
  e.py = qy;
  e.dp_db[0] = -1.0 / d1;
  e.dp_db[3] = -1.0 / d2;
  return true;
}

}  // namespace

ElementTraction solve_coulomb_element(double bx, double by, double d1, double d2, double g) {
  ElementTraction e;
  if (adhesion_trial(bx, by, d1, d2, g, e)) return e;
  e.slip = true;
  if (g <= 0.0) {  // no normal pressure: free slip, no traction
    e.sx = bx;
    e.sy = by;
    return e;
  }
  // Newton on phi(l) from l = 0 (monotone convergence from the left, see header).
  const double ax = d1 * g, ay = d2 * g;
  double l = 0.0;
  for (int it = 0; it < 100; ++it) {
    const double ux = bx / (ax + l), uy = by / (ay + l);
    const double phi = ux * ux + uy * uy - 1.0;
    const double dphi = -2.0 * (ux * ux / (ax + l) + uy * uy / (ay + l));
    const double step = -phi / dphi;
    l += step;
    if (step <= 1e-15 * (l + ax + ay)) break;
  }
  const double cx = bx / (ax + l), cy = by / (ay + l);
  const double norm = std::hypot(cx, cy);  // 1 up to round-off; keeps |p| = g exactly
  e.px = -g * cx / norm;
  e.py = -g * cy / norm;
  e.sx = l * cx / norm;
  e.sy = l * cy / norm;
  // implicit differentiation of u_k (a_k + l) = b_k, |u| = 1 (see header)
  const double ux = cx / norm, uy = cy / norm;
  const double Gx = 1.0 / (ax + l), Gy = 1.0 / (ay + l);
  const double uGu = ux * ux * Gx + uy * uy * Gy;
  const double vx = Gx * ux, vy = Gy * uy;
  e.dp_db[0] = -g * (Gx - vx * vx / uGu);
  e.dp_db[1] = -g * (-vx * vy / uGu);
  e.dp_db[2] = e.dp_db[1];
  e.dp_db[3] = -g * (Gy - vy * vy / uGu);
  return e;
}

ElementTraction solve_coulomb_element(double bx, double by, double d1, double d2, double g,
                                      const FallingFriction& law) {
  if (!law.active() || g <= 0.0) return solve_coulomb_element(bx, by, d1, d2, g);
  ElementTraction e;
  if (adhesion_trial(bx, by, d1, d2, g, e)) return e;  // the bound g = mu_s pn, as with constant mu
  e.slip = true;
  // phi(l) = sum (b_k/h_k)^2 - 1, h_k = l + d_k g r(l): Newton with a bisection safeguard on the
  // bracket [lo, hi], phi(lo) > 0 > phi(hi) (header).
  auto h = [&](double l, double d) { return l + d * g * law.ratio(l); };
  double lo = 0.0, hi = std::hypot(bx, by), l = 0.0;
  for (int it = 0; it < 200; ++it) {
    const double hx = h(l, d1), hy = h(l, d2), gs = g * law.ratio_slope(l);
    const double ux = bx / hx, uy = by / hy;
    const double phi = ux * ux + uy * uy - 1.0;
    if (phi > 0.0) lo = l; else hi = l;
    const double dphi = -2.0 * (ux * ux * (1.0 + d1 * gs) / hx + uy * uy * (1.0 + d2 * gs) / hy);
    double next = dphi < 0.0 ? l - phi / dphi : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = std::abs(next - l);
    l = next;
    if (step <= 1e-15 * (l + (d1 + d2) * g) || hi - lo <= 1e-15 * (hi + (d1 + d2) * g)) break;
  }
  const double gl = g * law.ratio(l), gs = g * law.ratio_slope(l);
  const double hx = l + d1 * gl, hy = l + d2 * gl;
  const double cx = bx / hx, cy = by / hy;
  const double norm = std::hypot(cx, cy);
  const double ux = cx / norm, uy = cy / norm;
  e.px = -gl * ux;
  e.py = -gl * uy;
  e.sx = l * ux;
  e.sy = l * uy;
  // dp = -g(l) G db + (g(l) G H' u - g'(l) u) dl,  dl = u'G db / (u'G H' u)   (header)
  const double Gx = 1.0 / hx, Gy = 1.0 / hy, Hx = 1.0 + d1 * gs, Hy = 1.0 + d2 * gs;
  const double uGHu = ux * ux * Gx * Hx + uy * uy * Gy * Hy;
  const double vx = gl * Gx * Hx * ux - gs * ux, vy = gl * Gy * Hy * uy - gs * uy;  // g G H' u - g' u
  const double wx = Gx * ux / uGHu, wy = Gy * uy / uGHu;                               // dl/db
  e.dp_db[0] = -gl * Gx + vx * wx;
  e.dp_db[1] = vx * wy;
  e.dp_db[2] = vy * wx;
  e.dp_db[3] = -gl * Gy + vy * wy;
  return e;
}

}  // namespace rollnoise::contact
