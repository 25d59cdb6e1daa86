// Reading a study file (docs/study.md):
//
//   base = "cases/curve_300m.toml"     # relative to the study file
//   output = "study_300m"              # folder, relative to the study file (default: the study's name)
//   combine = "product"                # or "zip"
//   [axes]
//   "curve.radius" = [300.0, 500.0, 1000.0]                      # a list (numbers, strings, arrays)
//   "rolling.speed" = { from = 15.0, to = 30.0, count = 4 }      # evenly spaced
//   "friction.mu" = { from = 0.1, to = 0.4, count = 4, scale = "log" }   # evenly spaced in log
//
// Errors name the study file and the key (e.g. `axes."curve.radius"`). The axis keys are checked
// against the case schema and applied to the base case once, so a mistyped key fails here and not
// in every case; values are checked by each case (a bad value fails only its case).
#pragma once

#include <string>

#include "pipeline/study_plan.hpp"

namespace rollnoise::io {

pipeline::StudyPlan read_study_file(const std::string& path);

}  // namespace rollnoise::io
