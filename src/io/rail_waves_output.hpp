// The waveguide rail's dispersion curves in the receptance output (docs/interface.md):
// /receptance/rail_waves/wavenumber (rad/m, [nk]) and /receptance/rail_waves/frequency (Hz,
// [nk][branches]): the lowest natural frequencies of the supported, undamped rail section at each
// real wavenumber (Eq. W2 of dynamics/rail_waveguide.hpp, on the loop's reduced model; the
// support at its static stiffness). Written only for track.model = "waveguide".
#pragma once

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"
#include "io/hdf5_writer.hpp"

namespace rollnoise::io {

void write_rail_waves(Hdf5Writer& w, const dynamics::RailModel& rail);

}  // namespace rollnoise::io
