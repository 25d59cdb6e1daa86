#include "fem/triangle6.hpp"

#include <cmath>

namespace rollnoise::fem {

const std::vector<TrianglePoint>& triangle_gauss_degree5() {
  // Dunavant (1985), degree 5, 7 points; weights there sum to 1 (multiplied by the area 1/2 here).
  static const std::vector<TrianglePoint> rule = [] {
    const double a1 = 0.059715871789770, b1 = 0.470142064105115;
    const double a2 = 0.797426985353087, b2 = 0.101286507323456;
    const double w0 = 0.225, w1 = 0.132394152788506, w2 = 0.125939180544827;
    std::vector<TrianglePoint> r;
    r.push_back({1.0 / 3.0, 1.0 / 3.0, 0.5 * w0});
    // Each orbit: barycentric (a, b, b) and its permutations; (xi, eta) = (L2, L3).
    for (const auto& [a, b, w] : {std::array<double, 3>{a1, b1, w1}, {a2, b2, w2}}) {
      r.push_back({b, b, 0.5 * w});
      r.push_back({a, b, 0.5 * w});
      r.push_back({b, a, 0.5 * w});
    }
    return r;
  }();
  return rule;
}

Eigen::Matrix<double, 6, 1> triangle6_shape(double xi, double eta) {
  const double l1 = 1.0 - xi - eta, l2 = xi, l3 = eta;
  Eigen::Matrix<double, 6, 1> n;
  n << l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), l3 * (2 * l3 - 1), 4 * l1 * l2, 4 * l2 * l3,
      4 * l3 * l1;
  return n;
}

Eigen::Matrix<double, 2, 6> triangle6_shape_derivatives(double xi, double eta) {
  const double l1 = 1.0 - xi - eta, l2 = xi, l3 = eta;
  // dL1/dxi = -1, dL2/dxi = 1, dL3/dxi = 0; dL1/deta = -1, dL2/deta = 0, dL3/deta = 1.
  Eigen::Matrix<double, 2, 6> d;
  d << -(4 * l1 - 1), 4 * l2 - 1, 0.0, 4 * (l1 - l2), 4 * l3, -4 * l3,  //
      -(4 * l1 - 1), 0.0, 4 * l3 - 1, -4 * l2, 4 * l2, 4 * (l1 - l3);
  return d;
}

Eigen::Matrix2d triangle6_jacobian(const Eigen::Matrix<double, 2, 6>& dN,
                                   const Eigen::Matrix<double, 2, 6>& xy) {
  return dN * xy.transpose();
}

Eigen::Matrix<double, 2, 6> triangle6_coordinates(const std::vector<Eigen::Vector2d>& nodes,
                                                  const std::array<int, 6>& triangle) {
  Eigen::Matrix<double, 2, 6> xy;
  for (int i = 0; i < 6; ++i) xy.col(i) = nodes[triangle[i]];
  return xy;
}

}  // namespace rollnoise::fem
