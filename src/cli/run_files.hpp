// What every run does around its command: the process set-up (stdout line-buffered, the command
// line recorded for the files' provenance, SIGXFSZ ignored), the check that nothing printed was lost,
// and the check of the run's output files before any computation (io/output_files.hpp).
#pragma once

#include <string>

#include "cli/commands.hpp"

namespace rollnoise::cli {

/// Call first in main: stdout line-buffered (a redirected log fills as the run goes and keeps what
/// was printed if the run is killed), and the command line and start time kept for the HDF5 files.
void start_process(int argc, char** argv);

/// Call last in main with the command's exit status: flushes stdout and returns 1 (with a message on
/// stderr) if anything printed was lost (a full disk, /dev/full, a file-size limit, a closed pipe),
/// else `status`.
int finish_process(int status);

/// -q: from here on nothing reaches standard output (it is sent to /dev/null, also for the worker
/// processes a study starts), so that every command prints only its warnings and errors (stderr).
/// One switch for every command, instead of a condition at each print.
void silence_stdout();

/// InputError (exit 2, naming the option and the path) unless every output of the run can be
/// written without overwriting an input or another output: -o (or CASENAME.COMMAND.h5) and `csv`
/// (--csv, if not empty). The default output (no -o) also must not replace an existing file that
/// another command wrote (or that is no rollnoise result): only -o naming it replaces such a file.
/// Prints the case's physical-range warnings (io::physical_range_warnings) on stderr, once.
void check_run_files(const CommonOptions& o, const std::string& csv);

}  // namespace rollnoise::cli
