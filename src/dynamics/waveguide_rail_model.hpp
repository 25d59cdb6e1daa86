// The waveguide rail (rail_waveguide.hpp) as the loop's RailModel (rail_model.hpp), from the
// reduced waveguide model on the continuous support of the track file's pads, sleepers and ballast:
//
//  * receptance(f): the 4x4 at the running surface's centre (the crown of the section), in the
//    loop's order (z, x, y, rotation about z), as `rollnoise receptance` writes it;
//  * contact_transfers / laplace_transfers (RailModel's interface at contact points, track.hpp):
//    the section loaded AT THE CONTACTS on the head, in each contact's frame (normal n, x, lateral
//    tangent t, rotation about n; the loop's frame, noise/loop.hpp), between any two contacts at
//    any distance along the rail (Eq. W4 with all the points' loads in one Ritz basis), given to
//    the loop as the 6x6 T_a A_ab T_b^T (G2 of rail_contact.hpp): the head's roll under an
//    eccentric, inclined force and the local deformation of the gauge corner are in the loop, not
//    the crown's receptance moved rigidly (docs/models.md Sec. 2.7, 2.8);
//  * contact_receptance*, contact_transfer*: the same 4x4 at one frequency, for checks.
//
// The contact point on the outline: where the outline's outward normal equals the contact's,
// n = (-sin gamma, cos gamma) in (y, z) (the contact condition: the rail's surface normal at the
// contact is the contact normal; Kalker, Three-dimensional elastic bodies in rolling contact,
// 1990, Sec. 1.3), on the head's top (z >= head_bottom); the outline being a polyline, a normal
// between two edges' is their common vertex, and among equal candidates the one nearest the
// lateral offset. The points of one query share one Ritz basis (the section's modes plus the
// static responses to those points' loads, RailWaveguide::reduced), built by the query: for the
// loop's frequency grid once (contact_transfers), for complex frequency once per set of pairs
// (laplace_transfers returns a function of s holding it). Between queries only the samplings of
// the grids are kept (SamplingMemo: a second query on the same grid evaluates nothing).
//
// The load acts through the head as a body (RailWaveguide::head_loads: the forces on the head's
// least-squares rigid motion at the point, so the head's roll under an eccentric force is in it,
// the local deformation under the patch, which the contact model's half-space holds, is not),
// and the response is the same projection (reciprocal); `head_load = false` takes the former
// uniform traction over the boundary within `patch_half_width` of the point. contact_transfers() on
// a grid of many frequencies computes them directly on an adaptively chosen part of it and
// interpolates the rest (cubic Hermite in ln f, each entry; waveguide_frequency_sampling.hpp;
// docs/record/waveguide_rail.md Sec. 8 gives the error).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/lazy.hpp"
#include "dynamics/rail_model.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_frequency_sampling.hpp"

