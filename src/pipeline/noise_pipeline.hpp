// The noise pipeline (docs/noise_loop.md): case -> curve contact state -> contact (patch, steady
// rolling, linear NSS model, creep coefficients) -> structures -> closed loop -> 1/3-octave bands.
// Each stage is callable alone; `rollnoise noise` runs them all, `rollnoise receptance` the first
// three, and a study reuses the stages whose inputs it shares.
//
//   1. the frequencies: narrow-band samples of the 1/3-octave bands (their count checked before
//      any work);
//   2.-3. mean_contact.hpp, one immutable value: the curve contact state and the case placed by it,
//      the patch on its final grid (the frequencies checked against its Nyquist limit once), its
//      normal stiffness dN/d(delta) on the frozen contact area, steady rolling, the linear model;
//      then f(w) and g(w) of one sweep, f(0) and g(0);
//   4. structures (wheel and rail receptances at the contact point, once), the loop variants
//      (noise/loop_variants.hpp): with the coupling g, without it, and the baseline of
//      noise.compare (quasi-steady f(0), g(0), or Kalker's coefficients);
//   5. the effective roughness (wheel + rail, contact filter) and the band levels of each variant.
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
#include "pipeline/contact_case.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/mean_contact.hpp"
#include "pipeline/noise_case.hpp"
#include "pipeline/band_lines.hpp"
#include "pipeline/bogie_noise.hpp"
#include "pipeline/wheel_noise.hpp"
#include "pipeline/sound_power.hpp"

namespace rollnoise::pipeline {

/// Kalker's linear theory (full adhesion) of the case's semi-axes at n frequencies: constant f,
/// g = 0 (no load coefficients).
noise::ContactCoefficients kalker_coefficients(const ContactCase& c, std::size_t n);

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
  /// as run: the curve state, the case at its contact point, normal force and creepages, patch,
  /// k_N, steady state, model
  MeanContact mean;
  BandAxis axis;
  std::vector<nss::CreepMatrix> creep;  ///< f(w) (N, N m, N m^2)
  std::vector<nss::LoadVector> load;    ///< g(w) (-, -, m)
  Eigen::Matrix3cd f0;                  ///< f(0)
  noise::LoadCoefficients g0;           ///< g(0)
  bool coupled = false;                 ///< the main loop ran with g
  noise::LoopVariants variants;
  std::string baseline_name;            ///< "quasi_steady" or "kalker" (when there is a baseline)
  noise::BandLevels bands, uncoupled_bands, baseline_bands;
  /// dB, force band levels with minus without the coupling (Fz, Fx, Fy, Mz); when uncoupled ran
  std::vector<std::array<double, 4>> coupling_difference;
  contact::TangentialForces mean_force;  ///< of the steady state
  /// 20 log10 |F_y / N| (dB): the level of mu F_z relative to F_z (NaN without a lateral force)
  double lateral_to_normal_db = 0.0;
  /// The wheel and rail spectra at the frequencies (shared by the wheels' loops).
  std::shared_ptr<const noise::StructureSpectra> spectra;
  /// curve.wheels: each wheel's contact state and its loop run alone (pipeline/wheel_noise.hpp);
  /// the leading outer wheel's is the main run above. Set by run_noise (not by run_noise_loop; a
  /// study runs run_noise, so its cases have them too).
  std::vector<WheelNoise> wheels;
  /// noise.contact_coupling = "bogie": the loop with all the wheels' contacts (contact a = wheels[a],
  /// one source each; pipeline/bogie_noise.hpp); then wheels[a].bands are its levels.
  std::shared_ptr<const noise::ContactSetLoopResult> bogie;
  /// noise.second_patch = "coupled": the second patch of a wheel (the flange patch of a two-point
  /// contact; pipeline/bogie_noise.hpp), its loop alone, and with `bogie` its coupled levels
  /// (contact wheels.size() + k of the bogie loop).
  std::vector<WheelNoise> patches;
  /// noise.band_refinement > 0: the loops on the case's lines and the lines added for the band
  /// means (band_lines.hpp); null without refinement. The band levels are taken from these.
  std::shared_ptr<const RefinedLoops> refined;
  /// Each roughness source's effective roughness levels in the bands (dB re 1 um; the bogie loop's
  /// sources, set by add_bands).
  std::vector<std::vector<double>> source_levels;
  /// noise.sound = "on": the sound powers (pipeline/noise_sound.hpp, docs/sound.md); null when off.
  std::shared_ptr<const SoundResult> sound;
  double seconds_contact = 0.0, seconds_structures = 0.0, seconds_wheels = 0.0, seconds_total = 0.0;
  /// Of seconds_contact: the curve state (the bogie's curving estimate and the main wheel's place
  /// in it), before any wheel's contact work starts.
  double seconds_curve = 0.0;
};

