// The contact's transfer function (docs/noise_loop.md, docs/nss_normal_load.md): the force
// variations of the contact for small creepage and normal-load variations,
//   F~ = -f(s) xi~ + g(s) N~,   F~ = (F~x, F~y, M~z), xi~ = (xi~x, xi~y, phi~),
// at the complex frequency s (1/s; s = i omega on the frequency axis), with where it holds: the
// lowest growth rate Re s at which a series representation still converges. The closed loop
// (noise/loop.hpp), the contact receptance (contact_receptance.hpp) and squeal (stability.hpp)
// need nothing else of the contact model.
//
// Implementations:
//   NssTransfer       the linear NSS model (nss::LinearContactModel): its sweep on the frequency
//                     axis, its Laplace evaluators at complex s, guarded by its Markov series
//                     (MarkovContact);
//   MarkovContact     a Markov series f = -sum h_j z^j, g = sum gm_j z^j, z = e^{-s dt}, with an
//                     optional exact evaluator (below);
//   ConstantTransfer  a frequency-independent f with g = 0: Kalker's linear theory (quasi-steady,
//                     kalker_linear.hpp).
// A new contact model plugs in as one more implementation (docs/architecture.md).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "contact/material.hpp"
#include "noise/contact_receptance.hpp"

namespace rollnoise::nss {
class LinearContactModel;
}  // namespace rollnoise::nss

namespace rollnoise::noise {

class ContactTransfer {
 public:
  virtual ~ContactTransfer();
  /// f at the complex frequency s (1/s).
  virtual Eigen::Matrix3cd creep(cdouble s) const = 0;
  /// g at s (-, -, m; zero without a normal-load input).
  virtual Eigen::Vector3cd load(cdouble s) const = 0;
  /// The lowest growth rate Re s (1/s) at which creep(s) and load(s) hold (-1e300: everywhere).
  virtual double min_sigma() const = 0;
  /// creep(s) and load(s) together (by default the two calls; a model may share their work).
  virtual std::pair<Eigen::Matrix3cd, Eigen::Vector3cd> creep_and_load(cdouble s) const;
  /// f at frequencies on the real axis (Hz); by default creep(2 pi i f) at each.
  virtual std::vector<Eigen::Matrix3cd> creep(const std::vector<double>& frequencies) const;
  /// g at frequencies on the real axis (Hz); by default load(2 pi i f) at each.
  virtual std::vector<LoadCoefficients> load(const std::vector<double>& frequencies) const;
};

/// A frequency-independent f, g = 0: Kalker's linear theory, quasi-steady.
class ConstantTransfer final : public ContactTransfer {
 public:
  explicit ConstantTransfer(const Eigen::Matrix3d& creep) : f_(creep) {}
  /// Kalker's creep coefficients from the semi-axes a, b (m), shear modulus G (Pa) and Poisson's
  /// ratio nu (kalker_creep_matrix: the one place Kalker's matrix is built from them).
  static ConstantTransfer kalker(double a, double b, double shear_modulus, double nu);
  /// The same from the patch's semi-axes and the bodies' material.
  static ConstantTransfer kalker(double a, double b, const contact::Material& material);
  using ContactTransfer::creep;
  using ContactTransfer::load;
  Eigen::Matrix3cd creep(cdouble) const override { return f_.cast<cdouble>(); }
  Eigen::Vector3cd load(cdouble) const override { return Eigen::Vector3cd::Zero(); }
  double min_sigma() const override { return -1e300; }
  /// The real matrix f.
  const Eigen::Matrix3d& matrix() const { return f_; }

