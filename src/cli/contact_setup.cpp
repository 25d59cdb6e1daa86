#include "cli/contact_setup.hpp"

#include "io/contact_case.hpp"

namespace rollnoise::cli {

MeanState solve_mean_state(const io::CaseReader& r, bool with_model) {
  io::ContactCase c = io::read_contact_case(r);
  return io::within_case(r, [&] { return pipeline::solve_mean_state(std::move(c), with_model); });
}

}  // namespace rollnoise::cli
