#include "io/case_reader.hpp"

#include "core/edit_distance.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "core/errors.hpp"

#ifndef ROLLNOISE_SOURCE_DIR
#define ROLLNOISE_SOURCE_DIR "."
#endif
#include "io/case_schema.hpp"
#include "io/input_file.hpp"

namespace rollnoise::io {

struct CaseReader::Doc {
  toml::table table;
};

namespace {

// "; did you mean 'KEY'?" for an unknown key near a declared one (a typing slip), else "".
std::string key_suggestion(const std::string& key) {
  std::vector<std::string> keys;
  for (const KeySpec& k : case_schema()) keys.push_back(k.key);
  const std::string best = nearest_word(key, keys);
  return best.empty() ? std::string() : "; did you mean '" + best + "'?";
}

}  // namespace

namespace {

// The node at a dotted key, or nullptr.
const toml::node* node_at(const toml::table& t, const std::string& key) {
  return t.at_path(key).node();
}

// The declared default of `key`, parsed, or nullptr if there is none.
std::shared_ptr<toml::table> default_table(const KeySpec& spec) {
  if (spec.default_value.empty()) return nullptr;
  return std::make_shared<toml::table>(toml::parse("v = " + spec.default_value));
}

// Flatten a table into dotted keys of its leaves (arrays are leaves).
void flatten(const toml::table& t, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [k, v] : t) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table())
      flatten(*sub, key, out);
    else
      out.push_back(key);
  }
}

std::string describe(const toml::node& n) {
  std::ostringstream os;
  if (n.is_array())
    os << toml::toml_formatter(*n.as_array());
  else if (n.is_string())
    os << '"' << n.as_string()->get() << '"';
  else
    n.visit([&](auto&& v) {
      if constexpr (toml::is_number<decltype(v)> || toml::is_boolean<decltype(v)>) os << v.get();
      else os << "(" << n.type() << ")";
    });
  return os.str();
}

}  // namespace

CaseReader::CaseReader(const CaseReader& o)
    : doc_(std::make_unique<Doc>(*o.doc_)), name_(o.name_), source_(o.source_), set_keys_(o.set_keys_) {}
CaseReader& CaseReader::operator=(const CaseReader& o) {
  doc_ = std::make_unique<Doc>(*o.doc_);
  name_ = o.name_;
  source_ = o.source_;
  set_keys_ = o.set_keys_;
  return *this;
}
CaseReader::~CaseReader() = default;

CaseReader CaseReader::from_string(const std::string& text, const std::string& name,
                                   const std::vector<std::string>& overrides) {
  CaseReader r;
  r.doc_ = std::make_unique<Doc>();
  r.source_ = name;
  r.name_ = std::filesystem::path(name).stem().string();
  try {
    r.doc_->table = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << name << ":" << e.source().begin.line << ":" << e.source().begin.column
        << ": malformed TOML: " << e.description();
    throw InputError("(syntax)", msg.str());
  }
  for (const auto& kv : overrides) r.set_keys_.push_back(r.apply_override(kv));
  r.check_keys();
  return r;
}

CaseReader CaseReader::from_file(const std::string& path,
                                 const std::vector<std::string>& overrides) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw InputError("(file)", path + ": no such case file");
  if (fs::is_directory(st)) throw InputError("(file)", path + ": is a directory, not a case file (TOML)");
  // read once (a pipe or <(...) can be read only once; the run and the check of its files share it)
  return from_string(read_input(path, "(file)", "the case file"), path, overrides);
}

std::string CaseReader::folder() const {
  return std::filesystem::path(source_).parent_path().string();
}

std::string CaseReader::toml_text() const {
  std::ostringstream os;
  os << toml::toml_formatter(doc_->table);
  return os.str();
}

CaseReader CaseReader::with(const std::string& kv) const {
  CaseReader r(*this);
  r.apply_override(kv);
  r.check_keys();
  return r;
}

std::string CaseReader::apply_override(const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set", "override '" + kv + "' is not of the form key=value");
  std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
  while (!key.empty() && key.back() == ' ') key.pop_back();
  if (!find_key(key))
    throw InputError(key, "--set " + key + ": unknown key" + key_suggestion(key) + " (see 'rollnoise keys')");
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    parsed = toml::table{{"v", value}};  // a bare word is a string
  }
  // walk/create the tables of the dotted path and assign the leaf
  toml::table* t = &doc_->table;
  std::stringstream path(key);
  std::string part, next;
  std::getline(path, part, '.');
  while (std::getline(path, next, '.')) {
    auto* sub = (*t)[part].as_table();
    if (!sub) {
      t->insert_or_assign(part, toml::table{});
      sub = (*t)[part].as_table();
    }
    t = sub;
    part = next;
  }
  t->insert_or_assign(part, *parsed.get("v"));
  return key;
}

