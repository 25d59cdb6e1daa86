// A parameter study (docs/study.md): a base case and axes over case keys, expanded into numbered
// cases. Each case is the base case with one `--set key=value` per axis, so a study case is by
// construction the single run `rollnoise noise BASE --set ...`.
//
//   combine = "product": every combination; the last axis varies fastest (nested loops in the
//                        order the axes are written);
//   combine = "zip":     the i-th value of every axis together (all axes of one length).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rollnoise::pipeline {

/// One value of an axis: its TOML text (what --set receives) and, for numbers, the number.
struct AxisValue {
  std::string toml;
  double number;  ///< NaN when the value is not a number
};

struct Axis {
  std::string key;  ///< a case key, e.g. "curve.radius"
  std::vector<AxisValue> values;
};

/// `from`, `to`, `count` evenly spaced (count = 1: `from`).
std::vector<double> linear_range(double from, double to, long count);
/// `count` values evenly spaced in log(value), from `from` to `to` (both > 0).
std::vector<double> log_range(double from, double to, long count);
/// A number as TOML text that reads back to the same double (the shortest of 15 to 17 significant
/// digits, with a decimal point or exponent so that TOML reads it as a float).
AxisValue number_value(double v);

enum class Combine { kProduct, kZip };

struct StudyPlan {
  std::string file;    ///< the study file (absolute)
  std::string base;    ///< the base case file (absolute)
  std::string output;  ///< the output folder (absolute)
  Combine combine = Combine::kProduct;
  std::vector<Axis> axes;
};

/// A case of the study: its number and one value per axis (in the order of the axes).
struct StudyCase {
  std::size_t index = 0;
  std::vector<AxisValue> values;
};

/// All cases, numbered from 0. InputError naming `axes` when an axis is empty, zipped axes differ
/// in length, or the study has more than `max_cases` cases.
std::vector<StudyCase> expand(const StudyPlan& plan, std::size_t max_cases = 1000000);

/// The case's `--set` overrides: "key=value" per axis.
std::vector<std::string> overrides(const StudyPlan& plan, const StudyCase& c);

/// Shard i of n (1 <= i <= n): case k belongs to shard (k mod n) + 1, so every case belongs to
/// exactly one shard and shards get cases from the whole study.
struct Shard {
  long index = 1, count = 1;
  bool contains(std::size_t case_index) const { return long(case_index % std::size_t(count)) + 1 == index; }
};
/// "i/N" (the value of option `what`); InputError naming `what` otherwise.
Shard parse_shard(const std::string& text, const std::string& what = "--shard");
/// From Slurm job arrays: SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT (and SLURM_ARRAY_TASK_MIN,
/// default 0, so arrays numbered 0..N-1 or 1..N both work, and SLURM_ARRAY_TASK_STEP, default 1,
/// for arrays with a step such as --array=1-9:2); the whole study when not set.
Shard shard_from_environment();

/// The case's files in the output folder: case_0007.h5 and, when it failed, case_0007.error.
std::string case_output(const StudyPlan& plan, std::size_t index);
std::string case_error(const StudyPlan& plan, std::size_t index);
/// The parameters of a case as one line, "curve.radius=300.0, rolling.speed=15.0" (stored in its
/// file, so a rerun recognises a complete case of the same study).
std::string describe(const StudyPlan& plan, const StudyCase& c);

}  // namespace rollnoise::pipeline
