// A minimal reader for the model parameter files in models/track and models/wheel.
//
// The numerics layers must not depend on a TOML library, so the parameter files use the trivial
// subset of TOML that this reader understands:
//
//   # comment                     (also after a value)
//   [section]                     (keys below become "section.key")
//   key = 1.25e9                  (one number per key, SI units stated in the comment)
//
// Anything else (strings, arrays, inline tables, a key given twice) is an InputError that names the
// file, the line and the key. A full TOML parser (the io layer) reads the same files unchanged.
#pragma once

#include <map>
#include <string>

namespace rollnoise::dynamics {

class ParameterFile {
 public:
  /// Reads `path`. Throws InputError(path:line, ...) on a malformed line.
  static ParameterFile read(const std::string& path);

  /// Parses text already in memory; `origin` names it in messages.
  static ParameterFile parse(const std::string& text, const std::string& origin);

  /// The value of dotted `key`; InputError("<origin>:<key>", ...) when it is missing.
  double get(const std::string& key) const;

  /// The value of `key`, or `fallback` when the file does not set it.
  double get_or(const std::string& key, double fallback) const;

  /// Like get(), and the value must be > 0 (or >= 0 with allow_zero).
  double positive(const std::string& key, bool allow_zero = false) const;

  bool has(const std::string& key) const { return values_.count(key) != 0; }
  const std::string& origin() const { return origin_; }
  const std::map<std::string, double>& values() const { return values_; }

 private:
  std::string origin_;
  std::map<std::string, double> values_;
};

}  // namespace rollnoise::dynamics
