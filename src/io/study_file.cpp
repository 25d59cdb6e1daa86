#include "io/study_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <toml++/toml.h>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/case_schema.hpp"
#include "io/input_file.hpp"

namespace rollnoise::io {
namespace {

namespace fs = std::filesystem;

struct StudyError {
  std::string file;
  [[noreturn]] void operator()(const std::string& key, const std::string& message) const {
    throw InputError(key, file + ": " + key + ": " + message);
  }
};

pipeline::AxisValue value_of(const toml::node& n, const std::string& key, const StudyError& fail) {
  if (const auto* d = n.as_floating_point()) {
    if (!std::isfinite(d->get())) fail(key, "values must be finite");
    return pipeline::number_value(d->get());
  }
  if (const auto* i = n.as_integer()) return {std::to_string(i->get()), double(i->get())};
  std::ostringstream os;
  if (n.is_string() || n.is_boolean() || n.is_array()) {
    n.visit([&](auto&& v) { os << v; });  // TOML text, what --set reads back
    return {os.str(), kNaN};
  }
  fail(key, "a value must be a number, a string, a boolean or an array");
}

long count_of(const toml::table& t, const std::string& key, const StudyError& fail) {
  const auto c = t["count"].value<int64_t>();
  if (!c || *c < 1 || *c > 1000000) fail(key + ".count", "an integer from 1 to 1000000 is required");
  return long(*c);
}

double real_of(const toml::table& t, const char* name, const std::string& key, const StudyError& fail) {
  const auto v = t[name].value<double>();
  if (!v || !std::isfinite(*v)) fail(key + "." + name, "a finite number is required");
  return *v;
}

// A range table { from, to, count [, scale] }.
std::vector<pipeline::AxisValue> range_of(const toml::table& t, const std::string& key, const StudyError& fail) {
  for (const auto& [k, v] : t)
    if (k != "from" && k != "to" && k != "count" && k != "scale")
      fail(key + "." + std::string(k.str()), "unknown entry of a range (from, to, count, scale)");
  const double from = real_of(t, "from", key, fail), to = real_of(t, "to", key, fail);
  const long count = count_of(t, key, fail);
  const std::string scale = t["scale"].value_or<std::string>("linear");
  std::vector<double> v;
  if (scale == "linear") {
    v = pipeline::linear_range(from, to, count);
  } else if (scale == "log") {
    if (!(from > 0 && to > 0)) fail(key, "scale = \"log\" needs from > 0 and to > 0");
    v = pipeline::log_range(from, to, count);
  } else {
    fail(key + ".scale", "\"linear\" or \"log\", got \"" + scale + "\"");
  }
  std::vector<pipeline::AxisValue> values;
  for (double x : v) values.push_back(pipeline::number_value(x));
  return values;
}

// A range table is recognised by its "from"; any other table is a level of a dotted key written
// unquoted (axes.curve.radius), which we flatten.
void collect_axes(const toml::table& t, const std::string& prefix, const StudyError& fail,
                  std::vector<std::pair<toml::source_position, pipeline::Axis>>& out) {
  for (const auto& [k, node] : t) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    const std::string where = "axes.\"" + key + "\"";
    pipeline::Axis axis;
    axis.key = key;
    if (const auto* a = node.as_array()) {
      for (const auto& v : *a) axis.values.push_back(value_of(v, where, fail));
    } else if (const auto* sub = node.as_table()) {
      if (!sub->contains("from")) {
        collect_axes(*sub, key, fail, out);
        continue;
      }
      axis.values = range_of(*sub, where, fail);
    } else {
      fail(where, "an axis is a list of values or a range { from, to, count }");
    }
    if (!find_key(key)) fail(where, "unknown case key (see 'rollnoise keys')");
    if (axis.values.empty()) fail(where, "an axis needs at least one value");
    out.push_back({node.source().begin, std::move(axis)});
  }
}

}  // namespace

pipeline::StudyPlan read_study_file(const std::string& path) {
  const StudyError fail{path};
  if (fs::is_directory(path)) throw InputError("(file)", path + ": is a directory, not a study file");
  toml::table doc;
  try {
    doc = toml::parse(read_input(path, "(file)", "the study file"), path);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << path << ":" << e.source().begin.line << ":" << e.source().begin.column
        << ": " << e.description();
    throw InputError("(syntax)", msg.str());
  }
  for (const auto& [k, v] : doc)
    if (k != "base" && k != "output" && k != "combine" && k != "axes")
      fail(std::string(k.str()), "unknown study key (base, output, combine, [axes])");

  pipeline::StudyPlan plan;
  const fs::path file = fs::absolute(path);
  plan.file = file.lexically_normal().string();
  const fs::path folder = file.parent_path();
  const auto base = doc["base"].value<std::string>();
  if (!base) fail("base", "the base case file is required (a string, relative to the study file)");
  plan.base = (folder / *base).lexically_normal().string();
  const std::string output = doc["output"].value_or<std::string>(file.stem().string());
  if (output.empty()) fail("output", "an output folder is required");
  plan.output = (folder / output).lexically_normal().string();
  const std::string combine = doc["combine"].value_or<std::string>("product");
  if (combine == "product")
    plan.combine = pipeline::Combine::kProduct;
  else if (combine == "zip")
    plan.combine = pipeline::Combine::kZip;
  else
    fail("combine", "\"product\" or \"zip\", got \"" + combine + "\"");

  const auto* axes = doc["axes"].as_table();
  if (!axes || axes->empty()) fail("axes", "a table [axes] with at least one axis is required");
  std::vector<std::pair<toml::source_position, pipeline::Axis>> found;
  collect_axes(*axes, "", fail, found);
  // the order written in the file (toml++ keeps tables sorted by key)
  std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) {
    return x.first.line != y.first.line ? x.first.line < y.first.line : x.first.column < y.first.column;
  });
  for (auto& f : found) plan.axes.push_back(std::move(f.second));

  // The keys on the base case, once: the base exists, parses, and takes every axis.
  if (!fs::is_regular_file(plan.base)) fail("base", "no case file " + plan.base);
  const pipeline::StudyCase first = pipeline::expand(plan).front();
  CaseReader::from_file(plan.base, pipeline::overrides(plan, first));
  return plan;
}

}  // namespace rollnoise::io
