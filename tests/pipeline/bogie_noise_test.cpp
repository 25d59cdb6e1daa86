// The loop with all the wheels of the bogie (pipeline/bogie_noise.hpp, docs/noise_loop.md Sec.
// 5.3): without the cross terms every wheel is its single-contact loop; on tangent track without
// cant deficiency the two sides of the coupled bogie give the same band levels.
#include "pipeline/bogie_noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;

io::NoiseInputs read_case(const std::string& name, const std::vector<std::string>& overrides) {
  std::vector<std::string> o = {"noise.points_per_band=4", "noise.band_max=1000.0",
                                "noise.compare=\"none\""};
  o.insert(o.end(), overrides.begin(), overrides.end());
  return io::read_noise_inputs(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/" + name, o));
}

double difference_relative_to_first(const noise::Vector4c& a, const noise::Vector4c& b) {
  return (a - b).norm() / std::max(a.norm(), 1e-300);
}

// One loop: four wheels of the 300 m curve with noise.contact_coupling = "none" (continuous
// support: the point receptance is the same at every rail position, so the trailing axle's rail_x
// changes nothing): the pipeline's loop of the four contacts gives each wheel's forces and
// velocities of its single-contact loop (loop.hpp, solve_loop) to 1e-10 (relative, per frequency)
// and its band levels to 1e-10 dB (both on the case's lines: noise.band_refinement = 0,
// so that the band means compare the loops, not the lines). The case's FE wheel (each wheel's modes
// at its own contact on the tread) on a coarse mesh (20 mm, modes to 3 kHz: the bands end at 1
// kHz).
TEST(BogieNoise, WithoutCouplingEachWheelIsItsSingleContactLoop) {
  const io::NoiseInputs in = read_case(
      "curve_300m.toml", {"curve.creepage=\"estimate\"", "track.support=\"continuous\"",
                          "grid.nx=24", "noise.contact_coupling=\"none\"", "wheel.mesh_size=0.02",
                          "wheel.f_max=3000", "noise.band_refinement=0"});
  const pipeline::NoiseResult r = pipeline::run_noise(in.contact, in.noise);
  ASSERT_EQ(r.wheels.size(), 4u);
  ASSERT_FALSE(r.coupled_contacts);
  double worst = 0.0, worst_db = 0.0;
  for (int a = 0; a < 4; ++a) {
    // the wheel's single-contact loop (loop.hpp) on its own structures and alpha_c
    const pipeline::WheelNoise& w = r.wheels[a];
    const noise::LoopResult single =
        noise::solve_loop(noise::structural_receptances(*in.noise.wheel, *in.noise.rail, w.position,
                                                        r.axis.frequency),
                          w.receptance.main);
    const noise::LoopResult set = noise::contact_response(r.loops.main, a, a);
    for (std::size_t k = 0; k < single.frequency.size(); ++k) {
      worst = std::max(worst, difference_relative_to_first(set.force[k], single.force[k]));
      worst = std::max(
          worst, difference_relative_to_first(set.wheel_velocity[k], single.wheel_velocity[k]));
      worst = std::max(worst,
                       difference_relative_to_first(set.rail_velocity[k], single.rail_velocity[k]));
    }
    const noise::BandLevels bands =
        noise::band_levels(single, r.axis.centres, pipeline::contact_roughness(in.noise, w.mean));
    for (std::size_t j = 0; j < bands.centre.size(); ++j)
      for (int i = 0; i < 4; ++i)
        worst_db =
            std::max(worst_db, std::abs(bands.force_level[j][i] - w.bands.force_level[j][i]));
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_db, 1e-10);
  std::printf("  uncoupled bogie loop vs single-contact loops: %.1e relative, %.1e dB\n", worst,
              worst_db);
}

// Tangent track, no cant deficiency, all four wheels coupled (rigid wheelset, both rails with
// discrete support and the other axle at the wheelbase): outer and inner wheel of each axle have
// mirrored contacts, so their band levels (forces and velocities) agree within 0.01 dB.
TEST(BogieNoise, TangentTrackGivesEqualLevelsOnBothSides) {
  const io::NoiseInputs in =
      read_case("tangent.toml", {"curve.wheels=[\"leading_outer\", \"leading_inner\", "
                                 "\"trailing_outer\", \"trailing_inner\"]"});
  ASSERT_EQ(in.noise.contact_coupling, pipeline::NoiseCase::ContactCoupling::kBogie);
  const pipeline::NoiseResult r = pipeline::run_noise(in.contact, in.noise);
  ASSERT_EQ(r.wheels.size(), 4u);
  ASSERT_TRUE(r.coupled_contacts);
  double worst = 0.0, coupling = 0.0;
  for (int axle = 0; axle < 2; ++axle) {
    const noise::BandLevels& outer = r.wheels[2 * axle].bands;
    const noise::BandLevels& inner = r.wheels[2 * axle + 1].bands;
    ASSERT_EQ(outer.centre.size(), inner.centre.size());
    for (std::size_t j = 0; j < outer.centre.size(); ++j)
      for (int i = 0; i < 4; ++i) {
        worst = std::max(worst, std::abs(outer.force_level[j][i] - inner.force_level[j][i]));
        for (int p = 0; p < 2; ++p)
          worst = std::max(worst,
                           std::abs(outer.velocity_level[j][p][i] - inner.velocity_level[j][p][i]));
      }
  }
  // the coupling changes the levels (so the check is not trivially of the single loops)
  const noise::LoopVariants alone = pipeline::contact_loop(
      r.wheels, in.noise, r.axis.frequency, {}, 1, nullptr, noise::CrossCoupling::none());
  const std::vector<noise::BandLevels> bands_alone =
      pipeline::bogie_bands(alone.main, r.wheels, in.noise, r.axis.centres);
  for (std::size_t j = 0; j < bands_alone[0].centre.size(); ++j)
    coupling = std::max(
        coupling, std::abs(r.wheels[0].bands.force_level[j][0] - bands_alone[0].force_level[j][0]));
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(coupling, 0.01);
  std::printf(
      "  tangent bogie: outer minus inner %.2e dB at most; coupled minus alone (Fz) up to %.2f "
      "dB\n",
      worst, coupling);
}

}  // namespace
