// The user-input checks of vehicle curving (input validation belongs to io and the
// pipeline, the numerics assert their contracts): the inputs of the curve contact state and of the
// bogie estimate on the conical tread, as the pipeline builds them from a case
// (pipeline/curve_setup.cpp), checked with InputError naming the case key that sets each field.
// noise::CurveStateInput::valid() and noise::BogieCurvingInput::valid() state the same conditions
// as contracts (ROLLNOISE_ASSERT) of noise::curve_contact_state and noise::estimate_bogie_curving.
#pragma once

#include <memory>
#include <string>

#include "vehicle/curve_state.hpp"
#include "vehicle/curving.hpp"

namespace rollnoise::pipeline {

/// InputError naming the curve./wheelset./trailing_wheelset. key (or contact.normal_force,
/// rolling.speed, friction.mu, contact.geometry) of the first field outside the model; with the
/// bogie estimate (not multibody) also curve.wheelbase and the load transfer dQ = 2 Q h_d h_cg /
/// s^2 of the cant deficiency (curve.cg_height), which the estimate takes from these inputs.
void check_curve_state_input(const noise::CurveStateInput& in);

/// InputError naming the key of the first field outside the estimate's model: curve.radius,
/// rolling.speed, curve.cant_deficiency, curve.wheelbase, curve.wheel_radius, curve.conicity,
/// curve.flange_clearance, contact.normal_force, friction.mu, curve.cg_height, or curving.<field>
/// for a field no case key sets.
void check_bogie_curving_input(const noise::BogieCurvingInput& in);

/// Nadal's limit (curving.hpp, K6): InputError naming `key` (friction.mu, or the key that set the
/// flange friction) when the flange friction reaches tan(delta_f).
void check_flange_friction(const noise::FlangeFriction& f, const std::string& key);

/// The profile table of the bogie estimate (noise::profile_curving_table, as curve_contact_state
/// makes it); InputError naming contact.wheel_profile when the profile pair has no flangeway
/// clearance (the centred wheelset's contact on the flange).
std::shared_ptr<const noise::ProfileCurvingTable> curving_profile_table(const noise::CurveStateInput& in);

}  // namespace rollnoise::pipeline
