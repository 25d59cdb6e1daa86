#include "acoustics/bem2d.hpp"

#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"
#include "linalg/gauss_legendre.hpp"

namespace rollnoise::acoustics {

namespace {

using cdouble = std::complex<double>;
using Eigen::Vector2d;

using linalg::GaussRule;

/// H_0^(2)(z) = J_0 - i Y_0 and H_1^(2)(z) = J_1 - i Y_1 (z > 0).
inline void hankel2_01(double z, cdouble& h0, cdouble& h1) {
  h0 = cdouble(gsl_sf_bessel_J0(z), -gsl_sf_bessel_Y0(z));
  h1 = cdouble(gsl_sf_bessel_J1(z), -gsl_sf_bessel_Y1(z));
}

/// Twice the signed area of a polygon (shoelace): > 0 counter-clockwise in (y, z).
double twice_signed_area(const std::vector<Vector2d>& p) {
  double s = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vector2d& a = p[i];
    const Vector2d& b = p[(i + 1) % p.size()];
    s += a.x() * b.y() - b.x() * a.y();
  }
  return s;
}

/// Distance from x to the segment [a, b] and the parameter t in [0, 1] of the nearest point.
double segment_distance(const Vector2d& x, const Vector2d& a, const Vector2d& b, double* t_out) {
  const Vector2d ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  if (t_out != nullptr) *t_out = t;
  return (x - (a + t * ab)).norm();
}

/// Proper crossing of two segments (shared end points do not count).
bool segments_cross(const Vector2d& p1, const Vector2d& p2, const Vector2d& q1,
                    const Vector2d& q2) {
  auto orient = [](const Vector2d& a, const Vector2d& b, const Vector2d& c) {
    const double v = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    return (v > 0.0) - (v < 0.0);
  };
  const int o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
  const int o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

/// Point in polygon (crossing number).
bool inside_polygon(const Vector2d& x, const std::vector<Vector2d>& p) {
  bool in = false;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y() > x.y()) != (p[j].y() > x.y()) &&
        x.x() < (p[j].x() - p[i].x()) * (x.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x())
      in = !in;
  }
  return in;
}

/// The outline checked (finite, >= 3 distinct points, non-zero area, not self-intersecting) and
/// made counter-clockwise; a repeated closing point and repeated consecutive points removed.
std::vector<Vector2d> checked_outline(const Section2d& section) {
  std::vector<Vector2d> p;
  for (const Vector2d& q : section.outline) {
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()))
      throw std::invalid_argument("bem2d: the section outline has a non-finite coordinate");
    if (p.empty() || (q - p.back()).norm() > 0.0) p.push_back(q);
  }
  while (p.size() > 1 && (p.front() - p.back()).norm() == 0.0) p.pop_back();
  if (p.size() < 3)
    throw std::invalid_argument(
        "bem2d: a cross-section outline needs at least 3 distinct points (a closed polygon)");
  double size = 0.0;
  for (const Vector2d& q : p) size = std::max(size, (q - p[0]).norm());
  const double area2 = twice_signed_area(p);
  if (!(std::abs(area2) > 1e-12 * size * size))
    throw std::invalid_argument("bem2d: the section outline encloses no area");
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing side
      if (segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]))
        throw std::invalid_argument("bem2d: the section outline intersects itself (sides " +
                                    std::to_string(i) + " and " + std::to_string(j) + ")");
    }
  if (area2 < 0.0) std::reverse(p.begin(), p.end());
  return p;
}

struct Model {
  std::vector<std::vector<Vector2d>> outlines;  // counter-clockwise
  std::vector<BoundaryElement2d> elements;      // radiating elements
  bool ground = false;
  double ground_z = 0.0;
  double max_length = 0.0;  // longest element (m)
};

