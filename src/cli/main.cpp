// rollnoise: railway rolling-contact and rolling-noise analysis in the frequency domain.
//
//   rollnoise steady    CASE.toml [-o OUT.h5] [--set key=value]... [--sweep KEY=VALUES]
//   rollnoise transient CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise creep     CASE.toml [-o OUT.h5] [--set key=value]... [--csv FILE] [--direct]
//   rollnoise response  CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise validate  CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise noise     CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise receptance CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise statespace CASE.toml [-o OUT.h5] [--set key=value]... [--csv PREFIX]
//   rollnoise squeal    CASE.toml [-o OUT.h5] [--set key=value]... [--route 1|2|both]
//   rollnoise bench     CASE.toml [-o OUT.h5] [--nx 10,14,20,...] [--csv FILE]
//   rollnoise study     STUDY.toml [-j N] [--shard i/N] [--list] [--case K] [--no-reuse]
//   rollnoise collect   STUDY.toml
//   rollnoise contact-input CASE.toml [-o DIR] [--steady]   CONTACT's input for the case
//   rollnoise keys                      the declared case keys with defaults and help
//
// Every command but keys takes -q (no progress output). Commands and options: docs/interface.md.
//
// Exit status: 0 success, 2 bad input (the message names the file and key), 1 numerical failure.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <gsl/gsl_errno.h>

#include "cli/command_suggestion.hpp"
#include "cli/commands.hpp"
#include "cli/run_files.hpp"
#include "core/errors.hpp"
#include "io/case_schema.hpp"

namespace rollnoise::cli {

std::string output_path(const CommonOptions& o, const std::string& case_name) {
  return o.output.empty() ? case_name + ".h5" : o.output;
}

}  // namespace rollnoise::cli

