// The rail as the loop, squeal and the sound see it: one interface, RailModel, whatever the model
// behind it (docs/models.md Sec. 2.8). Two implementations: the Timoshenko beams on their support
// (BeamRailModel, beam_rail_model.hpp) and the 2.5D waveguide section on the continuous or the
// discrete support (WaveguideRailModel, DiscreteWaveguideRailModel; waveguide_rail_model.hpp,
// waveguide_discrete_support.hpp).
//
// What a rail gives:
//  * at the centre line (receptance, line_transfers and their continuation to complex
//    frequency): the 4x4 (z, x, y, rot z) at the running surface's centre, between two positions
//    along the rail (the sound of the sleepers and of a rigid section, the decay rates);
//  * at contact points (contact_transfers, laplace_transfers): a contact is a RailContact (x along
//    the rail, offset on the head, contact angle); the result, per pair (a, b), is the 6x6 (x, y,
//    z, rot x, rot y, rot z; the rail's frame, rail_contact.hpp) displacement at a's point per
//    load at b's point, whose contact-frame 4x4 is T_a^T alpha T_b (G2);
//  * the surface spectra of a section that deforms (surface_spectra; the waveguides), for the
//    rail's sound wavenumber by wavenumber (pipeline/rail_section_sound.hpp).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "dynamics/rail_contact.hpp"
#include "dynamics/rail_surface_spectrum.hpp"
#include "dynamics/receptance.hpp"
#include "dynamics/track.hpp"

namespace rollnoise::dynamics {

class RailModel {
 public:
  /// `contact_position`: distance of the case's contact from a sleeper along the rail (m; 0 over a
  /// sleeper, L/2 mid-span); finite.
  RailModel(const TrackParameters& track, double contact_position);
  virtual ~RailModel() = default;

  /// The centre-line point receptance at position().
  virtual Receptance4 receptance(double frequency) const = 0;
  /// The receptance at the Laplace variable s = sigma + i omega (1/s), i omega -> s: the model
  /// continued to the complex frequency omega = -i s (docs/squeal.md Sec. 2);
  /// receptance_laplace(i omega) = receptance(omega / 2 pi) up to round-off.
  virtual Receptance4 receptance_laplace(cdouble s) const = 0;

  /// The centre-line 4x4 transfer, displacement at x_response per force at x_load (m along the
  /// rail from a sleeper), for several (x_response, x_load) pairs at one frequency.
  /// line_transfers(f, {{x, x}}) = receptance(f) at x = position().
  virtual std::vector<Receptance4> line_transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const = 0;
  Receptance4 line_transfer(double frequency, double x_response, double x_load) const {
    return line_transfers(frequency, {{x_response, x_load}}).front();
  }
  /// The same at the Laplace variable s (receptance_laplace's continuation).
  virtual Receptance4 line_transfer_laplace(cdouble s, double x_response, double x_load) const = 0;

  /// The 6x6 between contact points (header) for every pair at every frequency of a grid:
  /// out[k][p] is pair p at frequencies[k]. `interpolate`: a model may compute them on a coarser
  /// grid and interpolate (the waveguide; docs/models.md Sec. 2.7); false: each frequency
  /// directly.
  virtual std::vector<std::vector<Receptance6>> contact_transfers(
      const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs,
      bool interpolate = true) const = 0;
  /// The same at complex frequency: a function of the Laplace variable s for fixed pairs, whose
  /// setup (the waveguide's basis at those points) is done once, here.
  using LaplaceTransfers = std::function<std::vector<Receptance6>(cdouble s)>;
  virtual LaplaceTransfers laplace_transfers(const std::vector<RailContactPair>& pairs) const = 0;

  /// Whether contact_transfers(frequencies, pairs, true) at one frequency depends on the grid's
  /// other frequencies (a model that interpolates between direct evaluations): a caller that
  /// splits a grid among threads must then split it the same way for any thread count. The beams
  /// compute every frequency alone: false; the waveguide on either support samples (true unless
  /// its sampling is off; GridSamplingRail in waveguide_rail_model.hpp).
  virtual bool samples_grid() const { return false; }
  /// For a model that samples its grid: the same rail whose contact_transfers at any frequencies
  /// take them from its sampling of `grid` (interpolated where that sampling checked the
  /// interpolation, else computed), so that each frequency's value depends on `grid` and itself
  /// alone (the refinement's added lines, pipeline/band_lines.cpp); it refers to this model, which
  /// must outlive it. Null for a model that computes every frequency alone (use it as it is).
  virtual std::unique_ptr<RailModel> on_grid(std::vector<double> grid) const {
    (void)grid;
    return nullptr;
  }

  /// Whether the rail's section deforms (surface_spectra is not null): the waveguides.
  virtual bool section_deforms() const { return false; }
  /// The rail's surface spectra (rail_surface_spectrum.hpp) under loads at `points`, of the normal
  /// displacement patterns `patterns` over the outline pieces `pieces` (pieces x r: row = piece,
  /// column = pattern; U's rows are the patterns' amplitudes u^T patterns), per frequency: what the
  /// sound of a rail whose section deforms needs (pipeline/rail_section_sound.hpp). Null for a
  /// model without a section (the beams: their section moves rigidly, and their sound takes the
  /// centre line's response, line_transfers).
  virtual SurfaceSpectra surface_spectra(const std::vector<RailLoadPoint>& points,
                                         const std::vector<OutlinePiece>& pieces,
                                         const Eigen::MatrixXd& patterns) const {
    (void)points, (void)pieces, (void)patterns;
    return nullptr;
  }

  /// Loads on the head as combinations of a few load distributions per position along the rail
  /// (the waveguides: the head as a body, RailWaveguide::head_body, six distributions whatever
  /// the contact's offset and angle): the section's sound of any contacts at those positions then
  /// follows from that of the distributions, G = C^T G_D C (pipeline/rail_section_sound.hpp),
  /// and the distributions' G_D is shared by every contact state on the track. Empty where the
  /// loads are not such combinations (the beams; the waveguide's patch loads).
  virtual std::optional<RailLoadBasis> load_basis(const std::vector<RailLoadPoint>& points) const {
    (void)points;
    return std::nullopt;
  }
  /// The surface spectra (as surface_spectra) of load_basis's distributions at each of `x` (m
  /// along the rail; RailLoadBasis::per_position columns a position, the positions in order).
  /// Null where load_basis is empty.
  virtual SurfaceSpectra basis_surface_spectra(const std::vector<double>& x,
                                               const std::vector<OutlinePiece>& pieces,
                                               const Eigen::MatrixXd& patterns) const {
    (void)x, (void)pieces, (void)patterns;
    return nullptr;
  }

  /// The case's contact position along the rail (track.position; m from a sleeper).
  double position() const { return x_; }
  const TrackParameters& track() const { return track_; }

 private:
  TrackParameters track_;
  double x_;
};

}  // namespace rollnoise::dynamics