Model build_model(const std::vector<Section2d>& bodies, const Bem2dOptions& o) {
  if (bodies.empty()) throw std::invalid_argument("bem2d: no section given");
  if (o.target_elements < 3)
    throw std::invalid_argument("bem2d: target_elements must be at least 3, got " +
                                std::to_string(o.target_elements));
  if (!(o.max_element_length >= 0.0) || !std::isfinite(o.max_element_length))
    throw std::invalid_argument("bem2d: max_element_length must be >= 0 m (0: no bound)");
  if (o.gauss_points < 2 || o.gauss_points > 64)
    throw std::invalid_argument("bem2d: gauss_points must lie in 2..64, got " +
                                std::to_string(o.gauss_points));
  if (o.chief_points < 0)
    throw std::invalid_argument("bem2d: chief_points must be >= 0 (0: plain formulation)");
  Model m;
  double perimeter = 0.0, zmin = std::numeric_limits<double>::infinity(), size = 0.0;
  for (const Section2d& s : bodies) {
    m.outlines.push_back(checked_outline(s));
    const auto& p = m.outlines.back();
    for (size_t i = 0; i < p.size(); ++i) {
      perimeter += (p[(i + 1) % p.size()] - p[i]).norm();
      zmin = std::min(zmin, p[i].y());
      size = std::max(size, (p[i] - p[0]).norm());
    }
  }
  double h = perimeter / o.target_elements;
  if (o.max_element_length > 0.0) h = std::min(h, o.max_element_length);

  m.ground = o.ground_plane;
  const double tol = 1e-9 * std::max(size, 1e-3);
  if (m.ground) {
    m.ground_z = std::isnan(o.ground_z) ? zmin : o.ground_z;
    if (!std::isfinite(m.ground_z))
      throw std::invalid_argument("bem2d: the ground plane height must be finite");
    if (zmin < m.ground_z - tol)
      throw std::invalid_argument(
          "bem2d: the section extends below the rigid ground plane (lowest z " +
          std::to_string(zmin) + " m < ground_z " + std::to_string(m.ground_z) + " m)");
  }
  for (const auto& p : m.outlines) {
    for (size_t i = 0; i < p.size(); ++i) {
      const Vector2d a = p[i], b = p[(i + 1) % p.size()];
      const double side = (b - a).norm();
      // A side lying on the rigid plane is in contact with it: no radiating element.
      if (m.ground && std::abs(a.y() - m.ground_z) <= tol && std::abs(b.y() - m.ground_z) <= tol)
        continue;
      const int n = std::max(1, static_cast<int>(std::ceil(side / h - 1e-9)));
      const Vector2d t = (b - a) / side;
      // Counter-clockwise: the body lies to the left of t, the outward normal to the right.
      const Vector2d normal(t.y(), -t.x());
      for (int e = 0; e < n; ++e) {
        BoundaryElement2d el;
        el.start = a + (b - a) * (static_cast<double>(e) / n);
        el.end = a + (b - a) * (static_cast<double>(e + 1) / n);
        el.normal = normal;
        el.length = side / n;
        m.max_length = std::max(m.max_length, el.length);
        m.elements.push_back(el);
      }
    }
  }
  if (m.elements.empty())
    throw std::invalid_argument("bem2d: no radiating boundary left (every side on the ground)");
  return m;
}

/// CHIEF points inside each body (see the header): grid candidates, depth >= 0.3 max depth,
/// farthest-point sampling starting from the deepest.
std::vector<Vector2d> chief_points(const Model& m, int per_body) {
  std::vector<Vector2d> chosen_all;
  if (per_body <= 0) return chosen_all;
  constexpr int kGrid = 48;
  for (const auto& p : m.outlines) {
    Vector2d lo = p[0], hi = p[0];
    for (const Vector2d& q : p) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    std::vector<Vector2d> cand;
    std::vector<double> depth;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        // cell centres, offset by an irrational fraction so that symmetric sections do not put
        // every candidate on a symmetry line
        const Vector2d x(lo.x() + (hi.x() - lo.x()) * (i + 0.5 + 0.0917) / (kGrid + 0.2),
                         lo.y() + (hi.y() - lo.y()) * (j + 0.5 + 0.0613) / (kGrid + 0.2));
        if (!inside_polygon(x, p)) continue;
        double d = std::numeric_limits<double>::infinity();
        for (size_t s = 0; s < p.size(); ++s)
          d = std::min(d, segment_distance(x, p[s], p[(s + 1) % p.size()], nullptr));
        cand.push_back(x);
        depth.push_back(d);
      }
    // A sliver thinner than the grid: no CHIEF point (one outside the body would be wrong).
    if (cand.empty()) continue;
    const double dmax = *std::max_element(depth.begin(), depth.end());
    std::vector<Vector2d> pool;
    for (size_t i = 0; i < cand.size(); ++i)
      if (depth[i] >= 0.3 * dmax) pool.push_back(cand[i]);
    // the deepest candidate first
    std::vector<Vector2d> chosen{
        cand[std::max_element(depth.begin(), depth.end()) - depth.begin()]};
    std::vector<double> dist(pool.size());
    for (size_t i = 0; i < pool.size(); ++i) dist[i] = (pool[i] - chosen[0]).norm();
    while (static_cast<int>(chosen.size()) < per_body && chosen.size() < pool.size()) {
      const size_t far = std::max_element(dist.begin(), dist.end()) - dist.begin();
      if (!(dist[far] > 0.0)) break;
      chosen.push_back(pool[far]);
      for (size_t i = 0; i < pool.size(); ++i)
        dist[i] = std::min(dist[i], (pool[i] - pool[far]).norm());
    }
    chosen_all.insert(chosen_all.end(), chosen.begin(), chosen.end());
  }
  return chosen_all;
}