namespace rollnoise::dynamics {

struct WaveguideRailOptions {
  /// The section outline (y, z) (m), z up from the foot's bottom; empty: uic60_outline().
  std::vector<Eigen::Vector2d> outline;
  double mesh_size = 0.03;                ///< target element size h (m)
  double patch_half_width = 0.01;         ///< load patch radius around the crown (m)
  /// true: the contacts (and the crown) load the section through the head as a body
  /// (RailWaveguide::head_loads; the local deformation under the patch is the contact model's);
  /// false: the patch of patch_half_width (RailWaveguide::patch_loads), the former load.
  bool head_load = true;
  /// Discrete supports: each seat's force spread evenly over this length along the rail (m; a
  /// rail pad's length, assumed; 0: at one x, the former model). docs/models.md Sec. 2.11.
  double seat_length = 0.15;
  double head_bottom = kUic60HeadBottom;  ///< z of the head's underside (m), for the spin
  double poisson_ratio = 0.3;             ///< nu (-); E, rho, eta from the track's rail
  /// The basis at the crown and the contacts, on either support (WaveguideRailModel,
  /// DiscreteWaveguideRailModel; docs/record/waveguide_rail.md Sec. 11, "The contact points'
  /// basis").
  RailReduction contact_reduction = near_field_reduction();
  /// contact_transfers() on a grid: the frequencies computed directly, the others interpolated
  /// (waveguide_frequency_sampling.hpp; per_octave = 0: every frequency directly).
  FrequencySampling sampling;
  /// Where the samplings are kept beyond the run (null: nowhere; io/rail_sampling_cache.hpp), and
  /// this model's identity there: everything its values depend on besides the points, pairs and
  /// grid (the build, the track file, the support, the section).
  std::shared_ptr<const SamplingArchive> archive;
  std::string archive_identity;
};

/// The checks of a waveguide rail's inputs that its build makes (InputError naming the key): the
/// mesh size, load patch and sampling, the outline (fem::check_outline), the rail's material and
/// the supports (continuous, or the seats of the discrete support). The models make them up front
/// and build on first use.
void check_waveguide_inputs(const TrackParameters& track, const WaveguideRailOptions& options);

/// Two fixed contact points (offset, angle) whose eight load columns span every contact's four
/// (the head as a body: the six distributions of RailWaveguide::head_body), and each queried
/// point's columns as their combination (8 x 4: C_a = [C_0 C_1] alpha_a). A pair's 4x4 is then
/// alpha_a^T V alpha_b, V the two points' 8x8 at the pair's positions, so the sampling of V at a
/// set of positions serves every contact there (both rails, every contact state of a study).
struct SpanningPoints {
  std::vector<std::pair<double, double>> points;
  std::vector<Eigen::Matrix<double, 8, 4>> combination;  ///< per point of the query
};

/// The spanning points of the head as a body on `outline`: the crown (0, 0) and the point whose
/// normal is at 0.4 rad, each of `points` (offset, angle) solved for by least squares ([C_0 C_1]
/// has rank 6; null where it has not, or without head loads).
std::optional<SpanningPoints> head_spanning_points(
    const HeadBody& head, const std::vector<Eigen::Vector2d>& outline,
    const WaveguideRailOptions& options, const std::vector<std::pair<double, double>>& points);

/// A rail model that samples the frequency grids it is given and keeps the samplings (the
/// waveguide on the continuous and on the discrete support): contact_transfers computes each set
/// of coupled points (rail_point_sets) directly on an adaptively chosen part of the grid and
/// interpolates the rest (waveguide_frequency_sampling.hpp, sampled_values), and on_grid gives the
/// view of it that takes every frequency from the sampling of one grid (WaveguideOnGrid). A model
/// provides its sampling and, per set of points, the direct evaluation.
class GridSamplingRail : public RailModel {
 public:
  /// RailModel's, the samplings kept in `archive` (may be null) under `identity` as well.
  GridSamplingRail(const TrackParameters& track, double contact_position,
                   std::shared_ptr<const SamplingArchive> archive, std::string identity);
  /// Sampled as sampling() says (the rest interpolated) when `interpolate`, else every frequency
  /// directly.
  std::vector<std::vector<Receptance6>> contact_transfers(const std::vector<double>& frequencies,
                                                          const std::vector<RailContactPair>& pairs,
                                                          bool interpolate = true) const override;
  /// contact_transfers at `frequencies` from the sampling of `grid` (SampledGrid, sampled_at): a
  /// sampled frequency its value, one inside a checked interval interpolated, any other computed.
  /// The sampling of a grid is kept (SamplingMemo, shared by copies: every contact_transfers call
  /// keeps its own), so the case's lines' sampling serves the refinement's lines.
  std::vector<std::vector<Receptance6>> contact_transfers_from(
      const std::vector<double>& grid, const std::vector<double>& frequencies,
      const std::vector<RailContactPair>& pairs) const;
  /// True unless sampling() computes every frequency directly (per_octave = 0).
  bool samples_grid() const override { return sampling().per_octave > 0; }
  /// A WaveguideOnGrid of this rail (null where samples_grid() is false: every frequency alone
  /// already).
  std::unique_ptr<RailModel> on_grid(std::vector<double> grid) const override;
  /// The model's direct_laplace_transfers; with an archive, each s's values also kept in it (read
  /// at the first call, written when the last copy of the function goes) and taken from it where
  /// it holds them: a later run on the same path of s computes none. Refers to the rail, which
  /// must outlive it.
  LaplaceTransfers laplace_transfers(const std::vector<RailContactPair>& pairs) const final;

