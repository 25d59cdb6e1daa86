#include "contact/coulomb.hpp"

#include <cmath>

namespace rollnoise::contact {

ElementTraction solve_coulomb_element(double bx, double by, double d1, double d2, double g) {
  ElementTraction e;
  // adhesion trial
  const double qx = -bx / d1, qy = -by / d2;
  if (qx * qx + qy * qy <= g * g) {
    e.px = qx;
    e.py = qy;
    e.dp_db[0] = -1.0 / d1;
    e.dp_db[3] = -1.0 / d2;
    return e;
  }
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

}  // namespace rollnoise::contact
