// LAPACK entered from several threads at once (dynamics/lapack_section.hpp): the waveguide's
// eigenproblems (zgeev for the waves, zhseqr for the point receptance) computed on two threads give
// the bits of one thread, whatever LAPACK the system has installed. With Debian's
// libopenblas0-serial as the system LAPACK and no lock, this test failed: two threads' values
// differed from one thread's by O(1) at some frequencies.
#include "linalg/lapack_section.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "core/task_pool.hpp"
#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "fem/mesh.hpp"

namespace rd = rollnoise::dynamics;

namespace {

// The free UIC60 rail on a 60 mm mesh.
rd::RailWaveguide free_rail_on_60mm_mesh() {
  return rd::RailWaveguide(rollnoise::fem::mesh_polygon(rd::uic60_outline(), 0.06),
                           rd::RailMaterial{}, std::nullopt);
}

// Per frequency the waves' wavenumbers and the vertical point receptance at the crown
// (Eq. W4 at x = 0 from the waves, and Eq. W6 from the Schur form), on `threads` threads.
struct EigenValuesPerFrequency {
  std::vector<Eigen::VectorXcd> wavenumbers;
  std::vector<Eigen::MatrixXcd> from_waves, from_schur;
};
EigenValuesPerFrequency computed_on_threads(const rd::RailWaveguide& rail,
                                            const Eigen::MatrixXd& crown,
                                            const std::vector<double>& frequencies, int threads) {
  EigenValuesPerFrequency v;
  v.wavenumbers.resize(frequencies.size());
  v.from_waves.resize(frequencies.size());
  v.from_schur.resize(frequencies.size());
  rollnoise::parallel_for(frequencies.size(), threads, [&](std::size_t i, int) {
    const rd::cdouble omega = 2.0 * std::acos(-1.0) * frequencies[i];
    const rd::RailWaves w = rail.waves(omega);
    v.wavenumbers[i] = w.wavenumbers;
    v.from_waves[i] = rail.transfer(w, crown, crown, 0.0);
    v.from_schur[i] = rail.point_transfer(omega, crown, crown);
  });
  return v;
}

}  // namespace

// 32 frequencies from 100 Hz to 5 kHz (the reduced model of the loop), each computed alone (no
// state shared between them): on two threads the same bits as on one (tolerance: none).
TEST(LapackSection, WaveguideEigenproblemsOnTwoThreadsGiveOneThreadsBits) {
  std::printf("system LAPACK entered from several threads at once: %s\n",
              rollnoise::linalg::lapack_reentrant()
                  ? "yes"
                  : "no (OpenBLAS built single-threaded: calls locked)");
  const rd::RailWaveguide full = free_rail_on_60mm_mesh();
  const Eigen::Vector2d top(0.0, 0.172), up(0.0, 1.0);
  const Eigen::MatrixXd crown = full.patch_loads(top, 0.01, up, rd::kUic60HeadBottom);
  // reduced as in the loop (its section modes by dstevx, another LAPACK call)
  const rd::RailWaveguide rail = full.reduced(rd::near_field_reduction(), crown);
  std::vector<double> f;
  for (int i = 0; i < 32; ++i) f.push_back(100.0 * std::pow(50.0, i / 31.0));
  const EigenValuesPerFrequency one = computed_on_threads(rail, crown, f, 1);
  for (int repeat = 0; repeat < 2; ++repeat) {
    const EigenValuesPerFrequency two = computed_on_threads(rail, crown, f, 2);
    for (std::size_t i = 0; i < f.size(); ++i) {
      EXPECT_EQ(two.wavenumbers[i], one.wavenumbers[i]) << f[i] << " Hz";
      EXPECT_EQ(two.from_waves[i], one.from_waves[i]) << f[i] << " Hz";
      EXPECT_EQ(two.from_schur[i], one.from_schur[i]) << f[i] << " Hz";
    }
  }
}
