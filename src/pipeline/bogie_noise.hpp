// The one loop of the noise pipeline (docs/noise_loop.md Sec. 5.3), whatever the number of
// contacts: a single wheel is a loop of one contact, and noise.contact_coupling = "none" keeps
// each contact alone (no cross terms). One noise::ContactPoint per wheel (wheelset 0 leading / 1 trailing, side +1 outer / -1 inner, its
// contact position in its own frame, rail_x = track.position for the leading axle and
// track.position + curve.wheelbase for the trailing), the structures between them once
// (noise::contact_set_structures: rigid wheelset, flexible wheel, each rail's transfer receptance),
// each wheel's own contact receptance alpha_c (its k_N, f(w), g(w)), and one uncorrelated roughness
// source per wheel (Sec. 5.2, M3-M4).
//
// A second patch of a wheel (noise.second_patch = "coupled": the flange patch of a two-point
// contact, noise/flange_patch.hpp, docs/noise_loop.md Sec. 7.3) is one more ContactPoint of its
// wheel (same wheelset, side and rail_x, its own position on the flank), with its own alpha_c (its
// loop's k_N, f, g at its own mean state); it has a roughness source of its own only with
// noise.second_patch_roughness = "own". Contacts: the wheels in their order, then the patches.
#pragma once

#include <optional>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "noise/bands.hpp"
#include "noise/contact_set_loop.hpp"
#include "noise/loop_variants.hpp"
#include "pipeline/curve_setup.hpp"
#include "pipeline/noise_case.hpp"
#include "pipeline/wheel_noise.hpp"

namespace rollnoise::pipeline {

/// The contact points of the wheels (in their order), then of the second patches.
std::vector<noise::ContactPoint> bogie_contacts(const std::vector<WheelNoise>& wheels,
                                                const NoiseCase& nc,
                                                const std::vector<WheelNoise>& patches = {});

/// The second patches (noise.second_patch = "coupled"): the flange patch of the leading outer
/// wheel when its state is a two-point contact and the wheel is among `wheels`, with its contact
/// work (wheel_contact_noise); empty otherwise. InputError naming noise.second_patch with
/// noise.contact_coupling = "none".
std::vector<WheelNoise> second_patches(const CurveSetup& curve, const ContactCase& base,
                                       const NoiseCase& nc, const std::vector<WheelNoise>& wheels,
                                       const std::vector<double>& frequency);

/// Which contacts of bogie_contacts have a roughness source: every wheel; a second patch with
/// noise.second_patch_roughness = "own".
std::vector<bool> excited_contacts(std::size_t wheels, std::size_t patches, const NoiseCase& nc);

/// The cross terms the case's loop keeps: all with noise.contact_coupling = "bogie", none with
/// "none" (each contact alone at its own rail position).
noise::CrossCoupling loop_coupling(const NoiseCase& nc);

/// The loop (M3) of the contacts (the wheels, then the patches) with one source per excited
/// contact, at `frequency`, for every variant of the contacts' receptances (WheelNoise::receptance,
/// which must be at `frequency`); the cross terms of loop_coupling(nc), or `cross` if given. Any
/// rail model: nc.rail between the contact points (RailModel::contact_transfers), or `rail` if
/// given. The frequencies on `threads` threads (the same result for any count).
noise::LoopVariants contact_loop(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                 const std::vector<double>& frequency,
                                 const std::vector<WheelNoise>& patches = {}, int threads = 1,
                                 const dynamics::RailModel* rail = nullptr,
                                 const std::optional<noise::CrossCoupling>& cross = std::nullopt);

/// The effective roughness levels in the bands `centres` of each source of contact_loop (its
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
