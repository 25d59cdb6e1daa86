// rollnoise: railway rolling-contact and rolling-noise analysis in the frequency domain.
//
//   rollnoise steady    CASE.toml [-o OUT.h5] [--set key=value]... [--sweep KEY=VALUES]
//   rollnoise transient CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise creep     CASE.toml [-o OUT.h5] [--set key=value]... [--csv FILE] [--direct]
//   rollnoise response  CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise validate  CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise noise     CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise receptance CASE.toml [-o OUT.h5] [--set key=value]...
//   rollnoise passby    CASE.toml [-o OUT.h5] [--set key=value]...   a train passing by
//   rollnoise cnossos   CASE.toml [-o OUT.json] [--set key=value]... [--flow Q]   CNOSSOS-EU
//   rollnoise statespace CASE.toml [-o OUT.h5] [--set key=value]... [--csv PREFIX]
//   rollnoise squeal    CASE.toml [-o OUT.h5] [--set key=value]... [--route 1|2|both]
//   rollnoise corrugation CASE.toml [-o OUT.h5] [--set key=value]...   corrugation growth
//   rollnoise bench     CASE.toml [-o OUT.h5] [--nx 10,14,20,...] [--csv FILE]
//   rollnoise study     STUDY.toml [-j N] [--shard i/N] [--list] [--case K] [--no-reuse]
//   rollnoise collect   STUDY.toml
//   rollnoise contact-input CASE.toml [-o DIR] [--steady]   CONTACT's input for the case
//   rollnoise keys                      the declared case keys with defaults and help
//
// Every command but keys takes -q (only warnings and errors, on stderr). Commands and options: docs/interface.md.
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
#include "io/output_files.hpp"

namespace rollnoise::cli {

std::string output_path(const CommonOptions& o, const std::string& case_name) {
  if (!o.output.empty()) return o.output;
  return case_name + (o.command.empty() ? "" : "." + o.command) +
         (o.command == "cnossos" ? ".json" : ".h5");
}

}  // namespace rollnoise::cli

