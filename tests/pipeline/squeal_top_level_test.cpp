// The top-level /squeal/* of a Hertzian curve case with per-wheel states (noise.squeal_wheelsets =
// "on") describes the leading outer wheel with the same contact as /squeal/wheels/leading_outer
// (docs/squeal.md Sec. 8.2): its Hertz state with the load transfer, solved once and shared. On
// squeal_150m coarsened (16 x 12 elements, the axial n = 0 ... 2 modes at 300-700 Hz) with only the
// leading outer wheel listed, its wheelset is that one contact, so the per-wheel run's roots are
// the top level's single-contact roots: equal to the roots' own accuracy (|ds| <= 1e-11 |s|).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/squeal.hpp"
#include "pipeline/squeal_wheels.hpp"

namespace {

using namespace rollnoise;

struct SquealRun {
  pipeline::SquealResult top;
  std::vector<pipeline::WheelsetSqueal> wheelsets;
};

// `wheels`: curve.wheels set on the pipeline's case (the key itself is read for profile cases only)
SquealRun squeal_150m_coarse(const std::vector<std::string>& wheels) {
  const io::CaseReader reader =
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/squeal_150m.toml",
                                {"grid.nx=16", "grid.ny=12", "noise.band_max=700"});
  io::NoiseInputs in = io::read_noise_inputs(reader);
  in.noise.wheels = wheels;
  const pipeline::NoiseCase& nc = in.noise;
  SquealRun r;
  r.top = pipeline::run_squeal(std::move(in.contact), nc);
  r.wheelsets = pipeline::squeal_wheelsets(r.top, nc);
  return r;
}

TEST(SquealTopLevel, HertzianTopLevelRootsAreTheLeadingOuterWheelsOfThePerWheelRun) {
  const SquealRun r = squeal_150m_coarse({"leading_outer"});
  ASSERT_TRUE(r.top.mean_is_leading_outer_wheel) << "squeal_150m ships noise.squeal_wheelsets on";
  ASSERT_EQ(r.wheelsets.size(), 1u) << "the leading wheelset only";
  const pipeline::WheelsetSqueal& ws = r.wheelsets.front();
  ASSERT_TRUE(ws.skipped.empty()) << ws.skipped;
  ASSERT_EQ(ws.roots.size(), r.top.roots.size()) << "one root per mode of the band";
  // the load transfer is in the top level's contact: N = Q + dQ (K4), 1e-12 relative
  const double Q = 98100.0, dQ = 2.0 * Q * 0.08 * 1.5 / (1.5 * 1.5);
  EXPECT_NEAR(r.top.mean.contact().normal_force, Q + dQ, 1e-12 * Q);
  double worst = 0.0;
  for (const pipeline::WheelRoot& w : ws.roots) {
    const noise::ModeRoot& x = w.root;
    EXPECT_EQ(w.wheel, noise::WheelId::leading_outer);
    const noise::ModeRoot* top = nullptr;
    for (const noise::ModeRoot& t : r.top.roots)
      if (t.mode == x.mode) top = &t;
    ASSERT_NE(top, nullptr) << x.label;
    EXPECT_EQ(top->label, x.label);
    EXPECT_TRUE(top->converged && x.converged) << x.label;
    // both continuations stop at |ds| <= 1e-11 |s|, the same steps on the same arithmetic
    // (measured 2e-16: the single contact's route 2 and the contact set's coincide)
    const double d = std::abs(top->s - x.s) / std::abs(x.s);
    worst = std::max(worst, d);
    EXPECT_LT(d, 1e-10) << x.label << ": " << top->frequency << " Hz against " << x.frequency;
    EXPECT_EQ(top->unstable, x.unstable) << x.label;
  }
  std::printf("top level vs per-wheel leading outer: %zu roots, worst |ds|/|s| = %.2e\n",
              ws.roots.size(), worst);
}

}  // namespace
