#include "pipeline/sound_radiation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "acoustics/axisymmetric_bem.hpp"
#include "acoustics/bem2d.hpp"
#include "core/constants.hpp"
#include "core/task_pool.hpp"
#include "noise/bands.hpp"

namespace rollnoise::pipeline {
namespace {

// The section boundary of the FE mesh as one closed chain of nodes, counter-clockwise in (r, z):
// end, mid, end, mid, ... (each boundary edge's end and mid-side nodes), the first not repeated.
std::vector<int> boundary_chain(const fem::QuadraticTriangleMesh& mesh) {
  std::multimap<int, std::size_t> at;  // end node -> edges
  for (std::size_t e = 0; e < mesh.boundary_edges.size(); ++e) {
    at.emplace(mesh.boundary_edges[e][0], e);
    at.emplace(mesh.boundary_edges[e][2], e);
  }
  std::vector<int> chain;
  std::vector<bool> used(mesh.boundary_edges.size(), false);
  int node = mesh.boundary_edges.front()[0];
  for (std::size_t step = 0; step < mesh.boundary_edges.size(); ++step) {
    const auto [lo, hi] = at.equal_range(node);
    std::size_t next = mesh.boundary_edges.size();
    for (auto it = lo; it != hi; ++it)
      if (!used[it->second]) next = it->second;
    if (next == mesh.boundary_edges.size())
      throw std::invalid_argument("FE wheel: the section's boundary is not one closed chain");
    used[next] = true;
    const auto& e = mesh.boundary_edges[next];
    const bool forward = e[0] == node;
    chain.push_back(node);
    chain.push_back(e[1]);
    node = forward ? e[2] : e[0];
  }
  if (node != chain.front())
    throw std::invalid_argument("FE wheel: the section's boundary does not close");
  double area = 0.0;  // shoelace in (r, z)
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const Eigen::Vector2d& a = mesh.nodes[static_cast<std::size_t>(chain[i])];
    const Eigen::Vector2d& b = mesh.nodes[static_cast<std::size_t>(chain[(i + 1) % chain.size()])];
    area += a.x() * b.y() - b.x() * a.y();
  }
  if (area < 0.0) std::reverse(chain.begin(), chain.end());
  return chain;
}

// The boundary elements of the chain. per_edge = 1: one straight element per quadratic boundary
// edge (end a to end b), its collocation value that of the mid-side node m (the edge's midpoint);
// per_edge = 2: each edge split at m into a-m and m-b, the values at their midpoints from the
// edge's three nodes by the quadratic shape functions at xi = -+1/2:
//   N_a = xi (xi - 1)/2, N_m = 1 - xi^2, N_b = xi (xi + 1)/2  ->  (3/8, 3/4, -1/8) and (-1/8, 3/4,
//   3/8).
struct BoundaryElements {
  std::vector<Eigen::Vector2d>
      points;  // generator points (r, z): from the axis around the wheel back to it
  // per element: the three nodes of its edge and the weights at its midpoint
  std::vector<std::array<int, 3>> nodes;
  std::vector<std::array<double, 3>> weights;
  std::vector<Eigen::Vector2d> normal;  // outward (n_r, n_z)
  std::vector<double> length, radius;   // element length and midpoint radius (m)
};

BoundaryElements boundary_elements(const fem::QuadraticTriangleMesh& mesh, int per_edge) {
  const std::vector<int> chain = boundary_chain(mesh);
  // the quadratic edges in the chain's (counter-clockwise) order; the bore's (both ends at the
  // smallest radius) are replaced by the axle's end faces below
  std::vector<std::array<int, 3>> edges;
  for (std::size_t i = 0; i + 1 < chain.size(); i += 2)
    edges.push_back({chain[i], chain[i + 1], chain[(i + 2) % chain.size()]});
  double r_min = 1e300;
  for (int node : chain) r_min = std::min(r_min, mesh.nodes[static_cast<std::size_t>(node)].x());
  const auto on_bore = [&](const std::array<int, 3>& e) {
    return mesh.nodes[static_cast<std::size_t>(e[0])].x() <= r_min + 1e-9 &&
           mesh.nodes[static_cast<std::size_t>(e[2])].x() <= r_min + 1e-9;
  };
  // rotate so that the first edge after the bore comes first, then drop the bore's edges
  std::size_t first = 0;
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (on_bore(edges[i]) && !on_bore(edges[(i + 1) % edges.size()]))
      first = (i + 1) % edges.size();
  std::rotate(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(first), edges.end());
  while (!edges.empty() && on_bore(edges.back())) edges.pop_back();
  if (edges.empty() || std::any_of(edges.begin(), edges.end(), on_bore))
    throw std::invalid_argument("FE wheel: the bore is not one run of the section's boundary");

  BoundaryElements b;
  const auto node = [&](int i) { return mesh.nodes[static_cast<std::size_t>(i)]; };
  auto add = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const std::array<int, 3>& edge,
                 const std::array<double, 3>& weights) {
    const Eigen::Vector2d d = q - p;
    b.points.push_back(p);
    b.nodes.push_back(edge);
    b.weights.push_back(weights);
    b.length.push_back(d.norm());
    b.normal.push_back(Eigen::Vector2d(d.y(), -d.x()) / d.norm());  // counter-clockwise: right
    b.radius.push_back(0.5 * (p.x() + q.x()));
  };
  // a face across the bore, from the axis to the bore's edge or back, at rest (zero weights)
  const double h = (node(edges.front()[2]) - node(edges.front()[0])).norm();
  auto face = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    const int n = std::max(2, static_cast<int>(std::ceil((to - from).norm() / h)));
    for (int i = 0; i < n; ++i)
      add(from + (to - from) * (static_cast<double>(i) / n),
          from + (to - from) * (static_cast<double>(i + 1) / n), {0, 0, 0}, {0.0, 0.0, 0.0});
  };
  const Eigen::Vector2d start = node(edges.front()[0]), end = node(edges.back()[2]);
  face({0.0, start.y()}, start);
  for (const auto& e : edges) {
    if (per_edge == 1) {
      add(node(e[0]), node(e[2]), e, {0.0, 1.0, 0.0});
    } else {
      add(node(e[0]), node(e[1]), e, {0.375, 0.75, -0.125});
      add(node(e[1]), node(e[2]), e, {-0.125, 0.75, 0.375});
    }
  }
  face(end, {0.0, end.y()});
  b.points.push_back({0.0, end.y()});
  return b;
}

