// Reading case files (TOML) against the declared schema (case_schema.hpp).
//
// Every value is checked when it is read: its type, finiteness, sign and allowed values; every
// error names the file and the dotted key. `--set key=value` overrides are merged before reading,
// and toml_text() gives the case as run (stored in the output as /case).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace rollnoise::io {

class CaseReader {
 public:
  /// Parse `path` and apply `overrides` ("key=value", value in TOML syntax or a bare string).
  /// Unknown keys, malformed TOML and malformed overrides throw InputError.
  static CaseReader from_file(const std::string& path, const std::vector<std::string>& overrides = {});
  static CaseReader from_string(const std::string& toml, const std::string& name,
                                const std::vector<std::string>& overrides = {});
  CaseReader(const CaseReader&);
  CaseReader& operator=(const CaseReader&);
  ~CaseReader();

  /// Case name: the file name without folder and extension.
  const std::string& name() const { return name_; }
  /// The file the case came from (for messages).
  const std::string& source() const { return source_; }
  /// The folder of the case file (relative file keys are resolved against it).
  std::string folder() const;
  /// The case as run, after overrides, as TOML text.
  std::string toml_text() const;

  /// A copy with one more override applied (used by sweeps).
  CaseReader with(const std::string& override_kv) const;

  bool has(const std::string& key) const;
  double real(const std::string& key) const;
  long integer(const std::string& key) const;
  std::string string(const std::string& key) const;
  std::array<double, 3> real3(const std::string& key) const;
  std::vector<double> real_list(const std::string& key) const;
  /// An array of strings, each one of the key's allowed values (when it has any).
  std::vector<std::string> string_list(const std::string& key) const;

  /// An array of tables ([[key]] entries, or key = [{...}, ...]): each entry's numbers by field.
  /// Fails naming key[i].field for a field not in `fields` or a value that is not a finite number;
  /// empty when the key is absent.
  std::vector<std::map<std::string, double>> table_list(const std::string& key,
                                                        const std::vector<std::string>& fields) const;

  /// Throw InputError for `key` with the file name in front of `message`.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  CaseReader() = default;
  /// Applies KEY=VALUE; returns KEY.
  std::string apply_override(const std::string& kv);
  void check_keys() const;
  struct Doc;
  std::unique_ptr<Doc> doc_;
  std::string name_, source_;
  /// The keys the user's --set gave (from_file, from_string): their errors name the --set.
  std::vector<std::string> set_keys_;
};

/// Run a stage of the pipeline on the case read by `r`: an InputError it throws (naming a case
/// key, without the file) is thrown again with the case file in front, as r.fail does.
template <class Stage>
auto within_case(const CaseReader& r, Stage&& stage) {
  try {
    return stage();
  } catch (const InputError& e) {
    r.fail(e.key(), e.what());
  }
}

/// One line per key of the case (given in the file or by --set) whose value lies outside the key's
/// physical range (KeySpec::warn_min, warn_max): "warning: friction.mu = 5 is outside the physical
/// range [0, 1] (why); the run continues". A value that is invalid is left to its reader's error.
std::vector<std::string> physical_range_warnings(const CaseReader& r);

/// Resolve a model file: as given if absolute, else relative to the case file's folder, its
/// parent, or the source tree (in that order). InputError naming `key` if none exists.
std::string resolve_model_file(const CaseReader& r, const std::string& key);
/// The file resolve_model_file would return, or "" if there is none (no error).
std::string find_model_file(const CaseReader& r, const std::string& key);

/// The elements of a TOML array given as text ("[1, 2]" or "[[0,0,0],[1,0,0]]"), each as TOML text.
/// `what` names the option in error messages.
std::vector<std::string> split_toml_array(const std::string& text, const std::string& what);

}  // namespace rollnoise::io
