// The axisymmetric boundary elements (acoustics/axisymmetric_bem.hpp): the kernels' phi-integrals,
// their singular and near-singular parts, the CHIEF points, the least-squares solve, the power.
//
// 1. The phi-integrals. For an observation point x = (r_x, 0, z_x) and a surface point
//    y = (r_y cos phi, r_y sin phi, z_y) with outward normal (n_r cos phi, n_r sin phi, n_z):
//      R^2 = d^2 + 4 r_x r_y sin^2(phi/2),  d^2 = (r_x - r_y)^2 + (z_x - z_y)^2,
//      (y - x).n_y = q + 2 n_r r_x sin^2(phi/2),  q = n_r (r_y - r_x) + n_z (z_y - z_x),
//      G = e^{-ikR} / (4 pi R),  dG/dn_y = -e^{-ikR} (1 + ikR) (y - x).n_y / (4 pi R^3),
//    both written without the cancellations of R^2 = A - B cos phi near R = 0. The integrands are
//    even and 2 pi-periodic in phi: the trapezoidal rule on [0, pi] (end weights halved, all
//    doubled; "the far rule", M intervals) is exact for trigonometric polynomials of degree < 2 M
//    and converges geometrically for analytic integrands (Trefethen & Weideman, SIAM Rev. 56
//    (2014) 385, Sec. 3): with a the distance of the nearest singularity from the real phi-axis
//    and |e^{-ikR}| <= e^{k rho a} in that strip, the error is ~ exp(-(2 M - k rho) a). So M is
//    chosen from the bandwidths of e^{-ikR(phi)} (phase rate at most k rho <= k r_max per radian)
//    and of cos(n phi): 2 M = k r_max + n_max + 4 (k r_max)^{1/3} + 20. One rule serves all
//    orders: w_j cos(n phi_j) is tabulated once per call by the Chebyshev recurrence
//    cos((n+1) phi) = 2 cos(phi) cos(n phi) - cos((n-1) phi), and the moments of all orders of all
//    quadrature points of one observation point are one matrix product (no work per order and
//    phi-point and pair).
//
// 2. The near-singular phi-integrand. 1/R has its singularities at phi ~ +-i d / rho,
//    rho = sqrt(r_x r_y), d the meridian distance: the far rule is used where
//    d >= tau rho, tau = 12 / (2 M - k r_max) (error ~ e^{-12} = 6e-6). Nearer, the static kernel
//    of order 0 is subtracted and integrated analytically:
//      int G cos(n phi) = int (G - G0) cos(n phi) + int G0 (cos(n phi) - 1) + int G0,
//    G0 = 1/(4 pi R), and the same for dG/dn. The first two integrands are bounded, but
//    G - G0 = (-ik - k^2 R/2 + i k^3 R^2/6 + ...) / (4 pi) has the odd powers of R, whose kink at
//    phi = 0 (R -> rho |phi| as d -> 0) limits a uniform rule to O((h k rho)^2) (Euler-Maclaurin:
//    jumps of the odd derivatives), ~10 % at k rho = 20 with the far rule's h. These integrands
//    take "the near rule": the trapezoidal rule in t with phi = t - sin t (Sidi's sin^2
//    transformation, Sidi, ISNM 112 (1993) 359), 3 M / 2 intervals: phi ~ t^3/6 at t = 0 turns
//    the kink into a t^5 term (error O(h^6)); the phase rate in t, k rho cos(phi/2) phi'(t) with
//    phi' = 1 - cos t, stays below 1.2 k rho. With m = 4 r_x r_y / D^2,
//    D^2 = (r_x + r_y)^2 + (z_x - z_y)^2, 1 - m = d^2 / D^2,
//      int_0^{2 pi} G0 dphi      = K(m) / (pi D),
//      int_0^{2 pi} dG0/dn dphi  = -(1 / (pi D)) [ q E(m) / d^2 + (n_r / (2 r_y)) (K(m) - E(m)) ],
//    from int_0^{2 pi} (A - B cos phi)^{-1/2} = 4 K / sqrt(A + B),
//    int_0^{2 pi} (A - B cos phi)^{-3/2} = 4 E / ((A - B) sqrt(A + B)) (Gradshteyn & Ryzhik
//    3.674; the forms of Seybert et al.) and
//      (y - x).n_y = q - n_r d^2 / (2 r_y) + n_r R^2 / (2 r_y).
//    After the phi-integration the kernels are log-singular in d (K ~ ln(4 D / d)) and the double
//    layer has q / d^2 ~ 1 / d next to corners.
//
// 3. The integral along the generator. Gauss-Legendre on each segment; a segment nearer to the
//    observation point than its length is bisected until each piece is no longer than its
//    distance from the point (a geometric grading towards the point), so ln d and 1/d are
//    integrated to ~1e-6 by 4 points a piece. Long segments (k L > 1.5) are cut so that each
//    piece holds a quarter wavelength at most.
//    The singular segment (the observation point is its midpoint) is split there; on each half,
//    u in (0, 1] the distance from the midpoint over L/2, the analytic static parts carry the
//    logarithm explicitly: K(m) = L(1 - m) ln(1/(1 - m)) + (smooth), L(m1) = K(m1)/pi =
//    (1/2)(1 + m1/4 + 9 m1^2/64 + ...) (Abramowitz & Stegun 17.3.26; the series to m1^2 leaves
//    an m1^3 ln m1 term, smooth enough), ln(1/(1 - m)) = 2 ln(2 D / L) + 2 ln(1/u) on the segment
//    (d = u L/2 there, q = 0). The ln(1/u) part is integrated by the Gauss rule of that weight,
//    the rest (analytic minus logarithm, and the subtracted phi-integrals) by Gauss-Legendre.
//    This product integration is exact for the logarithm, unlike a polar (Duffy) patch, which
//    would need the 3D surface and a second rule per order; here the singular part is
//    order-independent (cos(n phi) - 1 vanishes at phi = 0), so one analytic term serves all n.
//
// 4. Points on the axis (an open generator's ends): collocation and CHIEF points have r > 0, the
//    Gauss points of the end segments r_y > 0, so R >= d > 0 and m < 1 everywhere; the factor
//    n_r / r_y is finite in the product with r_y (dS = r_y ds dphi), and the order-n integrals
//    vanish like (r_x r_y)^n at the axis without special cases.
#include "acoustics/axisymmetric_bem.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <utility>

