// Output files of a run: checked before any computation, written atomically, and stamped with
// their provenance (docs/conventions.md, "Output files").
//
//  - check_outputs(): every output (-o, --csv, ...) is refused, with InputError naming the option
//    and the path (exit 2), when it is an existing folder or non-regular file (e.g. /dev/null),
//    when its folder does not exist or is not writable, or when it is one of the run's inputs
//    (the case file and every model file the case names, case_input_files()) or another output
//    of the same run. Paths are compared resolved: std::filesystem::equivalent when both exist (a
//    symlink or hard link to the case is caught), weakly_canonical otherwise.
//  - TemporaryFile: a unique file `.NAME.XXXXXX` (mkstemp; NAME shortened so that the temporary's
//    name stays within NAME_MAX) in the output's folder, renamed onto
//    NAME by commit() (rename(2) within one folder is atomic: a reader sees the old file or the
//    complete new one, and two concurrent runs to one output each write their own temporary, so
//    the final file is one complete run, never a mix). It is removed when dropped uncommitted
//    (any failure) and on SIGINT, SIGTERM and SIGHUP: a fixed table of paths that the signal
//    handler unlink()s (async-signal-safe) before it restores the default action and raises the
//    signal again, so the exit status still shows the signal. A signal that was ignored when the
//    first temporary was made (nohup, background jobs) stays ignored.
//  - Provenance: record_invocation() (called once by main) keeps the command line, the command and
//    the start time; every HDF5 file gets them as root attributes with the program version
//    (git describe --always --dirty at build time, "unknown" outside git).
#pragma once

#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/case_reader.hpp"

namespace rollnoise::io {

/// One output of a run: the option that names it (for messages) and its path.
struct OutputFile {
  std::string option;
  std::string path;
};

/// One input of a run: what it is (for messages: "the case file", "contact.wheel_profile") and its
/// path.
struct InputFile {
  std::string what;
  std::string path;
};

/// The case file keys that name a model file (resolved by resolve_model_file or, for
/// excitation.file, excitation_file_path).
const std::vector<std::string>& case_file_keys();

/// The files a run on `r` reads: the case file and every existing file named by case_file_keys()
/// (explicitly or by default, resolved as the readers resolve them; a key whose file does not
/// exist, e.g. roughness.rail = "iso3095", is left to the reader).
std::vector<InputFile> case_input_files(const CaseReader& r);

/// InputError(option, ...) for the first output that cannot be written or would overwrite an input
/// or another output (see the header comment). Call before any computation.
void check_outputs(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs);

/// A unique temporary beside `final_path`, committed by rename (see the header comment). The file
/// exists (empty, with the permissions a new file gets under the umask) once constructed.
class TemporaryFile {
 public:
  /// InputError naming `option` if the temporary cannot be created.
  TemporaryFile(std::string final_path, const std::string& option);
  ~TemporaryFile();  // removes the temporary unless committed
  TemporaryFile(TemporaryFile&& o) noexcept;
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  TemporaryFile& operator=(TemporaryFile&&) = delete;

  /// The temporary's path (write here).
  const std::string& path() const { return temp_; }
  const std::string& final_path() const { return final_; }
  /// Rename the temporary onto the final path.
  void commit();

 private:
  std::string final_, temp_;
  int slot_ = -1;  ///< index in the signal handler's table; -1: committed or moved from
};

/// Write `bytes` to the temporary `t` (every write checked, then fsync and close checked).
/// std::runtime_error naming the output and the reason (e.g. "No space left on device") if any of
/// it fails; the caller drops `t`, which removes the temporary.
void write_bytes(const TemporaryFile& t, const std::string& bytes);

/// Flush the file `temp` (the temporary of `final_path`) to disk, checked: std::runtime_error naming
/// the output and the reason if the file system reports an error only now.
void sync_file(const std::string& temp, const std::string& final_path);

/// A text output (CSV) written by `fill(std::ostream&)` into memory, then into a TemporaryFile with
/// every write checked (write_bytes), returned uncommitted (the caller commits it with the run's
/// other outputs). InputError naming `option` if it cannot be created; std::runtime_error if
/// writing fails.
template <class Fill>
TemporaryFile write_text_file(const std::string& path, const std::string& option, Fill&& fill) {
  TemporaryFile t(path, option);
  std::ostringstream out;
  fill(static_cast<std::ostream&>(out));
  write_bytes(t, out.str());
  return t;
}

/// Keep the command line (shell-quoted) and the start time for the provenance attributes.
void record_invocation(int argc, const char* const* argv);

struct Provenance {
  std::string program_version;  ///< git describe --always --dirty at build time, or "unknown"
  std::string command_line;     ///< argv, shell-quoted (empty unless record_invocation was called)
  std::string date;             ///< start of the run, ISO 8601 UTC, e.g. 2025-01-31T12:00:00Z
  std::string command;          ///< the subcommand (the first argument not an option), e.g. "noise"
};
const Provenance& provenance();

/// The command that wrote the rollnoise result `path` (its root attribute `command`, or for files
/// written before that attribute the second word of `command_line`); nullopt when `path` is not an
/// HDF5 file holding either.
std::optional<std::string> recorded_command(const std::string& path);

/// `args` joined by spaces, each quoted for a POSIX shell where needed ('...' with ' as '\'').
std::string shell_quote(const std::vector<std::string>& args);

}  // namespace rollnoise::io
