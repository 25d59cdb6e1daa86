#include "dynamics/waveguide_rail_model.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/errors.hpp"
#include "dynamics/rail_section.hpp"
#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

RailMaterial rail_material(const TrackParameters& track, double poisson_ratio) {
  RailMaterial m;
  m.youngs_modulus = track.vertical.youngs_modulus;
  m.poisson_ratio = poisson_ratio;
  m.density = track.vertical.mass_per_length / track.vertical.area;
  m.loss_factor = track.vertical.loss_factor;
  return m;
}

namespace {

RailWaveguide full_model(const TrackParameters& track, const WaveguideRailOptions& o) {
  if (!(o.mesh_size > 0.0) || !(o.patch_half_width > 0.0))
    throw InputError("track.model", "waveguide rail: mesh size and load patch must be > 0");
  const std::vector<Eigen::Vector2d> outline = o.outline.empty() ? uic60_outline() : o.outline;
  return RailWaveguide(fem::mesh_polygon(outline, o.mesh_size),
                       rail_material(track, o.poisson_ratio),
                       FootSupport{track.vertical_support, track.lateral_support,
                                   track.longitudinal_support, track.sleeper_spacing});
}

// The crown: the highest point of the outline at the centre line (y = 0), or the highest vertex.
Eigen::Vector2d crown_of(const fem::QuadraticTriangleMesh& mesh) {
  double top = mesh.nodes.at(0).y();
  for (const auto& p : mesh.nodes) top = std::max(top, p.y());
  return Eigen::Vector2d(0.0, top);
}

}  // namespace

WaveguideRailModel::WaveguideRailModel(const TrackParameters& track,
                                       const WaveguideRailOptions& options)
    : RailModel(track, TrackSupport::kContinuous, 0.0), rail_(full_model(track, options)) {
  loads_ = rail_.patch_loads(crown_of(rail_.mesh()), options.patch_half_width,
                             Eigen::Vector2d(0.0, 1.0), options.head_bottom);
  rail_ = rail_.reduced(options.reduction, loads_);
}

Receptance4 WaveguideRailModel::at(cdouble omega) const {
  const std::pair<double, double> key(omega.real(), omega.imag());
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = memo_.find(key);
    if (it != memo_.end()) return it->second;
  }
  const Receptance4 r = rail_.contact_receptance(rail_.waves(omega), loads_, loads_, 0.0);
  const std::lock_guard<std::mutex> lock(mutex_);
  memo_.emplace(key, r);
  return r;
}

Receptance4 WaveguideRailModel::receptance(double frequency) const {
  if (!std::isfinite(frequency) || !(frequency > 0.0))
    throw InputError("frequency", "rail receptance needs a finite frequency > 0 Hz");
  return at(cdouble(angular(frequency), 0.0));
}

Receptance4 WaveguideRailModel::receptance_laplace(cdouble s) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  return at(cdouble(0.0, -1.0) * s);  // i omega = s
}

}  // namespace rollnoise::dynamics
