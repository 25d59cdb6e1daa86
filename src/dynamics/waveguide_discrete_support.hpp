// The waveguide rail (rail_waveguide.hpp) on discrete supports: the rail seats at the sleepers
// x_n = n L act on the *free* rail's foot, as the beam's DiscretelySupportedRail (track.hpp, Eq. 2)
// does on the free beam (receptance superposition; Heckl, Acustica 81, 1995; Wu & Thompson, JSV
// 224, 1999; Thompson, Railway Noise and Vibration, 2009, Ch. 3; for a waveguide FE rail on
// discrete supports, Nilsson, Jones, Thompson & Ryue, JSV 321, 2009, Sec. 4).
//
// Attachment at a sleeper. The rail seat (pad / sleeper / ballast, Eq. 1 of track.hpp per
// direction) acts on four resultants of the foot's bottom edges (width b, centre y_f) at x_n: the
// mean longitudinal, lateral and vertical displacements u_d = Int u_d ds / b (d = x, y, z) and the
// foot's roll theta = Int u_z (y - y_f) ds / I_f, I_f = Int (y - y_f)^2 ds, with the load
// distributions f_d = Int N ds / b (unit force) and f_theta = Int N (y - y_f) ds / I_f (unit
// moment), which are the same vectors (the projections are reciprocal). The seat's stiffness on
// them is
//
//   K = diag(K_x, K_y, K_z, K_z I_f / b)(omega),                                           (D1)
//
// the roll term that of the vertical pad spread uniformly over the foot's width (a Winkler layer
// K_z / b per unit width turned by theta). The foot's in-plane deformation (flapping) is not
// resisted at the seats: the seat is a rigid plate under the foot's mean motion.
//
// With g(x) the free rail's Green's function between these distributions (Eq. W4; 4 x 4 blocks),
// the seat forces R_n = -K v_n, v_n the four resultants at x_n, and a load u at x_e:
//
//   v_n = Sum_m g(x_n - x_m) R_m + B_e,n u   =>   (I + A K) v = B_e u,                       (D2)
//   H(x_r, x_e) = G(x_r - x_e) u - Sum_n G_rf(x_r - x_n) K v_n,                              (D3)
//
// A_nm = g(x_n - x_m) (block Toeplitz, g(-x) = g(x)^T), B_e,n = G_fe(x_n - x_e), G_rf(x) the
// response at the rail's response distributions to a foot load. Solved by a dense LU (4(2N + 1)
// unknowns; N = 60: 484). Truncation as in the beam model: the 2N + 1 seats nearest the midpoint of
// the two positions, the rail free beyond them.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_rail_model.hpp"

namespace rollnoise::dynamics {

/// The four load distributions of Eq. (D1) on the foot's bottom of `rail` (dofs() x 4: mean u_x,
/// u_y, u_z, roll), and I_f / b (m^2), the roll stiffness per vertical seat stiffness.
struct FootAttachment {
  Eigen::MatrixXd loads;
  double roll_arm_squared = 0.0;
};
FootAttachment foot_attachment(const RailWaveguide& rail);

class DiscretelySupportedWaveguide {
 public:
  /// `free_rail`: the rail without support (reduced or not), `foot` its foot_attachment (the
  /// reduced basis must contain the foot loads' static responses).
  DiscretelySupportedWaveguide(RailWaveguide free_rail, FootAttachment foot,
                               const FootSupport& support, int supports_each_side);

  /// Eq. (D3) at angular frequency omega (real, or complex omega = -i s): responses
  /// response.col(i) . u(x_response) per loads load.col(j) at x_load; positions along the rail from
  /// a sleeper (0 over a sleeper, L/2 mid-span).
  Eigen::MatrixXcd transfer(cdouble omega, const Eigen::MatrixXd& response, double x_response,
                            const Eigen::MatrixXd& load, double x_load) const;

  const RailWaveguide& free_rail() const { return rail_; }
  int supports_each_side() const { return n_; }

 private:
  RailWaveguide rail_;
  FootAttachment foot_;
  FootSupport support_;
  int n_;
};

/// The discretely supported waveguide rail as the loop's RailModel: the 4x4 receptance at the crown
/// (WaveguideRailModel's load patch, order and frame) at the contact position along the rail.
class DiscreteWaveguideRailModel : public RailModel {
 public:
  /// `contact_position`: from a sleeper (m; 0 over a sleeper, L/2 mid-span).
  DiscreteWaveguideRailModel(const TrackParameters& track, const WaveguideRailOptions& options,
                             double contact_position);

  Receptance4 receptance(double frequency) const override;
  Receptance4 receptance_laplace(cdouble s) const override;
  /// The 4x4 between crown loads at x_response and x_load along the rail (m, from a sleeper).
  Receptance4 transfer(double frequency, double x_response, double x_load) const;
  /// The crown's transfers: the contacts get them moved rigidly (RailModel::contact_transfers).
  std::vector<Receptance4> line_transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const override;
  Receptance4 line_transfer_laplace(cdouble s, double x_response, double x_load) const override;

  const DiscretelySupportedWaveguide& rail() const { return parts_.rail; }
  const Eigen::MatrixXd& crown_loads() const { return parts_.crown; }

 private:
  struct Parts {
    Eigen::MatrixXd crown;  // the crown's load patch (dofs() x 4)
    DiscretelySupportedWaveguide rail;
  };
  static Parts build(const TrackParameters& track, const WaveguideRailOptions& options);

  Parts parts_;
  double x_;

  Receptance4 at(cdouble omega) const;
};

}  // namespace rollnoise::dynamics