namespace {

int run_command(int argc, char** argv) {
  using namespace rollnoise;
  gsl_set_error_handler_off();  // GSL errors are checked where they matter
  CLI::App app{"rollnoise: railway rolling contact and rolling noise in the frequency domain"};
  app.require_subcommand(1);
  cli::CommonOptions common;
  auto add_common = [&](CLI::App* sub) {
    sub->add_option("case", common.case_file, "case file (TOML)")->required();
    sub->add_option("-o,--output", common.output, "output file (HDF5), default CASENAME.h5");
    sub->add_option("--set", common.overrides, "override a case entry: --set grid.nx=60")
        ->take_all();
    sub->add_flag("-q,--quiet", common.quiet, "no progress output");
  };

  std::vector<std::string> sweeps;
  auto* steady = app.add_subcommand("steady", "steady rolling at the mean creepage");
  add_common(steady);
  steady->add_option("--sweep", sweeps,
                     "steady solutions over a key: KEY=lo:hi:n, KEY[i]=lo:hi:n (component i) or "
                     "KEY=[v1, v2, ...]");
  auto* transient = app.add_subcommand("transient", "unsteady CONTACT time stepping (paper Eq. 2)");
  add_common(transient);
  std::string creep_csv;
  bool creep_direct = false;
  auto* creep = app.add_subcommand("creep", "creep coefficients f_jk(f) of the linear NSS model");
  add_common(creep);
  creep->add_option("--csv", creep_csv, "also write the table (f, then Re and Im of each f_jk) as CSV");
  creep->add_flag("--direct", creep_direct, "a complex LU per frequency (the reference) instead of the fast sweep");
  cli::ExtrapolationOptions creep_extrapolation;
  creep->add_flag("--extrapolate", creep_extrapolation.on, "grid-converged f, g by Richardson extrapolation, with errors");
  auto* creep_grids = creep->add_option("--extrapolate-grids", creep_extrapolation.factors,
                                        "grid factors of --extrapolate (default 1,1.5,2)")->delimiter(',');
  auto* response = app.add_subcommand("response", "linear-model force response to a creepage history");
  add_common(response);
  auto* validate = app.add_subcommand("validate", "linear model against the unsteady solver");
  add_common(validate);
  std::vector<std::string> reference;
  for (auto* sub : {steady, validate})
    sub->add_option("--reference", reference, "also compare with CONTACT's run in DIR: --reference contact DIR")
        ->expected(2);
  auto* noise_cmd = app.add_subcommand("noise", "closed-loop contact-force spectra from roughness");
  add_common(noise_cmd);
  auto* receptance = app.add_subcommand("receptance", "wheel, rail and contact receptances alone");
  add_common(receptance);
  auto* modes_cmd = app.add_subcommand("modes", "the wheel's axisymmetric FE modes and shapes along the tread");
  add_common(modes_cmd);
  std::string modes_csv;
  modes_cmd->add_option("--csv", modes_csv, "also write the tread shapes as CSV (the wheel.shapes import format)");
  auto* squeal = app.add_subcommand("squeal", "stability of the wheel-rail-contact loop: coupled wheel-mode eigenvalues");
  add_common(squeal);
  std::string squeal_route = "both";
  squeal->add_option("--route", squeal_route, "1 (rational fits, eigenvalues), 2 (continuation on the exact loop) or both")
      ->check(CLI::IsMember({"1", "2", "both"}));
  std::vector<int> bench_grids = {10, 14, 20, 28, 40, 56};
  std::string bench_csv;
  auto* bench = app.add_subcommand("bench", "run time against error under grid refinement");
  add_common(bench);
  bench->add_option("--nx", bench_grids, "elements in x of the grids, coarse to fine (the last is the reference)")
      ->delimiter(',');
  bench->add_option("--csv", bench_csv, "write the table as CSV (draw it with postprocess/plot_bench.py)");
  std::string statespace_csv;
  auto* statespace = app.add_subcommand("statespace", "the contact as a state-space model (continuous fit, discrete ERA)");
  add_common(statespace);
  statespace->add_option("--csv", statespace_csv, "also write each matrix as PREFIX_A.csv, ..., PREFIX_Dd.csv");
  std::vector<int> sweep_cost_grids;
  bench->add_option("--sweep-cost", sweep_cost_grids,
                    "instead: time and peak memory of the 1000-frequency sweep, dense and matrix-free, on "
                    "these grids (nx, e.g. 34,68,100,200)")
      ->delimiter(',');
  bool contact_input_steady = false;
  auto* contact_input = app.add_subcommand("contact-input", "CONTACT's input (.inp) for the case (docs/contact_interop.md)");
  contact_input->add_option("case", common.case_file, "case file (TOML)")->required();
  contact_input->add_option("-o,--output", common.output, "folder of CASENAME.inp (default: the current folder)");
  contact_input->add_option("--set", common.overrides, "override a case entry: --set grid.nx=60")->take_all();
  contact_input->add_flag("--steady", contact_input_steady, "only the steady case, also when the case has an [excitation]");
  contact_input->add_flag("-q,--quiet", common.quiet, "no progress output");
  auto* keys = app.add_subcommand("keys", "list the case-file keys with defaults and help");
  cli::StudyOptions study_options;
  auto* study = app.add_subcommand("study", "run a parameter study of noise cases (docs/study.md)");
  study->add_option("study", study_options.study_file, "study file (TOML)")->required();
  study->add_option("-j,--jobs", study_options.workers, "worker processes (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  study->add_option("--shard", study_options.shard,
                    "run shard i of N (i = 1..N); default from SLURM_ARRAY_TASK_ID/COUNT, else the whole study");
  study->add_flag("--list", study_options.list, "print one self-contained command per case (GNU parallel, HyperQueue)");
  study->add_option("--case", study_options.case_index, "run case K alone (what --list prints)")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            const bool digits = !v.empty() && v.find_first_not_of("0123456789") == std::string::npos;
            return digits ? "" : "--case " + v + ": a case number K = 0, 1, 2, ... (see --list)";
          },
          "K"));
  study->add_flag("--no-reuse", study_options.no_reuse, "compute every case from scratch (to measure the reuse)");
  study->add_flag("-q,--quiet", study_options.quiet, "no progress output");
  auto* collect = app.add_subcommand("collect", "merge a study's cases into OUTPUT/study.h5 and study.csv");
  collect->add_option("study", study_options.study_file, "study file (TOML)")->required();
  collect->add_flag("-q,--quiet", study_options.quiet, "no progress output");

  if (const std::string msg = cli::check_command(app, argc, argv); !msg.empty()) {
    std::fprintf(stderr, "rollnoise: error: %s\n", msg.c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (keys->parsed()) {
      std::cout << io::describe_schema();
      return 0;
    }
    if (!reference.empty()) {
      if (reference[0] != "contact")
        throw InputError("--reference", "--reference " + reference[0] + ": the known reference is 'contact DIR'");
      common.contact_reference = reference[1];
    }
    if (study->parsed()) return cli::run_study(study_options);  // its own output folder (docs/study.md)
    if (collect->parsed()) return cli::run_collect(study_options);
    if (contact_input->parsed()) return cli::run_contact_input(common, contact_input_steady);
    // the output files, before any computation
    cli::check_run_files(common, creep->parsed()       ? creep_csv
                                 : bench->parsed()     ? bench_csv
                                 : modes_cmd->parsed() ? modes_csv
                                                       : "");
    if (steady->parsed()) return cli::run_steady(common, sweeps);
    if (transient->parsed()) return cli::run_transient(common);
    creep_extrapolation.on = creep_extrapolation.on || creep_grids->count() > 0;
    if (creep->parsed()) return cli::run_creep(common, creep_csv, creep_direct, creep_extrapolation);
    if (response->parsed()) return cli::run_response(common);
    if (validate->parsed()) return cli::run_validate(common);
    if (noise_cmd->parsed()) return cli::run_noise(common);
    if (receptance->parsed()) return cli::run_receptance(common);
    if (modes_cmd->parsed()) return cli::run_modes(common, modes_csv);
    if (bench->parsed() && !sweep_cost_grids.empty()) return cli::run_sweep_cost(common, sweep_cost_grids);
    if (squeal->parsed()) return cli::run_squeal(common, squeal_route);
    if (bench->parsed()) return cli::run_bench(common, bench_grids, bench_csv);
    if (statespace->parsed()) return cli::run_statespace(common, statespace_csv);
  } catch (const InputError& e) {
    std::fprintf(stderr, "rollnoise: error: %s\n", e.what());
    return 2;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "rollnoise: numerical failure: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rollnoise: failure: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  rollnoise::cli::start_process(argc, argv);  // stdout line-buffered; command line kept for the provenance
  // exit 1 if anything printed was lost (a full disk or /dev/full as stdout): never 0 with lost output
  return rollnoise::cli::finish_process(run_command(argc, argv));
}