#include "acoustics/axisymmetric_quadrature.hpp"

namespace rollnoise::acoustics {
namespace {

using axi_cd = std::complex<double>;
constexpr double kAxiPi = 3.14159265358979323846;

std::string axi_point_text(const Eigen::Vector2d& p) {
  return "(r, z) = (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ") m";
}

double axi_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Distance from p to the segment [a, b].
double axi_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Whether the closed segments [a, b] and [c, d] share a point. Orientation tests with the
// round-off of collinear points (cross products below 1e-12 of their factors' lengths) taken as 0.
bool axi_segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& s) {
    const double x = axi_cross(q - p, s - p);
    return std::abs(x) <= 1e-12 * (q - p).norm() * (s - p).norm() ? 0 : (x > 0 ? 1 : -1);
  };
  const int d1 = side(a, b, c), d2 = side(a, b, d), d3 = side(c, d, a), d4 = side(c, d, b);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  auto on = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& s) {
    return std::min(p.x(), q.x()) <= s.x() && s.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= s.y() && s.y() <= std::max(p.y(), q.y());
  };
  return (d1 == 0 && on(a, b, c)) || (d2 == 0 && on(a, b, d)) || (d3 == 0 && on(c, d, a)) ||
         (d4 == 0 && on(c, d, b));
}

// The checked generator: its points (open ends snapped onto r = 0) and elements.
struct AxiMesh {
  std::vector<Eigen::Vector2d> points;
  std::vector<AxisymmetricElement> elements;
  bool closed = true;
  double r_max = 0.0;
};

AxiMesh axi_mesh(const AxisymmetricGenerator& g) {
  AxiMesh mesh;
  mesh.closed = g.closed;
  mesh.points = g.points;
  auto& pts = mesh.points;
  const std::size_t np = pts.size();
  if (np < 3)
    throw std::invalid_argument("axisymmetric generator: " + std::to_string(np) +
                                " points; a surface of revolution needs at least 3");
  double size = 0.0;
  for (const auto& p : pts) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw std::invalid_argument("axisymmetric generator: a point is not finite");
    size = std::max({size, std::abs(p.x()), std::abs(p.y())});
  }
  for (const auto& p : pts)
    if (p.x() < 0.0 && !(!g.closed && std::abs(p.x()) <= 1e-9 * size))
      throw std::invalid_argument("axisymmetric generator: point " + axi_point_text(p) +
                                  " has r < 0; the generator lies in the half-plane r >= 0");
  if (g.closed) {
    for (const auto& p : pts)
      if (!(p.x() > 0.0))
        throw std::invalid_argument(
            "axisymmetric generator: a closed generator (a ring) must not touch the axis, point " +
            axi_point_text(p) + " does; give a body reaching the axis as an open generator");
  } else {
    for (std::size_t i : {std::size_t(0), np - 1}) {
      if (std::abs(pts[i].x()) > 1e-9 * size)
        throw std::invalid_argument(
            "axisymmetric generator: an open generator must start and end on the axis (r = 0); " +
            axi_point_text(pts[i]) + " is an end off it");
      pts[i].x() = 0.0;
    }
    for (std::size_t i = 1; i + 1 < np; ++i)
      if (!(pts[i].x() > 0.0))
        throw std::invalid_argument("axisymmetric generator: inner point " +
                                    axi_point_text(pts[i]) +
                                    " of an open generator is on the axis; only its ends may be");
    if (pts.front().y() == pts.back().y())
      throw std::invalid_argument(
          "axisymmetric generator: an open generator's ends are one point of the axis; the "
          "surface would enclose no volume along the axis");
  }
  const std::size_t ne = g.closed ? np : np - 1;
  // Signed (doubled) area of the polygon (closed along the axis for an open generator, where
  // that side adds r_a z_b - r_b z_a = 0): > 0 counter-clockwise in (r, z).
  double area2 = 0.0;
  for (std::size_t i = 0; i < np; ++i) area2 += axi_cross(pts[i], pts[(i + 1) % np]);
  for (std::size_t e = 0; e < ne; ++e) {
    if ((pts[(e + 1) % np] - pts[e]).norm() <= 1e-12 * size)
      throw std::invalid_argument("axisymmetric generator: zero-length segment at " +
                                  axi_point_text(pts[e]));
  }
  if (!(std::abs(area2) > 1e-12 * size * size))
    throw std::invalid_argument("axisymmetric generator: the outline encloses no area");
  // No two segments may meet except consecutive ones at their shared point.
  for (std::size_t a = 0; a < ne; ++a)
    for (std::size_t b = a + 1; b < ne; ++b) {
      const bool adjacent = b == a + 1 || (g.closed && a == 0 && b == ne - 1);
      if (adjacent) continue;
      if (axi_segments_meet(pts[a], pts[(a + 1) % np], pts[b], pts[(b + 1) % np]))
        throw std::invalid_argument("axisymmetric generator: the outline crosses itself; " +
                                    std::string("the segments from ") + axi_point_text(pts[a]) +
                                    " and from " + axi_point_text(pts[b]) + " meet");
    }
  const double sense = area2 > 0.0 ? 1.0 : -1.0;  // flip the right-hand normal if clockwise
  mesh.elements.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    AxisymmetricElement& el = mesh.elements[e];
    el.start = pts[e];
    el.end = pts[(e + 1) % np];
    el.midpoint = 0.5 * (el.start + el.end);
    const Eigen::Vector2d ds = el.end - el.start;
    el.length = ds.norm();
    el.normal = sense * Eigen::Vector2d(ds.y(), -ds.x()) / el.length;
    el.r_ds = el.length * 0.5 * (el.start.x() + el.end.x());
  }
  for (const auto& p : pts) mesh.r_max = std::max(mesh.r_max, p.x());
  return mesh;
}

