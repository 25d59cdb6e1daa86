// The flange patch of a two-point contact as a second contact of the flanging wheel
// (pipeline/bogie_noise.hpp, noise/flange_patch.hpp, docs/noise_loop.md Sec. 7.3), on the 300 m
// curve's leading wheelset (the leading outer wheel at its flange, a two-point state).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "../noise/noise_fixture.hpp"
#include "core/errors.hpp"
#include "dynamics/rail_model.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/bogie_noise.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;
using cd = std::complex<double>;
using noise_test::relative_min_dissipation;

// The leading wheelset of the 300 m curve with the flange patch coupled: 8 points per band up to
// 1 kHz, 24 elements in x (cheap), continuous support (the point receptance is the same at every
// rail position).
io::NoiseInputs leading_wheelset_with_flange_patch() {
  const std::vector<std::string> o = {"curve.creepage=\"estimate\"",  // its two-point contact
                                      "noise.points_per_band=4",
                                      "noise.band_max=1000.0",
                                      "noise.compare=\"none\"",
                                      "grid.nx=24",
                                      "track.support=\"continuous\"",
                                      "noise.second_patch=\"coupled\"",
                                      "curve.wheels=[\"leading_outer\", \"leading_inner\"]"};
  return io::read_noise_inputs(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m.toml", o));
}

double relative_difference(const noise::Vector4c& a, const noise::Vector4c& b) {
  return (a - b).norm() / std::max(b.norm(), 1e-300);
}

class SecondPatch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    in_ = new io::NoiseInputs(leading_wheelset_with_flange_patch());
    r_ = new pipeline::NoiseResult(pipeline::run_noise(in_->contact, in_->noise));
  }
  static void TearDownTestSuite() {
    delete r_;
    delete in_;
  }
  static io::NoiseInputs* in_;
  static pipeline::NoiseResult* r_;
};
io::NoiseInputs* SecondPatch::in_ = nullptr;
pipeline::NoiseResult* SecondPatch::r_ = nullptr;

// The 300 m state is a two-point contact: the flange patch is found on the flank (angle within
// 0.1 rad of the estimate's flange angle, nearer the flange than the tread patch on wheel and
// rail), lowered under the estimate's flange vertical load Q_f (1e-8 relative, (V1)), and its
// normal pushes the wheel mostly laterally (|F_lat| from N > the vertical share N cos delta).
TEST_F(SecondPatch, FlangePatchSitsOnTheFlankUnderTheFlangeLoad) {
  ASSERT_TRUE(r_->mean.curve().state && r_->mean.curve().state->two_point);
  ASSERT_EQ(r_->patches.size(), 1u);
  const noise::CurveContactState& s = *r_->mean.curve().state;
  const noise::WheelContact& p = *r_->patches[0].state;
  const noise::WheelContact& tread = *r_->wheels[0].state;
  EXPECT_EQ(p.wheel, noise::WheelId::leading_outer);
  EXPECT_GE(p.contact.contact_angle, s.flange_angle - 0.1);
  EXPECT_LT(p.contact.wheel_s, tread.contact.wheel_s);  // towards the flange (field side > 0)
  EXPECT_LT(p.contact.rail_y, tread.contact.rail_y);    // on the gauge face
  EXPECT_NEAR(p.loaded->vertical_load, s.flange_vertical_load, 1e-8 * s.flange_vertical_load);
  EXPECT_GT(p.normal_force() * std::sin(p.contact.contact_angle),
            p.normal_force() * std::cos(p.contact.contact_angle));
  std::printf(
      "  flange patch: angle %.3f rad, wheel s %.1f mm, rail %.1f mm, Q_f %.2f kN, N %.2f kN, "
      "k_N %.3e N/m (tread: angle %.3f rad, k_N %.3e N/m)\n",
      p.contact.contact_angle, 1e3 * p.contact.wheel_s, 1e3 * p.contact.rail_y,
      1e-3 * p.vertical_load, 1e-3 * p.normal_force(), r_->patches[0].mean.normal_stiffness(),
      tread.contact.contact_angle, r_->wheels[0].mean.normal_stiffness());
}

