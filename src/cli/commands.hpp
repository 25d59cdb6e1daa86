// The subcommands of the rollnoise program. Each returns the exit status; InputError (exit 2)
// and NumericalError (exit 1) propagate to main().
#pragma once

#include <string>
#include <vector>

namespace rollnoise::cli {

struct CommonOptions {
  std::string case_file;
  std::string command;                 ///< the subcommand, e.g. "noise" (names the default output)
  std::string output;                  ///< empty: CASENAME.COMMAND.h5 in the current folder
  std::vector<std::string> overrides;  ///< --set key=value
  bool quiet = false;
  std::string contact_reference;       ///< --reference contact DIR (steady, validate)
};

/// Output path: -o, or CASENAME.COMMAND.h5 (curve_300m.noise.h5), so that the commands of one case
/// do not replace each other's results.
std::string output_path(const CommonOptions& o, const std::string& case_name);

/// rollnoise study / collect.
struct StudyOptions {
  std::string study_file;
  int workers = 0;         ///< -j; 0: the number of cores
  std::string shard;       ///< --shard i/N; empty: from SLURM_ARRAY_TASK_* or the whole study
  bool list = false;       ///< --list: print one command per case
  long case_index = -1;    ///< --case K: run case K alone
  bool no_reuse = false;   ///< --no-reuse: compute every case from scratch (benchmarks)
  bool quiet = false;
};
int run_study(const StudyOptions& o);
int run_collect(const StudyOptions& o);

int run_steady(const CommonOptions& o, const std::vector<std::string>& sweeps);
int run_transient(const CommonOptions& o);
/// rollnoise creep --extrapolate [--extrapolate-grids 1,1.5,2] (pipeline::run_creep_extrapolated).
struct ExtrapolationOptions {
  bool on = false;                            ///< --extrapolate (implied by --extrapolate-grids)
  std::vector<double> factors = {1.0, 1.5, 2.0};  ///< --extrapolate-grids
};
int run_creep(const CommonOptions& o, const std::string& csv, bool direct, const ExtrapolationOptions& x = {});
int run_response(const CommonOptions& o);
int run_validate(const CommonOptions& o);
int run_noise(const CommonOptions& o);
int run_receptance(const CommonOptions& o);
/// rollnoise passby (passby_command.cpp): the noise run, then its train passing the receiver.
int run_passby(const CommonOptions& o);
/// rollnoise cnossos (cnossos_command.cpp): CNOSSOS-EU transfer functions as JSON (-o), the power
/// per metre for `flow` vehicles per hour.
int run_cnossos(const CommonOptions& o, double flow);
/// rollnoise modes (modes_command.cpp): the FE wheel's modes; `csv` may be empty.
int run_modes(const CommonOptions& o, const std::string& csv);
/// rollnoise statespace (statespace_command.cpp); `csv_prefix` may be empty.
int run_statespace(const CommonOptions& o, const std::string& csv_prefix);
/// rollnoise squeal (squeal_command.cpp); `route` is "1", "2" or "both".
int run_squeal(const CommonOptions& o, const std::string& route);
/// rollnoise corrugation (corrugation_command.cpp): the growth rate of rail roughness per passage.
int run_corrugation(const CommonOptions& o);
/// rollnoise contact-input (contact_input_command.cpp): -o is the folder of CASENAME.inp.
int run_contact_input(const CommonOptions& o, bool steady_only);
int run_bench(const CommonOptions& o, const std::vector<int>& grids, const std::string& csv);
/// bench --sweep-cost: time and peak memory of the 1000-frequency sweep per grid, dense and
/// matrix-free (bench_sweep_cost.cpp).
int run_sweep_cost(const CommonOptions& o, const std::vector<int>& grids);

}  // namespace rollnoise::cli
