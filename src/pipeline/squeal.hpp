// `rollnoise squeal` (docs/squeal.md): the linear stability of the closed wheel-rail-contact loop
// at the curve's mean contact state, assembled exactly as the noise loop assembles it
// (noise_pipeline.hpp stages 1 and 3: curve state, contact patch, normal stiffness, steady rolling,
// the linear NSS model), then continued to complex frequency (noise/stability.hpp):
//   wheel: rigid wheelset + all modes of the modes file (mode shapes moved and rotated into the
//          contact frame), exact in s;
//   rail:  the case's track model at complex frequency;
//   contact: Hertz spring k_N, alpha_c,t = (V/s) f(s)^{-1}, and alpha_c,tn = -alpha_c,tt g(s) when
//          noise.normal_coupling = "on", f and g from the model's Markov parameters.
// Route 2 (Newton with homotopy continuation on (S3)) for every wheel mode with
// noise.band_min <= f_n <= noise.band_max. The contact law enters only through f and g, so any
// friction law whose linearisation the NSS model carries is handled the same way.
#pragma once

#include <vector>

#include "noise/stability.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

struct SquealResult {
  ContactCase contact;  ///< as run
  CurveSetup curve;
  ContactStage stage;
  bool coupled = false;                 ///< g in the loop (noise.normal_coupling and slip elements)
  double min_sigma = 0.0;               ///< the contact series converge for Re s above this (1/s)
  std::vector<noise::ModeRoot> roots;   ///< route 2, one per wheel mode in the band
  double seconds_contact = 0.0;         ///< curve state, patch, steady rolling, linear model, Markov parameters
  double seconds_roots = 0.0;           ///< route 2
  long evaluations = 0;                 ///< evaluations of the loop matrix at complex s
  int unstable_count() const;
};

/// The whole command (with the NSS model; with noise.contact_model = "kalker" the contact is
/// Kalker's constant f, g = 0). InputError (noise.band_max) when no mode lies in the band or the band
/// exceeds the grid's Nyquist limit.
SquealResult run_squeal(ContactCase c, const NoiseCase& nc, const noise::StabilityOptions& options = {});

/// The loop at complex s of a solved contact stage (for tests and other drivers): the contact's
/// Markov parameters must exist (the stage's model swept once).
noise::LaplaceLoop squeal_loop(const ContactCase& c, const NoiseCase& nc, const CurveSetup& curve,
                               const ContactStage& stage, const noise::MarkovContact& contact, bool coupled);

}  // namespace rollnoise::pipeline
