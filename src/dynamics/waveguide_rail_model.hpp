// The waveguide rail (rail_waveguide.hpp) as the loop's RailModel (track.hpp), from the reduced
// waveguide model on the continuous support of the track file's pads, sleepers and ballast:
//
//  * receptance(f): the 4x4 at the running surface's centre (the crown of the section), in the
//    loop's order (z, x, y, rotation about z), as `rollnoise receptance` writes it;
//  * contact_receptance*(f, offset, angle): the 4x4 with the section loaded AT THE CONTACT on the
//    head, in that contact's frame (normal n, x, lateral tangent t, rotation about n; the loop's
//    frame, noise/loop.hpp): the loop and squeal use it (loaded_at_contact() is true), so the
//    head's roll under an eccentric, inclined force and the local deformation of the gauge corner
//    are in the loop, not the crown's receptance moved rigidly (docs/models.md Sec. 2.5b).
//
// The contact point on the outline: where the outline's outward normal equals the contact's,
// n = (-sin gamma, cos gamma) in (y, z) (the contact condition: the rail's surface normal at the
// contact is the contact normal; Kalker, Three-dimensional elastic bodies in rolling contact,
// 1990, Sec. 1.3), on the head's top (z >= head_bottom); the outline being a polyline, a normal
// between two edges' is their common vertex, and among equal candidates the one nearest the
// lateral offset. Each contact point gets its own Ritz basis (the section's modes plus the static
// responses to that point's loads, RailWaveguide::reduced), built once and kept.
//
// The load is a uniform traction over the boundary within `patch_half_width` of the point (not a
// nodal point force, whose receptance grows as the mesh is refined), and the response is the same
// average (reciprocal). Receptances are memoised per frequency and point (the loop and squeal ask
// for the same frequencies repeatedly). contact_receptances() on a grid of many frequencies
// computes them on a logarithmic grid of `grid_per_octave` points per octave and interpolates
// (cubic Hermite in ln f, each entry; docs/models.md Sec. 2.5b gives the error).
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <utility>
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
  /// contact_receptances(): points per octave of the grid computed directly (0: every
  /// frequency directly).
  int grid_per_octave = 24;
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

  bool loaded_at_contact() const override { return true; }
  std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                               double offset_y,
                                               double contact_angle) const override;
  Receptance4 contact_receptance(double frequency, double offset_y,
                                 double contact_angle) const override;
  Receptance4 contact_receptance_laplace(cdouble s, double offset_y,
                                         double contact_angle) const override;
  /// The transfer between two contacts on this rail, a = (offset_a, angle_a) at x_a and
  /// b = (offset_b, angle_b) at x_b, x = x_a - x_b (m along the rail): the displacement of a in
  /// a's contact frame per unit force of b in b's frame (Eq. W4 of rail_waveguide.hpp with both
  /// points' loads in one Ritz basis). contact_transfer(f, a, a, 0) = contact_receptance(f, a)
  /// up to the basis (the pair's basis is richer); contact_transfer(f, a, b, x) =
  /// contact_transfer(f, b, a, -x)^T.
  Receptance4 contact_transfer(double frequency, double offset_a, double angle_a,
                               double offset_b, double angle_b, double x) const;
  Receptance4 contact_transfer_laplace(cdouble s, double offset_a, double angle_a,
                                       double offset_b, double angle_b, double x) const;
  /// The point (y, z) (m) of the outline where a contact at (offset_y, contact_angle) is loaded.
  Eigen::Vector2d contact_point(double offset_y, double contact_angle) const;

  const RailWaveguide& waveguide() const { return rail_; }
  /// The load (and response) distributions at the crown, dofs() x 4 (Receptance4 order).
  const Eigen::MatrixXd& crown_loads() const { return loads_; }

 private:
  /// Loaded points of the section (contacts, (offset, angle) each): their reduced model, their
  /// loads (dofs() x 4 per point) and a memo of the 4N x 4N transfer per (Re omega, Im omega, x).
  using Points = std::vector<std::pair<double, double>>;
  struct Station {
    RailWaveguide model;
    Eigen::MatrixXd loads;
    std::map<std::tuple<double, double, double>, Eigen::MatrixXcd> memo;
  };

  WaveguideRailOptions options_;
  std::vector<Eigen::Vector2d> outline_;
  RailWaveguide full_;  // the unreduced model, for the contacts' bases
  RailWaveguide rail_;  // the crown's reduced model
  Eigen::MatrixXd loads_;
  mutable std::mutex mutex_;
  mutable std::map<std::pair<double, double>, Receptance4> memo_;
  mutable std::map<Points, std::shared_ptr<Station>> stations_;

  Receptance4 at(cdouble omega) const;
  /// Block (a, b) of the transfer between `points` (a station's, sorted) at x.
  Receptance4 between(cdouble omega, const Points& points, int a, int b, double x) const;
  std::shared_ptr<Station> station(const Points& points) const;
};

/// The point of a counter-clockwise outline (y, z) (m) whose outward normal is
/// (-sin contact_angle, cos contact_angle), on the head's top (z >= head_bottom); see above.
Eigen::Vector2d outline_contact_point(const std::vector<Eigen::Vector2d>& outline,
                                      double head_bottom, double offset_y, double contact_angle);

/// Cubic Hermite interpolation in ln f of receptances sampled at increasing frequencies `grid`
/// (Hz), slopes from the parabola through each sample and its neighbours; at `frequencies`
/// within [grid.front(), grid.back()].
std::vector<Receptance4> interpolate_receptances(const std::vector<double>& grid,
                                                 const std::vector<Receptance4>& values,
                                                 const std::vector<double>& frequencies);

/// The rail's material from a track's vertical beam section: E, eta, rho = m' / A; nu given.
RailMaterial rail_material(const TrackParameters& track, double poisson_ratio);

}  // namespace rollnoise::dynamics
