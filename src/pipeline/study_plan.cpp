#include "pipeline/study_plan.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "core/errors.hpp"

namespace rollnoise::pipeline {

std::vector<double> linear_range(double from, double to, long count) {
  std::vector<double> v(static_cast<std::size_t>(count));
  for (long i = 0; i < count; ++i) v[i] = count == 1 ? from : from + (to - from) * double(i) / double(count - 1);
  if (count > 1) v.back() = to;  // exactly the given end
  return v;
}

std::vector<double> log_range(double from, double to, long count) {
  std::vector<double> v(static_cast<std::size_t>(count));
  const double l0 = std::log(from), l1 = std::log(to);
  for (long i = 0; i < count; ++i) v[i] = count == 1 ? from : std::exp(l0 + (l1 - l0) * double(i) / double(count - 1));
  if (count > 0) v.front() = from;
  if (count > 1) v.back() = to;
  return v;
}

AxisValue number_value(double v) {
  // the shortest of 15, 16, 17 significant digits that reads back to v (0.2, not 0.20000000000000001)
  char buf[64];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // a float for TOML, not an integer
  return {s, v};
}

std::vector<StudyCase> expand(const StudyPlan& plan, std::size_t max_cases) {
  if (plan.axes.empty()) throw InputError("axes", "the study has no axes");
  for (const Axis& a : plan.axes)
    if (a.values.empty()) throw InputError("axes." + a.key, "an axis needs at least one value");
  std::size_t n = 1;
  if (plan.combine == Combine::kZip) {
    n = plan.axes.front().values.size();
    for (const Axis& a : plan.axes)
      if (a.values.size() != n)
        throw InputError("axes." + a.key, "combine = \"zip\" needs axes of one length: " + std::to_string(a.values.size()) +
                                              " values, the first axis has " + std::to_string(n));
  } else {
    for (const Axis& a : plan.axes) {
      if (n > max_cases / a.values.size())
        throw InputError("axes", "the study has more than " + std::to_string(max_cases) + " cases");
      n *= a.values.size();
    }
  }
  if (n > max_cases) throw InputError("axes", "the study has more than " + std::to_string(max_cases) + " cases");

  std::vector<StudyCase> cases(n);
  for (std::size_t k = 0; k < n; ++k) {
    cases[k].index = k;
    cases[k].values.resize(plan.axes.size());
    // product: k written in the mixed radix of the axis lengths, the last axis the lowest digit
    std::size_t rest = k;
    for (std::size_t a = plan.axes.size(); a-- > 0;) {
      const auto& values = plan.axes[a].values;
      const std::size_t i = plan.combine == Combine::kZip ? k : rest % values.size();
      rest /= values.size();
      cases[k].values[a] = values[i];
    }
  }
  return cases;
}

std::vector<std::string> overrides(const StudyPlan& plan, const StudyCase& c) {
  std::vector<std::string> o;
  for (std::size_t a = 0; a < plan.axes.size(); ++a) o.push_back(plan.axes[a].key + "=" + c.values[a].toml);
  return o;
}

namespace {

// A whole decimal integer in [lo, hi]; false for anything else ("3x", "", "1e1", overflow).
bool parse_integer(const std::string& s, long lo, long hi, long& out) {
  if (s.empty() || s.size() > 18) return false;
  for (char ch : s)
    if (ch < '0' || ch > '9') return false;
  errno = 0;
  const long v = std::strtol(s.c_str(), nullptr, 10);
  if (errno != 0 || v < lo || v > hi) return false;
  out = v;
  return true;
}

}  // namespace

Shard parse_shard(const std::string& text, const std::string& what) {
  const auto slash = text.find('/');
  Shard s;
  const long max = 1000000;
  if (slash == std::string::npos || !parse_integer(text.substr(0, slash), 1, max, s.index) ||
      !parse_integer(text.substr(slash + 1), 1, max, s.count) || s.index > s.count)
    throw InputError(what, "expected i/N with 1 <= i <= N (shards numbered from 1), got \"" + text + "\"");
  return s;
}

Shard shard_from_environment() {
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count) return {};
  const char* min = std::getenv("SLURM_ARRAY_TASK_MIN");
  const char* step = std::getenv("SLURM_ARRAY_TASK_STEP");  // --array=1-9:2 runs tasks 1, 3, 5, 7, 9
  long i = 0, n = 0, m = 0, k = 1;
  if (!parse_integer(id, 0, 1000000, i) || !parse_integer(count, 1, 1000000, n) ||
      (min && !parse_integer(min, 0, 1000000, m)) || (step && !parse_integer(step, 1, 1000000, k)) || i - m < 0 ||
      (i - m) % k != 0 || (i - m) / k >= n)
    throw InputError("SLURM_ARRAY_TASK_ID", std::string("cannot take the shard from SLURM_ARRAY_TASK_ID=") + id +
                                                ", SLURM_ARRAY_TASK_COUNT=" + count +
                                                (min ? std::string(", SLURM_ARRAY_TASK_MIN=") + min : std::string()) +
                                                (step ? std::string(", SLURM_ARRAY_TASK_STEP=") + step : std::string()));
  return {(i - m) / k + 1, n};
}

namespace {
std::string numbered(const StudyPlan& plan, std::size_t index, const char* ext) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "case_%04zu%s", index, ext);
  return plan.output + "/" + buf;
}
}  // namespace

std::string case_output(const StudyPlan& plan, std::size_t index) { return numbered(plan, index, ".h5"); }
std::string case_error(const StudyPlan& plan, std::size_t index) { return numbered(plan, index, ".error"); }

std::string describe(const StudyPlan& plan, const StudyCase& c) {
  std::string s;
  for (std::size_t a = 0; a < plan.axes.size(); ++a) s += (a ? ", " : "") + plan.axes[a].key + "=" + c.values[a].toml;
  return s;
}

}  // namespace rollnoise::pipeline
