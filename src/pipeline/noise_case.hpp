// The structural, roughness and curve parts of a noise case as plain data (read by
// io/noise_case.hpp): wheel and track models, roughness spectra, the contact filter, the curve,
// the wheelset position of a multibody run, the band range and the loop's variants.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel.hpp"
#include "noise/roughness.hpp"
#include "noise/roughness_filter.hpp"
#include "pipeline/sound_power.hpp"
#include "vehicle/bogie_equilibrium.hpp"

namespace rollnoise::pipeline {

struct NoiseCase {
  double curve_radius = 0.0;  ///< m, 0: tangent track
  double cant_deficiency = 0.0;
  /// curve.creepage = "equilibrium" or "estimate": the creepages from the curve (a Hertzian case
  /// gets the estimate for both).
  bool estimate_creepage = true;
  bool equilibrium = true;  ///< curve.creepage = "equilibrium" (the bogie in equilibrium, profiles)
  bool multibody = false;   ///< curve.creepage = "multibody"
  /// [vehicle]: the bogie's masses, suspension and geometry of the equilibrium.
  noise::VehicleParameters vehicle;
  double cg_height = 1.5;
  double wheelbase = 2.5, wheel_radius = 0.46, conicity = 0.15, flange_clearance = 0.005;
  double contact_angle = 0.0;  ///< when the case gives the creepages
  /// [wheelset] of a multibody run: position, and optionally its own load and creepages.
  double wheelset_lateral = 0.0, wheelset_yaw = 0.0;
  std::optional<double> wheelset_load;
  std::optional<Eigen::Vector3d> wheelset_creepage;
  /// The other wheels of a multibody run: [trailing_wheelset] position, and per wheel (index
  /// noise::WheelId) its optional load and creepages (the leading outer's are wheelset_load and
  /// wheelset_creepage).
  double trailing_lateral = 0.0, trailing_yaw = 0.0;
  std::array<std::optional<double>, 4> wheel_loads;
  std::array<std::optional<Eigen::Vector3d>, 4> wheel_creepages;
  /// curve.wheels: the names of the wheels computed (empty: the default, docs/interface.md).
  std::vector<std::string> wheels;
  std::unique_ptr<dynamics::RailModel> rail;
  std::unique_ptr<dynamics::WheelModel> wheel;
  noise::RoughnessSpectrum rail_roughness, wheel_roughness;
  noise::ContactFilterModel filter = noise::ContactFilterModel::kIsotropic;
  bool use_nss = true;
  /// noise.normal_coupling: the contact's g (F~t = -f xi~ + g Fz) in the loop.
  bool normal_coupling = true;
  /// noise.contact_coupling: the wheels of curve.wheels coupled in one loop through the wheelset
  /// and the rails (kBogie, docs/noise_loop.md Sec. 5.3) or each wheel's loop alone (kNone).
  enum class ContactCoupling { kBogie, kNone };
  ContactCoupling contact_coupling = ContactCoupling::kBogie;
  /// noise.second_patch = "coupled": the flange patch of a two-point contact enters the bogie loop
  /// as a second contact of its wheel (docs/noise_loop.md Sec. 7.3); "off" (false): left out.
  bool second_patch = false;
  /// noise.second_patch_roughness = "own": the second patch has its own roughness source; "none"
  /// (false): it is excited through the coupling only.
  bool second_patch_roughness = false;
  /// noise.squeal_wheelsets: squeal also per wheelset of curve.wheels (pipeline/squeal_wheels.hpp).
  bool squeal_wheelsets = false;
  /// noise.compare: the comparison baseline of the loop (docs/noise_loop.md Sec. 5.1).
  enum class Baseline { kNone, kQuasiSteady, kKalker };
  Baseline compare = Baseline::kQuasiSteady;
  /// Non-empty when a deprecated key was mapped (for the command to print).
  std::string notice;
  double band_min = 100.0, band_max = 5000.0;
  int points_per_band = 48;
  /// noise.band_refinement: levels of lines added where the case's lines do not resolve a peak
  /// of the response (docs/noise_loop.md Sec. 6.1); 0: the band means on the case's lines only.
  int band_refinement = 6;
  /// noise.sound and [sound]: the sound powers of wheel, rail and sleepers (docs/sound.md).
  SoundCase sound;
};

}  // namespace rollnoise::pipeline
