// Seeded random combinations of the stress ranges: aspect ratio a/b in [0.1, 10]
// (log-uniform), grids of 4..26 elements per axis (element aspect ratio dx/dy within [0.2, 5]),
// mu in [0.05, 0.6], creepage 0 or of magnitude 1e-9..0.1 (log-uniform) in any direction, spin 0 or
// in [-2, 2] rad/m, spin offset 0 or 1/6, frequencies 0, Nyquist and random ones in between.
// The seed is printed; set ROLLNOISE_STRESS_SEED to run another sequence or to repeat one.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "stress_support.hpp"

using namespace rollnoise;
using namespace rollnoise::stress;

TEST(RandomStress, RandomMeanStatesGiveCoulombTractionsAndPassiveCreepCoefficients) {
  const std::uint64_t seed = stress_seed(20240607);
  std::printf("RandomStress seed = %llu (set ROLLNOISE_STRESS_SEED to change or repeat)\n",
              static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  auto uniform_int = [&](int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
  };
  const int cases = 60;
  const auto t_all = std::chrono::steady_clock::now();
  std::printf("%3s %6s %7s %5s %-32s %5s %9s %9s %9s %9s %6s\n", "#", "a/b", "grid", "mu",
              "creepage", "off", "adh/slip", "|F|/muN", "passive", "direct", "time");
  for (int i = 0; i < cases; ++i) {
    // draw everything first, so that a case depends on the seed and its index only
    const double r = std::pow(10.0, -1.0 + 2.0 * U(rng));
    int nx = 0, ny = 0;
    do {
      nx = uniform_int(4, 26), ny = uniform_int(4, 26);
    } while (r * ny / nx < 0.2 || r * ny / nx > 5.0);  // dx/dy = (2a/nx)/(2b/ny) = r ny/nx
    const double mu = 0.05 + 0.55 * U(rng);
    const bool zero_creepage = U(rng) < 0.15;
    const double mag = std::pow(10.0, -9.0 + 8.0 * U(rng)), angle = 2 * M_PI * U(rng);
    const bool zero_spin = U(rng) < 0.3;
    const double phi = -2.0 + 4.0 * U(rng);
    const double offset = U(rng) < 0.5 ? 0.0 : 1.0 / 6.0;
    const double f_spot = U(rng);
    std::vector<double> f_rel = {0.0, 1.0};
    for (int k = 0; k < 20; ++k) f_rel.push_back(U(rng));
    const Creepage c{zero_creepage ? 0.0 : mag * std::cos(angle),
                     zero_creepage ? 0.0 : mag * std::sin(angle), zero_spin ? 0.0 : phi};
    char label[160];
    std::snprintf(label, sizeof label,
                  "seed %llu case %d: a/b = %.3f, %d x %d, mu = %.3f, creepage %s, offset %.3f",
                  static_cast<unsigned long long>(seed), i, r, nx, ny, mu, describe(c).c_str(),
                  offset);
    SCOPED_TRACE(label);

    const auto t0 = std::chrono::steady_clock::now();
    std::unique_ptr<ContactPatch> patch;
    ASSERT_NO_THROW(patch = std::make_unique<ContactPatch>(hertz_patch(r, nx, ny)));
    const ContactPatch& p = *patch;
    TangentialSolution s;
    ASSERT_NO_THROW(s = solve_steady_rolling(p.influence, p.normal.pn, {mu, kSpeed, c, offset}));
    const SteadyCheck chk = check_steady(p, s, mu, kSpeed, c, offset);
    expect_physical(chk, "steady");

    // CONTACT's sampling: the pairing passivity is a theorem for (nss_stress_test.cpp)
    const nss::LinearContactModel m(p, s, {mu, kSpeed, offset, contact::CreepageSampling::contact});
    std::vector<double> freqs;
    for (double x : f_rel) freqs.push_back(x * m.nyquist_frequency());
    std::vector<nss::CreepMatrix> f;
    ASSERT_NO_THROW(f = m.creep_coefficients(freqs));
    double passive = 1.0;
    for (size_t k = 0; k < f.size(); ++k) {
      ASSERT_TRUE(f[k].allFinite()) << freqs[k] << " Hz";
      // (xi_x, xi_y) block always a power pairing; the full 3 x 3 without spin offset (the input
      // spin field then equals the output moment arm). Tolerance as in nss_stress_test.cpp.
      const double margin = passivity_margin(f[k], kC, offset != 0.0);
      passive = std::min(passive, margin);
      EXPECT_GE(margin, -1e-9) << "not passive at " << freqs[k] << " Hz";
    }
    // fast sweep against the direct solve (paper's form) at one random frequency: 1e-9, the fast
    // sweep's a-posteriori tolerance 1e-10 with a margin
    const double fr = f_spot * m.nyquist_frequency();
    const auto direct = m.creep_coefficients_direct(fr);
    const double e = (m.creep_coefficients({fr})[0] - direct).norm() / direct.norm();
    EXPECT_LE(e, 1e-9) << "fast vs direct at " << fr << " Hz";
    std::printf("%3d %6.3f %3dx%-3d %5.3f %-32s %5.3f %4d/%-4d %9.6f %9.1e %9.1e %6.3f\n", i, r, nx,
                ny, mu, describe(c).c_str(), offset, chk.adhesion, chk.slip,
                std::hypot(chk.F.Fx, chk.F.Fy) / chk.friction_force, passive, e, seconds_since(t0));
  }
  std::printf("%d random cases in %.2f s\n", cases, seconds_since(t_all));
}