namespace {

using namespace rollnoise;

// Every command's options, filled by CLI11's parse (its options point into this value, which
// therefore stays where it is built), and the subcommands to ask which one was given.
struct CommandLine {
  CommandLine() = default;
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  cli::CommonOptions common;
  cli::StudyOptions study_options;
  std::vector<std::string> sweeps;     // steady --sweep
  std::vector<std::string> reference;  // steady, validate --reference contact DIR
  std::string creep_csv, modes_csv, bench_csv, statespace_csv;
  bool creep_direct = false;
  cli::ExtrapolationOptions creep_extrapolation;
  CLI::Option* creep_grids = nullptr;
  std::string squeal_route = "both";
  std::vector<int> bench_grids = {10, 14, 20, 28, 40, 56};
  std::vector<int> sweep_cost_grids;
  bool contact_input_steady = false;
  double flow = 10.0;  ///< cnossos --flow
  CLI::App *steady = nullptr, *transient = nullptr, *creep = nullptr, *response = nullptr,
           *validate = nullptr, *noise = nullptr, *receptance = nullptr, *passby = nullptr,
           *cnossos = nullptr, *modes = nullptr, *squeal = nullptr, *corrugation = nullptr,
           *bench = nullptr, *statespace = nullptr, *contact_input = nullptr, *keys = nullptr,
           *study = nullptr, *collect = nullptr;
};

const char* const kQuietHelp = "only warnings and errors (stderr): no progress, no summary on stdout";

void add_common(CLI::App* sub, cli::CommonOptions& common) {
  sub->add_option("case", common.case_file, "case file (TOML)")->required();
  sub->add_option("-o,--output", common.output, "output file (HDF5), default CASENAME.COMMAND.h5");
  sub->add_option("--set", common.overrides, "override a case entry: --set grid.nx=60")->take_all();
  sub->add_flag("-q,--quiet", common.quiet, kQuietHelp);
}

// The contact commands: steady, transient, creep, response, validate.
void add_contact_commands(CLI::App& app, CommandLine& cl) {
  cl.steady = app.add_subcommand("steady", "steady rolling at the mean creepage");
  add_common(cl.steady, cl.common);
  cl.steady->add_option("--sweep", cl.sweeps,
                        "steady solutions over a key: KEY=lo:hi:n, KEY[i]=lo:hi:n (component i) or "
                        "KEY=[v1, v2, ...]");
  cl.transient = app.add_subcommand("transient", "unsteady CONTACT time stepping (paper Eq. 2)");
  add_common(cl.transient, cl.common);
  cl.creep = app.add_subcommand("creep", "creep coefficients f_jk(f) of the linear NSS model");
  add_common(cl.creep, cl.common);
  cl.creep->add_option("--csv", cl.creep_csv, "also write the table (f, then Re and Im of each f_jk) as CSV");
  cl.creep->add_flag("--direct", cl.creep_direct, "a complex LU per frequency (the reference) instead of the fast sweep");
  cl.creep->add_flag("--extrapolate", cl.creep_extrapolation.on, "grid-converged f, g by Richardson extrapolation, with errors");
  cl.creep_grids = cl.creep->add_option("--extrapolate-grids", cl.creep_extrapolation.factors,
                                        "grid factors of --extrapolate (default 1,1.5,2)")->delimiter(',');
  cl.response = app.add_subcommand("response", "linear-model force response to a creepage history");
  add_common(cl.response, cl.common);
  cl.validate = app.add_subcommand("validate", "linear model against the unsteady solver");
  add_common(cl.validate, cl.common);
  for (auto* sub : {cl.steady, cl.validate})
    sub->add_option("--reference", cl.reference, "also compare with CONTACT's run in DIR: --reference contact DIR")
        ->expected(2);
}

// The noise commands: noise, receptance, modes, squeal, corrugation.
void add_noise_commands(CLI::App& app, CommandLine& cl) {
  cl.noise = app.add_subcommand("noise", "closed-loop contact-force spectra from roughness");
  add_common(cl.noise, cl.common);
  cl.receptance = app.add_subcommand("receptance", "wheel, rail and contact receptances alone");
  add_common(cl.receptance, cl.common);
  cl.passby = app.add_subcommand("passby", "the noise run's bogie in a train passing the EN ISO 3095 receiver");
  add_common(cl.passby, cl.common);
  cl.cnossos = app.add_subcommand("cnossos", "CNOSSOS-EU transfer functions (NoiseModelling's JSON) and power per metre");
  add_common(cl.cnossos, cl.common);
  cl.cnossos->add_option("--flow", cl.flow, "vehicles per hour for the power per metre (default 10)");
  cl.modes = app.add_subcommand("modes", "the wheel's axisymmetric FE modes and shapes along the tread");
  add_common(cl.modes, cl.common);
  cl.modes->add_option("--csv", cl.modes_csv, "also write the tread shapes as CSV (the wheel.shapes import format)");
  cl.squeal = app.add_subcommand("squeal", "stability of the wheel-rail-contact loop: coupled wheel-mode eigenvalues");
  add_common(cl.squeal, cl.common);
  cl.squeal->add_option("--route", cl.squeal_route, "1 (rational fits, eigenvalues), 2 (continuation on the exact loop) or both")
      ->check(CLI::IsMember({"1", "2", "both"}));
  cl.corrugation = app.add_subcommand(
      "corrugation", "growth rate of rail roughness per passage against wavelength (wear)");
  add_common(cl.corrugation, cl.common);
}

// The tools: bench, statespace, contact-input, keys.
void add_tool_commands(CLI::App& app, CommandLine& cl) {
  cl.bench = app.add_subcommand("bench", "run time against error under grid refinement");
  add_common(cl.bench, cl.common);
  cl.bench->add_option("--nx", cl.bench_grids, "elements in x of the grids, coarse to fine (the last is the reference)")
      ->delimiter(',');
  cl.bench->add_option("--csv", cl.bench_csv, "write the table as CSV (draw it with postprocess/plot_bench.py)");
  cl.statespace = app.add_subcommand("statespace", "the contact as a state-space model (continuous fit, discrete ERA)");
  add_common(cl.statespace, cl.common);
  cl.statespace->add_option("--csv", cl.statespace_csv, "also write each matrix as PREFIX_A.csv, ..., PREFIX_Dd.csv");
  cl.bench->add_option("--sweep-cost", cl.sweep_cost_grids,
                       "instead: time and peak memory of the 1000-frequency sweep, dense and matrix-free, on "
                       "these grids (nx, e.g. 34,68,100,200)")
      ->delimiter(',');
  cl.contact_input = app.add_subcommand("contact-input", "CONTACT's input (.inp) for the case (docs/contact_interop.md)");
  cl.contact_input->add_option("case", cl.common.case_file, "case file (TOML)")->required();
  cl.contact_input->add_option("-o,--output", cl.common.output, "folder of CASENAME.inp (a profile case in a curve: CASENAME_<wheel>.inp per wheel; default: the current folder)");
  cl.contact_input->add_option("--set", cl.common.overrides, "override a case entry: --set grid.nx=60")->take_all();
  cl.contact_input->add_flag("--steady", cl.contact_input_steady, "only the steady case, also when the case has an [excitation]");
  cl.contact_input->add_flag("-q,--quiet", cl.common.quiet, kQuietHelp);
  cl.keys = app.add_subcommand("keys", "list the case-file keys with defaults and help");
}

// The parameter studies: study, collect (docs/study.md).
void add_study_commands(CLI::App& app, CommandLine& cl) {
  cli::StudyOptions& o = cl.study_options;
  cl.study = app.add_subcommand("study", "run a parameter study of noise cases (docs/study.md)");
  cl.study->add_option("study", o.study_file, "study file (TOML)")->required();
  cl.study->add_option("-j,--jobs", o.workers, "worker processes (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  cl.study->add_option("--shard", o.shard,
                       "run shard i of N (i = 1..N); default from SLURM_ARRAY_TASK_ID/COUNT, else the whole study");
  cl.study->add_flag("--list", o.list, "print one self-contained command per case (GNU parallel, HyperQueue)");
  cl.study->add_option("--case", o.case_index, "run case K alone (what --list prints)")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            const bool digits = !v.empty() && v.find_first_not_of("0123456789") == std::string::npos;
            return digits ? "" : "--case " + v + ": a case number K = 0, 1, 2, ... (see --list)";
          },
          "K"));
  cl.study->add_flag("--no-reuse", o.no_reuse, "compute every case from scratch (to measure the reuse)");
  cl.study->add_flag("-q,--quiet", o.quiet, kQuietHelp);
  cl.collect = app.add_subcommand("collect", "merge a study's cases into OUTPUT/study.h5 and study.csv");
  cl.collect->add_option("study", o.study_file, "study file (TOML)")->required();
  cl.collect->add_flag("-q,--quiet", o.quiet, kQuietHelp);
}

