#include "dynamics/wheel_fe.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "dynamics/wheel_mode_family.hpp"
#include "fem/eigen_solve.hpp"

namespace rollnoise::dynamics {
namespace {


// The contract of the FE wheel: every field is checked with its key where the case is read
// (io/wheel_fe_case.cpp, the schema, io/wheel_section_file.cpp).
void check_options(const WheelSection& s, const WheelFeOptions& o) {
  if (s.bore_segments.empty())
    throw std::invalid_argument("FE wheel: the section has no bore segment");
  if (s.tread_segments.empty())
    throw std::invalid_argument("FE wheel: the section has no tread segment");
  if (!(o.mesh_size > 0)) throw std::invalid_argument("FE wheel: the element size must be > 0 m");
  if (o.n_max < 0 || o.n_max > 50) throw std::invalid_argument("FE wheel: the highest nodal diameter n_max must lie in [0, 50]");
  if (!(o.f_max > 0)) throw std::invalid_argument("FE wheel: the highest natural frequency kept must be > 0 Hz");
  const auto& m = o.material;
  if (!(m.youngs_modulus > 0)) throw std::invalid_argument("FE wheel: Young's modulus must be > 0 Pa");
  if (!(m.poisson_ratio > -1 && m.poisson_ratio < 0.5))
    throw std::invalid_argument("FE wheel: Poisson's ratio must lie in (-1, 0.5)");
  if (!(m.density > 0)) throw std::invalid_argument("FE wheel: the density must be > 0 kg/m^3");
}

// Tread samples: points of the running-surface segments every `spacing` in s (the segments are
// monotone in z = s along the S1002 outline), ascending in s.
void sample_tread(const WheelSection& sec, double spacing, WheelFeModes& w) {
  std::map<double, double> r_of_s;
  const int n = static_cast<int>(sec.outline.size());
  for (int seg : sec.tread_segments) {
    const Eigen::Vector2d a = sec.outline[seg], b = sec.outline[(seg + 1) % n];
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(b.y() - a.y()) / spacing)));
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector2d p = a + (b - a) * (double(k) / steps);
      r_of_s[p.y()] = p.x();
    }
  }
  for (auto [s, r] : r_of_s)  // a segment's end and the next one's start: one sample
    if (w.tread_s.empty() || s - w.tread_s.back() > 1e-9) w.tread_s.push_back(s), w.tread_r.push_back(r);
}

// The mid-line of the section from the bore to the rim: at each radius, the middle of the section's
// extent in z (for counting nodal circles).
std::vector<fem::MeshPoint> mid_line(const fem::QuadraticTriangleMesh& mesh) {
  double rmin = 1e300, rmax = -1e300;
  for (const auto& p : mesh.nodes) rmin = std::min(rmin, p.x()), rmax = std::max(rmax, p.x());
  std::vector<fem::MeshPoint> line;
  const int samples = 120;
  for (int i = 0; i <= samples; ++i) {
    const double r = rmin + (rmax - rmin) * (0.02 + 0.96 * i / samples);
    double zlo = 1e300, zhi = -1e300;
    for (const auto& e : mesh.boundary_edges) {
      const Eigen::Vector2d a = mesh.nodes[e[0]], b = mesh.nodes[e[2]];
      if ((a.x() - r) * (b.x() - r) > 0 || a.x() == b.x()) continue;
      const double z = a.y() + (b.y() - a.y()) * (r - a.x()) / (b.x() - a.x());
      zlo = std::min(zlo, z), zhi = std::max(zhi, z);
    }
    if (zlo > zhi) continue;
    try {
      line.push_back(fem::locate(mesh, {r, 0.5 * (zlo + zhi)}, 1e-3));
    } catch (const std::invalid_argument&) {  // a mid-point outside a non-convex section
    }
  }
  return line;
}

// Sign changes of component c along the line, ignoring values below 5 % of the largest.
int sign_changes(const fem::QuadraticTriangleMesh& mesh, const Eigen::VectorXd& phi,
                 const std::vector<fem::MeshPoint>& line, int c) {
  std::vector<double> v;
  for (const auto& p : line) v.push_back(fem::displacement_at(mesh, phi, p)(c));
  return fem::sign_changes(v, 0.05);
}

}  // namespace

