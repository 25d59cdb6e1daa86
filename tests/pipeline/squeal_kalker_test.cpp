// Squeal with Kalker's constant creep coefficients (noise.contact_model = "kalker"). The contact is
// quasi-steady, f(s) = f_Kalker at every s (noise::ConstantTransfer): route 2's continuation must
// reach every root (before, the contact was a one-term Markov series whose convergence guard
// refused every s, and all roots came back not converged). Checked on curve_300m_table (the table
// wheel; coarse grid, 16 elements in x; band to 3 kHz, 22 modes; continuous track, as
// squeal_routes_test.cpp):
//  - every root converged and is a zero of (S1): sigma_min/sigma_max of the equilibrated A(s) at
//    most 1e-10 (measured <= 3e-12);
//  - no root unstable: without normal coupling (g = 0) Kalker's contact is a damper, F = -f e_t'/V
//    with the symmetric part of f positive definite (f23 = -f32), so the loop is passive;
//  - route 1 (the same contact exactly: no states, D = [-f | 0]; the rail as a rational fit) gives
//    the same roots to within its rail fit's error at each root (route1_deviation): Kalker's
//    damping moves some roots far from the axis (axial n = 1: zeta = 0.10), where the fit, made on
//    the real axis, is off by 1.2e-2 and the frequencies differ by 1.1e-3; the routes' 0.1 % holds
//    for the roots the fit represents well, so route 1 is no tighter reference here.
#include <gtest/gtest.h>

#include <cstdio>

#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/squeal.hpp"

namespace {

using namespace rollnoise;

TEST(SquealKalker, EveryRootConvergesIsStableAndMatchesRoute1WithinItsRailFit) {
  const std::vector<std::string> o = {"grid.nx=16", "track.support=\"continuous\"",
                                      "noise.band_max=3000", "noise.contact_model=\"kalker\""};
  const io::CaseReader reader =
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m_table.toml", o);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  ASSERT_FALSE(in.noise.use_nss);
  const pipeline::SquealResult r = pipeline::run_squeal(std::move(in.contact), in.noise);
  ASSERT_FALSE(r.roots.empty());
  const pipeline::Route1Result r1 = pipeline::squeal_route1(r, in.noise);
  const std::vector<noise::ModeRoot> roots1 = pipeline::match_route1(r1, r.roots);
  ASSERT_EQ(roots1.size(), r.roots.size());
  std::vector<dynamics::cdouble> s;
  for (const noise::ModeRoot& x : r.roots) s.push_back(x.s);
  const pipeline::Route1Deviation fit = pipeline::route1_deviation(r1, r, in.noise, s);
  EXPECT_TRUE(pipeline::route_agreement(roots1, r.roots).distinct);
  for (std::size_t k = 0; k < r.roots.size(); ++k) {
    const noise::ModeRoot& x = r.roots[k];
    const double df = std::abs(roots1[k].frequency - x.frequency) / x.frequency;
    const double dz = std::abs(roots1[k].damping_ratio - x.damping_ratio);
    std::printf(
        "%-24s %8.2f Hz  zeta %.3e  sv %.1e  route 1: df %.1e dzeta %.1e (rail fit %.1e at the "
        "root)\n",
        x.label.c_str(), x.frequency, x.damping_ratio, x.singular_ratio, df, dz, fit.rail[k]);
    EXPECT_TRUE(x.converged) << x.label;
    EXPECT_LE(x.singular_ratio, 1e-10) << x.label;
    EXPECT_FALSE(x.unstable) << x.label << ": Re s = " << x.s.real();
    EXPECT_LE(df, fit.rail[k]) << x.label;
    EXPECT_LE(dz, fit.rail[k]) << x.label;
  }
}

}  // namespace
