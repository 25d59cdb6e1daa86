#include "dynamics/parameter_file.hpp"
#include "core/text.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::dynamics {
namespace {

bool valid_key(const std::string& k) {
  if (k.empty()) return false;
  for (char c : k)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  return true;
}

}  // namespace

ParameterFile ParameterFile::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open parameter file '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path);
}

ParameterFile ParameterFile::parse(const std::string& text, const std::string& origin) {
  ParameterFile p;
  p.origin_ = origin;
  std::istringstream in(text);
  std::string raw, section;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string where = origin + ":" + std::to_string(line_no);
    std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']' || !valid_key(trim(line.substr(1, line.size() - 2))))
        throw InputError(where, where + ": malformed section header '" + line + "'");
      section = trim(line.substr(1, line.size() - 2));
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw InputError(where, where + ": expected 'key = number', got '" + line + "'");
    const std::string key = trim(line.substr(0, eq));
    const std::string value = trim(line.substr(eq + 1));
    if (!valid_key(key)) throw InputError(where, where + ": invalid key '" + key + "'");
    const std::string full = section.empty() ? key : section + "." + key;
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != value.size() || !std::isfinite(v))
      throw InputError(where + ":" + full,
                       where + ": key '" + full + "' needs a finite number, got '" + value + "'");
    if (!p.values_.emplace(full, v).second)
      throw InputError(where + ":" + full, where + ": key '" + full + "' is given twice");
  }
  return p;
}

double ParameterFile::get(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end())
    throw InputError(origin_ + ":" + key, origin_ + ": missing parameter '" + key + "'");
  return it->second;
}

double ParameterFile::get_or(const std::string& key, double fallback) const {
  const auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

double ParameterFile::positive(const std::string& key, bool allow_zero) const {
  const double v = get(key);
  if (allow_zero ? !(v >= 0.0) : !(v > 0.0))
    throw InputError(origin_ + ":" + key, origin_ + ": parameter '" + key + "' must be " +
                                              (allow_zero ? "non-negative" : "positive") +
                                              ", got " + std::to_string(v));
  return v;
}

}  // namespace rollnoise::dynamics