/// What the cases of a study share (docs/study.md). The wheel's modal and the rail's receptances
/// depend only on the models and the frequencies (not on the contact position, speed or roughness):
/// they are computed once per NoiseCase::structures_id and frequency axis and reused, which gives
/// the same bits as computing them again.
class NoiseReuse {
 public:
  /// The spectra of the case's models at `frequency`: from the store or computed (and stored).
  std::shared_ptr<const noise::StructureSpectra> spectra(const NoiseCase& nc, const std::vector<double>& frequency);
  long spectra_computed() const { return computed_; }
  long spectra_reused() const { return reused_; }

 private:
  std::map<std::string, std::shared_ptr<const noise::StructureSpectra>> spectra_;
  long computed_ = 0, reused_ = 0;
};

/// Stages 1-4 (curve state, bands' frequencies, contact, structures, loop): everything but the
/// roughness and the contact filter, which only stage 5 uses. `reuse` may be null.
NoiseResult run_noise_loop(ContactCase c, const NoiseCase& nc, NoiseReuse* reuse = nullptr);
/// Stage 5: the effective roughness (the case's roughness spectra and contact filter) and the band
/// levels of every loop variant; then, with noise.sound = "on", the sound powers (noise_sound.hpp),
/// which follow the roughness too. Cases that differ only in roughness share stages 1-4: a copy of
/// one run_noise_loop result, then add_bands with each case's NoiseCase. The contacts' roughness
/// levels on `threads` threads (the same result for any number).
void add_bands(NoiseResult& r, const NoiseCase& nc, int threads = 1);

/// Stage 4's loop variants at `freq` (the main wheel's f and g there, `creep` and `load`; the
/// wheel and rail spectra there): what run_noise_loop solves on the case's lines. `rail`: the
/// rail model, if not nc.rail (the refinement's RailModel::on_grid).
noise::LoopVariants loop_variants(const NoiseResult& r, const NoiseCase& nc,
                                  const noise::StructureSpectra& spectra,
                                  const std::vector<double>& freq,
                                  const std::vector<nss::CreepMatrix>& creep,
                                  const std::vector<nss::LoadVector>& load,
                                  const dynamics::RailModel* rail = nullptr);
/// noise.band_refinement: the loops of `r` (its variants, the bogie loop or the wheels' loops
/// alone) on the case's lines plus the lines each refinement level adds (noise/band_refinement.hpp),
/// at most nc.band_refinement levels; the added lines of a level on `threads` threads (the same
/// result for any number).
RefinedLoops refined_loops(const NoiseResult& r, const NoiseCase& nc, int threads = 1);
/// The whole pipeline for a read noise case (stages 1-5), and the loop of every wheel of
/// curve.wheels (pipeline/wheel_noise.hpp).
NoiseResult run_noise(ContactCase c, const NoiseCase& nc, NoiseReuse* reuse = nullptr);

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
ReceptanceResult run_receptance(ContactCase c, const NoiseCase& nc, const std::vector<double>& freq);

}  // namespace rollnoise::pipeline
