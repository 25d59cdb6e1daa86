// The loop with all the wheels of curve.wheels coupled (docs/noise_loop.md Sec. 5.3): one
// noise::ContactPoint per wheel (wheelset 0 leading / 1 trailing, side +1 outer / -1 inner, its
// contact position in its own frame, rail_x = track.position for the leading axle and
// track.position + curve.wheelbase for the trailing), the structures between them once
// (noise::contact_set_structures: rigid wheelset, flexible wheel, each rail's transfer receptance),
// each wheel's own contact receptance alpha_c (its k_N, f(w), g(w)), and one uncorrelated roughness
// source per wheel (Sec. 5.2, M3-M4).
#pragma once

#include <vector>

#include "noise/bands.hpp"
#include "noise/contact_set_loop.hpp"
#include "pipeline/noise_case.hpp"
#include "pipeline/wheel_noise.hpp"

namespace rollnoise::pipeline {

/// The contact points of the wheels (in their order).
std::vector<noise::ContactPoint> bogie_contacts(const std::vector<WheelNoise>& wheels,
                                                const NoiseCase& nc);

/// (M3) with the wheels' contacts and one source per wheel, at `frequency`; `cross` selects the
/// cross terms (CrossCoupling::none(): each wheel alone, at its own rail position). InputError
/// naming noise.contact_coupling for the waveguide rail (it has no transfer between two points).
/// `spectra` (optional): the single-contact loop's spectra of nc.rail at `frequency`, whose rail
/// point receptance at nc.rail_position is then not solved again (the same bits).
noise::ContactSetLoopResult bogie_loop(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                       const std::vector<double>& frequency,
                                       const noise::CrossCoupling& cross = {},
                                       const noise::StructureSpectra* spectra = nullptr);

/// Band levels (M4) of every wheel: each source with its own wheel's contact filter (a, b) on the
/// case's roughness spectra.
std::vector<noise::BandLevels> bogie_bands(const noise::ContactSetLoopResult& loop,
                                           const std::vector<WheelNoise>& wheels,
                                           const NoiseCase& nc, const std::vector<double>& centres);

}  // namespace rollnoise::pipeline
