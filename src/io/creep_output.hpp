// Writing the creep pipeline's results (pipeline/creep.hpp): /creep/* to HDF5 after the mean
// state, and the CSV table of `rollnoise creep --csv`.
#pragma once

#include <string>

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/creep.hpp"

namespace rollnoise::io {

void write_creep(Hdf5Writer& w, const CaseReader& r, const std::vector<double>& freq, const pipeline::CreepResult& c,
                 bool direct);

/// `creep --extrapolate`: /creep/f_error, /creep/g_error and /creep/extrapolation/* (write_creep
/// calls it when the result holds an extrapolation).
void write_extrapolation(Hdf5Writer& w, const std::vector<double>& freq, const pipeline::CreepExtrapolation& ex);

/// The creep sweep's method as written to /creep@method.
std::string creep_method(const pipeline::CreepResult& c, bool direct);

/// One row per frequency: frequency_Hz, re_f11, im_f11, ..., re_g3, im_g3, written to a temporary
/// beside `path` that the caller commits (output_files.hpp). InputError naming --csv when the file
/// cannot be written.
TemporaryFile write_creep_csv(const std::string& path, const std::vector<double>& freq, const pipeline::CreepResult& c);

}  // namespace rollnoise::io
