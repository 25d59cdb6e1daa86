// src/fem basics: the 6-node triangle (shape functions, quadrature) and mesh_polygon (gmsh): the
// meshed area and boundary equal the outline's, any orientation, an L-shape, bad outlines refused.
#include "fem/mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "core/errors.hpp"
#include "fem/triangle6.hpp"

using namespace rollnoise;
using namespace rollnoise::fem;

namespace {

// Area of the mesh by the Gauss rule over each element's Jacobian (exact for straight-sided
// triangles); fails if any element is clockwise (negative Jacobian).
double mesh_area(const QuadraticTriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) {
    const auto xy = triangle6_coordinates(m.nodes, t);
    for (const auto& q : triangle_gauss_degree5()) {
      const double det =
          triangle6_jacobian(triangle6_shape_derivatives(q.xi, q.eta), xy).determinant();
      EXPECT_GT(det, 0.0);
      a += q.weight * det;
    }
  }
  return a;
}

double perimeter(const std::vector<Eigen::Vector2d>& o) {
  double p = 0.0;
  for (std::size_t i = 0; i < o.size(); ++i) p += (o[(i + 1) % o.size()] - o[i]).norm();
  return p;
}

// Checks the boundary: edge lengths sum to the perimeter, each edge lies on its outline segment
// with its mid node at the middle, and every segment is covered by its edges.
void expect_boundary_on_outline(const QuadraticTriangleMesh& m,
                                const std::vector<Eigen::Vector2d>& o) {
  ASSERT_EQ(m.boundary_edges.size(), m.boundary_edge_segment.size());
  std::vector<double> covered(o.size(), 0.0);
  for (std::size_t e = 0; e < m.boundary_edges.size(); ++e) {
    const int s = m.boundary_edge_segment[e];
    const Eigen::Vector2d a = o[s], b = o[(s + 1) % o.size()];
    const Eigen::Vector2d t = (b - a).normalized();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = m.nodes[m.boundary_edges[e][k]] - a;
      EXPECT_NEAR(p.x() * t.y() - p.y() * t.x(), 0.0, 1e-12);  // on the segment's line
    }
    const auto& ed = m.boundary_edges[e];
    EXPECT_NEAR((0.5 * (m.nodes[ed[0]] + m.nodes[ed[2]]) - m.nodes[ed[1]]).norm(), 0.0, 1e-12);
    covered[s] += (m.nodes[ed[2]] - m.nodes[ed[0]]).norm();
  }
  for (std::size_t s = 0; s < o.size(); ++s)
    EXPECT_NEAR(covered[s], (o[(s + 1) % o.size()] - o[s]).norm(), 1e-12) << "segment " << s;
}

}  // namespace

