// The structural, roughness and curving parts of a noise case, read and checked: wheel and track
// models from their files, roughness spectra, the contact filter, the curve.
#pragma once

#include <memory>
#include <string>

#include "dynamics/track.hpp"
#include "dynamics/wheel.hpp"
#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "noise/curve_state.hpp"
#include "noise/roughness.hpp"

namespace rollnoise::io {

struct NoiseCase {
  double curve_radius = 0.0;  ///< m, 0: tangent track
  double cant_deficiency = 0.0;
  bool estimate_creepage = true;
  bool multibody = false;  ///< curve.creepage = "multibody"
  double cg_height = 1.5;
  double wheelbase = 2.5, wheel_radius = 0.46, conicity = 0.15, flange_clearance = 0.005;
  double contact_angle = 0.0;  ///< when the case gives the creepages
  std::unique_ptr<dynamics::RailModel> rail;
  std::unique_ptr<dynamics::WheelModel> wheel;
  noise::RoughnessSpectrum rail_roughness, wheel_roughness;
  noise::ContactFilterModel filter = noise::ContactFilterModel::kIsotropic;
  bool use_nss = true;
  /// noise.normal_coupling: the contact's g (F~t = -f xi~ + g Fz) in the loop.
  bool normal_coupling = true;
  /// noise.compare: the comparison baseline of the loop (docs/noise_loop.md Sec. 5.1).
  enum class Baseline { kNone, kQuasiSteady, kKalker };
  Baseline compare = Baseline::kQuasiSteady;
  /// Non-empty when a deprecated key was mapped (for the command to print).
  std::string notice;
  double band_min = 100.0, band_max = 5000.0;
  int points_per_band = 48;
};

NoiseCase read_noise_case(const CaseReader& r);

/// The inputs of the curve contact state (profile cases with curve.creepage = "estimate" or
/// "multibody"): the case's profiles, material, grid options, curve, wheel load
/// (contact.normal_force, or wheelset.wheel_load) and [wheelset].
noise::CurveStateInput curve_state_input(const CaseReader& r, const ContactCase& contact,
                                         const NoiseCase& noise);

/// The inputs of the bogie estimate on the conical tread (Hertzian curve cases): the curve, the
/// case's wheel load and friction, Kalker's f11, f22 of the case's semi-axes.
noise::BogieCurvingInput bogie_curving_input(const ContactCase& contact, const NoiseCase& noise);

}  // namespace rollnoise::io
