// `creep --extrapolate` (pipeline::run_creep_extrapolated, nss/extrapolation.hpp): on the paper's
// Hertzian case (Sec. 3.2 mean creepages, V = 50 km/h, midstep sampling) the creep coefficients
// extrapolated from three coarse grids (14 x 10, 21 x 15, 28 x 20) lie closer to the value of a
// fine grid (56 x 41) than the finest of them, and the error estimate beside them covers the
// distance to it; frequencies above the coarsest grid's Nyquist limit are refused before any solve.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "pipeline/creep.hpp"

namespace {

using namespace rollnoise;

pipeline::ContactCase paper_case(int nx, int ny) {
  pipeline::ContactCase c;
  c.material = {210e9, 0.28};
  c.mu = 0.3;
  c.speed = 13.8888888888889;
  c.normal_force = 98.1e3;
  c.a = 7.18e-3, c.b = 5.29e-3;
  c.grid = contact::Grid::around_ellipse(nx, ny, c.a, c.b, 1.25);  // a margin for the coarse grids
  c.creepage = {0.001, 0.001, -0.053};
  c.sampling = contact::CreepageSampling::midstep;
  c.placed = true;
  return c;
}

}  // namespace

TEST(CreepExtrapolation, ExtrapolatedCoefficientsAreCloserToTheFineGridThanTheFinestInputAndWithinTheirErrorBar) {
  const std::vector<double> freq = {1000.0, 5000.0};
  const pipeline::CreepResult ex =
      pipeline::run_creep_extrapolated(paper_case(14, 10), freq, false, "frequency.list", {1.0, 1.5, 2.0}, "--x");
  const pipeline::CreepResult fine = pipeline::run_creep(paper_case(56, 41), freq, false, "frequency.list");
  ASSERT_TRUE(ex.extrapolation.has_value());
  const pipeline::CreepExtrapolation& x = *ex.extrapolation;
  ASSERT_EQ(x.nx, (std::vector<int>{14, 21, 28}));
  ASSERT_EQ(x.ny, (std::vector<int>{10, 15, 20}));
  for (size_t n = 0; n < freq.size(); ++n)
    for (int j = 0; j < 2; ++j) {  // f11, f22
      const std::complex<double> ref = fine.f[n](j, j), r = ex.f[n](j, j), finest = x.f.back()[n](j, j);
      const double e_ex = std::abs(r - ref) / std::abs(ref), e_in = std::abs(finest - ref) / std::abs(ref);
      const double bar = x.f_error[n](j, j) / std::abs(ref);
      std::printf("f%d%d at %.0f Hz against 56 x 41: 28 x 20 %.2e, extrapolated %.2e (order %.2f), error bar %.2e\n",
                  j + 1, j + 1, freq[n], e_in, e_ex, x.f_order[n](j, j), bar);
      EXPECT_LT(e_ex, e_in) << "f" << j + 1 << j + 1 << " at " << freq[n] << " Hz";
      EXPECT_LT(e_ex, bar) << "f" << j + 1 << j + 1 << " at " << freq[n] << " Hz";
    }
  EXPECT_EQ(x.assumed_order, 2.0);  // midstep
  EXPECT_EQ(x.f_error.size(), freq.size());
}

TEST(CreepExtrapolation, AFrequencyAboveTheNyquistLimitOfAGridIsRefusedBeforeAnySolve) {
  pipeline::ContactCase c = paper_case(16, 12);
  c.tangential.max_iterations = 1;  // any solve would end in a NumericalError
  c.tangential.tolerance = 1e-300;
  const double fn = pipeline::nyquist_frequency(c);
  try {
    pipeline::run_creep_extrapolated(c, {0.5 * fn, 1.01 * fn}, false, "frequency.f_max", {1.0, 2.0}, "--x");
    FAIL() << "a frequency above the Nyquist limit was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "frequency.f_max");
    EXPECT_NE(std::string(e.what()).find("Nyquist"), std::string::npos) << e.what();
  }
  for (const std::vector<double>& bad : {std::vector<double>{1.0}, {1.0, 1.0}, {2.0, 1.0}, {1.0, 1.5, 2.0, 3.0}, {0.0, 1.0}}) {
    try {
      pipeline::run_creep_extrapolated(c, {0.5 * fn}, false, "frequency.f_max", bad, "--x");
      FAIL() << "bad grid factors were accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "--x");
    }
  }
  try {  // 16 x 12 scaled by 0.2: 3 x 2, too coarse for the patch
    pipeline::run_creep_extrapolated(c, {100.0}, false, "frequency.f_max", {0.2, 1.0}, "--x");
    FAIL() << "a grid too coarse for the patch was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--x");
    EXPECT_NE(std::string(e.what()).find("too coarse"), std::string::npos) << e.what();
  }
}
