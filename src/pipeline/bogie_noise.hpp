// The loop with all the wheels of curve.wheels coupled (docs/noise_loop.md Sec. 5.3): one
// noise::ContactPoint per wheel (wheelset 0 leading / 1 trailing, side +1 outer / -1 inner, its
// contact position in its own frame, rail_x = track.position for the leading axle and
// track.position + curve.wheelbase for the trailing), the structures between them once
// (noise::contact_set_structures: rigid wheelset, flexible wheel, each rail's transfer receptance),
// each wheel's own contact receptance alpha_c (its k_N, f(w), g(w)), and one uncorrelated roughness
// source per wheel (Sec. 5.2, M3-M4).
//
// A second patch of a wheel (noise.second_patch = "coupled": the flange patch of a two-point
// contact, noise/flange_patch.hpp, docs/noise_loop.md Sec. 7.4) is one more ContactPoint of its
// wheel (same wheelset, side and rail_x, its own position on the flank), with its own alpha_c (its
// loop's k_N, f, g at its own mean state); it has a roughness source of its own only with
// noise.second_patch_roughness = "own". Contacts: the wheels in their order, then the patches.
#pragma once

#include <vector>

#include "noise/bands.hpp"
#include "noise/contact_set_loop.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/noise_case.hpp"
#include "pipeline/wheel_noise.hpp"

namespace rollnoise::pipeline {

/// The contact points of the wheels (in their order), then of the second patches.
std::vector<noise::ContactPoint> bogie_contacts(const std::vector<WheelNoise>& wheels,
                                                const NoiseCase& nc,
                                                const std::vector<WheelNoise>& patches = {});

/// The second patches (noise.second_patch = "coupled"): the flange patch of the leading outer
/// wheel when its state is a two-point contact and the wheel is among `wheels`, with its loop
/// alone (wheel_noise on the shared spectra); empty otherwise. InputError naming
/// noise.second_patch with noise.contact_coupling = "none".
std::vector<WheelNoise> second_patches(const CurveSetup& curve, const ContactCase& base,
                                       const NoiseCase& nc, const std::vector<WheelNoise>& wheels,
                                       const noise::StructureSpectra& spectra,
                                       const std::vector<double>& frequency);

/// Which contacts of bogie_contacts have a roughness source: every wheel; a second patch with
/// noise.second_patch_roughness = "own".
std::vector<bool> excited_contacts(std::size_t wheels, std::size_t patches, const NoiseCase& nc);

/// (M3) with the wheels' contacts and one source per wheel, at `frequency`; `cross` selects the
/// cross terms (CrossCoupling::none(): each wheel alone, at its own rail position). Any rail
/// model: nc.rail between the contact points (RailModel::contact_transfers), or `rail` if given.
/// The frequencies on `threads` threads (the same result for any count).
noise::ContactSetLoopResult bogie_loop(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                       const std::vector<double>& frequency,
                                       const noise::CrossCoupling& cross = {},
                                       const std::vector<WheelNoise>& patches = {}, int threads = 1,
                                       const dynamics::RailModel* rail = nullptr);

/// The effective roughness levels in the bands `centres` of each source of bogie_loop (its
/// excited contacts, in order): each with its own contact's filter (a, b) on the case's roughness
/// spectra; the contacts shared out on `threads` threads (the filter's band means are quadratures).
std::vector<std::vector<double>> bogie_source_levels(const std::vector<WheelNoise>& wheels,
                                                     const NoiseCase& nc,
                                                     const std::vector<double>& centres,
                                                     const std::vector<WheelNoise>& patches = {},
                                                     int threads = 1);

/// Band levels (M4) of every contact (the wheels, then the patches) with the sources' roughness
/// levels `source_levels` (bogie_source_levels).
std::vector<noise::BandLevels> bogie_bands(const noise::ContactSetLoopResult& loop,
                                           const std::vector<double>& centres,
                                           const std::vector<std::vector<double>>& source_levels);
/// The same with the sources' levels of bogie_source_levels.
std::vector<noise::BandLevels> bogie_bands(const noise::ContactSetLoopResult& loop,
                                           const std::vector<WheelNoise>& wheels,
                                           const NoiseCase& nc, const std::vector<double>& centres,
                                           const std::vector<WheelNoise>& patches = {});

}  // namespace rollnoise::pipeline
