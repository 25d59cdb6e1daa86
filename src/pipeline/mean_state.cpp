#include "pipeline/mean_state.hpp"

namespace rollnoise::pipeline {

std::unique_ptr<nss::LinearContactModel> linear_model(const ContactCase& c, const contact::ContactPatch& patch,
                                                      const contact::TangentialSolution& steady) {
  nss::LinearModelInput in{c.mu, c.speed, c.spin_offset, c.falling, c.linear_solver, c.sampling};
  in.threads = c.threads;
  return std::make_unique<nss::LinearContactModel>(patch, steady, in);
}

MeanState solve_mean_state(ContactCase c, bool with_model) {
  MeanState s;
  place_contact(c);
  s.contact = std::move(c);
  s.patch = std::make_unique<contact::ContactPatch>(solve_patch(s.contact));
  s.contact.grid = s.patch->grid;  // profiles: the grid may have been enlarged
  s.steady = contact::solve_steady_rolling(s.patch->influence, s.patch->normal.pn, s.contact.steady_input(),
                                           s.contact.tangential);
  if (with_model) s.model = linear_model(s.contact, *s.patch, s.steady);
  return s;
}

}  // namespace rollnoise::pipeline
