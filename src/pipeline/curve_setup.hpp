// The curve stage of the noise pipeline: the mean contact state of the leading outer wheel.
//
//   profiles with curve.creepage = "equilibrium", "estimate" or "multibody": the curve contact
//     state (vehicle/curve_state.hpp: the bogie in equilibrium on the exact contacts
//     (vehicle/bogie_equilibrium.hpp), the bogie estimate or the given wheelset position, contact
//     point, load transfer and flange share, creepages);
//   Hertzian case in a curve with curve.creepage = "equilibrium" or "estimate": the quasi-static
//     bogie estimate on the conical tread (vehicle/curving.hpp), Kalker's f11, f22 from the case's
//     semi-axes (the equilibrium needs the profiles' contacts);
//   otherwise the case's creepage.mean and contact point (or contact.angle).
// The stage returns the case placed at the state's contact point with its normal force and
// creepages (pipeline/contact_case.hpp): geometry only, nothing is solved; the mean-contact stage
// (pipeline/mean_contact.hpp) solves it.
#pragma once

#include <optional>
#include <vector>

#include "vehicle/curve_state.hpp"
#include "vehicle/curving.hpp"
#include "noise/loop.hpp"
#include "pipeline/contact_case.hpp"
#include "pipeline/noise_case.hpp"

namespace rollnoise::pipeline {

struct CurveSetup {
  noise::ContactPosition position;  ///< where the loop couples wheel and rail
  noise::CurvingEstimate curving;   ///< when estimated
  bool estimated = false;           ///< the creepages come from a curving estimate
  std::optional<noise::CurveContactState> state;  ///< profiles (estimate or multibody)
  /// The inputs the state was found from (with `state`): the other wheels use them
  /// (curve_wheels).
  std::optional<noise::CurveStateInput> state_input;
  /// The creepages were set by the stage (estimate or multibody), not read from the case.
  bool creepage_from_curve() const { return state.has_value() || estimated; }
  /// The rolling radius of the contact (m): of the state, of the estimate or the nominal one.
  double rolling_radius(const NoiseCase& nc) const;
};

/// The case placed by the curve contact state, and the state.
struct CurvePlacement {
  ContactCase contact;  ///< placed: contact point, normal force, a, b, grid and creepage of the state
  CurveSetup curve;
};

/// Resolve the curve contact state and place the case accordingly. InputError (curve.* /
/// wheelset.* keys) for inputs outside the models.
CurvePlacement resolve_curve(const ContactCase& c, const NoiseCase& nc);

/// The wheels of curve.wheels (docs/interface.md): as listed, or by default all four in a curve and
/// the leading outer wheel alone on tangent track; none without a curve contact state.
std::vector<noise::WheelId> curve_wheel_ids(const CurveSetup& s, const NoiseCase& nc);
/// The wheels of curve.wheels as listed, or the default (all four in a curve, the leading outer
/// wheel alone on tangent track), whatever the contact state. InputError naming curve.wheels.
std::vector<noise::WheelId> listed_wheel_ids(const NoiseCase& nc);

/// Every wheel's contact state (noise::bogie_wheel_contacts) of curve_wheel_ids, one immutable
/// value per wheel; the leading outer wheel's is the state's.
std::vector<noise::WheelContact> curve_wheels(const CurveSetup& s, const NoiseCase& nc);

/// The inputs of the curve contact state: the case's profiles, material, grid options, curve,
/// wheel load (contact.normal_force, or wheelset.wheel_load) and [wheelset]; checked
/// (check_curve_state_input: InputError naming the key).
noise::CurveStateInput curve_state_input(const ContactCase& c, const NoiseCase& nc);

/// The inputs of the bogie estimate on the conical tread (Hertzian curve cases): the curve, the
/// case's wheel load and friction, Kalker's f11, f22 of the case's semi-axes.
noise::BogieCurvingInput bogie_curving_input(const ContactCase& c, const NoiseCase& nc);

}  // namespace rollnoise::pipeline
