#include "dynamics/waveguide_discrete_support.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "dynamics/rail_section.hpp"
#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

FootAttachment foot_attachment(const RailWaveguide& rail) {
  // The foot: the boundary edges along the lowest z (as RailWaveguide's continuous support).
  const fem::QuadraticTriangleMesh& mesh = rail.mesh();
  double zmin = mesh.nodes.at(0).y(), zmax = zmin;
  for (const auto& p : mesh.nodes) zmin = std::min(zmin, p.y()), zmax = std::max(zmax, p.y());
  const double tol = 1e-6 * (zmax - zmin);
  std::vector<int> edges;
  double width = 0.0, first = 0.0;
  for (int i = 0; i < static_cast<int>(mesh.boundary_edges.size()); ++i) {
    const auto& e = mesh.boundary_edges[i];
    bool on_foot = true;
    for (int v : e) on_foot = on_foot && std::abs(mesh.nodes[v].y() - zmin) < tol;
    if (!on_foot) continue;
    edges.push_back(i);
    const double len = (mesh.nodes[e[2]] - mesh.nodes[e[0]]).norm();
    width += len;
    first += len * mesh.nodes[e[1]].x();  // the mid node is the edge's centre
  }
  if (edges.empty()) throw InputError("rail_section", "the rail section has no flat foot");
  const double yf = first / width;
  FootAttachment a;
  a.loads = Eigen::MatrixXd::Zero(rail.dofs(), 4);
  for (int d = 0; d < 3; ++d) a.loads.col(d) = rail.edge_traction(edges, d);
  // Int N (y - y_f) ds on each straight quadratic edge by 3-point Gauss (exact, degree 3), and
  // I_f = Int (y - y_f)^2 ds (exact for the linear y).
  const double g = std::sqrt(0.6), gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}, gx[3] = {-g, 0.0, g};
  double inertia = 0.0;
  for (int i : edges) {
    const auto& e = mesh.boundary_edges[i];
    const double y0 = mesh.nodes[e[0]].x(), y2 = mesh.nodes[e[2]].x(), half = 0.5 * std::abs(y2 - y0);
    for (int q = 0; q < 3; ++q) {
      const double xi = gx[q], y = 0.5 * (y0 + y2) + 0.5 * (y2 - y0) * xi - yf;
      const double N[3] = {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
      for (int k = 0; k < 3; ++k) a.loads(RailWaveguide::dof(e[k], 2), 3) += gw[q] * half * N[k] * y;
      inertia += gw[q] * half * y * y;
    }
  }
  a.loads.col(3) /= inertia;
  a.roll_arm_squared = inertia / width;
  return a;
}

DiscretelySupportedWaveguide::DiscretelySupportedWaveguide(RailWaveguide free_rail,
                                                           FootAttachment foot,
                                                           const FootSupport& support,
                                                           int supports_each_side)
    : rail_(std::move(free_rail)), foot_(std::move(foot)), support_(support),
      n_(supports_each_side) {
  support_.vertical.validate("track.support.vertical");
  support_.lateral.validate("track.support.lateral");
  support_.longitudinal.validate("track.support.longitudinal");
  if (!(support_.sleeper_spacing > 0.0))
    throw InputError("rail_support", "sleeper spacing must be > 0");
  if (n_ < 1) throw InputError("rail_support", "at least one support each side");
  if (foot_.loads.rows() != rail_.dofs() || foot_.loads.cols() != 4)
    throw InputError("rail_section", "foot attachment does not match the rail's mesh");
}

