// noise.band_refinement (pipeline/band_lines.hpp, docs/noise_loop.md Sec. 6.1): the lines added
// for the band means leave the narrow-band outputs on the case's lines and bring the band levels
// to those of a fine uniform grid.
#include "pipeline/band_lines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;

pipeline::NoiseResult run(const std::vector<std::string>& overrides) {
  // The leading wheelset of the 300 m curve (the outer wheel in full slip, the inner in partial
  // adhesion) on a coarse grid, its FE wheel on a coarse mesh (modes to 3 kHz; bands to 2 kHz).
  std::vector<std::string> o = {"curve.creepage=\"estimate\"",
                                "noise.band_max=2000.0",
                                "grid.nx=24",
                                "wheel.mesh_size=0.02",
                                "wheel.f_max=3000",
                                "curve.wheels=[\"leading_outer\", \"leading_inner\"]"};
  o.insert(o.end(), overrides.begin(), overrides.end());
  const io::NoiseInputs in = io::read_noise_inputs(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m.toml", o));
  return pipeline::run_noise(in.contact, in.noise);
}

// Of both wheels' force band levels (the bogie loop's).
double largest_difference(const pipeline::NoiseResult& a, const pipeline::NoiseResult& b) {
  double worst = 0.0;
  for (std::size_t w = 0; w < a.wheels.size(); ++w)
    for (std::size_t j = 0; j < a.axis.centres.size(); ++j)
      for (int i = 0; i < 4; ++i)
        worst = std::max(worst, std::abs(a.wheels[w].bands.force_level[j][i] -
                                         b.wheels[w].bands.force_level[j][i]));
  return worst;
}

// 16 lines per band with 6 levels of refinement against 16 and 4096 uniform lines per band: the
// force band levels (Fz, Fx, Fy, Mz) of both wheels within 0.1 dB of the fine grid where the 16
// lines alone are more than 1 dB off (measured: 4.4 dB for the inner wheel, refined 0.05 dB;
// 2048 uniform lines 0.08 dB); the narrow-band forces on the case's lines are the same bits with
// and without the added lines.
TEST(BandLines, RefinedBandLevelsMatchAFineUniformGridAndLeaveTheNarrowBandAlone) {
  const pipeline::NoiseResult coarse = run({"noise.points_per_band=16", "noise.band_refinement=0"});
  const pipeline::NoiseResult refined =
      run({"noise.points_per_band=16", "noise.band_refinement=6"});
  const pipeline::NoiseResult fine = run({"noise.points_per_band=4096", "noise.band_refinement=0"});
  ASSERT_TRUE(refined.refined);
  EXPECT_GT(refined.refined->added_lines, 0);
  ASSERT_EQ(refined.wheels.size(), 2u);
  const double before = largest_difference(coarse, fine);
  const double after = largest_difference(refined, fine);
  EXPECT_GT(before, 1.0);
  EXPECT_LT(after, 0.1);
  ASSERT_EQ(coarse.loops.main.force.size(), refined.loops.main.force.size());
  for (std::size_t k = 0; k < coarse.loops.main.force.size(); ++k)
    ASSERT_EQ(coarse.loops.main.force[k], refined.loops.main.force[k]) << k;
  std::printf(
      "  force band levels against 4096 lines per band: 16 lines %.2f dB, refined %.3f dB "
      "(%ld lines added in %d levels)\n",
      before, after, refined.refined->added_lines, refined.refined->levels);
}

// The added lines go to the threads in slices fixed by their number (band_lines.cpp): a rail model
// that interpolates between direct evaluations on the grid it is given (the waveguide,
// dynamics/waveguide_frequency_sampling.hpp) sees the same grids on 1 and 2 threads, so the
// refined lines and every band level are the same bits (with slices per thread they moved by up
// to 0.06 dB on curve_300m_waveguide). A level adds more than 64 lines, the old slicing's step.
TEST(BandLines, WaveguideRailGivesTheSameBandLevelsOnOneAndTwoThreads) {
  const std::vector<std::string> o = {"curve.creepage=\"estimate\"",
                                      "noise.band_min=500.0",
                                      "noise.band_max=1000.0",
                                      "noise.points_per_band=12",
                                      "grid.nx=24",
                                      "curve.wheels=[\"leading_inner\"]",
                                      "track.model=\"waveguide\"",
                                      "track.support=\"continuous\"",
                                      "wheel.modes=\"models/wheel/wheel_920mm_modes.csv\""};
  auto run_on = [&](int threads) {
    std::vector<std::string> with = o;
    with.push_back("solver.threads=" + std::to_string(threads));
    const io::NoiseInputs in = io::read_noise_inputs(io::CaseReader::from_file(
        std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m.toml", with));
    return pipeline::run_noise(in.contact, in.noise);
  };
  const pipeline::NoiseResult one = run_on(1), two = run_on(2);
  ASSERT_TRUE(one.refined && two.refined);
  EXPECT_GT(one.refined->added_lines, 64);
  EXPECT_EQ(one.refined->added_lines, two.refined->added_lines);
  ASSERT_EQ(one.refined->loops.main.frequency, two.refined->loops.main.frequency);
  ASSERT_EQ(one.wheels.size(), two.wheels.size());
  for (std::size_t j = 0; j < one.axis.centres.size(); ++j)
    for (int i = 0; i < 4; ++i) {
      for (std::size_t w = 0; w < one.wheels.size(); ++w)
        EXPECT_EQ(one.wheels[w].bands.force_level[j][i], two.wheels[w].bands.force_level[j][i])
            << "wheel " << w << ", band " << j;
    }
}

}  // namespace