/// Int over the element [a, b] (unit normal n) of G(x, y) and dG/dn_y(x, y), y(t) = a + t (b - a),
/// t in [t0, t1], by the rule: adds to s and d.
void add_panel(const Vector2d& x, const Vector2d& a, const Vector2d& b, const Vector2d& n, double k,
               double t0, double t1, const GaussRule& rule, cdouble& s, cdouble& d) {
  const Vector2d ab = b - a;
  const double jac = ab.norm() * (t1 - t0);
  cdouble h0, h1;
  for (size_t q = 0; q < rule.nodes.size(); ++q) {
    const Vector2d y = a + (t0 + (t1 - t0) * rule.nodes[q]) * ab;
    const Vector2d r = y - x;
    const double R = r.norm();
    hankel2_01(k * R, h0, h1);
    const double w = rule.weights[q] * jac;
    s += w * cdouble(0.0, -0.25) * h0;                      // G = -(i/4) H_0^(2)(kR)
    d += w * cdouble(0.0, 0.25 * k) * h1 * (r.dot(n) / R);  // dG/dn_y = (ik/4) H_1^(2) r.n/R
  }
}

/// The regular (non-self) element integrals, graded towards the point of the element nearest to
/// x when x is closer than one element length: sub-intervals from that point of lengths d, d,
/// 2d, 4d, ... (each no longer than its distance from x); farther than 4 element lengths, the
/// far rule (half the points; the kernel varies on the scale of the distance and of 1/k, and
/// the mesh has >= 4 elements per wavelength).
void element_integrals(const Vector2d& x, const Vector2d& a, const Vector2d& b, const Vector2d& n,
                       double k, const GaussRule& rule, const GaussRule& far_rule, cdouble& s,
                       cdouble& d) {
  s = d = 0.0;
  double tstar = 0.0;
  const double L = (b - a).norm();
  const double dist = segment_distance(x, a, b, &tstar);
  if (dist >= 4.0 * L) {  // far: the kernel is smooth over the element, half the points suffice
    add_panel(x, a, b, n, k, 0.0, 1.0, far_rule, s, d);
    return;
  }
  if (dist >= L) {
    add_panel(x, a, b, n, k, 0.0, 1.0, rule, s, d);
    return;
  }
  if (!(dist > 1e-12 * L))
    throw std::logic_error("bem2d: a collocation point lies on another element");
  const double delta = dist / L;  // parameter length of the first sub-interval
  // to the right of t*
  for (double t = tstar; t < 1.0;) {
    const double len = std::max(delta, t - tstar);
    const double t1 = std::min(1.0, t + len);
    add_panel(x, a, b, n, k, t, t1, rule, s, d);
    t = t1;
  }
  // to the left of t*
  for (double t = tstar; t > 0.0;) {
    const double len = std::max(delta, tstar - t);
    const double t0 = std::max(0.0, t - len);
    add_panel(x, a, b, n, k, t0, t, rule, s, d);
    t = t0;
  }
}

/// The element's own single-layer integral Int_{-h}^{h} G(|t|) dt, the logarithm of G
/// subtracted and integrated analytically (header): G(t) + ln(t)/(2 pi) is smooth (to t^2 ln t)
/// and is integrated on [0, h/4] and [h/4, h] by the rule.
cdouble self_single_layer(double length, double k, const GaussRule& rule) {
  const double h = 0.5 * length;
  auto regular = [k](double t) {
    return cdouble(-0.25 * gsl_sf_bessel_Y0(k * t) + std::log(t) / (2.0 * kPi),
                   -0.25 * gsl_sf_bessel_J0(k * t));
  };
  cdouble reg = 0.0;
  for (const auto& [t0, t1] : {std::pair{0.0, 0.25 * h}, std::pair{0.25 * h, h}})
    for (size_t q = 0; q < rule.nodes.size(); ++q)
      reg += rule.weights[q] * (t1 - t0) * regular(t0 + (t1 - t0) * rule.nodes[q]);
  const double log_part = -(h * std::log(h) - h) / (2.0 * kPi);  // Int_0^h -(ln t)/(2 pi) dt
  return 2.0 * (log_part + reg);
}