Eigen::MatrixXcd DiscretelySupportedWaveguide::transfer(cdouble omega,
                                                        const Eigen::MatrixXd& response,
                                                        double x_response,
                                                        const Eigen::MatrixXd& load,
                                                        double x_load) const {
  const RailWaves w = rail_.waves(omega);
  const double L = support_.sleeper_spacing;
  const int m = 2 * n_ + 1, c = static_cast<int>(load.cols());
  const long centre = std::lround(0.5 * (x_response + x_load) / L);
  // Eq. (D1).
  const cdouble kz = support_.vertical.dynamic_stiffness(omega);
  const Eigen::Vector4cd K(support_.longitudinal.dynamic_stiffness(omega),
                           support_.lateral.dynamic_stiffness(omega), kz,
                           kz * foot_.roll_arm_squared);
  // A's blocks g(d L), d = 0..2N (g(-x) = g(x)^T, reciprocity of Eq. W4).
  std::vector<Eigen::MatrixXcd> g(m);
  for (int d = 0; d < m; ++d) g[d] = rail_.transfer(w, foot_.loads, foot_.loads, d * L);
  Eigen::MatrixXcd S = Eigen::MatrixXcd::Identity(4 * m, 4 * m);  // I + A K, Eq. (D2)
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const Eigen::Matrix4cd a = i >= j ? g[i - j] : g[j - i].transpose();
      S.block<4, 4>(4 * i, 4 * j) += a * K.asDiagonal();
    }
  Eigen::MatrixXcd B(4 * m, c);
  std::vector<double> x(m);
  for (int i = 0; i < m; ++i) {
    x[i] = (centre - n_ + i) * L;
    B.middleRows(4 * i, 4) = rail_.transfer(w, foot_.loads, load, x[i] - x_load);
  }
  const Eigen::MatrixXcd v = S.partialPivLu().solve(B);
  // Eq. (D3).
  Eigen::MatrixXcd H = rail_.transfer(w, response, load, x_response - x_load);
  for (int i = 0; i < m; ++i)
    H -= rail_.transfer(w, response, foot_.loads, x_response - x[i]) * K.asDiagonal() *
         v.middleRows(4 * i, 4);
  return H;
}

DiscreteWaveguideRailModel::Parts DiscreteWaveguideRailModel::build(
    const TrackParameters& track, const WaveguideRailOptions& o) {
  if (!(o.mesh_size > 0.0) || !(o.patch_half_width > 0.0))
    throw InputError("track.model", "waveguide rail: mesh size and load patch must be > 0");
  const std::vector<Eigen::Vector2d> outline = o.outline.empty() ? uic60_outline() : o.outline;
  const RailWaveguide full(fem::mesh_polygon(outline, o.mesh_size),
                           rail_material(track, o.poisson_ratio), std::nullopt);
  double top = full.mesh().nodes.at(0).y();
  for (const auto& p : full.mesh().nodes) top = std::max(top, p.y());
  Eigen::MatrixXd crown = full.patch_loads(Eigen::Vector2d(0.0, top), o.patch_half_width,
                                           Eigen::Vector2d(0.0, 1.0), o.head_bottom);
  FootAttachment foot = foot_attachment(full);
  Eigen::MatrixXd loads(full.dofs(), 8);
  loads << crown, foot.loads;
  const FootSupport support{track.vertical_support, track.lateral_support,
                            track.longitudinal_support, track.sleeper_spacing};
  return Parts{std::move(crown),
               DiscretelySupportedWaveguide(full.reduced(o.reduction, loads), std::move(foot),
                                            support, track.supports_each_side)};
}

DiscreteWaveguideRailModel::DiscreteWaveguideRailModel(const TrackParameters& track,
                                                       const WaveguideRailOptions& options,
                                                       double contact_position)
    : RailModel(track, TrackSupport::kContinuous, contact_position),
      parts_(build(track, options)),
      x_(contact_position) {
  if (!std::isfinite(x_) || x_ < 0.0)
    throw InputError("track.position", "contact position along the rail must be >= 0");
}

Receptance4 DiscreteWaveguideRailModel::at(cdouble omega) const {
  return parts_.rail.transfer(omega, parts_.crown, x_, parts_.crown, x_);
}

Receptance4 DiscreteWaveguideRailModel::receptance(double frequency) const {
  if (!std::isfinite(frequency) || !(frequency > 0.0))
    throw InputError("frequency", "rail receptance needs a finite frequency > 0 Hz");
  return at(cdouble(angular(frequency), 0.0));
}

Receptance4 DiscreteWaveguideRailModel::receptance_laplace(cdouble s) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  return at(cdouble(0.0, -1.0) * s);  // i omega = s
}

Receptance4 DiscreteWaveguideRailModel::transfer(double frequency, double x_response,
                                                 double x_load) const {
  return line_transfer(frequency, x_response, x_load);
}

std::vector<Receptance4> DiscreteWaveguideRailModel::line_transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  if (!std::isfinite(frequency) || !(frequency > 0.0))
    throw InputError("frequency", "rail receptance needs a finite frequency > 0 Hz");
  std::vector<Receptance4> out;
  for (const auto& [xr, xe] : pairs)
    out.push_back(parts_.rail.transfer(cdouble(angular(frequency), 0.0), parts_.crown, xr,
                                       parts_.crown, xe));
  return out;
}

Receptance4 DiscreteWaveguideRailModel::line_transfer_laplace(cdouble s, double x_response,
                                                              double x_load) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  return parts_.rail.transfer(cdouble(0.0, -1.0) * s, parts_.crown, x_response, parts_.crown,
                              x_load);
}

}  // namespace rollnoise::dynamics
