// Reading roughness spectra from CSV files (e.g. models/roughness/*.csv) into
// noise::RoughnessSpectrum.
#pragma once

#include <string>

#include "noise/roughness.hpp"

namespace rollnoise::io {

/// Reads a spectrum from CSV with the header "wavelength_m,level_dB" ('#' comment lines), one band
/// per line in any order. InputError key "<path>:<line>:<field>" on a bad line.
noise::RoughnessSpectrum read_roughness_csv(const std::string& path);

}  // namespace rollnoise::io
