// The rolling-noise loop for the variants the `noise` command compares (docs/noise_loop.md
// Sec. 5.1), from one set of structures (every contact of the loop, the same sources):
//
//  * main      the contact model (the linear NSS model, or Kalker's theory) with the normal ->
//              tangential friction coupling F~t = -f xi~ + g Fz (contact_receptance.hpp, Eq. C3)
//              when `normal_coupling` is on, without it (g = 0) when off;
//  * uncoupled the same contact with g = 0; solved only when the coupling is on and the model has a
//              g, so that main - uncoupled isolates the coupling;
//  * baseline  another contact of the same mean state, e.g. the quasi-steady one (f(0), g(0) of
//              the NSS model, real and frequency-independent: main - baseline isolates the
//              unsteadiness of the contact) or Kalker's full-adhesion coefficients (g = 0). The
//              baseline's g enters under the same `normal_coupling` switch as the main model's.
#pragma once

#include <array>
#include <vector>

#include "noise/bands.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/contact_set_loop.hpp"
#include "noise/loop.hpp"

namespace rollnoise::noise {

/// The linear contact per frequency: F~t = -f xi~ + g Fz.
struct ContactCoefficients {
  std::vector<Eigen::Matrix3cd> creep;  ///< f (N, N m, N m^2), rows Fx, Fy, Mz
  std::vector<LoadCoefficients> load;   ///< g (-, -, m); empty: no normal-load coupling (g = 0)
  bool empty() const { return creep.empty(); }
};

/// The same f and g at each of `n` frequencies (a quasi-steady or steady contact).
ContactCoefficients constant_coefficients(const Eigen::Matrix3cd& creep,
                                          const LoadCoefficients& load, std::size_t n);

/// The quasi-steady contact from the zero-frequency values of a linear model: Re f(0), Re g(0) at
/// each of `n` frequencies. f(0) and g(0) are real in theory (the sum of the real Markov
/// parameters); NumericalError if their imaginary parts exceed 1e-8 of their magnitude.
ContactCoefficients quasi_steady_coefficients(const Eigen::Matrix3cd& creep_at_zero,
                                              const LoadCoefficients& load_at_zero, std::size_t n);

struct LoopVariantsInput {
  double normal_stiffness = 0.0;  ///< k_H (N/m)
  double speed = 0.0;             ///< V (m/s)
  ContactCoefficients model;      ///< the main contact model, one entry per frequency
  bool normal_coupling = true;    ///< use g (Eq. C3) in the main and the baseline contact
  ContactCoefficients baseline;   ///< empty: no baseline
};

/// One contact's alpha_c per frequency for each variant (contact frame, Eq. C1-C3 of
/// contact_receptance.hpp). `uncoupled` is empty unless the coupling is on and the model has a g;
/// `baseline` is empty without a baseline.
struct ContactVariants {
  std::vector<Receptance4> main, uncoupled, baseline;
};
ContactVariants contact_variants(const std::vector<double>& frequency,
                                 const LoopVariantsInput& input);

/// The loop of a set of contacts (contact_set_loop.hpp; a single wheel is a set of one) for each
/// variant, on the same structures and sources.
struct LoopVariants {
  ContactSetLoopResult main;       ///< with g when normal_coupling (and the model has one)
  ContactSetLoopResult uncoupled;  ///< g = 0; no frequencies unless has_uncoupled()
  ContactSetLoopResult baseline;   ///< no frequencies unless has_baseline()
  bool has_uncoupled() const { return !uncoupled.frequency.empty(); }
  bool has_baseline() const { return !baseline.frequency.empty(); }
};

/// Solves (M3) of contact_set_loop.hpp for each variant: `contacts[a]` is contact a's alpha_c of
/// every variant (contact_variants); a variant is solved when every contact has it. The
/// frequencies on `threads` threads (the same result for any count).
LoopVariants solve_loop_variants(const ContactSetStructures& structures,
                                 const std::vector<ContactVariants>& contacts,
                                 const Eigen::MatrixXd& sources, int threads = 1);

/// Force band levels a - b per band (dB): Fz, Fx, Fy, Mz. InputError unless the bands match.
std::vector<std::array<double, 4>> force_level_difference(const BandLevels& a, const BandLevels& b);

}  // namespace rollnoise::noise
