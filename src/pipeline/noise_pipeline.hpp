// The noise pipeline (docs/noise_loop.md): case -> curve contact state -> contacts (patch, steady
// rolling, linear NSS model, creep coefficients) -> the loop of the contacts -> 1/3-octave bands.
// Each stage is callable alone; `rollnoise noise` runs them all, `rollnoise receptance` the first
// three.
//
//   1. the frequencies: narrow-band samples of the 1/3-octave bands (their count checked before
//      any work);
//   2.-3. mean_contact.hpp, one immutable value per contact: the curve contact state and the case
//      placed by it, the patch on its final grid (the frequencies checked against its Nyquist
//      limit once), its normal stiffness dN/d(delta) on the frozen contact area, steady rolling,
//      the linear model; then f(w) and g(w) of one sweep. The contacts: every wheel of
//      curve.wheels (and a second patch), or the case's one contact without a curve state;
//   4. one loop of all the contacts (pipeline/bogie_noise.hpp; a single wheel is a loop of one
//      contact): coupled through wheelsets and rails (noise.contact_coupling = "bogie") or each
//      alone ("none"), for each variant of the contact model (noise/loop_variants.hpp): with the
//      coupling g, without it, and the baseline of noise.compare;
//   5. the effective roughness of each contact (wheel + rail, contact filter) and the band levels
//      of each contact and variant.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact/forces.hpp"
#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"
#include "noise/bands.hpp"
#include "noise/loop.hpp"
#include "noise/loop_variants.hpp"
#include "nss/linear_model.hpp"
#include "pipeline/band_lines.hpp"
#include "pipeline/bogie_noise.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/mean_contact.hpp"
#include "pipeline/noise_case.hpp"
#include "pipeline/sound_power.hpp"
#include "pipeline/wheel_noise.hpp"

namespace rollnoise::pipeline {

/// The narrow-band frequencies of the case's bands (stage 1) and the band centres.
struct BandAxis {
  std::vector<double> centres;    ///< 1/3-octave centres (Hz)
  std::vector<double> frequency;  ///< narrow-band samples (Hz)
};
/// InputError naming noise.band_max when no band lies in the range, noise.points_per_band when
/// their count exceeds c.limits. (The Nyquist limit is checked by the mean-contact stage.)
BandAxis band_axis(const ContactCase& c, const NoiseCase& nc);

/// The mean-contact options of a noise case: the model with noise.contact_model = "nss", the
/// frequencies checked against the Nyquist limit naming noise.band_max.
MeanContactOptions noise_contact_options(const NoiseCase& nc, const std::vector<double>& frequency);

struct NoiseResult {
  /// as run: the curve state, the case at its (leading outer wheel's) contact point, normal force
  /// and creepages, patch, k_N, steady state, model
  MeanContact mean;
  BandAxis axis;
  std::vector<nss::CreepMatrix> creep;   ///< f(w) of `mean` (N, N m, N m^2)
  std::vector<nss::LoadVector> load;     ///< g(w) of `mean` (-, -, m)
  Eigen::Matrix3cd f0;                   ///< f(0) of `mean`
  noise::LoadCoefficients g0;            ///< g(0) of `mean`
  bool coupled = false;                  ///< the main loop ran with g
  std::string baseline_name;             ///< "quasi_steady" or "kalker" (when there is a baseline)
  contact::TangentialForces mean_force;  ///< of the steady state of `mean`
  /// The contacts of the loop, at least one: each wheel of curve.wheels with its contact state,
  /// or the case's one contact (`mean`, as the leading outer wheel, no state) without a curve
  /// contact state. Contact a of `loops` is wheels[a].
  std::vector<WheelNoise> wheels;
  /// noise.second_patch = "coupled": the second patch of a wheel (the flange patch of a two-point
  /// contact; pipeline/bogie_noise.hpp): contact wheels.size() + k of `loops`.
  std::vector<WheelNoise> patches;
  /// The loop of all the contacts (bogie_noise.hpp, contact_loop) on the case's lines, every
  /// variant: coupled with noise.contact_coupling = "bogie", each contact alone with "none".
  noise::LoopVariants loops;
  bool coupled_contacts = false;  ///< the contacts coupled (noise.contact_coupling = "bogie")
  /// The wheel whose answer the top-level outputs show (the leading outer wheel when it is one of
  /// `wheels`, else the first): index into `wheels`.
  std::size_t reported = 0;
  /// noise.band_refinement > 0: the loops on the case's lines and the lines added for the band
  /// means (band_lines.hpp); null without refinement. The band levels are taken from these.
  std::shared_ptr<const RefinedLoops> refined;
  /// Each roughness source's effective roughness levels in the bands (dB re 1 um; the loop's
  /// sources, set by add_bands).
  std::vector<std::vector<double>> source_levels;
  /// noise.sound = "on": the sound powers (pipeline/noise_sound.hpp, docs/sound.md); null when off.
  std::shared_ptr<const SoundResult> sound;
  double seconds_contact = 0.0, seconds_wheels = 0.0, seconds_total = 0.0;
  /// Of seconds_contact: the curve state (the bogie's curving estimate and the main wheel's place
  /// in it), before any wheel's contact work starts.
  double seconds_curve = 0.0;

  /// The reported wheel (wheels[reported]): its bands are the top-level answer.
  const WheelNoise& reported_wheel() const { return wheels.at(reported); }
  /// The loop variants the bands are taken from: refined where noise.band_refinement added lines.
  const noise::LoopVariants& band_loops() const;
};

/// The whole pipeline for a read noise case (stages 1-5): run_noise_loop on the band axis, then
/// the refined lines (noise.band_refinement) and add_bands.
NoiseResult run_noise(ContactCase c, const NoiseCase& nc);
/// Stages 2-4 on the frequencies of `axis` (its centres may be empty: no bands are made): the
/// contacts and the one loop of them, without band levels or sound (`rollnoise corrugation` runs
/// it on the frequencies of its wavelengths). seconds_total: of these stages.
NoiseResult run_noise_loop(ContactCase c, const NoiseCase& nc, BandAxis axis);
/// Stage 5: the effective roughness of each contact (the case's roughness spectra and contact
/// filter) and the band levels of every contact and loop variant; then, with noise.sound = "on",
/// the sound powers (noise_sound.hpp), which follow the roughness too. Cases that differ only in
/// roughness share stages 1-4: a copy of one run_noise result, then add_bands with each case's
/// NoiseCase. The contacts' roughness levels on `threads` threads (the same result for any number).
void add_bands(NoiseResult& r, const NoiseCase& nc, int threads = 1);

/// noise.band_refinement: the loops of `r` on the case's lines plus the lines each refinement level
/// adds (noise/band_refinement.hpp), at most nc.band_refinement levels; the added lines of a level
/// on `threads` threads (the same result for any number).
RefinedLoops refined_loops(const NoiseResult& r, const NoiseCase& nc, int threads = 1);

/// `rollnoise receptance`: wheel, rail and contact receptances at the contact point and mean state
/// of the noise case (contact frame: normal, x, y, rotation about the normal).
struct ReceptanceResult {
  MeanContact mean;
  std::vector<double> frequency;
  noise::StructuralReceptances structures;
  std::vector<noise::Receptance4> contact_receptance;
};
/// InputError naming frequency.f_min / frequency.f_max for non-positive frequencies or
/// frequencies above the Nyquist limit.
ReceptanceResult run_receptance(ContactCase c, const NoiseCase& nc,
                                const std::vector<double>& freq);

}  // namespace rollnoise::pipeline