// With every cross term off, the loop with the second patch splits into single-contact loops:
// each wheel's forces and velocities equal its loop alone to 1e-10 (relative, per frequency), and
// the second patch, without a roughness source of its own, carries no force at all.
TEST_F(SecondPatch, WithoutCouplingTheTreadContactsAreTheirSingleLoopsAndThePatchIsAtRest) {
  const noise::ContactSetLoopResult alone =
      pipeline::contact_loop(r_->wheels, in_->noise, r_->axis.frequency, r_->patches, 1, nullptr,
                             noise::CrossCoupling::none())
          .main;
  ASSERT_EQ(alone.contacts(), 3);
  ASSERT_EQ(alone.sources(), 2);
  double worst = 0.0, patch = 0.0;
  for (int a = 0; a < 2; ++a) {
    // the wheel's single-contact loop (loop.hpp); both wheels on the leading axle
    const pipeline::WheelNoise& w = r_->wheels[a];
    const noise::LoopResult single =
        noise::solve_loop(noise::structural_receptances(*in_->noise.wheel, *in_->noise.rail,
                                                        w.position, r_->axis.frequency),
                          w.receptance.main);
    const noise::LoopResult set = noise::contact_response(alone, a, a);
    for (std::size_t k = 0; k < single.frequency.size(); ++k) {
      worst = std::max(worst, relative_difference(set.force[k], single.force[k]));
      worst = std::max(worst, relative_difference(set.wheel_velocity[k], single.wheel_velocity[k]));
      worst = std::max(worst, relative_difference(set.rail_velocity[k], single.rail_velocity[k]));
    }
  }
  for (const Eigen::MatrixXcd& F : alone.force) patch = std::max(patch, F.middleRows(8, 4).norm());
  EXPECT_LT(worst, 1e-10);
  EXPECT_EQ(patch, 0.0);
  std::printf("  uncoupled loop with the flange patch vs single-contact loops: %.1e relative\n",
              worst);
}

// Coupled, the flange patch is driven through the wheel and the rail: its force is not zero, and
// the tread contact's levels move (the coupling does something).
TEST_F(SecondPatch, CoupledPatchIsDrivenThroughTheStructures) {
  ASSERT_TRUE(r_->coupled_contacts);
  ASSERT_EQ(r_->loops.main.contacts(), 3);
  double patch = 0.0;
  for (const Eigen::MatrixXcd& F : r_->loops.main.force)
    patch = std::max(patch, F.middleRows(8, 4).norm());
  EXPECT_GT(patch, 0.0);
  const std::vector<noise::BandLevels> off =
      pipeline::bogie_bands(pipeline::contact_loop(r_->wheels, in_->noise, r_->axis.frequency).main,
                            r_->wheels, in_->noise, r_->axis.centres);
  double moved = 0.0;
  for (std::size_t j = 0; j < off[0].centre.size(); ++j)
    for (int i = 0; i < 4; ++i)
      moved = std::max(moved,
                       std::abs(r_->wheels[0].bands.force_level[j][i] - off[0].force_level[j][i]));
  EXPECT_GT(moved, 0.01);
  std::printf(
      "  flange patch coupled vs off: the tread contact's force levels move by up to %.2f dB\n",
      moved);
}

// The structures between the three contacts (two treads and the flange patch, all cross terms,
// the shipped track with discrete support): wheel and rail receptances symmetric (reciprocity,
// M1) to 1e-12 relative and passive (dissipation >= -1e-10 of its largest eigenvalue).
TEST_F(SecondPatch, AssembledReceptanceWithTwoPatchesIsSymmetricAndPassive) {
  const pipeline::NoiseCase& nc = in_->noise;
  const std::vector<noise::ContactPoint> cs = pipeline::bogie_contacts(r_->wheels, nc, r_->patches);
  ASSERT_EQ(cs.size(), 3u);
  const dynamics::RailModel& rail = *nc.rail;  // the shipped case: discrete support
  for (double f : {80.0, 340.0, 1010.0, 2460.0, 4200.0}) {
    const noise::ContactSetReceptance r = noise::contact_set_receptance(*nc.wheel, rail, cs, f);
    EXPECT_LE((r.wheel - r.wheel.transpose()).norm(), 1e-12 * r.wheel.norm()) << f;
    EXPECT_LE((r.rail - r.rail.transpose()).norm(), 1e-12 * r.rail.norm()) << f;
    EXPECT_GT(r.wheel.block(0, 8, 4, 4).norm(), 0.0);  // tread and flange of one wheel
    EXPECT_GT(r.rail.block(0, 8, 4, 4).norm(), 0.0);   // on one rail
    EXPECT_GE(relative_min_dissipation(r.wheel), -1e-10) << f;
    EXPECT_GE(relative_min_dissipation(r.rail), -1e-10) << f;
    EXPECT_GE(relative_min_dissipation(r.wheel + r.rail), -1e-10) << f;
  }
}

// A second patch without the bogie loop is an input error naming noise.second_patch (at reading,
// before any work).
TEST(SecondPatchInput, CoupledPatchWithoutTheBogieLoopNamesTheKey) {
  try {
    io::read_noise_inputs(io::CaseReader::from_file(
        std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_flange_300m.toml",
        {"noise.contact_coupling=\"none\""}));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "noise.second_patch");
  }
}

}  // namespace
