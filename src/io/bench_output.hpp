// Writing `rollnoise bench`'s grid-refinement table to HDF5 (/bench/*, docs/interface.md Sec. 4.8):
// one entry per grid, coarse to fine, every dataset with its units.
#pragma once

#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "nss/grid_study.hpp"

namespace rollnoise::io {

/// A column of relative errors (one value per grid) and what it measures.
struct BenchColumn {
  std::string name;         ///< dataset name under /bench/error/, e.g. "err_f_1kHz_rel"
  std::string description;  ///< its `description` attribute
  const std::vector<double>* values;
};

void write_bench(Hdf5Writer& w, const CaseReader& r, const std::vector<nss::GridMeasurement>& grids,
                 const std::vector<BenchColumn>& errors, double c11_table);

}  // namespace rollnoise::io
