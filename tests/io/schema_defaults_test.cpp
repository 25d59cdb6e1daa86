// Defaults are declared once: the schema (src/io/case_schema.cpp) holds the default of every case
// key, and the structs the keys are read into (pipeline::ContactCase, pipeline::NoiseCase and their
// members) initialise the same fields for programs and tests that build them directly. This test
// ties the two: a case holding only its required keys, read by io, must give the same value as the
// default-constructed struct for every field whose struct initialiser stands for the case key's
// default. A default changed on one side only fails here, naming the key.
//
// Fields whose struct initialiser deliberately differs from the case default (they are not the
// case's default but the library's, and tests rely on them) are listed in kNotTied with the reason;
// the test checks that they do differ, so that a field which comes to agree moves to the tied list.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/case_schema.hpp"
#include "io/contact_case.hpp"
#include "io/corrugation_case.hpp"
#include "io/input_problems.hpp"
#include "io/noise_case.hpp"

namespace {

using namespace rollnoise;

// The required keys of a Hertzian case and nothing else.
const char* kMinimalCase = R"(
[contact]
normal_force = 98100.0
a = 7.18e-3
b = 5.29e-3
)";

struct Read {
  pipeline::ContactCase contact;
  pipeline::NoiseCase noise;
};

Read read_minimal() {
  const io::CaseReader r = io::CaseReader::from_string(kMinimalCase, "minimal.toml", {});
  Read out;
  out.contact = io::read_contact_case(r);
  io::InputProblems problems;
  out.noise = io::read_noise_case(r, problems);
  return out;
}

TEST(SchemaDefaults, DefaultConstructedStructsHoldTheSchemaDefaults) {
  const Read read = read_minimal();
  const pipeline::ContactCase c0;
  const pipeline::NoiseCase n0;
  const pipeline::ContactCase& c = read.contact;
  const pipeline::NoiseCase& n = read.noise;
  for (const char* key : {"material.E",
                          "material.nu",
                          "friction.mu",
                          "contact.geometry",
                          "grid.spin_offset",
                          "rolling.creepage_sampling",
                          "solver.influence",
                          "solver.linear_model",
                          "solver.threads",
                          "solver.normal_tolerance",
                          "curve.radius",
                          "curve.cant_deficiency",
                          "curve.cg_height",
                          "curve.wheelbase",
                          "curve.wheel_radius",
                          "curve.conicity",
                          "curve.flange_clearance",
                          "curve.creepage",
                          "contact.angle",
                          "noise.contact_model",
                          "noise.normal_coupling",
                          "noise.contact_coupling",
                          "noise.squeal_wheelsets",
                          "noise.second_patch",
                          "noise.second_patch_roughness",
                          "noise.compare",
                          "noise.band_min",
                          "noise.band_max",
                          "noise.points_per_band",
                          "roughness.filter"})
    ASSERT_NE(io::find_key(key), nullptr) << key << " is not a schema key";
  // exact equality: both sides are the same decimal literal
  EXPECT_EQ(c.material.E, c0.material.E) << "material.E";
  EXPECT_EQ(c.material.nu, c0.material.nu) << "material.nu";
  EXPECT_EQ(c.mu, c0.mu) << "friction.mu";
  EXPECT_EQ(c.geometry, c0.geometry) << "contact.geometry";
  EXPECT_EQ(c.spin_offset, c0.spin_offset) << "grid.spin_offset";
  EXPECT_EQ(c.sampling, c0.sampling) << "rolling.creepage_sampling";
  EXPECT_EQ(c.backend, c0.backend) << "solver.influence";
  EXPECT_EQ(c.linear_solver, c0.linear_solver) << "solver.linear_model";
  EXPECT_EQ(c.threads, c0.threads) << "solver.threads";
  EXPECT_EQ(c.normal.tolerance, c0.normal.tolerance) << "solver.normal_tolerance";
  EXPECT_EQ(n.curve_radius, n0.curve_radius) << "curve.radius";
  EXPECT_EQ(n.cant_deficiency, n0.cant_deficiency) << "curve.cant_deficiency";
  EXPECT_EQ(n.cg_height, n0.cg_height) << "curve.cg_height";
  EXPECT_EQ(n.wheelbase, n0.wheelbase) << "curve.wheelbase";
  EXPECT_EQ(n.wheel_radius, n0.wheel_radius) << "curve.wheel_radius";
  EXPECT_EQ(n.conicity, n0.conicity) << "curve.conicity";
  EXPECT_EQ(n.flange_clearance, n0.flange_clearance) << "curve.flange_clearance";
  EXPECT_EQ(n.estimate_creepage, n0.estimate_creepage) << "curve.creepage";
  EXPECT_EQ(n.multibody, n0.multibody) << "curve.creepage";
  EXPECT_EQ(n.contact_angle, n0.contact_angle) << "contact.angle";
  EXPECT_EQ(n.use_nss, n0.use_nss) << "noise.contact_model";
  EXPECT_EQ(n.normal_coupling, n0.normal_coupling) << "noise.normal_coupling";
  EXPECT_EQ(n.contact_coupling, n0.contact_coupling) << "noise.contact_coupling";
  EXPECT_EQ(n.squeal_wheelsets, n0.squeal_wheelsets) << "noise.squeal_wheelsets";
  EXPECT_EQ(n.second_patch, n0.second_patch) << "noise.second_patch";
  EXPECT_EQ(n.second_patch_roughness, n0.second_patch_roughness) << "noise.second_patch_roughness";
  EXPECT_EQ(n.compare, n0.compare) << "noise.compare";
  EXPECT_EQ(n.band_min, n0.band_min) << "noise.band_min";
  EXPECT_EQ(n.band_max, n0.band_max) << "noise.band_max";
  EXPECT_EQ(n.points_per_band, n0.points_per_band) << "noise.points_per_band";
  EXPECT_EQ(n.filter, n0.filter) << "roughness.filter";
}

