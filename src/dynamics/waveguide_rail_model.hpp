// The waveguide rail (rail_waveguide.hpp) as the loop's RailModel (track.hpp): the 4x4 receptance
// of the rail at the running surface's centre (the crown of the section), in the loop's order
// (z, x, y, rotation about z) and frame, from the reduced waveguide model on the continuous
// support of the track file's pads, sleepers and ballast, so that the loop, squeal and
// `rollnoise receptance` use it unchanged (the loop moves it to the contact's lateral offset and
// contact angle as it does the beam's).
//
// The load is a uniform traction over the boundary within `patch_half_width` of the crown (not a
// nodal point force, whose receptance grows as the mesh is refined), and the response is the same
// average (reciprocal). The receptance per frequency is memoised (the loop and squeal ask for the
// same frequencies repeatedly).
#pragma once

#include <Eigen/Core>
#include <map>
#include <mutex>
#include <vector>

#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"

namespace rollnoise::dynamics {

struct WaveguideRailOptions {
  /// The section outline (y, z) (m), z up from the foot's bottom; empty: uic60_outline().
  std::vector<Eigen::Vector2d> outline;
  double mesh_size = 0.03;                ///< target element size h (m)
  double patch_half_width = 0.01;         ///< load patch radius around the crown (m)
  double head_bottom = kUic60HeadBottom;  ///< z of the head's underside (m), for the spin
  double poisson_ratio = 0.3;             ///< nu (-); E, rho, eta from the track's rail
  RailReduction reduction;
};

class WaveguideRailModel : public RailModel {
 public:
  /// `track`: the supports (vertical, lateral, longitudinal), sleeper spacing, and the rail's E,
  /// density (mass per length / area) and loss factor from track.vertical.
  WaveguideRailModel(const TrackParameters& track, const WaveguideRailOptions& options);

  Receptance4 receptance(double frequency) const override;
  /// Continued to omega = -i s: the waves with Im k < 0 at the complex frequency (valid while no
  /// wave crosses the real k axis, i.e. for decay rates Re s > -(loss) x omega; docs/models.md).
  Receptance4 receptance_laplace(cdouble s) const override;

  const RailWaveguide& waveguide() const { return rail_; }
  /// The load (and response) distributions at the crown, dofs() x 4 (Receptance4 order).
  const Eigen::MatrixXd& crown_loads() const { return loads_; }

 private:
  RailWaveguide rail_;
  Eigen::MatrixXd loads_;
  mutable std::mutex mutex_;
  mutable std::map<std::pair<double, double>, Receptance4> memo_;

  Receptance4 at(cdouble omega) const;
};

/// The rail's material from a track's vertical beam section: E, eta, rho = m' / A; nu given.
RailMaterial rail_material(const TrackParameters& track, double poisson_ratio);

}  // namespace rollnoise::dynamics
