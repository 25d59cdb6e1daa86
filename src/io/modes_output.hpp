// The output of `rollnoise modes` (docs/interface.md): the FE wheel's modes under /modes.
#pragma once

#include "dynamics/wheel_fe.hpp"
#include "io/hdf5_writer.hpp"

namespace rollnoise::io {

/// Writes /modes/{frequency, n, family, nodal_circles, modal_mass, damping}, /modes/tread/{s, r,
/// shape}, /modes/mesh/{nodes, triangles} and /modes/mesh/shape (the whole section per mode), each
/// with its units attribute.
void write_wheel_modes(Hdf5Writer& w, const dynamics::WheelFeModes& modes,
                       const dynamics::WheelModalDamping& damping);

}  // namespace rollnoise::io
