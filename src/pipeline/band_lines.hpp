// noise.band_refinement (docs/noise_loop.md Sec. 6.1): the loop results on the case's lines and on
// the lines added where those do not resolve a peak of the response (noise/band_refinement.hpp).
// The band levels are taken from these; the narrow-band outputs stay on the case's lines.
#pragma once

#include <memory>
#include <vector>

#include "noise/contact_set_loop.hpp"
#include "noise/loop.hpp"
#include "noise/loop_variants.hpp"

namespace rollnoise::pipeline {

struct RefinedLoops {
  noise::LoopVariants loops;  ///< the loop of all the contacts, every variant (NoiseResult::loops)
  int levels = 0;             ///< refinement levels that added lines
  long added_lines = 0;       ///< lines added to the case's
  /// a level would have passed 16 x the case's lines or the case's limits: not taken
  bool capped = false;
};

}  // namespace rollnoise::pipeline
