// Passivity of the closed loop (docs/squeal.md Sec. 6): with constant friction and the normal ->
// tangential coupling off, the contact is passive (docs/stability.md Sec. 2), and so are the wheel
// and the rail: the coupled loop of passive parts has no eigenvalue with Re s > 0. Checked on 100
// seeded random curve states of the Hertzian 300 m case (radius, friction, cant deficiency and
// speed drawn in their physical range; the bogie estimate sets the creepages), on a coarse grid
// and the continuous track so that it runs in seconds.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/squeal.hpp"

namespace {

using namespace rollnoise;

TEST(SquealPassivity, ConstantFrictionWithoutNormalCouplingHasNoUnstableEigenvalue) {
  std::mt19937_64 rng(20240612);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  int cases = 0, roots = 0, stopped = 0;
  double largest = -1e300;  // the largest Re s / |s| found
  std::string where;
  for (int i = 0; i < 100; ++i) {
    char set[4][64];
    std::snprintf(set[0], sizeof set[0], "curve.radius=%.6g", std::exp(uniform(std::log(150.0), std::log(3000.0))));
    std::snprintf(set[1], sizeof set[1], "friction.mu=%.4g", uniform(0.1, 0.5));
    std::snprintf(set[2], sizeof set[2], "curve.cant_deficiency=%.4g", uniform(-0.05, 0.12));
    std::snprintf(set[3], sizeof set[3], "rolling.speed=%.4g", uniform(15.0, 35.0));
    const std::vector<std::string> o = {"grid.nx=12", "grid.ny=10", "grid.scale=1.3", "track.support=\"continuous\"",
                                        "noise.normal_coupling=\"off\"", "noise.band_max=4000",
                                        set[0], set[1], set[2], set[3]};
    const io::CaseReader reader =
        io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m_hertz.toml", o);
    io::NoiseInputs in = io::read_noise_inputs(reader);
    const pipeline::SquealResult r = pipeline::run_squeal(std::move(in.contact), in.noise);
    ++cases;
    EXPECT_FALSE(r.coupled);
    for (const auto& x : r.roots) {
      ++roots;
      // a continuation may stop where a heavily damped root leaves the contact series' range of
      // convergence (MarkovContact): far from the stability boundary
      if (!x.converged) {
        ++stopped;
        EXPECT_GT(x.damping_ratio, 0.05) << x.label << " in case " << i;
      }
      EXPECT_FALSE(x.unstable) << x.label << " s = " << x.s << " in case " << i << ": " << set[0] << " " << set[1]
                               << " " << set[2] << " " << set[3];
      if (x.s.real() / std::abs(x.s) > largest) {
        largest = x.s.real() / std::abs(x.s);
        where = x.label + " (" + set[0] + ", " + set[1] + ")";
      }
    }
  }
  std::printf("passivity: %d curve states, %d roots (%d continuations stopped at a heavily damped root); the least "
              "damped: Re s/|s| = %.3e, %s\n",
              cases, roots, stopped, largest, where.c_str());
  EXPECT_LE(stopped, roots / 100);
}

}  // namespace