// The shape functions: 1 at their own node, 0 at the others (nodal interpolation), sum to 1 and
// their derivatives to 0 everywhere (rigid-body modes reproduced), to round-off.
TEST(Triangle6, ShapeFunctionsInterpolateAtNodesAndPartitionUnity) {
  const double nodes[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (int i = 0; i < 6; ++i) {
    const auto n = triangle6_shape(nodes[i][0], nodes[i][1]);
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(n(j), i == j ? 1.0 : 0.0, 1e-15);
  }
  const auto n = triangle6_shape(0.2, 0.3);
  EXPECT_NEAR(n.sum(), 1.0, 1e-15);
  const auto d = triangle6_shape_derivatives(0.2, 0.3);
  EXPECT_NEAR(d.row(0).sum(), 0.0, 1e-14);
  EXPECT_NEAR(d.row(1).sum(), 0.0, 1e-14);
  // Derivatives against central differences (step 1e-6: error ~1e-12 for a quadratic, exact).
  const double e = 1e-6;
  const Eigen::Matrix<double, 6, 1> dxi =
      (triangle6_shape(0.2 + e, 0.3) - triangle6_shape(0.2 - e, 0.3)) / (2 * e);
  const Eigen::Matrix<double, 6, 1> deta =
      (triangle6_shape(0.2, 0.3 + e) - triangle6_shape(0.2, 0.3 - e)) / (2 * e);
  EXPECT_LT((dxi.transpose() - d.row(0)).norm(), 1e-9);
  EXPECT_LT((deta.transpose() - d.row(1)).norm(), 1e-9);
}

// The quadrature integrates every monomial xi^p eta^q with p + q <= 5 exactly:
// int_T xi^p eta^q = p! q! / (p + q + 2)! (to 1e-14 relative; the rule's digits are 15).
TEST(Triangle6, GaussRuleExactToDegreeFive) {
  auto fact = [](int k) { return std::tgamma(k + 1.0); };
  for (int p = 0; p <= 5; ++p)
    for (int q = 0; p + q <= 5; ++q) {
      double s = 0.0;
      for (const auto& g : triangle_gauss_degree5())
        s += g.weight * std::pow(g.xi, p) * std::pow(g.eta, q);
      const double exact = fact(p) * fact(q) / fact(p + q + 2);
      EXPECT_NEAR(s, exact, 1e-14 * exact) << p << " " << q;
    }
}

// A rectangle 0.1 m x 0.02 m in both orientations: the meshed area equals 2e-3 m^2 (to 1e-14
// relative: straight-sided triangles tile the polygon), the boundary lies on the outline and covers
// it, every triangle is counter-clockwise, and the element size follows h.
TEST(MeshPolygon, RectangleAreaAndBoundaryEqualOutlineInBothOrientations) {
  std::vector<Eigen::Vector2d> rect = {{0, 0}, {0.1, 0}, {0.1, 0.02}, {0, 0.02}};
  for (int orientation = 0; orientation < 2; ++orientation) {
    const auto m = mesh_polygon(rect, 0.01);
    EXPECT_NEAR(mesh_area(m), 2e-3, 2e-3 * 1e-12);
    expect_boundary_on_outline(m, rect);
    double boundary = 0.0;
    for (const auto& e : m.boundary_edges) boundary += (m.nodes[e[2]] - m.nodes[e[0]]).norm();
    EXPECT_NEAR(boundary, perimeter(rect), 1e-12);
    // At least 10 edges along the 0.1 m side, and each node count matches 6-node triangles:
    // nodes = corners + mid-sides, unique.
    EXPECT_GE(m.boundary_edges.size(), 24u);
    std::set<int> used;
    for (const auto& t : m.triangles) used.insert(t.begin(), t.end());
    EXPECT_EQ(used.size(), m.nodes.size());
    std::reverse(rect.begin(), rect.end());
  }
}

// An L-shape (a re-entrant corner), three squares of 0.1 m: the meshed area is 0.03 m^2 (to 1e-12
// relative) at two element sizes, the boundary lies on and covers the outline, and halving h gives
// about four times the elements.
TEST(MeshPolygon, LShapeAreaExactAndRefinementAddsElements) {
  const std::vector<Eigen::Vector2d> l = {{0, 0},     {0.2, 0},   {0.2, 0.1},
                                          {0.1, 0.1}, {0.1, 0.2}, {0, 0.2}};
  const auto coarse = mesh_polygon(l, 0.05);
  const auto fine = mesh_polygon(l, 0.025);
  EXPECT_NEAR(mesh_area(coarse), 0.03, 0.03 * 1e-12);
  EXPECT_NEAR(mesh_area(fine), 0.03, 0.03 * 1e-12);
  expect_boundary_on_outline(coarse, l);
  expect_boundary_on_outline(fine, l);
  // Halving h: about four times the elements (between 3x and 5x).
  const double ratio = double(fine.triangles.size()) / coarse.triangles.size();
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
}

// Bad outlines: a bow tie (self-intersecting), a repeated point, too few points, h <= 0.
TEST(MeshPolygon, SelfIntersectingOrDegenerateOutlineRefused) {
  EXPECT_THROW(mesh_polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0.1), InputError);
  EXPECT_THROW(mesh_polygon({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, 0.1), InputError);
  EXPECT_THROW(mesh_polygon({{0, 0}, {1, 0}}, 0.1), InputError);
  EXPECT_THROW(mesh_polygon({{0, 0}, {1, 0}, {0, 1}}, 0.0), InputError);
  EXPECT_THROW(mesh_polygon({{0, 0}, {1, 0}, {2, 0}}, 0.1), InputError);  // collinear: no area
}
