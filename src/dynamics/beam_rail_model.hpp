// The beam rail: the rail's receptance from the Timoshenko beams of track.hpp (vertical and
// lateral bending, the rod in x) on the continuous or the discrete support, as a RailModel
// (rail_model.hpp).
//
// At the centre line (receptance, line_transfers): the 4x4 (z, x, y, rot z) at the running
// surface's centre:
//   z, rot z  : vertical bending (z) and lateral bending (y, rotation about z = lateral slope),
//               from the continuous or discrete model;
//   x         : rod on the smeared longitudinal support plus the rotation of the cross-section
//               under the moment -h Fx of a force at the running surface, h = head_height:
//               u_head = u_rod - h psi_vert, so H_xx = H_rod + h^2 H_psiM, H_zx = -h H_wM;
//   y, rot z  : H_yy = H_wF, H_{y,rotz} = H_wM, H_{rotz,rotz} = H_psiM of the lateral model.
// Torsion of the rail and cross-section deformation are not modelled (docs/models.md).
//
// At contact points: the centre-line transfer between x_a and x_b moved rigidly to the two
// points (G1 of rail_contact.hpp):
//   alpha_ab = L(0, offset_a, 0) embed(line transfer(x_a, x_b)) L(0, offset_b, 0)^T.
#pragma once

#include <utility>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"

namespace rollnoise::dynamics {

class BeamRailModel final : public RailModel {
 public:
  /// `contact_position`: distance of the contact from a sleeper along the rail (m); 0 is over a
  /// sleeper, L/2 mid-span. Ignored by the continuous model.
  BeamRailModel(const TrackParameters& track, TrackSupport support, double contact_position);

  Receptance4 receptance(double frequency) const override;
  /// The closed forms continued to the complex frequency omega = -i s.
  Receptance4 receptance_laplace(cdouble s) const override;
  /// The discrete beams solve all pairs with one Toeplitz recursion (or the periodic track's
  /// Floquet waves; DiscretelySupportedRail::transfers), equal to one pair at a time to the bit.
  std::vector<Receptance4> line_transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const override;
  Receptance4 line_transfer_laplace(cdouble s, double x_response, double x_load) const override;
  /// Every frequency alone (`interpolate` has nothing to do), the centre line moved (header).
  std::vector<std::vector<Receptance6>> contact_transfers(const std::vector<double>& frequencies,
                                                          const std::vector<RailContactPair>& pairs,
                                                          bool interpolate = true) const override;
  LaplaceTransfers laplace_transfers(const std::vector<RailContactPair>& pairs) const override;

 private:
  TrackSupport support_;
  DiscretelySupportedRail vertical_, lateral_;
};

}  // namespace rollnoise::dynamics