// Halton radical inverse of i in base b (deterministic, well spread candidates).
double axi_halton(int i, int b) {
  double f = 1.0, x = 0.0;
  for (; i > 0; i /= b) {
    f /= b;
    x += f * (i % b);
  }
  return x;
}

// CHIEF points: candidates of a Halton sequence over the bounding box, kept inside the polygon
// (even-odd rule), scored by their clearance c = min(distance to the outline, r) (r: the order-n
// interior equation vanishes on the axis like r^n); the deepest first, then greedily the
// candidate farthest from the outline and from the points already taken (max of
// min(c, distance to the chosen)), among those with c >= 0.2 c_max. Spread, irregular positions
// make it unlikely that all points lie on a nodal surface of the same interior mode, the failure
// of CHIEF (Schenck 1968; Seybert & Rengarajan, JASA 81 (1987) 1299).
std::vector<Eigen::Vector2d> axi_chief_points(const AxiMesh& mesh, int count) {
  std::vector<Eigen::Vector2d> chosen;
  if (count <= 0) return chosen;
  const auto& pts = mesh.points;
  const std::size_t np = pts.size();
  Eigen::Vector2d lo = pts[0], hi = pts[0];
  for (const auto& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  struct Candidate {
    Eigen::Vector2d p;
    double clearance;
  };
  std::vector<Candidate> cand;
  const int n_candidates = 4096;
  for (int i = 1; i <= n_candidates; ++i) {
    const Eigen::Vector2d p(lo.x() + (hi.x() - lo.x()) * axi_halton(i, 2),
                            lo.y() + (hi.y() - lo.y()) * axi_halton(i, 3));
    bool inside = false;  // ray to +r; the open polygon's closing side lies on r = 0 < p.r
    double clearance = p.x();
    for (std::size_t a = 0; a < np; ++a) {
      const Eigen::Vector2d& u = pts[a];
      const Eigen::Vector2d& v = pts[(a + 1) % np];
      if ((u.y() > p.y()) != (v.y() > p.y()) &&
          p.x() < u.x() + (p.y() - u.y()) * (v.x() - u.x()) / (v.y() - u.y()))
        inside = !inside;
      if (mesh.closed || a + 1 < np) clearance = std::min(clearance, axi_segment_distance(p, u, v));
    }
    if (inside && clearance > 0.0) cand.push_back({p, clearance});
  }
  if (cand.empty()) return chosen;
  double c_max = 0.0;
  for (const auto& c : cand) c_max = std::max(c_max, c.clearance);
  std::vector<double> score;
  for (const auto& c : cand) score.push_back(c.clearance >= 0.2 * c_max ? c.clearance : -1.0);
  while (static_cast<int>(chosen.size()) < count) {
    const auto best = std::max_element(score.begin(), score.end());
    if (*best <= 0.0) break;
    const Eigen::Vector2d p = cand[best - score.begin()].p;
    chosen.push_back(p);
    for (std::size_t i = 0; i < cand.size(); ++i)
      if (score[i] > 0.0) score[i] = std::min(score[i], (cand[i].p - p).norm());
  }
  return chosen;
}

// A phi-rule on [0, pi] with its order tables: the trapezoidal rule in t, phi = t (the far rule)
// or phi = t - sin t (the near rule, Sec. 2), weights w_j = 2 h phi'(t_j) (halved at the ends).
// Rows of the tables: the requested orders, in their order.
struct AxiPhiRule {
  int intervals = 0;
  Eigen::VectorXd half_sin2;  // sin^2(phi_j / 2), j = 0..M
  Eigen::MatrixXd cos_n;      // orders x (M + 1): w_j cos(n phi_j)
  Eigen::MatrixXd cos_n_m1;   // orders x (M + 1): w_j (cos(n phi_j) - 1)
};

AxiPhiRule axi_phi_rule(int intervals, const std::vector<int>& orders, bool graded) {
  AxiPhiRule rule;
  rule.intervals = intervals;
  const int np = intervals + 1;
  const int no = static_cast<int>(orders.size());
  rule.half_sin2.resize(np);
  rule.cos_n.resize(no, np);
  rule.cos_n_m1.resize(no, np);
  const double h = kAxiPi / intervals;
  std::vector<double> d(orders.back() + 1);
  for (int j = 0; j < np; ++j) {
    const double t = j * h;
    const double phi = graded ? t - std::sin(t) : t;
    const double dphi_dt = graded ? 2.0 * std::pow(std::sin(0.5 * t), 2) : 1.0;  // 1 - cos t
    const double s = std::sin(0.5 * phi);
    rule.half_sin2(j) = s * s;
    // 2 for [pi, 2 pi] (even integrands), 1/2 at the ends (trapezoid)
    const double w = 2.0 * h * dphi_dt * ((j == 0 || j == intervals) ? 0.5 : 1.0);
    // d_n = cos(n phi) - 1 by the Chebyshev recurrence written for d: d_0 = 0,
    // d_1 = -2 sin^2(phi/2), d_{n+1} = 2 cos(phi) d_n - d_{n-1} + 2 d_1 (accurate near phi = 0).
    d[0] = 0.0;
    if (d.size() > 1) d[1] = -2.0 * s * s;
    for (std::size_t n = 2; n < d.size(); ++n)
      d[n] = 2.0 * (1.0 + d[1]) * d[n - 1] - d[n - 2] + 2.0 * d[1];
    for (int o = 0; o < no; ++o) {
      rule.cos_n(o, j) = w * (1.0 + d[orders[o]]);
      rule.cos_n_m1(o, j) = w * d[orders[o]];
    }
  }
  return rule;
}

// A quadrature point y of the generator integral for one observation point.
struct AxiNode {
  int element;
  double weight;  // Gauss weight * ds * r_y
  double r, z;    // y
  double nr, nz;  // outward normal at y
  bool subtract;  // the static kernel subtracted (Sec. 2 of the file comment)
  bool on_line;   // y on the observation point's own segment: q = 0
};

// Static (order-0, k = 0) phi-integrals of G0 and dG0/dn_y, Sec. 2.
struct AxiStatic {
  double g, h;
};
AxiStatic axi_static(double rx, double zx, const AxiNode& y) {
  const double dz = y.z - zx;
  const double d2 = (rx - y.r) * (rx - y.r) + dz * dz;
  const double big_d2 = (rx + y.r) * (rx + y.r) + dz * dz;
  const double big_d = std::sqrt(big_d2);
  const AxisymmetricEllipticKE ke = axisymmetric_elliptic_ke(d2 / big_d2);
  const double q = y.on_line ? 0.0 : y.nr * (y.r - rx) + y.nz * dz;
  return {ke.K / (kAxiPi * big_d),
          -(q * ke.E / d2 + 0.5 * y.nr / y.r * (ke.K - ke.E)) / (kAxiPi * big_d)};
}

// The shared rules and buffers of one call.
struct AxiWork {
  AxisymmetricQuadratureRule gauss, gauss_singular, log_singular;
  AxiPhiRule phi_far, phi_near;
  double k = 0.0;
  double tau = 0.0;  // subtract the static kernel where d < tau sqrt(r_x r_y)
  std::vector<AxiNode> nodes;
  Eigen::MatrixXd f_far, f_near, f0_near, mom_far, mom_near, mom0_near;
  Eigen::MatrixXcd row_g, row_h;           // orders x elements
  Eigen::VectorXd static_g, static_h;      // per element: the row's analytic static parts
  std::vector<double> kr, cos_kr, sin_kr;  // phase buffers, one phi-rule long
};

// The Gauss points of segment e between parameters ta < tb, bisected towards x (Sec. 3).
void axi_graded_nodes(const AxisymmetricElement& el, int e, const Eigen::Vector2d& x, double ta,
                      double tb, int depth, AxiWork& w) {
  const Eigen::Vector2d a = el.start + ta * (el.end - el.start);
  const Eigen::Vector2d b = el.start + tb * (el.end - el.start);
  const double len = (tb - ta) * el.length;
  if (len > axi_segment_distance(x, a, b) && depth < 50) {
    const double tm = 0.5 * (ta + tb);
    axi_graded_nodes(el, e, x, ta, tm, depth + 1, w);
    axi_graded_nodes(el, e, x, tm, tb, depth + 1, w);
    return;
  }
  const double rho_x = x.x();
  for (Eigen::Index g = 0; g < w.gauss.nodes.size(); ++g) {
    const Eigen::Vector2d y = a + w.gauss.nodes(g) * (b - a);
    const double weight = w.gauss.weights(g) * len * y.x();
    const bool near = (y - x).norm() < w.tau * std::sqrt(rho_x * y.x());
    w.nodes.push_back({e, weight, y.x(), y.y(), el.normal.x(), el.normal.y(), near, false});
  }
}

// The coefficients of ln(1/u) in the static phi-integrals on the singular segment (Sec. 3):
// K(m) = L(1 - m) ln(1/(1 - m)) + (smooth), L(m1) = K(m1)/pi ~ (1/2)(1 + m1/4 + 9 m1^2/64),
// so S_g = 2 L(m1) / (pi D), S_h = -(n_r / (2 r_y)) S_g.
AxiStatic axi_log_coefficients(double rx, double zx, const AxiNode& y) {
  const double dz = y.z - zx;
  const double big_d2 = (rx + y.r) * (rx + y.r) + dz * dz;
  const double m1 = ((rx - y.r) * (rx - y.r) + dz * dz) / big_d2;
  const double lm = 0.5 * (1.0 + m1 * (0.25 + m1 * 9.0 / 64.0));
  const double sg = 2.0 * lm / (kAxiPi * std::sqrt(big_d2));
  return {sg, -0.5 * y.nr / y.r * sg};
}

// One half of the singular segment e, from its midpoint x to `tip`, u = distance / (L/2) (Sec. 3).
// The Gauss-Legendre nodes go to w.nodes (their subtracted phi-integrals are integrated with the
// others); the static part goes to w.static_g(e), w.static_h(e): the analytic phi-integrals minus
// their logarithm by Gauss-Legendre, plus the logarithm by the Gauss rule of the weight ln(1/u).
void axi_singular_half(const AxisymmetricElement& el, int e, const Eigen::Vector2d& tip,
                       const Eigen::Vector2d& x, AxiWork& w) {
  const double rx = x.x(), zx = x.y();
  const double half = 0.5 * el.length;
  auto at = [&](double u) -> AxiNode {
    const Eigen::Vector2d y = el.midpoint + u * (tip - el.midpoint);
    return {e, 0.0, y.x(), y.y(), el.normal.x(), el.normal.y(), true, true};
  };
  for (Eigen::Index g = 0; g < w.gauss_singular.nodes.size(); ++g) {
    const double u = w.gauss_singular.nodes(g);
    AxiNode y = at(u);
    y.weight = w.gauss_singular.weights(g) * half * y.r;
    const AxiStatic s = axi_static(rx, zx, y);
    const AxiStatic c = axi_log_coefficients(rx, zx, y);
    const double log_u = std::log(1.0 / u);
    w.static_g(e) += y.weight * (s.g - c.g * log_u);
    w.static_h(e) += y.weight * (s.h - c.h * log_u);
    w.nodes.push_back(y);
  }
  for (Eigen::Index g = 0; g < w.log_singular.nodes.size(); ++g) {
    const AxiNode y = at(w.log_singular.nodes(g));
    const double wt = w.log_singular.weights(g) * half * y.r;
    const AxiStatic c = axi_log_coefficients(rx, zx, y);
    w.static_g(e) += wt * c.g;
    w.static_h(e) += wt * c.h;
  }
}

// The quadrature nodes of the generator integral for the observation point x (on element
// `singular`, or -1) into w.nodes (Sec. 3), with the singular segment's static part.
void axi_row_nodes(const AxiMesh& mesh, const Eigen::Vector2d& x, int singular, AxiWork& w) {
  w.nodes.clear();
  const int ne = static_cast<int>(mesh.elements.size());
  for (int e = 0; e < ne; ++e) {
    const AxisymmetricElement& el = mesh.elements[e];
    if (e == singular) {
      axi_singular_half(el, e, el.start, x, w);
      axi_singular_half(el, e, el.end, x, w);
      continue;
    }
    // Long segments first cut to k L <= 1.5, then graded towards x.
    const int pieces = std::max(1, static_cast<int>(std::ceil(w.k * el.length / 1.5)));
    for (int p = 0; p < pieces; ++p)
      axi_graded_nodes(el, e, x, double(p) / pieces, double(p + 1) / pieces, 0, w);
  }
}

// The analytic static phi-integrals (Sec. 2) of the nodes off the singular segment whose static
// kernel is subtracted, weighted into w.static_g, w.static_h.
void axi_add_subtracted_statics(double rx, double zx, AxiWork& w) {
  for (const AxiNode& y : w.nodes)
    if (y.subtract && !y.on_line) {
      const AxiStatic s = axi_static(rx, zx, y);
      w.static_g(y.element) += y.weight * s.g;
      w.static_h(y.element) += y.weight * s.h;
    }
}

// The meridian terms of one pair x, y (Sec. 1): R^2 = d2 + c4 sin^2(phi/2),
// (y - x).n_y = q + p2 sin^2(phi/2).
struct AxiPairTerms {
  double d2, c4, q, p2;
};
AxiPairTerms axi_pair_terms(double rx, double zx, const AxiNode& y) {
  const double dz = y.z - zx;
  const double d2 = (rx - y.r) * (rx - y.r) + dz * dz;
  const double c4 = 4.0 * rx * y.r;
  const double q = y.on_line ? 0.0 : y.nr * (y.r - rx) + y.nz * dz;
  const double p2 = 2.0 * y.nr * rx;
  return {d2, c4, q, p2};
}

constexpr double kAxiInv4Pi = 1.0 / (4.0 * kAxiPi);

// The far-rule phi-integrands of one pair (Sec. 1) into columns col..col + 3 of w.f_far:
// Re G, Im G, Re dG/dn, Im dG/dn at the rule's points.
void axi_far_integrands(const AxiPairTerms& t, int col, AxiWork& w) {
  double* fg_re = w.f_far.col(col).data();
  double* fg_im = w.f_far.col(col + 1).data();
  double* fh_re = w.f_far.col(col + 2).data();
  double* fh_im = w.f_far.col(col + 3).data();
  const double k = w.k;
  const Eigen::VectorXd& half_sin2 = w.phi_far.half_sin2;
  const int np = static_cast<int>(half_sin2.size());
  for (int j = 0; j < np; ++j) w.kr[j] = k * std::sqrt(t.d2 + t.c4 * half_sin2(j));
  axisymmetric_cos_sin(np, w.kr.data(), w.cos_kr.data(), w.sin_kr.data());
  for (int j = 0; j < np; ++j) {
    const double s2 = half_sin2(j);
    const double kr = w.kr[j];
    const double inv_r = k / kr;
    const double c = w.cos_kr[j], s = w.sin_kr[j];
    const double g = kAxiInv4Pi * inv_r;
    fg_re[j] = c * g;
    fg_im[j] = -s * g;
    // dG/dn = -e^{-ikR} (1 + ikR) P / (4 pi R^3), e^{-ikR}(1 + ikR) = c + kR s + i (kR c - s)
    const double hp = -(t.q + t.p2 * s2) * g * inv_r * inv_r;
    fh_re[j] = (c + kr * s) * hp;
    fh_im[j] = (kr * c - s) * hp;
  }
}

// The near-rule phi-integrands of one pair (Sec. 2) into columns col..col + 3 of w.f_near:
// G - G0 and dG/dn - dG0/dn (Re, Im), and into columns col0, col0 + 1 of w.f0_near: the static
// G0 and dG0/dn. The phases come as cos, sin of kR/2, so that cos kR - 1 = -2 sin^2(kR/2) keeps
// its accuracy at small kR.
void axi_near_integrands(const AxiPairTerms& t, int col, int col0, AxiWork& w) {
  double* fg_re = w.f_near.col(col).data();
  double* fg_im = w.f_near.col(col + 1).data();
  double* fh_re = w.f_near.col(col + 2).data();
  double* fh_im = w.f_near.col(col + 3).data();
  double* f0g = w.f0_near.col(col0).data();
  double* f0h = w.f0_near.col(col0 + 1).data();
  const double k = w.k;
  const Eigen::VectorXd& half_sin2 = w.phi_near.half_sin2;
  const int np = static_cast<int>(half_sin2.size());
  for (int j = 0; j < np; ++j) w.kr[j] = 0.5 * k * std::sqrt(t.d2 + t.c4 * half_sin2(j));
  axisymmetric_cos_sin(np, w.kr.data(), w.cos_kr.data(), w.sin_kr.data());  // of kR/2
  for (int j = 0; j < np; ++j) {
    const double s2 = half_sin2(j);
    const double kr = 2.0 * w.kr[j];
    const double inv_r = k / kr;
    const double sh = w.sin_kr[j], ch = w.cos_kr[j];
    const double s = 2.0 * sh * ch, cm1 = -2.0 * sh * sh;  // sin kR, cos kR - 1
    const double g = kAxiInv4Pi * inv_r;
    fg_re[j] = cm1 * g;  // (e^{-ikR} - 1) / (4 pi R)
    fg_im[j] = -s * g;
    const double hp = -(t.q + t.p2 * s2) * g * inv_r * inv_r;  // dG0/dn
    // e^{-ikR}(1 + ikR) - 1 = (cos kR - 1 + kR sin kR) + i (kR cos kR - sin kR)
    fh_re[j] = (cm1 + kr * s) * hp;
    fh_im[j] = (kr * (1.0 + cm1) - s) * hp;
    f0g[j] = g;
    f0h[j] = hp;
  }
}

// The phi-integrands at every node of w.nodes (Sec. 1, 2), each on its rule: node i of the far
// (near) ones in columns 4 i..4 i + 3 of w.f_far (w.f_near) and 2 i, 2 i + 1 of w.f0_near.
// Returns the counts of far and near nodes.
std::pair<int, int> axi_phi_integrands(double rx, double zx, AxiWork& w) {
  int n_far = 0, n_near = 0;
  for (const AxiNode& y : w.nodes) (y.subtract ? n_near : n_far) += 1;
  // (buffers grow only: no allocation per row once the largest row has been seen)
  if (w.f_far.cols() < 4 * n_far) w.f_far.resize(w.phi_far.intervals + 1, 4 * n_far);
  if (w.f_near.cols() < 4 * n_near) w.f_near.resize(w.phi_near.intervals + 1, 4 * n_near);
  if (w.f0_near.cols() < 2 * n_near) w.f0_near.resize(w.phi_near.intervals + 1, 2 * n_near);
  int i_far = 0, i_near = 0;
  for (const AxiNode& y : w.nodes) {
    const AxiPairTerms t = axi_pair_terms(rx, zx, y);
    if (!y.subtract) {
      axi_far_integrands(t, 4 * i_far, w);
      ++i_far;
    } else {
      axi_near_integrands(t, 4 * i_near, 2 * i_near, w);
      ++i_near;
    }
  }
  return {n_far, n_near};
}

// The moments of all orders at once, (w_j cos(n phi_j)) x integrands (Sec. 1), and each node's,
// weighted, added to its element's entry of w.row_g, w.row_h (near nodes: the subtracted part
// with the static one's (cos(n phi) - 1)-moment, Sec. 2).
void axi_add_moments(int n_far, int n_near, AxiWork& w) {
  const int nn = static_cast<int>(w.phi_far.cos_n.rows());
  w.mom_far.noalias() = w.phi_far.cos_n * w.f_far.leftCols(4 * n_far);
  w.mom_near.noalias() = w.phi_near.cos_n * w.f_near.leftCols(4 * n_near);
  w.mom0_near.noalias() = w.phi_near.cos_n_m1 * w.f0_near.leftCols(2 * n_near);
  int i_far = 0, i_near = 0;
  for (const AxiNode& y : w.nodes) {
    const Eigen::MatrixXd& mom = y.subtract ? w.mom_near : w.mom_far;
    const int col = 4 * (y.subtract ? i_near : i_far);
    for (int n = 0; n < nn; ++n) {
      axi_cd g(mom(n, col), mom(n, col + 1));
      axi_cd h(mom(n, col + 2), mom(n, col + 3));
      if (y.subtract) {
        g += w.mom0_near(n, 2 * i_near);
        h += w.mom0_near(n, 2 * i_near + 1);
      }
      w.row_g(n, y.element) += y.weight * g;
      w.row_h(n, y.element) += y.weight * h;
    }
    (y.subtract ? i_near : i_far) += 1;
  }
}

// One row of the equations: the order-n integrals over every element, int r_y ds int K cos(n
// phi) dphi for K = G and dG/dn_y, of the observation point x (on element `singular`, its
// midpoint, or -1 for an interior point), into w.row_g, w.row_h: the phi-rules' moments plus the
// static parts, which are the same for all orders.
void axi_row(const AxiMesh& mesh, const Eigen::Vector2d& x, int singular, AxiWork& w) {
  const int ne = static_cast<int>(mesh.elements.size());
  const int nn = static_cast<int>(w.phi_far.cos_n.rows());
  w.row_g.setZero(nn, ne);
  w.row_h.setZero(nn, ne);
  w.static_g.setZero(ne);
  w.static_h.setZero(ne);
  axi_row_nodes(mesh, x, singular, w);
  axi_add_subtracted_statics(x.x(), x.y(), w);
  const auto [n_far, n_near] = axi_phi_integrands(x.x(), x.y(), w);
  axi_add_moments(n_far, n_near, w);
  for (int n = 0; n < nn; ++n) {
    w.row_g.row(n) += w.static_g.transpose().cast<axi_cd>();
    w.row_h.row(n) += w.static_h.transpose().cast<axi_cd>();
  }
}

double axi_order_weight(int n) {
  return n == 0 ? 2.0 * kAxiPi : kAxiPi;
}

// The wavenumber, fluid and options of a call checked (see radiated_power_matrices).
void axi_check_call(double k, const Fluid& fluid, const AxisymmetricBemOptions& options) {
  if (!(k > 0.0) || !std::isfinite(k))
    throw std::invalid_argument("axisymmetric BEM: wavenumber k = " + std::to_string(k) +
                                " 1/m; radiation needs a finite k > 0");
  if (!(fluid.density > 0.0) || !(fluid.sound_speed > 0.0))
    throw std::invalid_argument(
        "axisymmetric BEM: the fluid needs density > 0 and sound speed > 0");
  if (options.gauss_points < 1 || options.gauss_points > 20)
    throw std::invalid_argument("axisymmetric BEM: gauss_points " +
                                std::to_string(options.gauss_points) + " outside 1..20");
  if (options.chief_points < 0)
    throw std::invalid_argument("axisymmetric BEM: chief_points " +
                                std::to_string(options.chief_points) + " < 0");
  if (options.phi_intervals < 0)
    throw std::invalid_argument("axisymmetric BEM: phi_intervals " +
                                std::to_string(options.phi_intervals) + " < 0");
}

// The orders with a pattern, ascending; each pattern checked against the ne elements.
std::vector<int> axi_pattern_orders(const std::vector<Eigen::MatrixXd>& patterns, int ne) {
  std::vector<int> orders;
  for (std::size_t n = 0; n < patterns.size(); ++n) {
    if (patterns[n].size() == 0) continue;
    if (patterns[n].rows() != ne)
      throw std::invalid_argument("axisymmetric BEM: the pattern of order " + std::to_string(n) +
                                  " has " + std::to_string(patterns[n].rows()) +
                                  " rows; the generator has " + std::to_string(ne) + " elements");
    if (!patterns[n].allFinite())
      throw std::invalid_argument("axisymmetric BEM: the pattern of order " + std::to_string(n) +
                                  " has non-finite velocities");
    orders.push_back(static_cast<int>(n));
  }
  return orders;
}

// The rules and buffers of one call at wavenumber k for the given orders (ascending).
AxiWork axi_work(const AxiMesh& mesh, double k, const std::vector<int>& orders,
                 const AxisymmetricBemOptions& options) {
  AxiWork w;
  w.k = k;
  w.gauss = axisymmetric_gauss_legendre(options.gauss_points);
  w.gauss_singular = axisymmetric_gauss_legendre(8);
  w.log_singular = axisymmetric_log_gauss(8);
  // Sec. 1: 2 M > k r_max + n_max with a margin for the tails of the Fourier coefficients of
  // e^{-ikR(phi)} (Bessel-like, decaying past order k r + (k r)^{1/3}). Sec. 2: the near rule
  // takes 3 M / 2 intervals: its integrands (d < tau rho) have the phase rate
  // k rho cos(phi/2) phi'(t) <= 1.2 k rho in t, and cos(n phi) the rate n phi' <= 2 n.
  const int n_max = orders.back();
  const double kr = k * mesh.r_max;
  const int intervals =
      options.phi_intervals > 0
          ? options.phi_intervals
          : std::max(16,
                     static_cast<int>(std::ceil(0.5 * (kr + n_max) + 2.0 * std::cbrt(kr) + 10)));
  const int near_intervals = (3 * intervals + 1) / 2;
  w.phi_far = axi_phi_rule(intervals, orders, false);
  w.phi_near = axi_phi_rule(near_intervals, orders, true);
  w.f_far.resize(intervals + 1, 0);
  w.f_near.resize(near_intervals + 1, 0);
  w.f0_near.resize(near_intervals + 1, 0);
  w.tau = 12.0 / std::max(1.0, 2.0 * intervals - kr);
  w.kr.resize(near_intervals + 1);
  w.cos_kr.resize(near_intervals + 1);
  w.sin_kr.resize(near_intervals + 1);
  return w;
}

// The order-n integrals of every row (surface collocation points, then CHIEF points) into
// g_n[o], h_n[o] (rows x elements), o indexing the orders of w's phi-rules.
void axi_assemble(const AxiMesh& mesh, const std::vector<Eigen::Vector2d>& chief, AxiWork& w,
                  std::vector<Eigen::MatrixXcd>& g_n, std::vector<Eigen::MatrixXcd>& h_n) {
  const int ne = static_cast<int>(mesh.elements.size());
  const int rows = ne + static_cast<int>(chief.size());
  const int no = static_cast<int>(w.phi_far.cos_n.rows());
  g_n.resize(no);
  h_n.resize(no);
  for (int o = 0; o < no; ++o) {
    g_n[o].resize(rows, ne);
    h_n[o].resize(rows, ne);
  }
  for (int row = 0; row < rows; ++row) {
    const bool surface = row < ne;
    axi_row(mesh, surface ? mesh.elements[row].midpoint : chief[row - ne], surface ? row : -1, w);
    for (int o = 0; o < no; ++o) {
      g_n[o].row(row) = w.row_g.row(o);
      h_n[o].row(row) = w.row_h.row(o);
    }
  }
}

// The surface pressures of the patterns (a column each) from the order's integrals h (turned into
// the system matrix in place) and g: [1/2 I - H; -H_chief] p = i k rho c [G; G_chief] v, least
// squares (Householder QR).
Eigen::MatrixXcd axi_surface_pressures(Eigen::MatrixXcd& h, const Eigen::MatrixXcd& g,
                                       const Eigen::MatrixXd& pattern, axi_cd ik_rho_c) {
  const Eigen::Index ne = g.cols();
  Eigen::MatrixXcd& a = h;
  a = -a;
  a.topRows(ne).diagonal().array() += 0.5;
  const Eigen::MatrixXcd rhs = ik_rho_c * (g * pattern.cast<axi_cd>());
  return a.householderQr().solve(rhs);
}

// The power matrix of order n from the patterns and their surface pressures p.
// W = (1/2) Re (V a)^H D (P a) = (1/2) Re a^H M a, M = V^T D P, D = diag(r_ds c_n).
// By reciprocity (int p_1 v_2 dS = int p_2 v_1 dS) the exact M is complex symmetric, so its
// Hermitian part is Re M: the power matrix of real patterns is real symmetric. Collocation
// keeps that symmetry only to the discretisation error, and the antisymmetric part of the
// discrete M, small against the reactive (mass-like) impedance, is not small against the
// radiation resistance of a weak radiator (a high-order pattern at low k a): taken into the
// Hermitian part (M + M^H)/2 it would make P_n indefinite. So M is symmetrised first:
// P_n = (1/2) Re (M + M^T)/2, exact where M is.
Eigen::MatrixXcd axi_power_matrix(const AxiMesh& mesh, int n, const Eigen::MatrixXd& pattern,
                                  const Eigen::MatrixXcd& p) {
  const int ne = static_cast<int>(mesh.elements.size());
  Eigen::VectorXd d(ne);
  for (int e = 0; e < ne; ++e) d(e) = mesh.elements[e].r_ds * axi_order_weight(n);
  const Eigen::MatrixXcd m = pattern.transpose().cast<axi_cd>() * (d.asDiagonal() * p);
  const Eigen::MatrixXd resistance = 0.5 * (m.real() + m.real().transpose());
  return (0.5 * resistance).cast<axi_cd>();
}

}  // namespace