Vector2d mirror(const Vector2d& p, double z0) {
  return Vector2d(p.x(), 2.0 * z0 - p.y());
}

void check_wavenumber(double k, const Model& m) {
  if (!(k > 0.0) || !std::isfinite(k))
    throw std::invalid_argument(
        "bem2d: the acoustic wavenumber k must be positive and finite, got " + std::to_string(k) +
        " 1/m");
  const double per_wavelength = 2.0 * kPi / (k * m.max_length);
  if (per_wavelength < 4.0)
    throw std::invalid_argument(
        "bem2d: mesh too coarse for the frequency: " + std::to_string(per_wavelength) +
        " elements per acoustic wavelength (at least 4, about 8 for 1 %); raise target_elements "
        "or set max_element_length");
}

/// Assembles and solves Eqs. (1)-(2): the element pressures for the given velocities.
Eigen::MatrixXcd solve_pressures(const Model& m, const std::vector<Vector2d>& chief, double k,
                                 const Eigen::MatrixXcd& v, const Fluid& fluid,
                                 const Bem2dOptions& o) {
  check_wavenumber(k, m);
  if (!(fluid.density > 0.0) || !(fluid.sound_speed > 0.0))
    throw std::invalid_argument("bem2d: the fluid needs a positive density and sound speed");
  const int n = static_cast<int>(m.elements.size());
  if (v.rows() != n)
    throw std::invalid_argument("bem2d: " + std::to_string(v.rows()) + " velocity rows for " +
                                std::to_string(n) + " boundary elements");
  const int nc = static_cast<int>(chief.size());
  const GaussRule rule = linalg::gauss_legendre_01(o.gauss_points);
  const GaussRule far_rule = linalg::gauss_legendre_01(std::max(2, o.gauss_points / 2));
  // Rows: c p(x_i) - Int p dG/dn = -Int G dp/dn, i.e. A p = B q, q = dp/dn = -i k rho c v.
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(n + nc, n), B(n + nc, n);
  for (int i = 0; i < n + nc; ++i) {
    const bool on_boundary = i < n;
    const Vector2d x = on_boundary ? m.elements[i].midpoint() : chief[i - n];
    for (int j = 0; j < n; ++j) {
      const BoundaryElement2d& e = m.elements[j];
      cdouble s, d;
      if (on_boundary && i == j) {
        s = self_single_layer(e.length, k, rule);  // dG/dn = 0 on the straight element itself
        d = 0.0;
      } else {
        element_integrals(x, e.start, e.end, e.normal, k, rule, far_rule, s, d);
      }
      if (m.ground) {  // the image element (mirrored end points and normal)
        cdouble si, di;
        const Vector2d ni(e.normal.x(), -e.normal.y());
        element_integrals(x, mirror(e.start, m.ground_z), mirror(e.end, m.ground_z), ni, k, rule,
                          far_rule, si, di);
        s += si;
        d += di;
      }
      A(i, j) = (on_boundary && i == j ? 0.5 : 0.0) - d;
      B(i, j) = -s;
    }
  }
  const Eigen::MatrixXcd q = cdouble(0.0, -k * fluid.impedance()) * v;  // Eq. (1)
  const Eigen::MatrixXcd rhs = B * q;
  if (nc == 0) return A.partialPivLu().solve(rhs);
  return A.householderQr().solve(rhs);  // least squares (CHIEF)
}

}  // namespace

std::vector<BoundaryElement2d> boundary_elements_2d(const std::vector<Section2d>& bodies,
                                                    const Bem2dOptions& options) {
  return build_model(bodies, options).elements;
}

std::vector<BoundaryElement2d> boundary_elements_2d(const Section2d& section,
                                                    const Bem2dOptions& options) {
  return boundary_elements_2d(std::vector<Section2d>{section}, options);
}

std::vector<Eigen::Vector2d> chief_points_2d(const std::vector<Section2d>& bodies,
                                             const Bem2dOptions& options) {
  return chief_points(build_model(bodies, options), options.chief_points);
}

