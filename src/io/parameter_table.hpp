// Numeric model-parameter files (models/track/*.toml, models/wheel/*.toml) read with toml++.
//
// A parameter file is TOML whose every value is a finite number (integer or float; a boolean only
// where a flag is read):
//
//   # comment                     (also after a value)
//   [section]                     (keys below become "section.key")
//   key = 1.25e9                  (SI units stated in the comment)
//
// Errors are InputErrors that name the file, the line and the dotted key: malformed TOML
// ("<file>:<line>[:<key>]"), a value that is not a finite number ("<file>:<line>:<key>"), a missing
// parameter ("<file>:<key>"), a value out of range and a key the reader does not know
// ("<file>:<line>:<key>"; unknown keys are errors, as in case files).
#pragma once

#include <map>
#include <set>
#include <string>

namespace rollnoise::io {

class ParameterTable {
 public:
  /// Reads `path`. InputError (key: the path) if it cannot be opened.
  static ParameterTable read(const std::string& path);

  /// Parses text already in memory; `origin` names it in messages.
  static ParameterTable parse(const std::string& text, const std::string& origin);

  /// The value of dotted `key`; InputError("<origin>:<key>", ...) when it is missing.
  double get(const std::string& key) const;

  /// The value of `key`, or `fallback` when the file does not set it.
  double get_or(const std::string& key, double fallback) const;

  /// Like get(), and the value must be > 0 (or >= 0 with allow_zero).
  double positive(const std::string& key, bool allow_zero = false) const;

  /// A flag: a boolean, or a number (any non-zero number is true); `fallback` when not set.
  bool flag_or(const std::string& key, bool fallback) const;

  /// InputError for the first key of the file that none of the calls above asked for.
  void reject_unread_keys() const;

  const std::string& origin() const { return origin_; }

 private:
  struct Entry {
    double value = 0.0;
    bool boolean = false;  ///< given as true/false (value 1/0)
    int line = 0;
  };
  const Entry* find(const std::string& key) const;
  std::string where(const std::string& key) const;  ///< "<origin>:<line>"

  std::string origin_;
  std::map<std::string, Entry> values_;
  mutable std::set<std::string> read_;
};

}  // namespace rollnoise::io
