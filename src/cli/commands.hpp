// The subcommands of the rollnoise program. Each returns the exit status; InputError (exit 2)
// and NumericalError (exit 1) propagate to main().
#pragma once

#include <string>
#include <vector>

namespace rollnoise::cli {

struct CommonOptions {
  std::string case_file;
  std::string output;                  ///< empty: CASENAME.h5 in the current folder
  std::vector<std::string> overrides;  ///< --set key=value
  bool quiet = false;
};

/// Output path: -o, or CASENAME.h5.
std::string output_path(const CommonOptions& o, const std::string& case_name);

int run_steady(const CommonOptions& o, const std::vector<std::string>& sweeps);
int run_transient(const CommonOptions& o);
int run_creep(const CommonOptions& o, const std::string& csv, bool direct);
int run_response(const CommonOptions& o);
int run_validate(const CommonOptions& o);
int run_noise(const CommonOptions& o);
int run_receptance(const CommonOptions& o);
int run_bench(const CommonOptions& o, const std::vector<int>& grids, const std::string& csv);

}  // namespace rollnoise::cli