std::vector<AxisymmetricElement> axisymmetric_elements(const AxisymmetricGenerator& generator) {
  return axi_mesh(generator).elements;
}

std::vector<Eigen::Vector2d> axisymmetric_chief_points(const AxisymmetricGenerator& generator,
                                                       int count) {
  if (count < 0)
    throw std::invalid_argument("CHIEF points: count " + std::to_string(count) + " < 0");
  return axi_chief_points(axi_mesh(generator), count);
}

std::vector<Eigen::MatrixXcd> radiated_power_matrices(const AxisymmetricGenerator& generator,
                                                      double k,
                                                      const std::vector<Eigen::MatrixXd>& patterns,
                                                      const Fluid& fluid,
                                                      const AxisymmetricBemOptions& options) {
  axi_check_call(k, fluid, options);
  const AxiMesh mesh = axi_mesh(generator);
  const std::vector<int> orders =
      axi_pattern_orders(patterns, static_cast<int>(mesh.elements.size()));
  std::vector<Eigen::MatrixXcd> result(patterns.size());
  if (orders.empty()) return result;
  const std::vector<Eigen::Vector2d> chief = axi_chief_points(mesh, options.chief_points);
  AxiWork w = axi_work(mesh, k, orders, options);
  std::vector<Eigen::MatrixXcd> g_n, h_n;
  axi_assemble(mesh, chief, w, g_n, h_n);
  const axi_cd ik_rho_c(0.0, k * fluid.impedance());
  for (std::size_t o = 0; o < orders.size(); ++o) {
    const int n = orders[o];
    const Eigen::MatrixXcd p = axi_surface_pressures(h_n[o], g_n[o], patterns[n], ik_rho_c);
    result[n] = axi_power_matrix(mesh, n, patterns[n], p);
  }
  return result;
}