// The normal velocity pattern (U_r n_r + U_z n_z at each element's midpoint) of a mode.
Eigen::VectorXd normal_pattern(const BoundaryElements& b, const Eigen::VectorXd& dofs) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(b.length.size()));
  for (std::size_t e = 0; e < b.length.size(); ++e) {
    double ur = 0.0, uz = 0.0;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Index node = b.nodes[e][static_cast<std::size_t>(j)];
      ur += b.weights[e][static_cast<std::size_t>(j)] * dofs(3 * node);
      uz += b.weights[e][static_cast<std::size_t>(j)] * dofs(3 * node + 2);
    }
    v(static_cast<Eigen::Index>(e)) = ur * b.normal[e].x() + uz * b.normal[e].y();
  }
  return v;
}

}  // namespace

std::vector<double> radiation_grid(const std::vector<double>& centres, int per_band) {
  if (centres.empty()) return {};
  const auto [lo, unused_lo] = noise::third_octave_edges(centres.front());
  const auto [unused_hi, hi] = noise::third_octave_edges(centres.back());
  (void)unused_lo, (void)unused_hi;
  // 1/3 octave (base 10): a factor 10^{1/10}; per_band steps a band
  const int steps = static_cast<int>(std::ceil(per_band * 10.0 * std::log10(hi / lo) - 1e-9));
  std::vector<double> grid;
  for (int i = 0; i <= steps; ++i)
    grid.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / steps));
  return grid;
}

GridPlace grid_place(const std::vector<double>& grid, double f) {
  if (grid.size() < 2 || f <= grid.front()) return {0, 0.0};
  if (f >= grid.back()) return {grid.size() - 2, 1.0};
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(grid.begin(), grid.end(), f) - grid.begin()) - 1;
  return {i, std::log(f / grid[i]) / std::log(grid[i + 1] / grid[i])};
}