 private:
  Eigen::Matrix3d f_;
};

/// The linear contact at complex s from the Markov parameters of the discrete-time NSS model
/// (nss::LinearContactModel::markov_parameters(), load_markov_parameters()):
///   f(s) = -sum_j h_j z^j,   g(s) = sum_j gm_j z^j,   z = exp(-s dt)
/// (the model's own sums with z = e^{-i omega dt} continued; Horner). |z| = exp(-sigma dt): for a
/// growing s (sigma > 0) the series converges faster than on the unit circle, for a decaying one
/// it converges while |z| rho < 1, rho the decay ratio per step of h_j (|h_j| ~ rho^j), i.e. for
/// sigma > ln(rho)/dt; min_sigma() = 0.9 ln(rho)/dt. Evaluations beyond that, or where the truncated tail
/// |h_J| |z|^J exceeds 1e-6 of the largest term, throw NumericalError (the guard).
///
/// With an exact evaluator (LaplaceEvaluator: pipeline/squeal passes the NSS model's
/// creep_coefficients_laplace and normal_load_coefficients_laplace, which carry the creepage
/// sampling's factor and fall back to the model's Hessenberg form where the series does not
/// converge) creep() and load() return the evaluator's values; the Markov parameters, where the
/// model has them (constant friction), still set min_sigma() and the guard. Without them (falling
/// friction: the model has no Markov parameters) there is no guard (min_sigma() = -1e300): the
/// evaluator is exact at every s but the contact's own poles.
struct LaplaceEvaluator {
  std::function<Eigen::Matrix3cd(cdouble)> creep;
  std::function<Eigen::Vector3cd(cdouble)> load;  ///< empty: g = 0
};

class MarkovContact final : public ContactTransfer {
 public:
  /// `load` may be empty (no normal-load input: g = 0).
  MarkovContact(std::vector<Eigen::Matrix3d> creep, std::vector<Eigen::Vector3d> load, double time_step);
  /// With an exact evaluator (see above); `creep` and `load` may be empty (no guard).
  MarkovContact(std::vector<Eigen::Matrix3d> creep, std::vector<Eigen::Vector3d> load, double time_step,
                LaplaceEvaluator exact);
  using ContactTransfer::creep;
  using ContactTransfer::load;
  Eigen::Matrix3cd creep(cdouble s) const override;
  Eigen::Vector3cd load(cdouble s) const override;
  /// The lowest growth rate (most negative sigma, 1/s) at which the series still converge.
  double min_sigma() const override { return min_sigma_; }
  double time_step() const { return dt_; }

 private:
  /// min_sigma_ from the decay of the series (none without one); the time step checked.
  void set_guard();
  void check(cdouble z, double tail_head, double tail_last) const;
  std::vector<Eigen::Matrix3d> h_;
  std::vector<Eigen::Vector3d> gm_;
  double dt_ = 0.0, min_sigma_ = 0.0;
  LaplaceEvaluator exact_;
};

/// The linear NSS model as a ContactTransfer: on the frequency axis its sweep
/// (creep_coefficients, normal_load_coefficients), at complex s its Laplace evaluators
/// (creep_coefficients_laplace, normal_load_coefficients_laplace: exact, with the creepage
/// sampling's factor) under the guard of its Markov series (MarkovContact; none with falling
/// friction). `with_load` false: g = 0 (the loop without the normal coupling).
class NssTransfer final : public ContactTransfer {
 public:
  NssTransfer(std::shared_ptr<const nss::LinearContactModel> model, bool with_load);
  Eigen::Matrix3cd creep(cdouble s) const override { return guarded_.creep(s); }
  Eigen::Vector3cd load(cdouble s) const override { return guarded_.load(s); }
  double min_sigma() const override { return guarded_.min_sigma(); }
  /// Without Markov parameters (no guard: falling friction) one Hessenberg solve for both.
  std::pair<Eigen::Matrix3cd, Eigen::Vector3cd> creep_and_load(cdouble s) const override;
  std::vector<Eigen::Matrix3cd> creep(const std::vector<double>& frequencies) const override;
  std::vector<LoadCoefficients> load(const std::vector<double>& frequencies) const override;
  const nss::LinearContactModel& model() const { return *model_; }

 private:
  std::shared_ptr<const nss::LinearContactModel> model_;
  bool with_load_ = false;
  MarkovContact guarded_;
};

}  // namespace rollnoise::noise
