// Writing a CONTACT run (io/contact_reference.hpp) beside rollnoise's results (docs/interface.md):
//   steady:   /reference/contact/force (Fx, Fy, Mz of case 1 in rollnoise's conventions; from the
//             .mat when present, else the printed totals), force_printed, and the traction field
//             of case 1 (x, y, pn, px, py, state) when its .mat is there;
//   validate: /validate/contact/{time, force, force_integrated, normal_force}, the differences
//             unsteady - CONTACT and linear - CONTACT at CONTACT's times, and the linear model's
//             errors against CONTACT (/validate/contact/errors/*, as /validate/errors/*).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "io/contact_reference.hpp"
#include "io/hdf5_writer.hpp"
#include "nss/validation.hpp"

namespace rollnoise::io {

/// The steady reference force of case 1: integrated from its .mat if present, else printed.
Eigen::Vector3d contact_steady_force(const ContactReference& ref);

void write_contact_steady_reference(Hdf5Writer& w, const ContactReference& ref);

/// `unsteady` and `linear` at rollnoise's t_k = k dt, k = 0.. (at least as long as CONTACT's run);
/// `errors` the linear model against CONTACT (nss::compare_linear_unsteady on CONTACT's times).
void write_contact_validation(Hdf5Writer& w, const ContactReference& ref,
                              const std::vector<Eigen::Vector3d>& unsteady,
                              const std::vector<Eigen::Vector3d>& linear,
                              const nss::ValidationErrors& errors);

}  // namespace rollnoise::io
