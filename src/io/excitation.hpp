// The creepage history of a case ([excitation] with creepage.mean): harmonic (paper Eq. 31),
// multiharmonic (paper Eq. 32, seeded phases), a CSV time series, or none.
#pragma once

#include "contact/creepage_history.hpp"
#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"

namespace rollnoise::io {

/// Read the excitation of the case. A CSV file (columns t [s], xi_x, xi_y, phi [rad/m] and an
/// optional 5th column dN [N], the normal-load variation; one header line allowed) is resolved
/// relative to the case file's folder. The normal load N_mean + dN (N_mean = contact.normal_force)
/// must stay positive: checked here for harmonic histories (at the minimum) and CSV samples; for
/// multiharmonic ones on the time steps of a run by normal_load_series.
contact::CreepageHistory read_excitation(const CaseReader& r);

/// The path of excitation.file: relative to the case file's folder unless absolute.
std::string excitation_file_path(const CaseReader& r);

/// The total normal load N_k = normal_mean + dN(k dt), k = 0..steps. InputError naming
/// excitation.normal_amplitude (excitation.file for a CSV history) unless every N_k is finite and
/// positive.
std::vector<double> normal_load_series(const CaseReader& r, const contact::CreepageHistory& h,
                                       double normal_mean, double dt, long steps);

/// Write what defines the history (type, amplitudes, frequencies, phases) under `group`, so that a
/// run can be repeated exactly.
void write_excitation(Hdf5Writer& w, const std::string& group, const contact::CreepageHistory& h);

}  // namespace rollnoise::io
