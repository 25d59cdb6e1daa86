// Writing the state-space pipeline's results (pipeline/statespace.hpp, docs/statespace.md): the
// mean state and /creep/* as `rollnoise creep` writes them (at the fitted frequencies), then
// /statespace/* (continuous model, fit error, band, poles) and /statespace/discrete/* (the model at
// step dt); and the matrices as CSV, one file per matrix.
#pragma once

#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/statespace.hpp"

namespace rollnoise::io {

/// statespace.* of the case; InputError naming the key for a tolerance not below 1.
pipeline::StateSpaceOptions read_statespace_options(const CaseReader& r);

void write_statespace(Hdf5Writer& w, const CaseReader& r, const pipeline::StateSpaceResult& s);

/// The CSV files of `--csv PREFIX`: PREFIX_A.csv, _B, _C, _D (continuous) and _Ad, _Bd, _Cd, _Dd
/// (discrete), each the matrix's rows as lines of comma-separated numbers (17 significant digits,
/// no header: MATLAB's readmatrix/csvread, numpy.loadtxt(delimiter=",")).
std::vector<std::string> statespace_csv_paths(const std::string& prefix);

/// Write them to temporaries beside the final paths, returned uncommitted (output_files.hpp).
std::vector<TemporaryFile> write_statespace_csv(const std::string& prefix,
                                                const pipeline::StateSpaceResult& s);

}  // namespace rollnoise::io
