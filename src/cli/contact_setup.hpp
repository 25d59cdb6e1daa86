// What the contact commands share: the case's patch, the steady state at the mean creepage, and
// (for creep/response/validate) the linear model around it.
#pragma once

#include <memory>

#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "io/contact_case.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::cli {

struct MeanState {
  io::ContactCase contact;
  std::unique_ptr<contact::ContactPatch> patch;
  contact::TangentialSolution steady;
  std::unique_ptr<nss::LinearContactModel> model;  ///< built on request
};

MeanState solve_mean_state(const io::CaseReader& r, bool with_model);

}  // namespace rollnoise::cli
