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
// response at the rail's response distributions to a foot load. I + A K is block Toeplitz (block
// (n, m) = delta_nm I + a(n - m) K, a(d) = g(d L), a(-d) = g(d L)^T): solved by the block Levinson
// recursion (linalg/block_toeplitz_solve.hpp, O(N^2) 4 x 4 block products, residual-checked), a
// dense LU of its 4(2N + 1) unknowns (N = 60: 484) where the check fails. Truncation as in the
// beam model: one window of 2N + 1 seats for all pairs of a query (nearest the midpoint of the
// positions' extent, or a given centre), the rail free beyond them. I + A K depends on the seats'
// spacing only, not on where they are centred, so one factorisation per frequency serves every
// pair, and Eq. (D2) is solved once per distinct load position (by reciprocity, H(x_r, x_l) =
// H(x_l, x_r)^T in one window, from whichever side has fewer distinct positions); Eq. (D3)'s sums
// over the seats are running sums (supported_transfers in the .cpp).
//
// At the contacts (DiscreteWaveguideRailModel::contact_transfers): the distributions of Eq. (D3)
// are the contacts' loads at their own points of the head, in their frames (as the continuous
// waveguide, waveguide_rail_model.hpp), G, G_fe, G_rf the free rail's Green's function between
// them and the foot (Eq. W4 with the points' and the foot's loads in one Ritz basis); the 6 x 6 is
// T_a H_ab T_b^T (G2 of rail_contact.hpp). No rigid move. With the head loaded as a body (the
// default) every contact's loads are D C_a, D the head's six distributions
// (RailWaveguide::head_body): one basis (the static responses to D and the foot's loads) for every
// contact, the seats nearest the case's contact position for every pair, and the head's 6 x 6 at
// (omega, x_a, x_b) kept across queries (HeadStation). On a frequency grid they are
// computed directly on an adaptively chosen part of it and interpolated at the rest, the samplings
// kept for the refinement's lines, as on the continuous support (waveguide_frequency_sampling.hpp;
// GridSamplingRail).
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

#include "dynamics/rail_surface_spectrum.hpp"
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
  /// Eq. (D3) between the distributions `points` (dofs() rows; responses and loads alike) for each
  /// (x_response, x_load) of `positions`, at omega: one wave solution and one LU of I + A K for
  /// all. out[p] is points.cols() square; transfers(w, P, {{x, y}})[0] = transfer(w, P, x, P, y).
  std::vector<Eigen::MatrixXcd> transfers(
      cdouble omega, const Eigen::MatrixXd& points,
      const std::vector<std::pair<double, double>>& positions) const;
  /// The same with the 2N + 1 seats nearest `centre` (m from a sleeper) for every pair, each pair
  /// as asked (not from its reciprocal): a pair's value does not depend on the others asked with
  /// it.
  std::vector<Eigen::MatrixXcd> transfers(cdouble omega, const Eigen::MatrixXd& points,
                                          const std::vector<std::pair<double, double>>& positions,
                                          double centre) const;

  /// Eq. (D4) of rail_surface_spectrum.hpp at angular frequency omega: the spectrum of `response`
  /// (dofs() x pieces) per loads `load` (dofs() x c) at `load_x` (m from a sleeper, per column).
  SurfaceSpectrum surface_spectrum(double omega, const Eigen::MatrixXd& response,
                                   const Eigen::MatrixXd& load,
                                   const std::vector<double>& load_x) const;

  const RailWaveguide& free_rail() const { return rail_; }
  const FootAttachment& foot() const { return foot_; }
  const FootSupport& support() const { return support_; }
  int supports_each_side() const { return n_; }

 private:
  RailWaveguide rail_;
  FootAttachment foot_;
  FootSupport support_;
  int n_;
};

/// The discretely supported waveguide rail as the loop's RailModel: receptance() and the line
/// transfers are the 4x4 at the crown (WaveguideRailModel's load patch, order and frame);
/// contact_transfers() and laplace_transfers() load the section at the contacts themselves.
class DiscreteWaveguideRailModel : public GridSamplingRail {
 public:
  /// The head's six distributions (RailWaveguide::head_body) on the rail reduced on them and the
  /// foot: every contact's loads are a combination of them, so the contacts of every query share
  /// this one model, and its 6 x 6 transfers, computed once per (omega, x_response, x_load) with
  /// the seats nearest the case's contact position, are kept for all of them (queries of up to
  /// `keep_up_to` positions, the loop's; a larger one, the response along the rail for the sound,
  /// is computed as asked, the seats nearest the midpoint of its extent).
  struct HeadStation {
    HeadStation(DiscretelySupportedWaveguide r, Eigen::MatrixXd l, double c)
        : rail(std::move(r)), loads(std::move(l)), centre(c) {}
    DiscretelySupportedWaveguide rail;
    Eigen::MatrixXd loads;  ///< dofs() x 6
    double centre = 0.0;    ///< the seats' window (m from a sleeper)
    std::vector<Eigen::MatrixXcd> transfers(cdouble omega,
                                            const std::vector<std::pair<double, double>>& positions,
                                            std::size_t keep_up_to) const;
    mutable std::mutex mutex;
    mutable std::map<std::tuple<double, double, double, double>, Eigen::MatrixXcd> kept;
  };