void CaseReader::check_keys() const {
  std::vector<std::string> keys;
  flatten(doc_->table, "", keys);
  for (const auto& k : keys)
    if (!find_key(k))
      fail(k, "unknown key" + key_suggestion(k) + " (see 'rollnoise keys' for the declared ones)");
}

[[noreturn]] void CaseReader::fail(const std::string& key, const std::string& message) const {
  // a value the user's --set gave is named as that --set, not as the case file's
  if (std::find(set_keys_.begin(), set_keys_.end(), key) != set_keys_.end())
    throw InputError(key, "--set " + key + ": " + message);
  throw InputError(key, source_ + ": " + key + ": " + message);
}

bool CaseReader::has(const std::string& key) const { return node_at(doc_->table, key) != nullptr; }

namespace {

struct Value {
  const toml::node* node = nullptr;
  std::shared_ptr<toml::table> keep;  // owns a parsed default
};

}  // namespace

// Look up a value or its declared default; fail if neither exists.
static Value lookup(const CaseReader& r, const toml::table& t, const std::string& key) {
  const KeySpec* spec = find_key(key);
  if (!spec) r.fail(key, "internal: key not declared in the schema");
  Value v;
  v.node = node_at(t, key);
  if (!v.node) {
    v.keep = default_table(*spec);
    if (!v.keep) r.fail(key, "required but missing");
    v.node = v.keep->get("v");
  }
  return v;
}

double CaseReader::real(const std::string& key) const {
  const Value v = lookup(*this, doc_->table, key);
  const auto x = v.node->value<double>();
  if (!x || !(v.node->is_number())) fail(key, "expected a number, got " + describe(*v.node));
  if (!std::isfinite(*x)) fail(key, "must be finite, got " + describe(*v.node));
  const KeySpec& spec = *find_key(key);
  if (spec.type == KeyType::PositiveReal && !(*x > 0.0))
    fail(key, "must be positive, got " + describe(*v.node));
  if (spec.type == KeyType::NonNegReal && !(*x >= 0.0))
    fail(key, "must not be negative, got " + describe(*v.node));
  return *x;
}

long CaseReader::integer(const std::string& key) const {
  const Value v = lookup(*this, doc_->table, key);
  // TOML integers are 64-bit (toml++ int64_t): read whole, then range-checked into the target
  const KeySpec& spec = *find_key(key);
  const std::string range =
      "must be an integer between " + std::to_string(spec.minimum) + " and " + std::to_string(spec.maximum);
  if (!v.node->is_integer()) fail(key, range + ", got " + describe(*v.node));
  const std::int64_t x = v.node->as_integer()->get();
  if (x < spec.minimum || x > spec.maximum) fail(key, range + ", got " + std::to_string(x));
  return static_cast<long>(x);
}

std::string CaseReader::string(const std::string& key) const {
  const Value v = lookup(*this, doc_->table, key);
  if (!v.node->is_string()) fail(key, "expected a string, got " + describe(*v.node));
  const std::string s = v.node->as_string()->get();
  const KeySpec& spec = *find_key(key);
  if (!spec.allowed.empty() &&
      std::find(spec.allowed.begin(), spec.allowed.end(), s) == spec.allowed.end()) {
    std::string list;
    for (const auto& a : spec.allowed) list += " \"" + a + "\"";
    fail(key, "\"" + s + "\" is not one of" + list);
  }
  return s;
}

std::vector<double> CaseReader::real_list(const std::string& key) const {
  const Value v = lookup(*this, doc_->table, key);
  const auto* arr = v.node->as_array();
  if (!arr) fail(key, "expected an array of numbers, got " + describe(*v.node));
  std::vector<double> out;
  for (size_t i = 0; i < arr->size(); ++i) {
    const auto x = (*arr)[i].value<double>();
    if (!x || !(*arr)[i].is_number())
      fail(key, "element " + std::to_string(i) + " is not a number");
    if (!std::isfinite(*x))
      fail(key, "element " + std::to_string(i) + " must be finite, got " + describe((*arr)[i]));
    out.push_back(*x);
  }
  return out;
}

std::vector<std::string> CaseReader::string_list(const std::string& key) const {
  const Value v = lookup(*this, doc_->table, key);
  const auto* arr = v.node->as_array();
  if (!arr) fail(key, "expected an array of strings, got " + describe(*v.node));
  const KeySpec& spec = *find_key(key);
  std::vector<std::string> out;
  for (size_t i = 0; i < arr->size(); ++i) {
    if (!(*arr)[i].is_string()) fail(key, "element " + std::to_string(i) + " is not a string");
    out.push_back((*arr)[i].as_string()->get());
    if (!spec.allowed.empty() &&
        std::find(spec.allowed.begin(), spec.allowed.end(), out.back()) == spec.allowed.end()) {
      std::string list;
      for (const auto& a : spec.allowed) list += " \"" + a + "\"";
      fail(key, "element \"" + out.back() + "\" is not one of" + list);
    }
  }
  return out;
}