// The parsed command, run: its exit status (InputError and NumericalError propagate).
int dispatch(CommandLine& cl) {
  if (cl.keys->parsed()) {
    std::cout << io::describe_schema();
    return 0;
  }
  if (!cl.reference.empty()) {
    if (cl.reference[0] != "contact")
      throw InputError("--reference", "--reference " + cl.reference[0] + ": the known reference is 'contact DIR'");
    cl.common.contact_reference = cl.reference[1];
  }
  for (const CLI::App* sub :
       {cl.steady, cl.transient, cl.creep, cl.response, cl.validate, cl.noise, cl.receptance,
        cl.passby, cl.cnossos, cl.modes, cl.squeal, cl.corrugation, cl.bench, cl.statespace})
    if (sub->parsed()) cl.common.command = sub->get_name();
  const cli::CommonOptions& common = cl.common;
  // -q: warnings and errors only (stderr); study --list still prints its commands, which are its result
  const bool study_like = cl.study->parsed() || cl.collect->parsed();
  if (study_like ? cl.study_options.quiet && !cl.study_options.list : common.quiet) cli::silence_stdout();
  if (cl.study->parsed()) return cli::run_study(cl.study_options);  // its own output folder (docs/study.md)
  if (cl.collect->parsed()) return cli::run_collect(cl.study_options);
  if (cl.contact_input->parsed()) return cli::run_contact_input(common, cl.contact_input_steady);
  // the output files, before any computation
  cli::check_run_files(common, cl.creep->parsed()   ? cl.creep_csv
                               : cl.bench->parsed() ? cl.bench_csv
                               : cl.modes->parsed() ? cl.modes_csv
                                                    : "");
  if (cl.steady->parsed()) return cli::run_steady(common, cl.sweeps);
  if (cl.transient->parsed()) return cli::run_transient(common);
  cl.creep_extrapolation.on = cl.creep_extrapolation.on || cl.creep_grids->count() > 0;
  if (cl.creep->parsed()) return cli::run_creep(common, cl.creep_csv, cl.creep_direct, cl.creep_extrapolation);
  if (cl.response->parsed()) return cli::run_response(common);
  if (cl.validate->parsed()) return cli::run_validate(common);
  if (cl.noise->parsed()) return cli::run_noise(common);
  if (cl.receptance->parsed()) return cli::run_receptance(common);
  if (cl.passby->parsed()) return cli::run_passby(common);
  if (cl.cnossos->parsed()) return cli::run_cnossos(common, cl.flow);
  if (cl.modes->parsed()) return cli::run_modes(common, cl.modes_csv);
  if (cl.bench->parsed() && !cl.sweep_cost_grids.empty()) return cli::run_sweep_cost(common, cl.sweep_cost_grids);
  if (cl.squeal->parsed()) return cli::run_squeal(common, cl.squeal_route);
  if (cl.corrugation->parsed()) return cli::run_corrugation(common);
  if (cl.bench->parsed()) return cli::run_bench(common, cl.bench_grids, cl.bench_csv);
  if (cl.statespace->parsed()) return cli::run_statespace(common, cl.statespace_csv);
  return 0;
}

int run_command(int argc, char** argv) {
  gsl_set_error_handler_off();  // GSL errors are checked where they matter
  CLI::App app{"rollnoise: railway rolling contact and rolling noise in the frequency domain"};
  app.require_subcommand(1);
  // the build's version (git describe at build time), as every result file records it
  app.set_version_flag("--version", "rollnoise " + io::provenance().program_version,
                       "print the program's version and exit");
  CommandLine cl;
  add_contact_commands(app, cl);
  add_noise_commands(app, cl);
  add_tool_commands(app, cl);
  add_study_commands(app, cl);

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
    return dispatch(cl);
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
}

}  // namespace

int main(int argc, char** argv) {
  rollnoise::cli::start_process(argc, argv);  // stdout line-buffered; command line kept for the provenance
  // exit 1 if anything printed was lost (a full disk or /dev/full as stdout): never 0 with lost output
  return rollnoise::cli::finish_process(run_command(argc, argv));
}
