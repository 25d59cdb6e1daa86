// mesh_polygon through gmsh's C API (gmsh 4.8, Debian libgmsh-dev), loaded at the first mesh
// (fem/gmsh_library.hpp): built-in geometry kernel, Frontal-Delaunay triangles, second order with
// straight mid-side nodes. gmsh keeps one global model, so calls are serialised by a mutex and
// each call initialises and finalises the library.
#include "fem/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

#include "core/errors.hpp"
#include "fem/gmsh_library.hpp"

namespace rollnoise::fem {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// True when the closed segments p0-p1 and q0-q1 share a point (including touching and overlap).
bool segments_intersect(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                        const Eigen::Vector2d& q0, const Eigen::Vector2d& q1, double tol) {
  const Eigen::Vector2d r = p1 - p0, s = q1 - q0;
  const double d1 = cross(r, q0 - p0), d2 = cross(r, q1 - p0);
  const double d3 = cross(s, p0 - q0), d4 = cross(s, p1 - q0);
  const double scale_r = r.norm(), scale_s = s.norm();
  if (((d1 > tol * scale_r && d2 < -tol * scale_r) ||
       (d1 < -tol * scale_r && d2 > tol * scale_r)) &&
      ((d3 > tol * scale_s && d4 < -tol * scale_s) || (d3 < -tol * scale_s && d4 > tol * scale_s)))
    return true;  // proper crossing
  // Touching: a point of one segment within tol of the other segment.
  auto near = [tol](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm() <= tol;
  };
  return near(q0, q1, p0) || near(q0, q1, p1) || near(p0, p1, q0) || near(p0, p1, q1);
}

// Runs gmsh on the outline (already checked); fills nodes by tag, triangles and boundary lines.
struct GmshMesh {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords;
  std::vector<std::size_t> triangle_nodes;           // 6 per triangle, gmsh order
  std::vector<std::vector<std::size_t>> line_nodes;  // per segment: 3 per line (end, end, mid)
};

// Throws NumericalError when the gmsh call `call` reported failure (ierr != 0).
void check_gmsh_call(int ierr, const char* call) {
  if (ierr != 0)
    throw NumericalError(std::string("gmsh failed to mesh the section outline (") + call + ")");
}

// Copies an array gmsh allocated into a vector and frees it (null when gmsh allocated none).
template <class T>
std::vector<T> take_gmsh_array(const GmshApi& api, T* data, std::size_t n) {
  std::vector<T> v(data, data + (data ? n : 0));
  api.free(data);
  return v;
}

// Fills `out` from gmsh's mesh of the (synchronised) model; lines: the outline's curve tags.
void read_gmsh_mesh(const GmshApi& api, const std::vector<int>& lines, GmshMesh& out) {
  int ierr = 0;
  std::size_t *tags = nullptr, *nodes = nullptr;
  double *coords = nullptr, *parametric = nullptr;
  std::size_t n_tags = 0, n_nodes = 0, n_coords = 0, n_parametric = 0;
  api.mesh_get_nodes(&tags, &n_tags, &coords, &n_coords, &parametric, &n_parametric, -1, -1, 0, 0,
                     &ierr);
  out.node_tags = take_gmsh_array(api, tags, n_tags);
  out.coords = take_gmsh_array(api, coords, n_coords);
  take_gmsh_array(api, parametric, n_parametric);
  check_gmsh_call(ierr, "getNodes");
  // 9: 6-node triangle, over all surfaces (tag -1), in one task.
  api.mesh_get_elements_by_type(9, &tags, &n_tags, &nodes, &n_nodes, -1, 0, 1, &ierr);
  take_gmsh_array(api, tags, n_tags);
  out.triangle_nodes = take_gmsh_array(api, nodes, n_nodes);
  check_gmsh_call(ierr, "getElementsByType");
  for (const int line : lines) {
    // 8: 3-node line, on this outline segment.
    api.mesh_get_elements_by_type(8, &tags, &n_tags, &nodes, &n_nodes, line, 0, 1, &ierr);
    take_gmsh_array(api, tags, n_tags);
    out.line_nodes.push_back(take_gmsh_array(api, nodes, n_nodes));
    check_gmsh_call(ierr, "getElementsByType");
  }
}

// Builds the outline's plane surface in gmsh's built-in kernel and meshes it; returns the curve
// tags of the outline's segments.
std::vector<int> mesh_outline_in_gmsh(const GmshApi& api,
                                      const std::vector<Eigen::Vector2d>& outline, double h) {
  int ierr = 0;
  const auto set_option = [&](const char* name, double value) {
    api.option_set_number(name, value, &ierr);
    check_gmsh_call(ierr, name);
  };
  set_option("General.Terminal", 0);
  set_option("General.Verbosity", 0);
  set_option("Mesh.Algorithm", 6);  // Frontal-Delaunay
  set_option("Mesh.ElementOrder", 2);
  set_option("Mesh.SecondOrderLinear", 1);  // mid-side nodes on straight edges
  set_option("Mesh.CharacteristicLengthMax", h);
  api.model_add("section", &ierr);
  check_gmsh_call(ierr, "model::add");
  const int n = static_cast<int>(outline.size());
  std::vector<int> points, lines;
  for (const auto& p : outline) {
    points.push_back(api.geo_add_point(p.x(), p.y(), 0.0, h, -1, &ierr));
    check_gmsh_call(ierr, "geo::addPoint");
  }
  for (int i = 0; i < n; ++i) {
    lines.push_back(api.geo_add_line(points[i], points[(i + 1) % n], -1, &ierr));
    check_gmsh_call(ierr, "geo::addLine");
  }
  int loop = api.geo_add_curve_loop(lines.data(), lines.size(), -1, 0, &ierr);
  check_gmsh_call(ierr, "geo::addCurveLoop");
  api.geo_add_plane_surface(&loop, 1, -1, &ierr);
  check_gmsh_call(ierr, "geo::addPlaneSurface");
  api.geo_synchronize(&ierr);
  check_gmsh_call(ierr, "geo::synchronize");
  api.mesh_generate(2, &ierr);
  check_gmsh_call(ierr, "mesh::generate");
  api.mesh_set_order(2, &ierr);
  check_gmsh_call(ierr, "mesh::setOrder");
  return lines;
}

// One gmsh session (initialize ... finalize) meshing the outline.
GmshMesh run_gmsh(const std::vector<Eigen::Vector2d>& outline, double h) {
  const GmshApi& api = gmsh_library();  // loads libgmsh at the first mesh of the process
  GmshMesh out;
  int ierr = 0;
  api.initialize(0, nullptr, 0, &ierr);  // no argv, no configuration files
  try {
    check_gmsh_call(ierr, "initialize");
    read_gmsh_mesh(api, mesh_outline_in_gmsh(api, outline, h), out);
  } catch (...) {
    api.finalize(&ierr);
    throw;
  }
  api.finalize(&ierr);
  check_gmsh_call(ierr, "finalize");
  return out;
}

}  // namespace

