// The mean contact: one immutable value from one pipeline stage, what every contact command
// (noise, receptance, squeal, creep, response, validate) and every wheel of the bogie starts from.
//
//   case as read --(curve state: resolve_curve, or the wheel's contact, or placed_contact)-->
//   placed case --(normal problem)--> patch on its final grid (profiles may enlarge it)
//   --(Nyquist limit V/(2 dx) of that grid checked ONCE against the command's frequencies)-->
//   normal stiffness k_N --> steady rolling at the mean creepage --> linear NSS model (on request)
//   --> contact transfer at complex s (on request: squeal).
//
// The value holds the case as run (placed, its grid the patch's), the curve state, the patch, k_N,
// the steady state, the model and the transfer; nothing edits it after the stage. The bogie is a
// list of these values, one per wheel (pipeline/wheel_noise.hpp, pipeline/squeal_wheels.cpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "noise/contact_transfer.hpp"
#include "noise/wheel_contact.hpp"
#include "nss/linear_model.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/noise_case.hpp"

namespace rollnoise::pipeline {

/// What the stage builds besides patch, k_N and steady state, and the frequencies it checks.
struct MeanContactOptions {
  bool with_model = true;  ///< the linear NSS model (noise.contact_model = "nss")
  /// The ContactTransfer at complex s (squeal): NssTransfer with the model, else Kalker's
  /// ConstantTransfer. With falling friction and a linearised contact that is unstable alone
  /// (spectral radius of M0^{-1} M1 >= 1) none is built (transfer() null; spectral_radius() says).
  bool with_transfer = false;
  bool normal_coupling = false;  ///< the transfer's g (when the model has a normal-load input)
  /// Checked against the Nyquist limit of the patch's final grid (InputError naming
  /// frequency_key); empty: not checked.
  std::vector<double> frequencies;
  std::string frequency_key;
};

class MeanContact {
 public:
  MeanContact() = default;
  /// The case as run: placed (contact point, N, a, b, creepage), its grid the patch's final grid.
  const ContactCase& contact() const { return contact_; }
  /// The curve state the case was placed by (default: none; a wheel of the bogie carries its state
  /// in its noise::WheelContact).
  const CurveSetup& curve() const { return curve_; }
  const contact::ContactPatch& patch() const { return *patch_; }
  const std::shared_ptr<const contact::ContactPatch>& shared_patch() const { return patch_; }
  /// k_N = dN/d(delta) on the frozen contact area (N/m), contact::normal_load_sensitivity.
  double normal_stiffness() const { return normal_stiffness_; }
  const contact::TangentialSolution& steady() const { return steady_; }
  /// The linear NSS model (null unless MeanContactOptions::with_model).
  const std::shared_ptr<const nss::LinearContactModel>& model() const { return model_; }
  /// The contact's transfer at complex s (null unless with_transfer, or when unstable alone).
  const std::shared_ptr<const noise::ContactTransfer>& transfer() const { return transfer_; }
  /// The transfer carries g (normal_coupling and the model has a normal-load input).
  bool coupled() const { return coupled_; }
  /// Of M0^{-1} M1 when checked (with_transfer, the model without Markov parameters: falling
  /// friction); else -1.
  double spectral_radius() const { return spectral_radius_; }

 private:
  friend MeanContact solve_mean_contact(ContactCase placed, CurveSetup curve,
                                        const MeanContactOptions& o);
  ContactCase contact_;
  CurveSetup curve_;
  std::shared_ptr<const contact::ContactPatch> patch_;
  double normal_stiffness_ = 0.0;
  contact::TangentialSolution steady_;
  std::shared_ptr<const nss::LinearContactModel> model_;
  std::shared_ptr<const noise::ContactTransfer> transfer_;
  bool coupled_ = false;
  double spectral_radius_ = -1.0;
};

/// The stage on a placed case (pipeline/contact_case.hpp) and the curve state it came from.
MeanContact solve_mean_contact(ContactCase placed, CurveSetup curve, const MeanContactOptions& o);

/// The case placed as read (placed_contact), no curve state.
MeanContact mean_contact(const ContactCase& c, const MeanContactOptions& o);

/// The curve's mean contact (the leading outer wheel): resolve_curve, then the stage.
MeanContact curve_mean_contact(const ContactCase& c, const NoiseCase& nc,
                               const MeanContactOptions& o);

/// One wheel of the bogie: `base` placed at the wheel's contact point with its normal force and
/// creepages (this side's frame), then the stage.
MeanContact wheel_mean_contact(const ContactCase& base, const noise::WheelContact& w,
                               const MeanContactOptions& o);

/// The linear NSS model of a solved patch and steady state of the case.
std::unique_ptr<nss::LinearContactModel> linear_model(const ContactCase& c,
                                                      const contact::ContactPatch& patch,
                                                      const contact::TangentialSolution& steady);

}  // namespace rollnoise::pipeline
