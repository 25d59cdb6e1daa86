// Writing the results of the noise pipeline (pipeline/noise_pipeline.hpp) to HDF5: /noise/* of
// `rollnoise noise` and /receptance/* of `rollnoise receptance` (docs/noise_loop.md Sec. 6), each
// after /case, the patch and the steady state of the mean contact.
#pragma once

#include "io/case_reader.hpp"
#include "io/hdf5_writer.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::io {

/// The case as run: when the curve stage set the creepages, creepage.mean records them.
CaseReader case_as_run(const CaseReader& r, const pipeline::ContactCase& c, const pipeline::CurveSetup& curve);

/// GROUP/*: the contact state a loop ran on (normal_stiffness, angle, position_wheel, position_rail,
/// normal_force, creepage, rolling_radius, two_point, flange_*, and with profiles wheel_load,
/// load_transfer, tread_load, wheelset_lateral, wheelset_yaw); /noise/contact of `noise`.
void write_contact_state(Hdf5Writer& w, const std::string& group, const pipeline::NoiseCase& nc,
                         const pipeline::ContactCase& c, const pipeline::CurveSetup& curve, double normal_stiffness);

/// /noise/wheels/<wheel>/{contact, bands}: each wheel's contact state and its loop's band levels
/// (curve.wheels), with the attribute `loop` saying that each ran alone.
void write_wheels(Hdf5Writer& w, const pipeline::NoiseResult& res);
/// One sentence on the loop the run solved: its contacts, how they are coupled, its sources and
/// which wheel the top-level outputs report.
std::string loop_description(const pipeline::NoiseResult& r);

void write_noise(Hdf5Writer& w, const CaseReader& r, const pipeline::NoiseCase& nc, const pipeline::NoiseResult& res);

void write_receptance(Hdf5Writer& w, const CaseReader& r, const pipeline::ReceptanceResult& res);

}  // namespace rollnoise::io
