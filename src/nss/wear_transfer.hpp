// The wear transfer of the linearised contact (docs/corrugation.md Sec. 2-3): how much rail a
// contact wears away per passage, at a rail position, for a harmonic variation of its inputs.
//
// Frictional power density. With the traction p on the wheel and the slip velocity s of the wheel
// against the rail (contact/tangential_solver.hpp), the power dissipated per unit area is
// D = -p . s (= mu pn |s| in slip, 0 in adhesion). Its variation about the steady state (p_bar,
// s_bar) is
//   D~ = -(s_bar . p~ + p_bar . s~)                                                        (W1)
// (the linearised frictional power of Hempelmann & Knothe 1996, Wear 191, and Mueller 1999, J.
// Sound Vib. 227: the steady slip times the traction variation plus the steady traction times the
// slip variation; equation labels W1-W4 are this project's, docs/corrugation.md Sec. 2). In
// adhesion s_bar = 0 and s~ = 0 (the frozen areas of the linear model), so only slip elements wear
// to first order; in slip (constant friction) (W1) is mu (pn~ |s_bar| + pn_bar d|s|~).
//
// Wear law. The depth worn per unit time is proportional to D:
//   dh/dt = K D                                                                             (W2)
//   frictional_work:  K = k_w (m^3/J, volume per dissipated energy; Pearce & Sherratt 1991 as
//                     used by Braghin et al. 2006, Wear 261: 5.3 ug/(m mm^2) per N/mm^2 in the
//                     mild regime = 6.75e-13 m^3/J at 7850 kg/m^3);
//   archard:          dh/dt = k pn |s| / H (Archard 1953), and in slip pn |s| = D / mu, so
//                     K = k / (mu H) (k dimensionless, H the hardness in Pa; Jendel 2002, Wear
//                     253: k = 1e-4..1e-3 mild, 3e-3..4e-3 severe, 3e-2..4e-2 catastrophic).
//
// Rail-fixed averaging. The contact moves towards +x at V (docs/conventions.md Sec. 1); the
// element at x_a (patch frame, origin at the loop's contact point) is over rail position X at
// t = (X - x_a)/V and stays there dt = dx/V. A harmonic input u e^{i w t} with k = w/V gives the
// depth, averaged across the running band of width w_b (the lateral extent of the contact
// elements), per passage:
//   h(X) = e^{ikX} (K dx dy / (w_b V)) sum_a e^{-ik x_a} D^_a(w)                           (W3)
// (the passage average of Hempelmann & Knothe 1996 and Mueller 1999). With the
// element fields of the model as an impulse response, D_a(t_j) = sum_j D_{j,a} u_{k-j}, and
// x_a = x_0 + i_a dx, the sum is one series in z = e^{-i w dt}:
//   T(w) = (K dx dy / (w_b V)) e^{-ik x_0} sum_m z^m Y_m,   Y_m = sum_{j + i_a = m} D_{j,a}   (W4)
// (the creepage columns times the model's creepage_sampling_factor). T has 4 columns: per unit
// xi_x, xi_y (-), phi (rad/m) and N~ (N); h = T u is the depth (m) per passage for the roughness
// phase e^{ikX} at which the contact point sees u.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::nss {

struct WearLaw {
  enum class Kind { frictional_work, archard };
  Kind kind = Kind::frictional_work;
  /// frictional_work: k_w (m^3/J); archard: k (-)
  double coefficient = 6.75e-13;
  /// archard: the hardness H of the rail (Pa)
  double hardness = 2.8e9;
  /// K of (W2) (m^3/J) at the friction coefficient mu
  double depth_per_energy(double mu) const;
};

using WearRow = Eigen::Matrix<std::complex<double>, 1, 4>;

/// The roughness the frozen contact area of `patch` sees of a rail roughness r e^{ikX} uniform
/// across the rail, per unit r, at the wavenumbers k (rad/m): on a frozen contact area the normal
/// load changes by k_N times the roughness averaged with the unit-load pressure of a rigid punch of
/// that area (Betti's reciprocal theorem, e.g. Johnson 1985, Contact Mechanics, Ch. 3: dN = k_N
/// (d delta - sum_a (dpn/dN)_a dx dy r_a)), so
///   H(k) = sum_a (dpn/dN)_a dx dy e^{ik x_a}                                               (W6)
/// (contact::normal_load_sensitivity; H(0) = 1). For Hertz's ellipse dpn/dN is the flat punch's
/// 1/sqrt(1 - x^2/a^2 - y^2/b^2), whose lateral integral is uniform in x: H = sin(ka)/(ka).
std::vector<std::complex<double>> rail_roughness_filter(const contact::ContactPatch& patch,
                                                        const std::vector<double>& wavenumbers);

