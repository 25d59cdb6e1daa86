// The creepage history of a case ([excitation] with creepage.mean): harmonic (paper Eq. 31),
// multiharmonic (paper Eq. 32, seeded phases), a CSV time series, or none.
#pragma once

#include "contact/creepage_history.hpp"
#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"

namespace rollnoise::io {

/// Read the excitation of the case. A CSV file (columns t [s], xi_x, xi_y, phi [rad/m], one header
/// line allowed) is resolved relative to the case file's folder.
contact::CreepageHistory read_excitation(const CaseReader& r);

/// Write what defines the history (type, amplitudes, frequencies, phases) under `group`, so that a
/// run can be repeated exactly.
void write_excitation(Hdf5Writer& w, const std::string& group, const contact::CreepageHistory& h);

}  // namespace rollnoise::io
