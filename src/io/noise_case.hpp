// Reading the structural, roughness and curve parts of a noise case into pipeline::NoiseCase:
// wheel and track models from their files, roughness spectra, the contact filter, the curve, the
// multibody wheelset, the bands and the loop's variants. Values checked, nothing solved.
#pragma once

#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "io/input_problems.hpp"
#include "pipeline/noise_case.hpp"

namespace rollnoise::io {

using pipeline::NoiseCase;

/// Read and check the noise keys of a case, recording every problem in `problems`.
NoiseCase read_noise_case(const CaseReader& r, InputProblems& problems);

}  // namespace rollnoise::io

namespace rollnoise::io {

/// Both parts of a noise case.
struct NoiseInputs {
  ContactCase contact;
  NoiseCase noise;
};

/// Read the contact and noise parts of a case (and, when `freq` is given, its [frequency] axis
/// into `freq`); one InputError with every problem found.
NoiseInputs read_noise_inputs(const CaseReader& r, std::vector<double>* freq = nullptr);

}  // namespace rollnoise::io