  /// `contact_position`: from a sleeper (m; 0 over a sleeper, L/2 mid-span).
  DiscreteWaveguideRailModel(const TrackParameters& track, const WaveguideRailOptions& options,
                             double contact_position);

  Receptance4 receptance(double frequency) const override;
  Receptance4 receptance_laplace(cdouble s) const override;
  /// The 4x4 between crown loads at x_response and x_load along the rail (m, from a sleeper).
  Receptance4 transfer(double frequency, double x_response, double x_load) const;
  /// The crown's transfers (the centre-line model of this rail).
  std::vector<Receptance4> line_transfers(
      double frequency, const std::vector<std::pair<double, double>>& pairs) const override;
  Receptance4 line_transfer_laplace(cdouble s, double x_response, double x_load) const override;

  /// The 4x4 between two contacts in their frames, a = (offset_a, angle_a) at x_a and
  /// b = (offset_b, angle_b) at x_b along the rail (m from a sleeper), one basis for both.
  Receptance4 contact_transfer(double frequency, double offset_a, double angle_a, double x_a,
                               double offset_b, double angle_b, double x_b) const;

  /// Eq. (D4) of rail_surface_spectrum.hpp: the section loaded at the points (one Ritz basis of
  /// the free rail with the foot's loads).
  bool section_deforms() const override { return true; }
  SurfaceSpectra surface_spectra(const std::vector<RailLoadPoint>& points,
                                 const std::vector<OutlinePiece>& pieces,
                                 const Eigen::MatrixXd& patterns) const override;
  /// With head loads: the head's six distributions on the head's model (HeadStation).
  std::optional<RailLoadBasis> load_basis(const std::vector<RailLoadPoint>& points) const override;
  SurfaceSpectra basis_surface_spectra(const std::vector<double>& x,
                                       const std::vector<OutlinePiece>& pieces,
                                       const Eigen::MatrixXd& patterns) const override;

  const DiscretelySupportedWaveguide& rail() const { return *parts_.get().rail; }
  const Eigen::MatrixXd& crown_loads() const { return parts_.get().crown; }

 private:
  struct Parts {
    WaveguideRailOptions options;
    std::vector<Eigen::Vector2d> outline;
    RailWaveguide section;     // the free rail, unreduced: the contact points' bases
    RailReductionModes modes;  // its section modes, the load-independent part of every basis
    Eigen::MatrixXd crown;     // the crown's load patch (dofs() x 4)
    std::shared_ptr<const HeadStation> head;  // head_load: the head's basis, shared
    std::shared_ptr<const DiscretelySupportedWaveguide> rail;  // the crown's: the head's, or
                                                               // reduced on the crown and foot
  };
  /// Contact points on the rail with their reduced model and loads (dofs() x 4 per point); with
  /// head loads the head's model, and the points' coefficients on its six distributions.
  struct Station {
    std::shared_ptr<const DiscretelySupportedWaveguide> rail;
    Eigen::MatrixXd loads;
    std::shared_ptr<const HeadStation> head;
    Eigen::MatrixXd coefficients;  ///< 6 x 4 per point (head only)
  };
  static Parts build(const TrackParameters& track, const WaveguideRailOptions& options,
                     double contact_position);
  std::shared_ptr<const Station> station(
      const std::vector<std::pair<double, double>>& points) const;
  /// The contact-frame 4x4 of each pair (point a, point b, x_a, x_b) of one station at omega.
  static std::vector<Receptance4> between(
      const Station& s, cdouble omega,
      const std::vector<std::tuple<int, int, double, double>>& pairs);

  WaveguideRailOptions options_;
  // Built on first use (shared by copies): a run whose samplings all come from the archive
  // meshes and solves nothing.
  Lazy<Parts> parts_;
  Lazy<HeadBody> head_;  // section_head_body
  double x_;
  // GridSamplingRail's: at the contacts themselves (header comment), one Ritz basis per set of
  // coupled points (rail_point_sets), each pair at its own positions between the sleepers.
  const FrequencySampling& sampling() const override { return options_.sampling; }
  std::optional<SpanningPoints> spanning_points(const Points& points) const override;
  bool along_rail_invariant() const override { return false; }
  Evaluator evaluator(const Points& points, const SetPairs& pairs) const override;
  LaplaceTransfers direct_laplace_transfers(
      const std::vector<RailContactPair>& pairs) const override;

  Receptance4 at(cdouble omega) const;
};

}  // namespace rollnoise::dynamics