class WearTransfer {
 public:
  /// `model` linearises `steady` (its patch, speed, friction mu); the element fields are computed
  /// here, once (LinearContactModel::element_impulse_response).
  WearTransfer(const LinearContactModel& model, const contact::TangentialSolution& steady,
               double speed, double mu, const WearLaw& law);
  /// T(w) of (W4) at the frequencies (Hz): depth per passage (m) per unit xi_x, xi_y, phi, N~.
  std::vector<WearRow> depth(const std::vector<double>& frequencies) const;
  /// The frictional power of the whole patch, sum_a D~_a dx dy (W per unit input), at the
  /// frequencies (Hz; no rail-fixed phase).
  std::vector<WearRow> power(const std::vector<double>& frequencies) const;
  /// w_b of (W3): the lateral extent of the contact elements (m).
  double band_width() const { return band_width_; }
  /// Steps of the impulse response.
  int steps() const { return static_cast<int>(D_.size()); }

 private:
  std::vector<WearRow> series_sum(const std::vector<Eigen::RowVector4d>& y,
                                  const std::vector<double>& frequencies, bool rail_fixed) const;
  std::vector<Eigen::RowVector4d> Y_;  ///< (W4) per unit K dx dy / (w_b V)
  std::vector<Eigen::RowVector4d> D_;  ///< sum_a D_{j,a} (W/m^2 per unit input)
  double dt_ = 0.0, speed_ = 0.0, x0_ = 0.0, area_ = 0.0, band_width_ = 0.0, K_ = 0.0;
  contact::CreepageSampling sampling_ = contact::CreepageSampling::average;
};

/// The wear of the pressure a rail roughness makes within the frozen patch at a given load
/// (docs/corrugation.md Sec. 4). On the frozen contact area C the gap h + r + A pn - delta stays
/// zero, so a roughness r~ (under each element) and an approach change delta~ change the pressure
/// by A_CC pn~ = delta~ 1 - r~. For r(X) = r^ e^{ikX} uniform across the rail, the column i of the
/// patch (at x_i) sees r^ e^{ik x_i} when the contact point sees r^, and with
/// v_i = A_CC^{-1} 1_(column i), k_N = dx dy 1' A_CC^{-1} 1 (N1) and H of (W6),
/// pn~ = sum_i v_i (delta~ - e^{ik x_i} r^), N~ = k_N (delta~ - H r^), sum_i v_i = k_N dpn/dN:
///   pn~ = (dpn/dN) N~ + r^ q(k),   q(k) = sum_i (H(k) - e^{ik x_i}) v_i                     (W7)
/// (this project's labels W7-W8, docs/corrugation.md Sec. 4). The first term is the normal-load
/// input of the linear model (G1), which T's column N~ carries; q is the pressure the roughness
/// moves within the patch at a given load (zero total), which it does not. Its wear per passage per
/// unit roughness, with T_i the (W4) series of the element fields for the pressure v_i
/// (LinearContactModel::element_pressure_response), is
///   T_r(k) = sum_i (H(k) - e^{ik x_i}) T_i(w),   w = k V,                                 (W8)
/// so that the depth per passage of a contact with the inputs u at the roughness r^ is
/// e^{ikX} (T u + T_r r^).
///
/// The fields run once for all k, not for every column's pattern: the weights w_i(k) = H(k) -
/// e^{ik x_i} of the columns, for 0 <= k <= k_max, lie in the span of the vectors 1, cos(k x),
/// sin(k x) over the columns x_i, whose numerical rank is about k_max L / pi + 10 for a patch of
/// length L (the count of the prolate spheroidal functions of that band; Slepian 1978, Bell
/// Syst. Tech. J. 57). Its orthonormal basis U (left singular vectors of those vectors sampled
/// in k, to 1e-10 of the largest singular value) gives the patterns v~_l = sum_i U_il v_i, and
/// T_r(k) = sum_l (U' w(k))_l T~_l(w), T~_l the (W4) series of v~_l: (k_max L / pi + 10)
/// responses instead of one per column (64 columns at curve_300m's grid).
class RoughnessWearTransfer {
 public:
  /// `model` linearises `steady` on `patch` (as for WearTransfer); depth() then for 0 <= k <=
  /// k_max (rad/m).
  RoughnessWearTransfer(const contact::ContactPatch& patch, const LinearContactModel& model,
                        const contact::TangentialSolution& steady, double speed, double mu,
                        const WearLaw& law, double k_max);
  /// T_r of (W8) at the wavenumbers k <= k_max (rad/m): depth per passage (m) per unit rail
  /// roughness (m).
  std::vector<std::complex<double>> depth(const std::vector<double>& wavenumbers) const;
  /// The columns i of the patch.
  int columns() const { return static_cast<int>(x_.size()); }
  /// The patterns v~_l whose responses were computed (the rank of the columns' weights).
  int patterns() const { return static_cast<int>(basis_.cols()); }

 private:
  std::vector<Eigen::RowVectorXd> Y_;  ///< (W4) per pattern v~_l, per unit K dx dy / (w_b V)
  std::vector<double> x_;              ///< x_i of the columns (m)
  std::vector<double> weight_;         ///< dx dy 1' v_i (N/m): k_N is their sum
  Eigen::MatrixXd basis_;              ///< U: columns x patterns, orthonormal
  double dt_ = 0.0, speed_ = 0.0, x0_ = 0.0, scale_ = 0.0, k_max_ = 0.0;
};

}  // namespace rollnoise::nss
