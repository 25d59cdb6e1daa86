// The declared case-file schema: every key a case file may hold, with its type, default, allowed
// values, units and help text (in the spirit of deal.II's ParameterHandler). `rollnoise keys` prints
// it; the reader rejects any key not declared here, naming it.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace rollnoise::io {

enum class KeyType {
  Real,          ///< finite real number
  PositiveReal,  ///< finite, > 0
  NonNegReal,    ///< finite, >= 0
  Integer,       ///< integer in [minimum, maximum] (read as 64 bits, then range-checked)
  String,        ///< one of `allowed` (any string if empty)
  Real3,         ///< array of three finite reals
  RealList,      ///< array of finite reals
  StringList,    ///< array of strings
  TableList,     ///< array of tables ([[key]] entries; CaseReader::table_list)
};

struct KeySpec {
  std::string key;            ///< dotted TOML key, e.g. "grid.nx"
  KeyType type;
  std::string default_value;  ///< TOML text of the default; empty: see `absent`
  std::string units;
  std::string help;
  std::vector<std::string> allowed = {};
  long minimum = 0;           ///< for Integer
  /// Keys without a default: "required" (and where), or "optional: " and what happens without it.
  std::string absent = {};
  long maximum = std::numeric_limits<int>::max();  ///< for Integer: the target's range (int by default)
  /// The physical range of a real key: a value outside [warn_min, warn_max] is accepted (it is
  /// valid for the model) with a warning (physical_range_warnings, case_reader.hpp); why: warn_why.
  double warn_min = -std::numeric_limits<double>::infinity();
  double warn_max = std::numeric_limits<double>::infinity();
  std::string warn_why = {};
};

/// All declared keys, in the order they are documented.
const std::vector<KeySpec>& case_schema();
/// The spec of `key`, or nullptr if the key is not declared.
const KeySpec* find_key(const std::string& key);
/// Human-readable listing of the schema (for `rollnoise keys`): one block per table ([material],
/// [contact], ...) in the order of first appearance, each key with its default, or "required ..."
/// or "optional: ..." for keys without one, units, help and allowed values.
std::string describe_schema();

}  // namespace rollnoise::io
