// Plane meshes of 6-node (quadratic) triangles for cross-sections: the wheel section in (r, z), the
// rail section in (y, z). Meshing goes through gmsh's C API in memory (no files, no terminal
// output); libgmsh is loaded at the first mesh of the process (fem/gmsh_library.hpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace rollnoise::fem {

/// A plane mesh of 6-node (quadratic) triangles. Coordinates in metres.
struct QuadraticTriangleMesh {
  std::vector<Eigen::Vector2d> nodes;
  /// Corners 0, 1, 2 counter-clockwise; mid-side nodes 3 (edge 0-1), 4 (edge 1-2), 5 (edge 2-0).
  std::vector<std::array<int, 6>> triangles;
  /// (end, mid, end) nodes of each boundary edge.
  std::vector<std::array<int, 3>> boundary_edges;
  /// Per boundary edge: the index i of the outline segment outline[i] -> outline[i + 1] it lies on.
  std::vector<int> boundary_edge_segment;
};

/// Meshes the closed polygon `outline` (either orientation, last point not repeated) with target
/// element size h (m) through gmsh's C API (in memory, no files, terminal output off). Mid-side
/// nodes lie at the middle of straight edges. Throws InputError (key "outline") on a
/// self-intersecting or degenerate outline or h <= 0, NumericalError if gmsh fails,
/// std::runtime_error if libgmsh cannot be loaded (gmsh_library()).
QuadraticTriangleMesh mesh_polygon(const std::vector<Eigen::Vector2d>& outline, double h);

/// The checks mesh_polygon makes before meshing: throws InputError (key "mesh_size" for h <= 0,
/// "outline" for fewer than 3 points, a non-finite or repeated point, zero area or crossing
/// segments).
void check_outline(const std::vector<Eigen::Vector2d>& outline, double h);

/// Signed area of a closed polygon (positive when counter-clockwise), shoelace formula.
double polygon_signed_area(const std::vector<Eigen::Vector2d>& outline);

}  // namespace rollnoise::fem
