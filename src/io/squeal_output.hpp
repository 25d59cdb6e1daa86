// Writing `rollnoise squeal` (pipeline/squeal.hpp) to HDF5 (docs/squeal.md Sec. 5): /squeal/* after
// /case, the patch and the steady state of the mean contact (write_mean_state) and the contact
// state the loop ran on (/squeal/contact/*, as /noise/contact/*).
#pragma once

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/squeal.hpp"

namespace rollnoise::io {

void write_squeal(Hdf5Writer& w, const CaseReader& r, const pipeline::NoiseCase& nc, const pipeline::SquealResult& res);

/// /squeal/route1/{eigenvalue, frequency, damping_ratio, unstable} (one per root in `roots`),
/// {fit_error_rail, fit_error_contact, fit_band, poles_rail, poles_contact, all_eigenvalues}, and
/// /squeal/route_agreement, /squeal/route_agreement_within, /squeal/route1/within and the attribute
/// route_warning of /squeal (`warning`, pipeline::route_warning; "none" when the routes agree) when
/// `agreement` is given (`--route both`).
void write_squeal_route1(Hdf5Writer& w, const pipeline::Route1Result& r1,
                         const std::vector<noise::ModeRoot>& roots,
                         const pipeline::RouteAgreement* agreement,
                         const std::string& warning = "");

}  // namespace rollnoise::io
