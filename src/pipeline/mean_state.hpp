// The mean state every contact command starts from: the case's patch, steady rolling at the mean
// creepage and (on request) the linear NSS model around it.
#pragma once

#include <memory>

#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "nss/linear_model.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::pipeline {

struct MeanState {
  ContactCase contact;  ///< placed, its grid the patch's (profiles may enlarge it)
  std::unique_ptr<contact::ContactPatch> patch;
  contact::TangentialSolution steady;
  std::unique_ptr<nss::LinearContactModel> model;  ///< built on request
};

/// Place the case, solve its normal problem and steady rolling at the mean creepage, and build
/// the linear model when `with_model`.
MeanState solve_mean_state(ContactCase c, bool with_model);

/// The linear NSS model of a solved patch and steady state of the case.
std::unique_ptr<nss::LinearContactModel> linear_model(const ContactCase& c, const contact::ContactPatch& patch,
                                                      const contact::TangentialSolution& steady);

}  // namespace rollnoise::pipeline
