#include "io/parameter_table.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "io/input_file.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {
namespace {

bool bare_key(const std::string& k) {
  if (k.empty()) return false;
  for (char c : k)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  return true;
}

// The dotted key that line `line_no` (1-based) of `text` sets, or "" when the line has none: used
// only to name the key in a TOML syntax error (the parser stops there).
std::string key_on_line(const std::string& text, int line_no) {
  std::istringstream in(text);
  std::string raw, section;
  for (int n = 1; std::getline(in, raw); ++n) {
    const std::string t = trim(raw.substr(0, raw.find('#')));
    if (n == line_no) {
      const auto eq = t.find('=');
      if (t.empty() || t.front() == '[' || eq == std::string::npos) return "";
      const std::string k = trim(t.substr(0, eq));
      if (!bare_key(k)) return "";
      return section.empty() ? k : section + "." + k;
    }
    if (!t.empty() && t.front() == '[' && t.back() == ']')
      section = trim(t.substr(1, t.size() - 2));
  }
  return "";
}

struct Leaf {
  std::string key;
  const toml::node* node;
  int line;
};

void flatten(const toml::table& t, const std::string& prefix, std::vector<Leaf>& out) {
  for (const auto& [k, v] : t) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table())
      flatten(*sub, key, out);
    else
      out.push_back({key, &v, static_cast<int>(v.source().begin.line)});
  }
}

std::string describe_entry(const toml::node& n) {
  std::ostringstream os;
  if (n.is_string())
    os << '"' << n.as_string()->get() << '"';
  else if (n.is_array())
    os << toml::toml_formatter(*n.as_array());
  else if (n.is_number())
    os << n.value<double>().value_or(0.0);
  else
    os << "(" << n.type() << ")";
  return os.str();
}

}  // namespace

ParameterTable ParameterTable::read(const std::string& path) {
  return parse(read_input(path, path, "the parameter file"), path);
}

ParameterTable ParameterTable::parse(const std::string& text, const std::string& origin) {
  toml::table doc;
  try {
    doc = toml::parse(std::string_view(text), std::string_view(origin));
  } catch (const toml::parse_error& e) {
    const int line = static_cast<int>(e.source().begin.line);
    const std::string where = origin + ":" + std::to_string(line);
    const std::string key = key_on_line(text, line);
    std::ostringstream msg;
    msg << where << ":" << e.source().begin.column << ": malformed TOML (" << e.description()
        << "); a parameter file holds 'key = number' lines, each a finite number";
    throw InputError(key.empty() ? where : where + ":" + key, msg.str());
  }
  std::vector<Leaf> leaves;
  flatten(doc, "", leaves);
  std::stable_sort(leaves.begin(), leaves.end(),
                   [](const Leaf& a, const Leaf& b) { return a.line < b.line; });
  ParameterTable p;
  p.origin_ = origin;
  for (const Leaf& l : leaves) {
    Entry e;
    e.line = l.line;
    if (const auto* b = l.node->as_boolean()) {
      e.boolean = true;
      e.value = b->get() ? 1.0 : 0.0;
    } else if (const auto* i = l.node->as_integer()) {
      e.value = static_cast<double>(i->get());
    } else if (const auto* f = l.node->as_floating_point()) {
      e.value = f->get();
    } else {
      e.value = std::nan("");
    }
    if (!std::isfinite(e.value)) {
      const std::string where = origin + ":" + std::to_string(l.line);
      throw InputError(
          where + ":" + l.key,
          where + ": key '" + l.key + "' needs a finite number, got " + describe_entry(*l.node));
    }
    p.values_.emplace(l.key, e);
  }
  return p;
}

const ParameterTable::Entry* ParameterTable::find(const std::string& key) const {
  read_.insert(key);
  const auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

std::string ParameterTable::where(const std::string& key) const {
  const auto it = values_.find(key);
  return origin_ + ":" + std::to_string(it == values_.end() ? 0 : it->second.line);
}

double ParameterTable::get(const std::string& key) const {
  const Entry* e = find(key);
  if (!e) throw InputError(origin_ + ":" + key, origin_ + ": missing parameter '" + key + "'");
  if (e->boolean)
    throw InputError(where(key) + ":" + key, where(key) + ": key '" + key +
                                                 "' needs a finite number, got " +
                                                 (e->value != 0.0 ? "true" : "false"));
  return e->value;
}

double ParameterTable::get_or(const std::string& key, double fallback) const {
  return find(key) ? get(key) : fallback;
}

double ParameterTable::positive(const std::string& key, bool allow_zero) const {
  const double v = get(key);
  if (allow_zero ? !(v >= 0.0) : !(v > 0.0))
    throw InputError(where(key) + ":" + key, where(key) + ": parameter '" + key + "' must be " +
                                                 (allow_zero ? "non-negative" : "positive") +
                                                 ", got " + std::to_string(v));
  return v;
}

bool ParameterTable::flag_or(const std::string& key, bool fallback) const {
  const Entry* e = find(key);
  return e ? e->value != 0.0 : fallback;
}

void ParameterTable::reject_unread_keys() const {
  const std::pair<const std::string, Entry>* first = nullptr;
  for (const auto& kv : values_)
    if (!read_.count(kv.first) && (!first || kv.second.line < first->second.line)) first = &kv;
  if (!first) return;
  // Name the parameters of the same section (a typo is most likely one of them).
  const std::string& key = first->first;
  const auto dot = key.rfind('.');
  const std::string section = dot == std::string::npos ? "" : key.substr(0, dot + 1);
  std::string known;
  for (const std::string& k : read_)
    if (k.compare(0, section.size(), section) == 0 &&
        k.find('.', section.size()) == std::string::npos)
      known += (known.empty() ? "" : ", ") + k;
  throw InputError(where(key) + ":" + key,
                   where(key) + ": unknown parameter '" + key + "'" +
                       (known.empty() ? std::string() : " (known here: " + known + ")"));
}

}  // namespace rollnoise::io
