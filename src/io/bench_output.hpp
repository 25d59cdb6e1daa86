// Writing `rollnoise bench`'s grid-refinement table to HDF5 (/bench/*, docs/interface.md Sec. 4.8):
// one entry per grid, coarse to fine, every dataset with its units.
#pragma once

#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/grid_study.hpp"

namespace rollnoise::io {

/// A quantity of the refinement table: its relative errors, one per grid.
struct BenchColumn {
  std::string name;    ///< what it measures (the printed tables; the dataset's `description`)
  std::string column;  ///< CSV column and dataset name under /bench/error/, e.g. "err_f_1kHz_rel"
  std::string header;  ///< header in the printed error table (empty: not printed there)
  const std::vector<double>* err;
};

void write_bench(Hdf5Writer& w, const CaseReader& r, const std::vector<pipeline::GridMeasurement>& grids,
                 const std::vector<BenchColumn>& errors, double c11_table);

/// The creepage-sampling study (pipeline::sampling_accuracy): /bench/time_sweep_contact,
/// /bench/time_sweep_midstep, /bench/time_sweep_average (s per grid) and /bench/sampling/{frequency,
/// converged_f (attribute reference_sampling), converged_f_error, order}; its errors are
/// BenchColumns of write_bench.
void write_bench_sampling(Hdf5Writer& w, const std::vector<pipeline::GridMeasurement>& grids,
                          const pipeline::SamplingAccuracy& a, const std::vector<double>& frequencies);

}  // namespace rollnoise::io
