// The noise loop for each wheel of the bogie (curve.wheels, docs/noise_loop.md Sec. 7.3): until the
// loop couples several contacts (issue 25), every wheel's main patch runs the single-contact loop
// ALONE on its own contact state (noise/wheel_contact.hpp): its patch, normal stiffness, steady
// rolling, linear model, f(w) and g(w), the structures at its contact position and its band levels.
// The wheel and rail spectra are shared (one structure_spectra for all wheels); the leading outer
// wheel is the main run's (not repeated). Under the bogie loop (noise.contact_coupling = "bogie",
// pipeline/bogie_noise.hpp) a wheel's loop alone is not computed: the coupled loop takes its
// contact receptance instead.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "contact/forces.hpp"
#include "noise/bands.hpp"
#include "noise/roughness.hpp"
#include "noise/loop.hpp"
#include "noise/loop_variants.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/mean_contact.hpp"
#include "pipeline/noise_case.hpp"

namespace rollnoise::pipeline {

/// One wheel's loop alone: its state, what the loop ran on and its levels.
struct WheelNoise {
  noise::WheelContact state;
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
  /// The main variant (with g when normal_coupling), the wheel alone. Under the bogie loop
  /// (noise.contact_coupling = "bogie") only the leading outer wheel's (the main run's); the
  /// others' are not computed (the bogie loop replaces them; wheel_loop_alone gives them).
  noise::LoopResult loop;
  /// alpha_c of the main loop per frequency (contact frame) and the contact position it ran at:
  /// what the loop with several contacts takes (pipeline/bogie_noise.hpp).
  std::vector<noise::Receptance4> contact_receptance;
  noise::ContactPosition position;
  noise::BandLevels bands;  ///< set by add_wheel_bands
};

/// The loop of each wheel but the leading outer one (the main run's), on the shared spectra at
/// `frequency` (its loop alone only without the bogie loop, WheelNoise::loop). `base`: the case as
/// read (placed or not); InputError naming noise.band_max when a wheel's grid cannot resolve the
/// frequencies.
WheelNoise wheel_noise(const ContactCase& base, const NoiseCase& nc, const noise::WheelContact& w,
                       const noise::StructureSpectra& spectra,
                       const std::vector<double>& frequency);

/// wheel_noise without the loop alone (WheelNoise::loop empty): the wheel's contact work (mean
/// contact, NSS model, f(w), g(w), contact receptance), which needs no spectra. Independent of the
/// other wheels: run_noise runs the further wheels' on a pool of threads.
WheelNoise wheel_contact_noise(const ContactCase& base, const NoiseCase& nc,
                               const noise::WheelContact& w, const std::vector<double>& frequency);

/// The wheel's single-contact loop alone (its structures at its contact position from the shared
/// spectra, its contact receptance): WheelNoise::loop. `rail`: the rail model, if not nc.rail.
noise::LoopResult wheel_loop_alone(const WheelNoise& w, const NoiseCase& nc,
                                   const noise::StructureSpectra& spectra,
                                   const dynamics::RailModel* rail = nullptr);

/// The wheel's alpha_c (as wheel_contact_noise computes it) at other frequencies.
std::vector<noise::Receptance4> wheel_contact_receptance(const WheelNoise& w, const NoiseCase& nc,
                                                         const std::vector<double>& frequency);
/// The same from the wheel's f and g at `frequency` where the caller has them already (the NSS
/// model's; with noise.contact_model = "kalker" Kalker's are taken, as wheel_contact_receptance).
std::vector<noise::Receptance4> wheel_contact_receptance(const WheelNoise& w, const NoiseCase& nc,
                                                         const std::vector<double>& frequency,
                                                         const noise::ContactCoefficients& nss);
/// alpha_c of the main loop: with g when `normal_coupling` and the model has one (as
/// noise::solve_loop_variants's main variant).
std::vector<noise::Receptance4> main_contact_receptance(const std::vector<double>& frequency,
                                                        double normal_stiffness, double speed,
                                                        const noise::ContactCoefficients& model,
                                                        bool normal_coupling);

/// The band levels of a wheel's loop (w.loop, or its lines refined: noise.band_refinement) with
/// its contact filter's semi-axes and the case's roughness.
/// The effective roughness (the case's wheel and rail roughness, its contact filter on the patch
/// semi-axes a, b) of the mean contact `m` at its rolling speed: what each contact's bands take.
noise::ContactRoughness contact_roughness(const NoiseCase& nc, const MeanContact& m);

noise::BandLevels wheel_bands(const WheelNoise& w, const noise::LoopResult& loop,
                              const NoiseCase& nc, const std::vector<double>& centres);

}  // namespace rollnoise::pipeline