double radiation_efficiency(const AxisymmetricGenerator& generator, int n, double k,
                            const Eigen::VectorXd& pattern, const Fluid& fluid,
                            const AxisymmetricBemOptions& options) {
  if (n < 0)
    throw std::invalid_argument("radiation efficiency: circumferential order " + std::to_string(n) +
                                " < 0");
  const std::vector<AxisymmetricElement> elements = axisymmetric_elements(generator);
  if (pattern.size() != static_cast<Eigen::Index>(elements.size()))
    throw std::invalid_argument("radiation efficiency: the pattern has " +
                                std::to_string(pattern.size()) + " values; the generator has " +
                                std::to_string(elements.size()) + " elements");
  double mean_square = 0.0;  // S <v^2> = (1/2) sum |v_e|^2 r_ds c_n
  for (std::size_t e = 0; e < elements.size(); ++e)
    mean_square += 0.5 * pattern(e) * pattern(e) * elements[e].r_ds * axi_order_weight(n);
  if (!(mean_square > 0.0))
    throw std::invalid_argument(
        "radiation efficiency: the velocity pattern vanishes (or is not "
        "finite): no mean-square velocity to refer the power to");
  std::vector<Eigen::MatrixXd> patterns(n + 1);
  patterns[n] = pattern;
  const double power =
      radiated_power_matrices(generator, k, patterns, fluid, options)[n](0, 0).real();
  return power / (fluid.impedance() * mean_square);
}

}  // namespace rollnoise::acoustics