WheelRadiation wheel_radiation(const dynamics::WheelFeModes& w, int n_min,
                               const std::vector<double>& grid, const acoustics::Fluid& fluid,
                               int threads, int per_edge) {
  if (w.mesh.boundary_edges.empty())
    throw std::invalid_argument("wheel radiation: the modes have no section mesh");
  const BoundaryElements b = boundary_elements(w.mesh, per_edge);
  WheelRadiation out;
  out.frequency = grid;
  out.elements = static_cast<int>(b.length.size());
  for (std::size_t e = 0; e < b.length.size();
       ++e)  // the wheel's surface (not the faces across the bore)
    if (b.weights[e][1] != 0.0) out.surface += 2 * kPi * b.radius[e] * b.length[e];

  // the modes by order, and their patterns
  int n_max = -1;
  for (const auto& m : w.modes) n_max = std::max(n_max, m.n);
  std::vector<Eigen::MatrixXd> patterns(static_cast<std::size_t>(std::max(n_max + 1, 0)));
  for (int n = std::max(n_min, 0); n <= n_max; ++n) {
    WheelRadiation::Order order;
    order.n = n;
    for (std::size_t k = 0; k < w.modes.size(); ++k)
      if (w.modes[k].n == n) {
        if (w.modes[k].dofs.size() != 3 * static_cast<Eigen::Index>(w.mesh.nodes.size()))
          throw std::invalid_argument("wheel radiation: a mode has no section shape");
        order.modes.push_back(static_cast<int>(k));
      }
    if (order.modes.empty()) continue;
    Eigen::MatrixXd p(static_cast<Eigen::Index>(b.length.size()),
                      static_cast<Eigen::Index>(order.modes.size()));
    for (std::size_t j = 0; j < order.modes.size(); ++j)
      p.col(static_cast<Eigen::Index>(j)) =
          normal_pattern(b, w.modes[static_cast<std::size_t>(order.modes[j])].dofs);
    patterns[static_cast<std::size_t>(n)] = p;
    out.orders.push_back(std::move(order));
  }

  // the BEM at each grid frequency: every order in one call (its phi integrals shared)
  acoustics::AxisymmetricGenerator generator;
  generator.points = b.points;
  generator.closed =
      false;  // from the axis across the bore's face, around the wheel, back to the axis
  for (auto& order : out.orders) order.power.resize(grid.size());
  parallel_for(grid.size(), threads, [&](std::size_t i, int) {
    const double k = 2 * kPi * grid[i] / fluid.sound_speed;
    const std::vector<Eigen::MatrixXcd> P =
        acoustics::radiated_power_matrices(generator, k, patterns, fluid);
    for (auto& order : out.orders) order.power[i] = P[static_cast<std::size_t>(order.n)];
  });

  // sigma_k = P_kk / (rho c S <v_n^2>), S <v_n^2> = (1/2) c_n sum_e l_e r_e v_e^2,
  // c_n = Int cos^2(n theta) dtheta = 2 pi (n = 0), pi (n >= 1)
  for (const auto& order : out.orders) {
    const double cn = order.n == 0 ? 2 * kPi : kPi;
    const Eigen::MatrixXd& p = patterns[static_cast<std::size_t>(order.n)];
    for (Eigen::Index j = 0; j < p.cols(); ++j) {
      double msq = 0.0;
      for (Eigen::Index e = 0; e < p.rows(); ++e)
        msq += 0.5 * cn * b.length[static_cast<std::size_t>(e)] *
               b.radius[static_cast<std::size_t>(e)] * p(e, j) * p(e, j);
      const dynamics::WheelFeMode& mode =
          w.modes[static_cast<std::size_t>(order.modes[static_cast<std::size_t>(j)])];
      out.family.push_back(static_cast<int>(mode.family));
      out.nodal_circles.push_back(mode.nodal_circles);
      std::vector<double> sigma;
      for (const Eigen::MatrixXcd& P : order.power)
        sigma.push_back(P(j, j).real() / (fluid.impedance() * msq));
      out.efficiency.push_back(std::move(sigma));
    }
  }
  return out;
}

acoustics::Bem2dOptions rail_bem_options(const std::vector<Eigen::Vector2d>& outline, bool ground,
                                         double k) {
  double perimeter = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i)
    perimeter += (outline[(i + 1) % outline.size()] - outline[i]).norm();
  acoustics::Bem2dOptions options;
  options.ground_plane = ground;
  options.target_elements =
      std::clamp(static_cast<int>(std::ceil(10 * perimeter * k / (2 * kPi))), 40, 400);
  return options;
}

RailRadiation rail_radiation(const std::vector<Eigen::Vector2d>& outline, bool ground,
                             const std::vector<double>& grid, const acoustics::Fluid& fluid,
                             int threads) {
  acoustics::Section2d section;
  section.outline = outline;
  RailRadiation out;
  out.frequency = grid;
  out.ground = ground;
  const std::size_t n = grid.size();
  out.vertical.resize(n), out.lateral.resize(n), out.sigma_vertical.resize(n),
      out.sigma_lateral.resize(n);
  parallel_for(n, threads, [&](std::size_t i, int) {
    const double k = 2 * kPi * grid[i] / fluid.sound_speed;
    const acoustics::Bem2dOptions options = rail_bem_options(outline, ground, k);
    const std::vector<acoustics::RigidRadiation2d> r = acoustics::rigid_translation_radiation_2d(
        section, k, std::vector<Eigen::Vector2d>{{0.0, 1.0}, {1.0, 0.0}}, fluid, options);
    // per unit velocity amplitude squared: <v^2> = |V|^2 / 2
    out.vertical[i] = 0.5 * r[0].power_per_mean_square_velocity;
    out.lateral[i] = 0.5 * r[1].power_per_mean_square_velocity;
    out.sigma_vertical[i] = r[0].efficiency;
    out.sigma_lateral[i] = r[1].efficiency;
  });
  return out;
}

}  // namespace rollnoise::pipeline