const char* family_name(ModeFamily f) {
  switch (f) {
    case ModeFamily::kAxial:
      return "axial";
    case ModeFamily::kRadial:
      return "radial";
    default:
      return "circumferential";
  }
}

ModeFamily tread_family(const Eigen::MatrixX3d& tread_shape) {
  // the direction with the largest mean square on the tread ("dominant at the rim"): for modes
  // known on the tread only (imported); the FE modes are classified by the section
  // (wheel_mode_family.hpp)
  const Eigen::Vector3d ms = tread_shape.colwise().squaredNorm().transpose();
  const int c = ms(0) >= ms(1) && ms(0) >= ms(2) ? 0 : (ms(2) >= ms(1) ? 2 : 1);
  return c == 0 ? ModeFamily::kRadial : (c == 2 ? ModeFamily::kAxial : ModeFamily::kCircumferential);
}

namespace {

// Orders first .. last - 1 as one solver going up in n finds them: each order's count of modes is
// the guess for the next one's (fem::LowestModesSolver::solve's `expected`, which sets the Lanczos
// size and so the modes' last bits), starting from `guess`. An order whose guess is at most 1 (the
// high orders, whose lowest mode nears f_max) is first counted by inertia (count_below: one numeric
// factorisation); when that finds none, it has no mode below f_max and the Lanczos (a factorisation
// and ~25 operator applications even for no mode) is not run. The shipped 920 mm wheel: n = 9 and
// 10 (guesses 1 and 0) have none. An order counted non-empty is solved as before.
void solve_chain(const fem::AxisymmetricOrders& orders, fem::LowestModesSolver& solver,
                 std::size_t first, std::size_t last, int guess, std::vector<fem::Modes>& modes) {
  for (std::size_t n = first; n < last; ++n) {
    const auto km = orders.matrices(static_cast<int>(n));
    if (guess >= 0 && guess <= 1 && solver.count_below(km.stiffness, km.mass) == 0) {
      modes[n].omega.resize(0);  // as solve() returns no mode
      modes[n].shapes = Eigen::MatrixXd::Zero(km.stiffness.rows(), 0);
    } else {
      modes[n] = solver.solve(km.stiffness, km.mass, guess);
    }
    guess = static_cast<int>(modes[n].omega.size());
  }
}

// The modes of every order n = 0 .. n_max as the chain over all orders finds them (solve_chain
// from n = 0, guess unknown), bit for bit. On T threads the orders are cut into T consecutive
// blocks, one chain each (one solver, i.e. factorisation, per thread); a block's first guess, the
// count of the order below it, is found by inertia (count_below: one more numeric factorisation
// per block, not per order). A block whose first guess differs from the count the block below
// actually found is solved again after it (none on the shipped wheels).
std::vector<fem::Modes> order_modes(const fem::AxisymmetricOrders& orders,
                                    const std::vector<int>& fixed, double omega_max, int n_max,
                                    int threads) {
  const std::size_t count = static_cast<std::size_t>(n_max) + 1;
  std::vector<fem::Modes> modes(count);
  const int blocks = std::min<int>(resolved_threads(threads), static_cast<int>(count));
  std::vector<std::unique_ptr<fem::LowestModesSolver>> solvers;
  for (int t = 0; t < blocks; ++t)
    solvers.push_back(std::make_unique<fem::LowestModesSolver>(fixed, omega_max));
  std::vector<std::size_t> start(blocks + 1);  // block t: orders start[t] .. start[t + 1] - 1
  for (int t = 0; t <= blocks; ++t) start[t] = count * t / blocks;
  std::vector<int> guess(blocks, -1);
  parallel_for(blocks, blocks, [&](std::size_t t, int worker) {
    fem::LowestModesSolver& solver = *solvers[worker];
    if (t > 0) {
      const auto below = orders.matrices(static_cast<int>(start[t] - 1));
      guess[t] = solver.count_below(below.stiffness, below.mass);
    }
    solve_chain(orders, solver, start[t], start[t + 1], guess[t], modes);
  });
  for (int t = 1; t < blocks; ++t) {
    const int found = static_cast<int>(modes[start[t] - 1].omega.size());
    if (guess[t] != found) solve_chain(orders, *solvers[0], start[t], start[t + 1], found, modes);
  }
  return modes;
}

}  // namespace

