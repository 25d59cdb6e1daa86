#include "cli/contact_setup.hpp"

#include "io/contact_case.hpp"

namespace rollnoise::cli {

MeanContact solve_mean_contact(const io::CaseReader& r) {
  const io::ContactCase c = io::read_contact_case(r);
  return io::within_case(r, [&] { return pipeline::mean_contact(c, pipeline::MeanContactOptions{}); });
}

}  // namespace rollnoise::cli