std::vector<std::map<std::string, double>> CaseReader::table_list(const std::string& key,
                                                                  const std::vector<std::string>& fields) const {
  std::vector<std::map<std::string, double>> out;
  const toml::node* n = node_at(doc_->table, key);
  if (!n) return out;
  const auto* arr = n->as_array();
  if (!arr) fail(key, "expected [[" + key + "]] entries (an array of tables), got " + describe(*n));
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const std::string at = key + "[" + std::to_string(i) + "]";
    const auto* t = (*arr)[i].as_table();
    if (!t) fail(key, at + " is not a table");
    std::map<std::string, double> entry;
    for (const auto& [k, v] : *t) {
      const std::string field(k.str());
      if (std::find(fields.begin(), fields.end(), field) == fields.end())
        fail(key, at + "." + field + ": unknown key (see 'rollnoise keys')");
      const auto x = v.value<double>();
      if (!x || !v.is_number() || !std::isfinite(*x))
        fail(key, at + "." + field + ": expected a finite number, got " + describe(v));
      entry[field] = *x;
    }
    out.push_back(entry);
  }
  return out;
}

std::array<double, 3> CaseReader::real3(const std::string& key) const {
  const auto v = real_list(key);
  if (v.size() != 3)
    fail(key, "expected three numbers, got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

std::vector<std::string> split_toml_array(const std::string& text, const std::string& what) {
  toml::table t;
  try {
    t = toml::parse("v = " + text);
  } catch (const toml::parse_error& e) {
    throw InputError(what, what + ": malformed TOML array: " + std::string(e.description()));
  }
  const auto* arr = t.get_as<toml::array>("v");
  if (!arr || arr->empty()) throw InputError(what, what + ": expected a non-empty TOML array");
  std::vector<std::string> out;
  for (const auto& el : *arr) {
    toml::table one{{"v", el}};
    std::ostringstream os;
    os << toml::toml_formatter(one);
    std::string line = os.str();  // "v = <value>"
    out.push_back(line.substr(line.find('=') + 2));
  }
  return out;
}

std::vector<std::string> physical_range_warnings(const CaseReader& r) {
  std::vector<std::string> lines;
  for (const KeySpec& k : case_schema()) {
    if (k.warn_why.empty() || !r.has(k.key)) continue;
    double x = 0.0;
    try {
      x = r.real(k.key);
    } catch (const InputError&) {
      continue;  // an invalid value: its reader reports it
    }
    if (x >= k.warn_min && x <= k.warn_max) continue;
    std::ostringstream os;
    os << "warning: " << k.key << " = " << x << (k.units == "-" ? "" : " " + k.units)
       << " is outside the physical range [" << k.warn_min << ", " << k.warn_max << "] (" << k.warn_why
       << "); the run continues";
    lines.push_back(os.str());
  }
  return lines;
}

namespace fs = std::filesystem;

std::string find_model_file(const CaseReader& r, const std::string& key) {
  const fs::path given = r.string(key);
  std::error_code ec;  // a symbolic-link loop or an unreadable folder: not found here
  if (given.is_absolute()) return fs::exists(given, ec) ? given.string() : std::string();
  const fs::path folder = r.folder().empty() ? fs::path(".") : fs::path(r.folder());
  for (const fs::path& base : {folder, folder / "..", fs::path(ROLLNOISE_SOURCE_DIR)})
    if (fs::exists(base / given, ec)) return (base / given).lexically_normal().string();
  return {};
}

std::string resolve_model_file(const CaseReader& r, const std::string& key) {
  const std::string found = find_model_file(r, key);
  if (!found.empty()) {
    // read it now, once and bounded, so that a folder, a device or a huge file is refused naming the key
    try {
      read_input(found, key, "the file of " + key);
    } catch (const InputError& e) {
      r.fail(key, e.what());
    }
    return found;
  }
  const fs::path given = r.string(key);
  std::error_code ec;
  if (given.is_absolute() && !fs::exists(given, ec) && ec && ec != std::errc::no_such_file_or_directory)
    r.fail(key, "file " + given.string() + " cannot be opened: " + ec.message());
  if (given.is_absolute()) r.fail(key, "file " + given.string() + " does not exist");
  r.fail(key, "file " + given.string() + " found neither beside the case file, in its parent folder, "
              "nor in the source tree");
}

}  // namespace rollnoise::io