WheelFeModes wheel_fe_modes(const WheelSection& section, const WheelFeOptions& options) {
  check_options(section, options);
  WheelFeModes w;
  w.mesh = fem::mesh_polygon(section.outline, options.mesh_size);
  sample_tread(section, options.tread_spacing, w);
  std::vector<int> fixed;
  for (int node : fem::nodes_on_segments(w.mesh, section.bore_segments))
    for (int c = 0; c < 3; ++c) fixed.push_back(3 * node + c);
  const auto line = mid_line(w.mesh);
  std::vector<fem::MeshPoint> tread_points;
  for (std::size_t i = 0; i < w.tread_s.size(); ++i)
    tread_points.push_back(fem::locate(w.mesh, {w.tread_r[i], w.tread_s[i]}, 1e-4));
  // one solver per thread for all n: the orders share the mesh's sparsity pattern (one symbolic
  // analysis per solver)
  const fem::AxisymmetricOrders orders(w.mesh, options.material);
  // M_n = c_n M_1 for every n (fem/axisymmetric.hpp): one mass matrix gives every order's shares
  const Eigen::SparseMatrix<double> m0 = orders.matrices(0).mass;
  w.mass = Eigen::VectorXd::Ones(m0.rows()).dot(m0 * Eigen::VectorXd::Ones(m0.rows())) / 3.0;
  const std::vector<fem::Modes> modes =
      order_modes(orders, fixed, 2 * kPi * options.f_max, options.n_max, options.threads);
  // each order's tread shapes, families and nodal circles (independent: in parallel too)
  std::vector<std::vector<WheelFeMode>> per_order(modes.size());
  parallel_for(modes.size(), resolved_threads(options.threads), [&](std::size_t n, int) {
    const fem::Modes& on = modes[n];
    for (int j = 0; j < on.omega.size(); ++j) {
      WheelFeMode m;
      m.frequency = on.omega(j) / (2 * kPi);
      m.n = static_cast<int>(n);
      m.tread_shape.resize(w.tread_s.size(), 3);
      for (std::size_t i = 0; i < w.tread_s.size(); ++i)
        m.tread_shape.row(i) =
            fem::displacement_at(w.mesh, on.shapes.col(j), tread_points[i]).transpose();
      // the family from the whole section's motion, the circles along its mid-line
      // (wheel_mode_family.hpp)
      m.family = section_family(fem::kinetic_energy_shares(m0, on.shapes.col(j)));
      m.nodal_circles =
          sign_changes(w.mesh, on.shapes.col(j), line, nodal_circle_component(m.family));
      m.dofs = on.shapes.col(j);
      per_order[n].push_back(std::move(m));
    }
  });
  for (auto& order : per_order)
    for (WheelFeMode& m : order) w.modes.push_back(std::move(m));
  return w;
}

WheelFeModes wheel_fe_tread(const WheelSection& section, const WheelFeOptions& options) {
  check_options(section, options);
  WheelFeModes w;
  sample_tread(section, options.tread_spacing, w);
  return w;
}

Eigen::Vector3d tread_shape_at(const WheelFeModes& w, const WheelFeMode& mode, double s) {
  const auto& t = w.tread_s;
  if (t.empty() || s < t.front() - 1e-9 || s > t.back() + 1e-9)
    throw InputError("tread_position", "contact position s = " + std::to_string(s) +
                                           " m is outside the wheel's running surface");
  const auto it = std::upper_bound(t.begin(), t.end(), s);
  const std::size_t i1 =
      std::min<std::size_t>(std::max<std::ptrdiff_t>(it - t.begin(), 1), t.size() - 1);
  const std::size_t i0 = i1 - 1;
  const double x = std::clamp((s - t[i0]) / (t[i1] - t[i0]), 0.0, 1.0);
  return ((1 - x) * mode.tread_shape.row(i0) + x * mode.tread_shape.row(i1)).transpose();
}

}  // namespace rollnoise::dynamics

