#include "cli/contact_setup.hpp"

namespace rollnoise::cli {

MeanState solve_mean_state(const io::CaseReader& r, bool with_model) {
  MeanState s;
  s.contact = io::read_contact_case(r);
  s.patch = std::make_unique<contact::ContactPatch>(io::solve_case_patch(s.contact));
  s.contact.grid = s.patch->grid;  // profiles: the grid may have been enlarged
  s.steady = contact::solve_steady_rolling(s.patch->influence, s.patch->normal.pn,
                                           s.contact.steady_input(), s.contact.tangential);
  if (with_model)
    s.model = std::make_unique<nss::LinearContactModel>(
        *s.patch, s.steady, nss::LinearModelInput{s.contact.mu, s.contact.speed, s.contact.spin_offset});
  return s;
}

}  // namespace rollnoise::cli