TEST(SchemaDefaults, UntiedStructInitialisersAreTheListedOnes) {
  const Read read = read_minimal();
  const pipeline::ContactCase c0;
  const pipeline::ContactCase& c = read.contact;
  // rolling.speed: ContactCase::speed = 0 means "not set" (the numerics refuse it); the case's
  // default is 50 km/h.
  EXPECT_NE(c.speed, c0.speed) << "rolling.speed now agrees: tie it in the test above";
  // solver.tangential_tolerance, solver.max_iterations: contact::TangentialSolverSettings holds the
  // solver's own defaults (1e-11, 20000), which the contact tests that build a solver directly use;
  // a case always sets both from the schema (1e-12, 200).
  EXPECT_NE(c.tangential.tolerance, c0.tangential.tolerance)
      << "solver.tangential_tolerance now agrees";
  EXPECT_NE(c.tangential.max_iterations, c0.tangential.max_iterations)
      << "solver.max_iterations now agrees";
}

}  // namespace

// [corrugation] and [wear] (io/corrugation_case.hpp): a case without them reads the schema's
// defaults, which are pipeline::CorrugationCase's initialisers, and Archard's law without a
// coefficient takes its own default.
namespace {
pipeline::CorrugationCase read_corrugation(const std::vector<std::string>& overrides) {
  return io::read_corrugation_case(
      io::CaseReader::from_string(kMinimalCase, "minimal.toml", overrides));
}
}  // namespace

TEST(CorrugationCase, WithoutTheKeysTheStructsInitialisersAreTheSchemaDefaults) {
  const pipeline::CorrugationCase read = read_corrugation({}), init;
  EXPECT_EQ(read.wavelength_min, init.wavelength_min) << "corrugation.wavelength_min";
  EXPECT_EQ(read.wavelength_max, init.wavelength_max) << "corrugation.wavelength_max";
  EXPECT_EQ(read.points, init.points) << "corrugation.points";
  EXPECT_EQ(read.law.kind, init.law.kind) << "wear.law";
  EXPECT_EQ(read.law.coefficient, init.law.coefficient) << "wear.coefficient";
  EXPECT_EQ(read.law.hardness, init.law.hardness) << "wear.hardness";
}

TEST(CorrugationCase, ArchardWithoutACoefficientTakesTheMildRegimes1e4) {
  const pipeline::CorrugationCase a = read_corrugation({"wear.law=\"archard\""});
  EXPECT_EQ(a.law.kind, nss::WearLaw::Kind::archard);
  EXPECT_EQ(a.law.coefficient, 1e-4);
  const pipeline::CorrugationCase b =
      read_corrugation({"wear.law=\"archard\"", "wear.coefficient=3e-3"});
  EXPECT_EQ(b.law.coefficient, 3e-3);
}