 protected:
  /// Loaded points of the section ((offset, angle) each), and the pairs of one set of them as
  /// (point a, point b, x_a, x_b) (m along the rail).
  using Points = std::vector<std::pair<double, double>>;
  using SetPairs = std::vector<std::tuple<int, int, double, double>>;
  using Evaluator = std::function<std::vector<Receptance4>(double)>;
  virtual const FrequencySampling& sampling() const = 0;
  /// Whether a pair's value depends on x_a - x_b alone (the continuous support; the discrete one
  /// depends on where the two points are between the sleepers).
  virtual bool along_rail_invariant() const = 0;
  /// The direct evaluation of one set: f (Hz) -> the contact-frame 4x4 of each of `pairs`, one
  /// basis for the points (built on the first call); safe to call concurrently.
  virtual Evaluator evaluator(const Points& points, const SetPairs& pairs) const = 0;
  /// The contact transfers at complex s, computed at every call (RailModel::laplace_transfers).
  virtual LaplaceTransfers direct_laplace_transfers(
      const std::vector<RailContactPair>& pairs) const = 0;
  /// The SpanningPoints of `points` (null: none; sampled per set of points).
  virtual std::optional<SpanningPoints> spanning_points(const Points& points) const {
    (void)points;
    return std::nullopt;
  }

 private:
  /// The samplings kept: per point set, its pairs (with the scales' points) and the grid; its
  /// archive (if any) keeps the values at complex s too.
  std::shared_ptr<const SamplingMemo> memo_;
  /// contact_transfers (grid null) and contact_transfers_from (from the sampling of *grid).
  std::vector<std::vector<Receptance6>> transfers(const std::vector<double>& frequencies,
                                                  const std::vector<RailContactPair>& pairs,
                                                  bool interpolate,
                                                  const std::vector<double>* grid) const;
  /// The contact-frame 4x4 of each pair at every frequency (per pair, per frequency): sampled per
  /// set of coupled points (set_values), or where interpolated, from the spanning points'
  /// samplings.
  std::vector<std::vector<Receptance4>> frame_values(const std::vector<double>& frequencies,
                                                     const std::vector<RailContactPair>& pairs,
                                                     bool interpolate,
                                                     const std::vector<double>* grid) const;
  std::vector<std::vector<Receptance4>> set_values(const std::vector<double>& frequencies,
                                                   const std::vector<RailContactPair>& pairs,
                                                   bool interpolate,
                                                   const std::vector<double>* grid) const;
};

class WaveguideRailModel : public GridSamplingRail {
 public:
  /// `track`: the supports (vertical, lateral, longitudinal), sleeper spacing, and the rail's E,
  /// density (mass per length / area) and loss factor from track.vertical.
  WaveguideRailModel(const TrackParameters& track, const WaveguideRailOptions& options);

  Receptance4 receptance(double frequency) const override;
  /// Continued to omega = -i s: the waves with Im k < 0 at the complex frequency (valid while no
  /// wave crosses the real k axis, i.e. for decay rates Re s > -(loss) x omega; docs/models.md).
  Receptance4 receptance_laplace(cdouble s) const override;

  /// The crown's transfer between x_response and x_load (the centre-line model of this rail).
  std::vector<Receptance4> line_transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const override;
  Receptance4 line_transfer_laplace(cdouble s, double x_response, double x_load) const override;

  /// The 4x4 in the contact frame of a contact at (offset_y, contact_angle) per frequency of
  /// `frequencies` (interpolated as contact_transfers), at one frequency and at s.
  std::vector<Receptance4> contact_receptances(const std::vector<double>& frequencies,
                                               double offset_y, double contact_angle) const;
  Receptance4 contact_receptance(double frequency, double offset_y, double contact_angle) const;
  Receptance4 contact_receptance_laplace(cdouble s, double offset_y, double contact_angle) const;
  /// The transfer between two contacts on this rail, a = (offset_a, angle_a) at x_a and
  /// b = (offset_b, angle_b) at x_b, x = x_a - x_b (m along the rail): the displacement of a in
  /// a's contact frame per unit force of b in b's frame (Eq. W4 with both points' loads in one
  /// Ritz basis). contact_transfer(f, a, a, 0) = contact_receptance(f, a) up to the basis (the
  /// pair's basis is richer); contact_transfer(f, a, b, x) = contact_transfer(f, b, a, -x)^T.
  Receptance4 contact_transfer(double frequency, double offset_a, double angle_a, double offset_b,
                               double angle_b, double x) const;
  Receptance4 contact_transfer_laplace(cdouble s, double offset_a, double angle_a, double offset_b,
                                       double angle_b, double x) const;
  /// The point (y, z) (m) of the outline where a contact at (offset_y, contact_angle) is loaded.
  Eigen::Vector2d contact_point(double offset_y, double contact_angle) const;