void check_outline(const std::vector<Eigen::Vector2d>& outline, double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw InputError("mesh_size", "mesh size must be positive, got " + std::to_string(h) + " m");
  const int n = static_cast<int>(outline.size());
  if (n < 3)
    throw InputError("outline",
                     "a section outline needs at least 3 points, got " + std::to_string(n));
  double extent = 0.0;
  for (const auto& p : outline) {
    if (!p.allFinite()) throw InputError("outline", "outline point is not finite");
    extent = std::max(extent, (p - outline[0]).norm());
  }
  const double tol = 1e-9 * extent;
  for (int i = 0; i < n; ++i)
    if ((outline[(i + 1) % n] - outline[i]).norm() <= tol)
      throw InputError("outline", "outline points " + std::to_string(i) + " and " +
                                      std::to_string((i + 1) % n) +
                                      " coincide (degenerate segment)");
  if (std::abs(polygon_signed_area(outline)) <= 1e-12 * extent * extent)
    throw InputError("outline", "outline encloses no area");
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing segment
      if (segments_intersect(outline[i], outline[(i + 1) % n], outline[j], outline[(j + 1) % n],
                             tol))
        throw InputError("outline", "outline is self-intersecting: segment " + std::to_string(i) +
                                        " meets segment " + std::to_string(j));
    }
}

double polygon_signed_area(const std::vector<Eigen::Vector2d>& outline) {
  double a = 0.0;
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) a += cross(outline[i], outline[(i + 1) % n]);
  return 0.5 * a;
}

QuadraticTriangleMesh mesh_polygon(const std::vector<Eigen::Vector2d>& outline, double h) {
  check_outline(outline, h);
  static std::mutex gmsh_mutex;  // gmsh holds one global model
  GmshMesh g;
  {
    std::lock_guard<std::mutex> lock(gmsh_mutex);
    g = run_gmsh(outline, h);
  }
  QuadraticTriangleMesh mesh;
  std::map<std::size_t, int> index;
  for (std::size_t i = 0; i < g.node_tags.size(); ++i) {
    index[g.node_tags[i]] = static_cast<int>(i);
    mesh.nodes.emplace_back(g.coords[3 * i], g.coords[3 * i + 1]);
  }
  for (std::size_t e = 0; 6 * e < g.triangle_nodes.size(); ++e) {
    std::array<int, 6> t;
    for (int k = 0; k < 6; ++k) t[k] = index.at(g.triangle_nodes[6 * e + k]);
    const Eigen::Vector2d a = mesh.nodes[t[1]] - mesh.nodes[t[0]],
                          b = mesh.nodes[t[2]] - mesh.nodes[t[0]];
    if (cross(a, b) < 0.0) {  // make it counter-clockwise: swap corners 1, 2 and mid-sides 3, 5
      std::swap(t[1], t[2]);
      std::swap(t[3], t[5]);
    }
    mesh.triangles.push_back(t);
  }
  for (std::size_t s = 0; s < g.line_nodes.size(); ++s)
    for (std::size_t e = 0; 3 * e < g.line_nodes[s].size(); ++e) {
      // gmsh's 3-node line: end, end, mid.
      mesh.boundary_edges.push_back({index.at(g.line_nodes[s][3 * e]),
                                     index.at(g.line_nodes[s][3 * e + 2]),
                                     index.at(g.line_nodes[s][3 * e + 1])});
      mesh.boundary_edge_segment.push_back(static_cast<int>(s));
    }
  if (mesh.triangles.empty()) throw NumericalError("gmsh produced no triangles for the outline");
  return mesh;
}

}  // namespace rollnoise::fem
