// Writing the contact results (grid, normal problem, steady rolling) to HDF5 (docs/conventions.md Sec. 4).
#pragma once

#include "contact/forces.hpp"
#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"
#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"

namespace rollnoise::io {

/// /case (attribute toml: the case as run).
void write_case(Hdf5Writer& w, const CaseReader& r);
/// /grid/x, /grid/y, /normal/pn, /normal/force, /normal/approach.
void write_patch(Hdf5Writer& w, const contact::ContactPatch& patch);
/// A tangential solution under `group` (px, py, sx, sy, state, force, creepage).
void write_tangential(Hdf5Writer& w, const std::string& group, const contact::Grid& g,
                      const contact::Creepage& c, const contact::TangentialSolution& s);

/// /case, the patch and the steady state at the mean creepage under /steady: what every command
/// that linearises or time-steps around a mean state writes first.
void write_mean_state(Hdf5Writer& w, const CaseReader& r, const contact::ContactPatch& patch,
                      const contact::Creepage& mean, const contact::TangentialSolution& steady);

}  // namespace rollnoise::io
