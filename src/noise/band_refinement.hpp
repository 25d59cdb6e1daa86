// Adaptive band means (docs/noise_loop.md Sec. 6.1): more narrow-band lines where the case's lines
// do not resolve a lightly damped peak of the loop's response.
//
// The band mean <|H|^2>_b of Eq. B1 is a midpoint rule on the cells of the samples. The wheel's
// modes are lightly damped (zeta ~ 1e-4; half-power width 2 zeta f ~ 0.4 Hz at 2 kHz) and those
// the contact hardly damps (motion tangential at the contact) stay so in the loop, while the lines
// of 48 per band are 2-20 Hz apart: the mean of a band depends on where its peaks fall between the
// lines (measured on the four-wheel curve_300m: force levels 1-2.5 dB, Mz up to 7.5 dB, the
// wheel's tangential velocity 7-16 dB from the 768-line mean).
//
// Refinement, level by level: a sample i is refined when, in any of the sampled powers p = |H|^2
// (every output of every source), it and its neighbours differ by more than `ratio`
//     max(p_{i-1}, p_i, p_{i+1}) > ratio min(p_{i-1}, p_i, p_{i+1})
// (the response varies strongly within a few cells: the flank of a peak; a Lorentzian's tail
// gives ((d + h)/d)^2 >= 4 between samples h apart at a distance d <= h from its peak, 2.25 at
// d = 2h) and its cell can matter to the band (max p times the cell width above `share` times
// the band's integral). A refined sample gets two new lines at f_i -+ w_i / 3, w_i the distance
// to its nearer neighbour (a cell cut in three for an even grid; never past a neighbour). The new
// lines are computed exactly (the whole loop at those frequencies) and merged with the others;
// the band mean then uses all lines with their (now unequal) cells. Lines are added only between
// the lowest and highest line of the case (the frequencies checked against the grid's Nyquist
// limit). What is left: the midpoint rule's error on the flanks where neighbours differ by less
// than `ratio` (cells up to 0.4 times the distance to the peak): about 1 % (0.03 dB) of a band
// mean that one resonance dominates (tests/noise/band_refinement_test.cpp); and a peak whose
// flanks stay below the response's background at the case's lines is not seen.
// Measured against a second-difference (midpoint-error) criterion on the four-wheel curve_300m:
// for the same agreement with the refined runs (0.01-0.03 dB) it added 2.4 times the lines.
#pragma once

#include <vector>

#include "noise/contact_set_loop.hpp"
#include "noise/loop.hpp"
#include "noise/loop_variants.hpp"

namespace rollnoise::noise {

struct BandRefinementOptions {
  double ratio = 2.0;   ///< neighbouring powers differing by more than this (3 dB): refine
  double share = 1e-2;  ///< cells whose max power x width is below this share of the band: skip
};

/// The new lines of one refinement level: sorted, none equal to a line of `f` (increasing). Each
/// entry of `powers` is one sampled |H|^2 at `f`; `centres` the 1/3-octave bands (cells are taken
/// within their band).
std::vector<double> refinement_frequencies(const std::vector<double>& f,
                                           const std::vector<std::vector<double>>& powers,
                                           const std::vector<double>& centres,
                                           const BandRefinementOptions& options = {});

/// |H|^2 of every output of a loop result, one series per component (forces, then the velocities
/// when present), and of a loop with several contacts, one per output row and source.
std::vector<std::vector<double>> sampled_powers(const LoopResult& r);
std::vector<std::vector<double>> sampled_powers(const ContactSetLoopResult& r);

/// The union of two results on disjoint frequencies, sorted by frequency (b's rho is a's); the
/// lines are moved out of a and b (pass std::move where they are not needed any more).
LoopResult merged(LoopResult a, LoopResult b);
ContactSetLoopResult merged(ContactSetLoopResult a, ContactSetLoopResult b);
LoopVariants merged(LoopVariants a, LoopVariants b);

}  // namespace rollnoise::noise
