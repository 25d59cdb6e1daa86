// Writing the results of `rollnoise response` and `validate` to HDF5 (docs/conventions.md Sec. 4):
// the linear model's force response (nss/linear_response.hpp) and its comparison with the
// unsteady solver (nss/validation.hpp).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "io/hdf5_writer.hpp"
#include "nss/linear_response.hpp"
#include "nss/validation.hpp"

namespace rollnoise::io {

/// GROUP/time, creepage, normal_force, force (the recursion) and, with harmonics, force_synthesis.
void write_linear_response(Hdf5Writer& w, const std::string& group, const nss::LinearResponse& r);

/// /validate/time, /validate/unsteady/force, /validate/errors/* and /validate/spectrum/* for the
/// unsteady forces at lin.time and their comparison `v` on the excited `frequencies`.
void write_validation(Hdf5Writer& w, const nss::LinearResponse& lin,
                      const std::vector<Eigen::Vector3d>& unsteady, const nss::ValidationErrors& v,
                      const std::vector<double>& frequencies);

}  // namespace rollnoise::io
