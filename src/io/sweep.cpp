#include "io/sweep.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/errors.hpp"
#include "io/case_schema.hpp"
#include "pipeline/limits.hpp"
#include "pipeline/steady_sweep.hpp"

namespace rollnoise::io {
namespace {

[[noreturn]] void bad(const std::string& arg, const std::string& why) {
  throw InputError("--sweep", "--sweep '" + arg + "': " + why);
}

// A whole token as a decimal integer (digits only, no sign, exponent or trailing text); false if
// it is not one or does not fit a long.
bool whole_integer(const std::string& s, long& out) {
  if (s.empty() || s.size() > 18) return false;
  for (char ch : s)
    if (ch < '0' || ch > '9') return false;
  out = std::stol(s);
  return true;
}

// A whole token as a finite real number.
bool whole_real(const std::string& s, double& out) {
  if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno == 0 && std::isfinite(out);
}

}  // namespace

SweepSpec parse_sweep(const std::string& arg) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    bad(arg, "expected KEY=lo:hi:n, KEY[i]=lo:hi:n or KEY=[v1, v2, ...]");
  SweepSpec s;
  s.key = arg.substr(0, eq);
  const std::string rhs = arg.substr(eq + 1);
  if (const auto br = s.key.find('['); br != std::string::npos) {
    const std::string index = s.key.substr(br + 1);
    s.key = s.key.substr(0, br);
    long i = 0;
    if (index.empty() || index.back() != ']' ||
        !whole_integer(index.substr(0, index.size() - 1), i))
      bad(arg, "the component of " + s.key + "[i] must be a non-negative integer index");
    const KeySpec* spec = find_key(s.key);
    if (spec && spec->type != KeyType::Real3)
      bad(arg, s.key + " is not an array of three numbers: no [i]");
    if (i > 2)
      bad(arg, "component index " + std::to_string(i) + " of " + s.key + " must be 0, 1 or 2");
    s.component = static_cast<int>(i);
  }
  if (!find_key(s.key)) bad(arg, "unknown key " + s.key + " (see 'rollnoise keys')");
  if (!rhs.empty() && rhs.front() == '[') {
    if (s.component >= 0) bad(arg, "KEY[i] takes lo:hi:n, not a list");
    s.list = split_toml_array(rhs, "--sweep " + s.key);
    return s;
  }
  const auto c1 = rhs.find(':'), c2 = c1 == std::string::npos ? c1 : rhs.find(':', c1 + 1);
  if (c2 == std::string::npos || rhs.find(':', c2 + 1) != std::string::npos)
    bad(arg, "expected lo:hi:n or a TOML array after '='");
  if (!whole_real(rhs.substr(0, c1), s.lo))
    bad(arg, "lo '" + rhs.substr(0, c1) + "' is not a finite number");
  if (!whole_real(rhs.substr(c1 + 1, c2 - c1 - 1), s.hi))
    bad(arg, "hi '" + rhs.substr(c1 + 1, c2 - c1 - 1) + "' is not a finite number");
  const std::string n = rhs.substr(c2 + 1);
  if (!whole_integer(n, s.n) || s.n < 1)
    bad(arg, "the number of points n = '" + n + "' must be a positive integer (decimal digits)");
  return s;
}

std::vector<std::string> expand_sweep(const std::string& arg, const CaseReader& base,
                                      const pipeline::ContactCase& c, std::vector<double>& values) {
  const SweepSpec s = parse_sweep(arg);
  const double count = s.list.empty() ? double(s.n) : double(s.list.size());
  try {
    pipeline::check_size(c.limits, "--sweep", count, "sweep points",
                         pipeline::sweep_bytes(c, count));
  } catch (const InputError& e) {
    bad(arg, e.what());
  }
  std::vector<std::string> out;
  if (!s.list.empty()) {
    for (const auto& v : s.list) {
      values.push_back(double(out.size()));
      out.push_back(s.key + "=" + v);
    }
    return out;
  }
  std::array<double, 3> arr{};
  if (s.component >= 0) arr = base.real3(s.key);
  for (const double v : pipeline::linear_points(s.lo, s.hi, s.n)) {
    values.push_back(v);
    std::ostringstream val;
    val.precision(17);
    if (s.component >= 0) {
      arr[s.component] = v;
      val << "[" << arr[0] << ", " << arr[1] << ", " << arr[2] << "]";
    } else {
      val << v;
    }
    out.push_back(s.key + "=" + val.str());
  }
  return out;
}

}  // namespace rollnoise::io
