// The mean contact of a case file, for the commands that start from it (response, validate): the
// case read by io, the mean contact solved by the pipeline (pipeline/mean_contact.hpp).
#pragma once

#include "io/case_reader.hpp"
#include "pipeline/mean_contact.hpp"

namespace rollnoise::cli {

using pipeline::MeanContact;

/// Read the contact part of the case and solve its mean contact with the linear model.
MeanContact solve_mean_contact(const io::CaseReader& r);

}  // namespace rollnoise::cli
