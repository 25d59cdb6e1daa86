// Writing the CNOSSOS-EU transfer functions (pipeline/cnossos.hpp) as JSON in the layout of
// NoiseModelling's railway source data (its RailwayCnossosEU_2020.json: Vehicle/Transfer/<id> and
// Track/TrackTransfer/<id>, each with Default, Reference, Description and a 24-value Spectre in dB,
// 50 Hz - 10 kHz), so that the entries can be put beside its defaults; docs/interface.md.
#pragma once

#include <string>

#include "pipeline/cnossos.hpp"

namespace rollnoise::io {

/// What the entries say of their origin.
struct CnossosOrigin {
  std::string case_name;
  double speed = 0.0;           ///< km/h
  double wheel_diameter = 0.0;  ///< mm
};

/// The JSON text: the two entries under the id "1000" (above NoiseModelling's own ids), and a
/// "rollnoise" object with the band centres, which bands were computed and which filled (and how),
/// and L_R,TOT.
std::string cnossos_json(const pipeline::CnossosTransfer& t, const CnossosOrigin& origin);

/// Write it to `path` (io::write_text_file; `option` names the path in errors) and commit.
void write_cnossos(const std::string& path, const std::string& option,
                   const pipeline::CnossosTransfer& t, const CnossosOrigin& origin);

}  // namespace rollnoise::io
