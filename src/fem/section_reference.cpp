#include "fem/section_reference.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace rollnoise::fem {

PlaneSectionProperties section_properties(const std::vector<Eigen::Vector2d>& polygon) {
  // Green's theorem over the edges (a_i, b_i) -> (a_j, b_j), c = a_i b_j - a_j b_i:
  // A = sum c / 2, S_a = sum c (a_i + a_j) / 6, I_aa(origin) = sum c (a_i^2 + a_i a_j + a_j^2)
  // / 12.
  double area = 0, sa = 0, sb = 0, iaa = 0, ibb = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    const double c = p.x() * q.y() - q.x() * p.y();
    area += c / 2;
    sa += c * (p.x() + q.x()) / 6;
    sb += c * (p.y() + q.y()) / 6;
    iaa += c * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) / 12;
    ibb += c * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) / 12;
  }
  if (area == 0.0) throw std::invalid_argument("section_properties: polygon of zero area");
  PlaneSectionProperties s;
  const double sign = area > 0 ? 1.0 : -1.0;
  s.area = sign * area;
  s.centroid = Eigen::Vector2d(sa / area, sb / area);
  s.i_aa = sign * iaa - s.area * s.centroid.x() * s.centroid.x();
  s.i_bb = sign * ibb - s.area * s.centroid.y() * s.centroid.y();
  return s;
}

std::vector<Eigen::Vector2d> clip_half_plane(const std::vector<Eigen::Vector2d>& polygon,
                                             const Eigen::Vector2d& normal, double offset) {
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    const double dp = normal.dot(p) - offset, dq = normal.dot(q) - offset;
    if (dp >= 0) out.push_back(p);
    if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return out;
}

double cowper_rectangle_shear_coefficient(double poisson_ratio) {
  return 10.0 * (1.0 + poisson_ratio) / (12.0 + 11.0 * poisson_ratio);
}

double thin_ring_inplane_frequency(const RingSection& ring, const IsotropicMaterial& material,
                                   int n) {
  if (n < 2) throw std::invalid_argument("thin_ring_inplane_frequency: n >= 2");
  const double n2 = double(n) * n;
  const double r4 = std::pow(ring.radius, 4);
  const double omega2 = material.youngs_modulus * ring.second_moment /
                        (material.density * ring.area * r4) * n2 * (n2 - 1) * (n2 - 1) / (n2 + 1);
  return std::sqrt(omega2) / (2 * kPi);
}

double thick_ring_inplane_frequency(const RingSection& ring, const IsotropicMaterial& material,
                                    int n, const RingFoundation& foundation) {
  if (n < 2) throw std::invalid_argument("thick_ring_inplane_frequency: n >= 2");
  const double e = material.youngs_modulus;
  const double g = e / (2 * (1 + material.poisson_ratio));
  const double r = ring.radius, a = ring.area, i = ring.second_moment;
  // Per cos/sin factor, q = (W, V, Psi): eps = (W + n V)/R, kappa = n Psi/R,
  // gamma = -((n W + V)/R + Psi); K = sum of (stiffness) b b^T over the three strains.
  const Eigen::Vector3d b_eps(1 / r, n / r, 0), b_kappa(0, 0, n / r), b_gamma(n / r, 1 / r, 1);
  const Eigen::Matrix3d k =
      e * a * b_eps * b_eps.transpose() + e * i * b_kappa * b_kappa.transpose() +
      ring.shear_coefficient * g * a * b_gamma * b_gamma.transpose() +
      Eigen::Vector3d(foundation.radial_stiffness, foundation.tangential_stiffness, 0)
          .asDiagonal()
          .toDenseMatrix();
  const double mu = material.density * a + foundation.added_mass;
  const Eigen::Matrix3d m = Eigen::Vector3d(mu, mu, material.density * i).asDiagonal();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> es(k, m);
  return std::sqrt(es.eigenvalues()(0)) / (2 * kPi);
}

BeamElement hermite_beam_element(double bending_stiffness, double mass_per_length, double le) {
  BeamElement e;
  e.stiffness << 12, 6 * le, -12, 6 * le, 6 * le, 4 * le * le, -6 * le, 2 * le * le, -12, -6 * le,
      12, -6 * le, 6 * le, 2 * le * le, -6 * le, 4 * le * le;
  e.mass << 156, 22 * le, 54, -13 * le, 22 * le, 4 * le * le, 13 * le, -3 * le * le, 54, 13 * le,
      156, -22 * le, -13 * le, -3 * le * le, -22 * le, 4 * le * le;
  e.stiffness *= bending_stiffness / (le * le * le);
  e.mass *= mass_per_length * le / 420;
  return e;
}

double cantilever_strip_frequency(const std::function<double(double)>& thickness, double length,
                                  const IsotropicMaterial& material, int elements) {
  if (elements < 1 || length <= 0)
    throw std::invalid_argument("cantilever_strip_frequency: length > 0, elements >= 1");
  const int dofs = 2 * (elements + 1);  // (w, w') per node; node 0 clamped
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(dofs, dofs), m = Eigen::MatrixXd::Zero(dofs, dofs);
  const double le = length / elements;
  const double nu = material.poisson_ratio;
  for (int el = 0; el < elements; ++el) {
    const double h = thickness((el + 0.5) * le);  // mid-element thickness
    const double d = material.youngs_modulus * h * h * h / (12 * (1 - nu * nu));
    const double mu = material.density * h;
    const BeamElement e = hermite_beam_element(d, mu, le);
    k.block<4, 4>(2 * el, 2 * el) += e.stiffness;
    m.block<4, 4>(2 * el, 2 * el) += e.mass;
  }
  const int free = dofs - 2;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(k.bottomRightCorner(free, free),
                                                               m.bottomRightCorner(free, free));
  return std::sqrt(es.eigenvalues()(0)) / (2 * kPi);
}

}  // namespace rollnoise::fem
