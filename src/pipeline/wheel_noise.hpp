// One contact of the noise loop (docs/noise_loop.md Sec. 5.3, 7.2): a wheel of curve.wheels on its
// own contact state (noise/wheel_contact.hpp), or the case's one contact when there is no curve
// contact state (a Hertzian case). Each contact's own work: its patch, normal stiffness, steady
// rolling, linear model, f(w) and g(w), and its contact receptance alpha_c of every loop variant
// (noise/loop_variants.hpp). The loop then couples the contacts (pipeline/bogie_noise.hpp): all of
// them through wheelsets and rails with noise.contact_coupling = "bogie", each alone with "none";
// a single wheel is a loop with one contact.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "contact/forces.hpp"
#include "noise/bands.hpp"
#include "noise/loop.hpp"
#include "noise/loop_variants.hpp"
#include "noise/roughness.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/mean_contact.hpp"
#include "pipeline/noise_case.hpp"

namespace rollnoise::pipeline {

/// One contact of the loop: its wheel, state, what the loop ran on and its levels.
struct WheelNoise {
  noise::WheelId wheel = noise::WheelId::leading_outer;
  /// The wheel's contact state in the curve; empty for the case's one contact without a curve
  /// contact state (a Hertzian case: the case's contact point, N and creepages).
  std::optional<noise::WheelContact> state;
  /// The wheel's mean contact: the case placed at its contact with its creepages and N, patch, k_N,
  /// steady state, model
  MeanContact mean;
  contact::TangentialForces mean_force;  ///< of the steady state on the loop's (planar) patch
  int adhesion_elements = 0, slip_elements = 0;
  /// Wall time (s) of the wheel's own contact work: its contact state in the curve, patch, steady
  /// rolling, linear model and f, g on the case's lines (on its own thread: the wheels run
  /// concurrently, so the times of several wheels do not add up to the run's). The curve state
  /// they all start from (the bogie's curving estimate) is not in it.
  double seconds = 0.0;
  /// f(w), g(w) of the linear NSS model on the case's lines (empty with noise.contact_model =
  /// "kalker").
  noise::ContactCoefficients coefficients;
  /// alpha_c of every loop variant per frequency (contact frame) and the contact position the loop
  /// takes (pipeline/bogie_noise.hpp).
  noise::ContactVariants receptance;
  noise::ContactPosition position;
  /// The contact's band levels in the loop (set by add_bands): the main variant, and without the
  /// coupling g and of the baseline when the case has them.
  noise::BandLevels bands, uncoupled_bands, baseline_bands;
};

/// Kalker's linear theory (full adhesion) of the case's semi-axes at n frequencies: constant f,
/// g = 0 (no load coefficients).
noise::ContactCoefficients kalker_coefficients(const ContactCase& c, std::size_t n);

/// The contact work of wheel `w` (mean contact, NSS model, f(w), g(w), the variants' contact
/// receptances), which needs no structures. Independent of the other wheels: run_noise runs them
/// on a pool of threads. `base`: the case as read (placed or not); InputError naming noise.band_max
/// when a wheel's grid cannot resolve the frequencies.
WheelNoise wheel_contact_noise(const ContactCase& base, const NoiseCase& nc,
                               const noise::WheelContact& w, const std::vector<double>& frequency);

/// The contact of an already solved mean contact `m` (the case's main contact), with f(w), g(w)
/// already computed on `frequency` (`coefficients`; empty with Kalker's model).
WheelNoise contact_noise(noise::WheelId wheel, std::optional<noise::WheelContact> state,
                         MeanContact m, const NoiseCase& nc, const std::vector<double>& frequency,
                         noise::ContactCoefficients coefficients);

/// The contact's alpha_c of every variant at other frequencies (f and g of its model there):
/// `nss` are its model's f and g at `frequency` where the caller has them (else computed).
noise::ContactVariants contact_variants_at(const WheelNoise& w, const NoiseCase& nc,
                                           const std::vector<double>& frequency,
                                           const noise::ContactCoefficients* nss = nullptr);

/// The effective roughness (the case's wheel and rail roughness, its contact filter on the patch
/// semi-axes a, b) of the mean contact `m` at its rolling speed: what each contact's bands take.
noise::ContactRoughness contact_roughness(const NoiseCase& nc, const MeanContact& m);

}  // namespace rollnoise::pipeline