Eigen::MatrixXcd surface_pressure_2d(const std::vector<Section2d>& bodies, double k,
                                     const Eigen::MatrixXcd& normal_velocities, const Fluid& fluid,
                                     const Bem2dOptions& options) {
  const Model m = build_model(bodies, options);
  return solve_pressures(m, chief_points(m, options.chief_points), k, normal_velocities, fluid,
                         options);
}

Eigen::MatrixXcd radiated_power_matrix_2d(const std::vector<Section2d>& bodies, double k,
                                          const Eigen::MatrixXd& patterns, const Fluid& fluid,
                                          const Bem2dOptions& options) {
  const Model m = build_model(bodies, options);
  if (patterns.cols() < 1) throw std::invalid_argument("bem2d: no velocity pattern given");
  const Eigen::MatrixXcd v = patterns.cast<cdouble>();
  const Eigen::MatrixXcd p =
      solve_pressures(m, chief_points(m, options.chief_points), k, v, fluid, options);
  // W' = (1/2) Re sum_j L_j p_j conj(v_j) = a^H [(C + C^H) / 4] a, C = V^T diag(L) P.
  Eigen::VectorXd L(m.elements.size());
  for (size_t j = 0; j < m.elements.size(); ++j) L[j] = m.elements[j].length;
  const Eigen::MatrixXcd C = v.transpose() * L.asDiagonal() * p;
  return 0.25 * (C + C.adjoint());
}

Eigen::MatrixXcd radiated_power_matrix_2d(const Section2d& section, double k,
                                          const Eigen::MatrixXd& patterns, const Fluid& fluid,
                                          const Bem2dOptions& options) {
  return radiated_power_matrix_2d(std::vector<Section2d>{section}, k, patterns, fluid, options);
}

Eigen::VectorXd rigid_translation_pattern(const Section2d& section,
                                          const Eigen::Vector2d& direction,
                                          const Bem2dOptions& options) {
  const double norm = direction.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw std::invalid_argument("bem2d: a translation needs a non-zero, finite direction");
  const Vector2d d = direction / norm;
  const auto elements = boundary_elements_2d(section, options);
  Eigen::VectorXd v(elements.size());
  for (size_t j = 0; j < elements.size(); ++j) v[j] = d.dot(elements[j].normal);
  return v;
}

std::vector<RigidRadiation2d> rigid_translation_radiation_2d(
    const Section2d& section, double k, const std::vector<Eigen::Vector2d>& directions,
    const Fluid& fluid, const Bem2dOptions& options) {
  if (directions.empty()) throw std::invalid_argument("bem2d: no translation direction given");
  const auto elements = boundary_elements_2d(section, options);
  Eigen::MatrixXd patterns(elements.size(), directions.size());
  for (size_t c = 0; c < directions.size(); ++c)
    patterns.col(c) = rigid_translation_pattern(section, directions[c], options);
  const Eigen::MatrixXcd P = radiated_power_matrix_2d(section, k, patterns, fluid, options);
  std::vector<RigidRadiation2d> out(directions.size());
  for (size_t c = 0; c < directions.size(); ++c) {
    double width = 0.0;  // Int (d.n)^2 ds
    for (size_t j = 0; j < elements.size(); ++j)
      width += elements[j].length * patterns(j, c) * patterns(j, c);
    const double power = P(c, c).real();  // W' at unit velocity amplitude, <v^2> = 1/2
    out[c].radiating_width = width;
    out[c].power_per_mean_square_velocity = 2.0 * power;
    out[c].efficiency = width > 0.0 ? power / (fluid.impedance() * 0.5 * width) : 0.0;
  }
  return out;
}

RigidRadiation2d rigid_translation_radiation_2d(const Section2d& section, double k,
                                                const Eigen::Vector2d& direction,
                                                const Fluid& fluid, const Bem2dOptions& options) {
  return rigid_translation_radiation_2d(section, k, std::vector<Eigen::Vector2d>{direction}, fluid,
                                        options)[0];
}

double axial_wave_efficiency(double k, double kappa,
                             const std::function<double(double)>& efficiency_2d) {
  if (!(k > 0.0) || !std::isfinite(k))
    throw std::invalid_argument("bem2d: the acoustic wavenumber k must be positive and finite");
  if (!std::isfinite(kappa))
    throw std::invalid_argument("bem2d: the axial wavenumber kappa must be finite");
  if (std::abs(kappa) >= k) return 0.0;  // subsonic wave along the body: no far field
  const double kr = std::sqrt((k - kappa) * (k + kappa));
  return (k / kr) * efficiency_2d(kr);
}

}  // namespace rollnoise::acoustics
