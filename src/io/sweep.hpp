// `rollnoise steady --sweep ARG`: the argument parsed strictly and expanded into one case override
// per point. Forms:
//   KEY=lo:hi:n      n points from lo to hi, equally spaced (a scalar key);
//   KEY[i]=lo:hi:n   component i of an array key (creepage.mean[0]), the others from the case;
//   KEY=[v1, v2, ...] one TOML value per point.
// lo and hi are whole numbers in C syntax (1e-3, -0.5), n a positive integer in decimal digits
// (not 1e1) no larger than limits.steps, i a decimal index within the key's array. Anything else,
// including trailing characters, is an InputError naming the --sweep argument (exit 2).
#pragma once

#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::io {

struct SweepSpec {
  std::string key;     ///< the swept case key
  int component = -1;  ///< KEY[i]: i; -1 for a scalar key or a list
  double lo = 0.0, hi = 0.0;
  long n = 0;                     ///< lo:hi:n points; 0 for a list
  std::vector<std::string> list;  ///< KEY=[...]: the TOML value of each point
};

/// Parse `arg` (the text after --sweep); InputError naming "--sweep" on any malformed part.
SweepSpec parse_sweep(const std::string& arg);

/// The overrides "KEY=value", one per point, and the swept values (index for lists) of `arg`, on
/// the case read by `base` whose contact part is `c` (limits, grid). The count and the memory of
/// the points (pipeline::sweep_bytes) are checked against c.limits before any point is made.
std::vector<std::string> expand_sweep(const std::string& arg, const CaseReader& base,
                                      const pipeline::ContactCase& c, std::vector<double>& values);

}  // namespace rollnoise::io
