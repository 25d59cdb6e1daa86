#include "dynamics/rail_section.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>

#include "core/errors.hpp"
#include "fem/triangle6.hpp"

namespace rollnoise::dynamics {

std::vector<Eigen::Vector2d> uic60_outline() {
  // Half outline (y >= 0) in mm from the foot's centre, upwards: foot (150 mm wide, 9.5 mm at the
  // tip, sloping top), web (16.5 mm), head underside, head side (72 mm wide), crown.
  static const std::array<std::array<double, 2>, 14> half = {{{0.0, 0.0},
                                                              {75.0, 0.0},
                                                              {75.0, 10.5},
                                                              {30.0, 18.5},
                                                              {14.0, 25.0},
                                                              {8.25, 36.0},
                                                              {8.25, 120.0},
                                                              {16.0, 128.0},
                                                              {36.0, 133.0},
                                                              {36.0, 158.0},
                                                              {33.0, 166.5},
                                                              {25.0, 170.8},
                                                              {12.0, 171.8},
                                                              {0.0, 172.0}}};
  std::vector<Eigen::Vector2d> outline;
  for (const auto& p : half) outline.emplace_back(1e-3 * p[0], 1e-3 * p[1]);
  for (int i = static_cast<int>(half.size()) - 2; i >= 1; --i)
    outline.emplace_back(-1e-3 * half[i][0], 1e-3 * half[i][1]);
  return outline;
}

double rail_head_bottom(const std::vector<Eigen::Vector2d>& outline) {
  if (outline.empty()) throw InputError("rail_section", "empty rail outline");
  double lo = outline[0].y(), hi = lo;
  for (const auto& p : outline) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
  return lo + (133.0 / 172.0) * (hi - lo);
}

std::vector<SectionPoint> section_points(const fem::QuadraticTriangleMesh& mesh, int t) {
  const Eigen::Matrix<double, 2, 6> xy = fem::triangle6_coordinates(mesh.nodes, mesh.triangles[t]);
  std::vector<SectionPoint> points;
  for (const fem::TrianglePoint& g : fem::triangle_gauss_degree5()) {
    SectionPoint p;
    p.shape = fem::triangle6_shape(g.xi, g.eta);
    const Eigen::Matrix<double, 2, 6> dN = fem::triangle6_shape_derivatives(g.xi, g.eta);
    const Eigen::Matrix2d J = fem::triangle6_jacobian(dN, xy);
    const double det = J.determinant();
    if (!(det > 0.0)) throw NumericalError("rail section: inverted or degenerate triangle");
    p.gradient = J.inverse() * dN;
    p.position = xy * p.shape;
    p.weight = g.weight * det;
    points.push_back(p);
  }
  return points;
}

namespace {

// Area, centroid and second moments about the centroid.
void area_moments(const fem::QuadraticTriangleMesh& mesh, SectionProperties& s) {
  double a = 0.0;
  Eigen::Vector2d first(0.0, 0.0);
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (const SectionPoint& p : section_points(mesh, t)) {
      a += p.weight;
      first += p.weight * p.position;
      second += p.weight * p.position * p.position.transpose();
    }
  s.area = a;
  s.centroid = first / a;
  const Eigen::Matrix2d central = second - a * s.centroid * s.centroid.transpose();
  s.second_moment_zz = central(0, 0);
  s.second_moment_yy = central(1, 1);
  s.product_moment = central(0, 1);
}

}  // namespace

SectionProperties section_properties(const fem::QuadraticTriangleMesh& mesh) {
  SectionProperties s;
  area_moments(mesh, s);
  const int n = static_cast<int>(mesh.nodes.size());
  // Eq. (S1): stiffness of the Laplacian and the load Int grad(N_i).(z, -y) dA, centroidal axes.
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    for (const SectionPoint& p : section_points(mesh, t)) {
      const Eigen::Vector2d r = p.position - s.centroid;
      const Eigen::Matrix<double, 6, 6> ke = p.weight * p.gradient.transpose() * p.gradient;
      const Eigen::Matrix<double, 6, 1> fe = p.weight * (p.gradient.row(0).transpose() * r.y() -
                                                         p.gradient.row(1).transpose() * r.x());
      for (int i = 0; i < 6; ++i) {
        f(tri[i]) += fe(i);
        for (int j = 0; j < 6; ++j) K(tri[i], tri[j]) += ke(i, j);
      }
    }
  }
  // phi is fixed up to a constant: pin node 0 (phi = 0) and solve the rest.
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(n);
  phi.tail(n - 1) = K.bottomRightCorner(n - 1, n - 1).ldlt().solve(f.tail(n - 1));
  // Eqs. (S2), (S3) integrands.
  double J = 0.0, phi_y = 0.0, phi_z = 0.0;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    Eigen::Matrix<double, 6, 1> pe;
    for (int i = 0; i < 6; ++i) pe(i) = phi(mesh.triangles[t][i]);
    for (const SectionPoint& p : section_points(mesh, t)) {
      const Eigen::Vector2d r = p.position - s.centroid;
      const Eigen::Vector2d g = p.gradient * pe;
      const double value = p.shape.dot(pe);
      J += p.weight * (r.squaredNorm() + r.x() * g.y() - r.y() * g.x());
      phi_y += p.weight * value * r.x();
      phi_z += p.weight * value * r.y();
    }
  }
  s.torsion_constant = J;
  Eigen::Matrix2d A;
  A << s.second_moment_zz, -s.product_moment, s.product_moment, -s.second_moment_yy;
  const Eigen::Vector2d zy = A.partialPivLu().solve(Eigen::Vector2d(phi_y, phi_z));
  s.shear_centre = Eigen::Vector2d(zy(1), zy(0));
  // Eq. (S4): phi_P = phi - z_p y + y_p z, its variance over the section.
  double m0 = 0.0, m2 = 0.0;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    Eigen::Matrix<double, 6, 1> pe;
    for (int i = 0; i < 6; ++i) pe(i) = phi(mesh.triangles[t][i]);
    for (const SectionPoint& p : section_points(mesh, t)) {
      const Eigen::Vector2d r = p.position - s.centroid;
      const double v = p.shape.dot(pe) - zy(0) * r.x() + zy(1) * r.y();
      m0 += p.weight * v;
      m2 += p.weight * v * v;
    }
  }
  s.warping_constant = m2 - m0 * m0 / s.area;
  return s;
}

}  // namespace rollnoise::dynamics
