// The case pipeline (src/pipeline): stages on plain case structs, callable alone, composing to the
// whole; input checks that need the placed contact (the Nyquist limit) run before any solve.
#include <gtest/gtest.h>

#include <string>

#include "contact/hertz.hpp"
#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/creep.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;

// The paper's Hertzian patch on 34 x 25 elements, built as a plain struct (no case file).
pipeline::ContactCase hertz_case() {
  pipeline::ContactCase c;
  c.material = {210e9, 0.28};
  c.mu = 0.3;
  c.speed = 30.0;
  c.normal_force = 98.1e3;
  c.a = 7.18e-3, c.b = 5.29e-3;
  c.grid = contact::Grid::around_ellipse(34, 25, c.a, c.b, 1.25);
  c.creepage = {0.001, 0.0, 0.0};
  c.placed = true;
  return c;
}

TEST(Pipeline, TheNyquistLimitIsCheckedBeforeAnySolve) {
  pipeline::ContactCase c = hertz_case();
  // a tangential solver that cannot converge: any solve ends in a NumericalError
  c.tangential.max_iterations = 1;
  c.tangential.tolerance = 1e-300;
  const double fn = pipeline::nyquist_frequency(c);
  EXPECT_DOUBLE_EQ(fn, 0.5 * c.speed / c.grid.dx);
  EXPECT_THROW(pipeline::run_creep(c, {0.5 * fn}, false, "frequency.f_max"), NumericalError);
  try {
    pipeline::run_creep(c, {0.5 * fn, 1.01 * fn}, false, "frequency.f_max");
    FAIL() << "a frequency above the Nyquist limit was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "frequency.f_max");
    EXPECT_NE(std::string(e.what()).find("Nyquist"), std::string::npos) << e.what();
  }
}

// The Hertzian 300 m case of cases/, read by io, with few samples per band.
io::NoiseInputs curve_300m_hertz(const std::vector<std::string>& overrides) {
  std::vector<std::string> o = {"noise.points_per_band=4", "track.support=\"continuous\""};
  o.insert(o.end(), overrides.begin(), overrides.end());
  return io::read_noise_inputs(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m_hertz.toml", o));
}

TEST(Pipeline, TheCurveStageSetsTheCreepagesOnlyWhenItEstimatesThem) {
  io::NoiseInputs est = curve_300m_hertz({});
  const pipeline::CurvePlacement ps = pipeline::resolve_curve(est.contact, est.noise);
  const pipeline::ContactCase& c = ps.contact;
  const pipeline::CurveSetup& s = ps.curve;
  ASSERT_TRUE(s.estimated);
  EXPECT_TRUE(s.creepage_from_curve());
  EXPECT_EQ(c.creepage.xi_y, s.curving.xi_y);
  EXPECT_LT(c.creepage.xi_y, 0.0);  // the leading outer wheel under-steers: lateral creepage < 0 (docs)

  io::NoiseInputs given = curve_300m_hertz({"curve.creepage=\"case\"", "creepage.mean=[0.001, 0.002, 0.3]"});
  const pipeline::CurvePlacement pt = pipeline::resolve_curve(given.contact, given.noise);
  const pipeline::ContactCase& g = pt.contact;
  const pipeline::CurveSetup& t = pt.curve;
  EXPECT_FALSE(t.creepage_from_curve());
  EXPECT_EQ(g.creepage.xi_x, 0.001);
  EXPECT_EQ(g.creepage.xi_y, 0.002);
  EXPECT_EQ(g.creepage.phi, 0.3);
}

TEST(Pipeline, StagesCalledAloneGiveTheWholePipelinesNumbers) {
  io::NoiseInputs in = curve_300m_hertz({});
  const pipeline::NoiseResult whole = pipeline::run_noise(in.contact, in.noise);
  const pipeline::CurvePlacement placed = pipeline::resolve_curve(in.contact, in.noise);
  const pipeline::CurveSetup& curve = placed.curve;
  const pipeline::BandAxis axis = pipeline::band_axis(placed.contact, in.noise);
  ASSERT_EQ(axis.frequency, whole.axis.frequency);
  const pipeline::MeanContact mean =
      pipeline::solve_mean_contact(placed.contact, curve, pipeline::noise_contact_options(in.noise, axis.frequency));
  EXPECT_EQ(mean.normal_stiffness(), whole.mean.normal_stiffness());
  EXPECT_EQ(mean.contact().grid.dx, whole.mean.contact().grid.dx);
  const auto f = mean.model()->creep_coefficients(axis.frequency);
  ASSERT_EQ(f.size(), whole.creep.size());
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_TRUE(f[i] == whole.creep[i]) << axis.frequency[i] << " Hz";
  const auto st = noise::structural_receptances(*in.noise.wheel, *in.noise.rail, curve.position, axis.frequency);
  EXPECT_TRUE(st.wheel_contact.back() == noise::structural_receptances(*in.noise.wheel, *in.noise.rail,
                                                                       whole.mean.curve().position, axis.frequency)
                                             .wheel_contact.back());
}

}  // namespace
