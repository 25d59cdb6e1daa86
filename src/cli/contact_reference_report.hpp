// `--reference contact DIR` of steady and validate: CONTACT's run read before any computation,
// written beside rollnoise's results and compared in the printed summary
// (io/contact_reference.hpp, docs/contact_interop.md Sec. 3).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "cli/commands.hpp"
#include "io/contact_reference.hpp"
#include "io/hdf5_writer.hpp"
#include "nss/linear_response.hpp"

namespace rollnoise::cli {

/// CONTACT's run of --reference contact DIR, or nothing without the option.
std::optional<io::ContactReference> read_reference(const CommonOptions& o);

/// /reference/contact/* and the printed comparison with rollnoise's steady force (N, N, N m).
void report_steady_reference(io::Hdf5Writer& w, const io::ContactReference& ref,
                             const Eigen::Vector3d& steady);

/// /validate/contact/* and the printed comparison of the unsteady solver and the linear model with
/// CONTACT's series. InputError naming --reference when CONTACT's time step is not rollnoise's or
/// its run is longer than rollnoise's.
void report_validate_reference(io::Hdf5Writer& w, const io::ContactReference& ref,
                               const nss::LinearResponse& lin,
                               const std::vector<Eigen::Vector3d>& unsteady, double t_start,
                               const std::vector<double>& frequencies, double dt);

}  // namespace rollnoise::cli