  /// Eq. (W7) of rail_surface_spectrum.hpp: the section loaded at the points (one Ritz basis;
  /// with head loads, the head's six distributions' basis and spectra, combined).
  bool section_deforms() const override { return true; }
  SurfaceSpectra surface_spectra(const std::vector<RailLoadPoint>& points,
                                 const std::vector<OutlinePiece>& pieces,
                                 const Eigen::MatrixXd& patterns) const override;
  /// With head loads: the head's six distributions (RailWaveguide::head_body), reduced on them.
  std::optional<RailLoadBasis> load_basis(const std::vector<RailLoadPoint>& points) const override;
  SurfaceSpectra basis_surface_spectra(const std::vector<double>& x,
                                       const std::vector<OutlinePiece>& pieces,
                                       const Eigen::MatrixXd& patterns) const override;

  /// The crown's reduced model (built on first use: the loop at the contacts does not need it).
  const RailWaveguide& waveguide() const { return crown().model; }
  /// The load (and response) distributions at the crown, dofs() x 4 (Receptance4 order).
  const Eigen::MatrixXd& crown_loads() const { return crown().loads; }

 private:
  /// Loaded points of the section (Points: contacts, (offset, angle) each), their reduced model
  /// and loads (dofs() x 4 per point): a value built for one query.
  struct Station {
    RailWaveguide model;
    Eigen::MatrixXd loads;
  };

  /// The unreduced model, for the contacts' bases, and its section modes (the load-independent
  /// part of every basis).
  struct Section {
    RailWaveguide full;
    RailReductionModes modes;
  };

  WaveguideRailOptions options_;
  std::vector<Eigen::Vector2d> outline_;
  // Built on first use (shared by copies): a run whose samplings all come from the archive
  // meshes and solves nothing.
  Lazy<Section> section_;
  Lazy<Station> crown_;
  Lazy<HeadBody> head_;  // section_head_body

  // GridSamplingRail's: at the contacts themselves (header comment), one Ritz basis per set.
  const FrequencySampling& sampling() const override { return options_.sampling; }
  bool along_rail_invariant() const override { return true; }
  Evaluator evaluator(const Points& points, const SetPairs& pairs) const override;
  LaplaceTransfers direct_laplace_transfers(
      const std::vector<RailContactPair>& pairs) const override;

  const Station& crown() const;
  Receptance4 at(cdouble omega) const;
  std::shared_ptr<const Station> station(const Points& points) const;
  /// The contact-frame 4x4 of every pair at omega, the pairs given as (point a, point b, x_a -
  /// x_b) into the station's points: one wave solution, one Eq. (W4) per distinct distance.
  std::vector<Receptance4> between(const Station& s, cdouble omega,
                                   const std::vector<std::tuple<int, int, double>>& pairs) const;
};

/// A waveguide rail whose contact transfers come from its sampling of one grid
/// (GridSamplingRail::on_grid; RailModel::on_grid): every frequency's value depends on that
/// grid and itself alone, whatever other frequencies a call asks for. Everything else is the
/// rail's own. Refers to the rail, which must outlive it.
class WaveguideOnGrid final : public RailModel {
 public:
  WaveguideOnGrid(const GridSamplingRail& rail, std::vector<double> grid);
  Receptance4 receptance(double frequency) const override { return rail_.receptance(frequency); }
  Receptance4 receptance_laplace(cdouble s) const override { return rail_.receptance_laplace(s); }
  std::vector<Receptance4> line_transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const override {
    return rail_.line_transfers(frequency, pairs);
  }
  Receptance4 line_transfer_laplace(cdouble s, double x_response, double x_load) const override {
    return rail_.line_transfer_laplace(s, x_response, x_load);
  }
  std::vector<std::vector<Receptance6>> contact_transfers(const std::vector<double>& frequencies,
                                                          const std::vector<RailContactPair>& pairs,
                                                          bool interpolate = true) const override;
  /// Each frequency from the grid's sampling alone: no dependence on the frequencies asked for.
  bool samples_grid() const override { return false; }
  LaplaceTransfers laplace_transfers(const std::vector<RailContactPair>& pairs) const override {
    return rail_.laplace_transfers(pairs);
  }
  bool section_deforms() const override { return rail_.section_deforms(); }
  SurfaceSpectra surface_spectra(const std::vector<RailLoadPoint>& points,
                                 const std::vector<OutlinePiece>& pieces,
                                 const Eigen::MatrixXd& patterns) const override {
    return rail_.surface_spectra(points, pieces, patterns);
  }

