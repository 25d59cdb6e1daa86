// Reading the contact part of a case (material, friction, speed, geometry, grid, mean creepage,
// solver settings) into pipeline::ContactCase: values checked, profile files read, nothing solved
// (the contact point of a profile case is found by pipeline::placed_contact).
#pragma once

#include "io/case_reader.hpp"
#include "io/input_problems.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::io {

using pipeline::ContactCase;

/// The [limits] of a case (limits.memory, limits.steps; pipeline/limits.hpp). limits.memory
/// absent: 0, i.e. half the physical memory.
pipeline::Limits read_limits(const CaseReader& r);

/// Read and check the contact keys of a case, recording every problem in `problems`.
ContactCase read_contact_case(const CaseReader& r, InputProblems& problems);

/// The same, throwing one InputError with every problem found.
ContactCase read_contact_case(const CaseReader& r);

}  // namespace rollnoise::io