 private:
  const GridSamplingRail& rail_;
  std::vector<double> grid_;
};

/// Where a contact at lateral offset `offset_y` (m, the rail profile's coordinate) with the
/// contact angle `contact_angle` (rad) loads a counter-clockwise outline (y, z) (m): the head's
/// top (z >= head_bottom) at y = offset_y where the top spans it; beyond it (a gauge-face
/// offset), the point whose outward normal is (-sin contact_angle, cos contact_angle).
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

/// The four load (and response) distributions of a contact at `point` (y, z) with the rail's
/// outward normal `normal`: RailWaveguide::head_loads, or patch_loads (options.head_load false).
Eigen::MatrixXd contact_loads_at(const RailWaveguide& section, const WaveguideRailOptions& options,
                                 const Eigen::Vector2d& point, const Eigen::Vector2d& normal);

/// The points' loads on the head's six distributions `head` (RailWaveguide::head_body) at their
/// distinct positions (RailModel::load_basis): each point's 6 x 4 is head.at(its point on
/// `outline`, its normal), exactly as contact_loads_at loads it. Empty without head loads
/// (options.head_load false: the patch is no combination of the six).
/// The head body (RailWaveguide::head_body at options.head_bottom) of the options' section, from
/// its mesh alone (no model assembled, no mode solved): what head_load_basis needs, cheap for a
/// run whose rail values all come from the caches.
HeadBody section_head_body(const WaveguideRailOptions& options);

std::optional<RailLoadBasis> head_load_basis(const HeadBody& head,
                                             const std::vector<Eigen::Vector2d>& outline,
                                             const WaveguideRailOptions& options,
                                             const std::vector<RailLoadPoint>& points);

/// The load (and response) distributions of contacts at `points` ((offset_y, contact_angle) each)
/// on `section`'s outline (outline_contact_point), dofs() x 4 per point in the contact frame
/// (RailWaveguide::head_loads, or patch_loads with options.head_load false): what
/// WaveguideRailModel loads at a contact, for other models of the same section (the discrete
/// supports, waveguide_discrete_support.hpp).
Eigen::MatrixXd contact_point_loads(const RailWaveguide& section,
                                    const std::vector<Eigen::Vector2d>& outline,
                                    const WaveguideRailOptions& options,
                                    const std::vector<std::pair<double, double>>& points);

/// Loads at RailLoadPoints on one Ritz basis: the distinct (offset_y, contact_angle) of the points
/// (a station's points) and, per point, which of them it is.
struct LoadPointColumns {
  std::vector<std::pair<double, double>> distinct;
  std::vector<int> which;
  std::vector<double> x;  ///< per column of columns() (m)
  /// Each point's four columns of `distinct_loads` (dofs() x 4 per distinct point), side by side.
  Eigen::MatrixXd columns(const Eigen::MatrixXd& distinct_loads) const;
};
LoadPointColumns load_point_columns(const std::vector<RailLoadPoint>& points);

/// The pairs' contact points grouped into the sets that are coupled (a pair joins its two points),
/// as WaveguideRailModel gives each set one Ritz basis: per set its points (offset_y,
/// contact_angle), sorted; per pair its set and (point a, point b, x_a - x_b) within the set.
struct RailPointSets {
  std::vector<std::vector<std::pair<double, double>>> points;
  std::vector<int> set;
  std::vector<std::tuple<int, int, double>> within;
};
RailPointSets rail_point_sets(const std::vector<RailContactPair>& pairs);

}  // namespace rollnoise::dynamics
