// The FE wheel's orders n on several threads (dynamics::wheel_fe_modes, WheelFeOptions::threads):
// the inertia count of each order equals the number of modes its eigen solve finds, and the modes
// on 2 and 3 threads are bit-identical to the serial chain's (each order's count the guess of the
// next). The 920 mm section on a coarse mesh (20 mm, modes to 3 kHz, n = 0..6): cheap.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/constants.hpp"
#include "dynamics/wheel_fe.hpp"
#include "fem/eigen_solve.hpp"
#include "support/test_inputs.hpp"

using namespace rollnoise;
using namespace rollnoise::dynamics;

namespace {

WheelFeOptions coarse_options(int threads) {
  WheelFeOptions o;
  o.mesh_size = 0.02;
  o.f_max = 3000.0;
  o.n_max = 6;
  o.threads = threads;
  return o;
}

// The DOFs held at the bore (what wheel_fe_modes fixes).
std::vector<int> bore_dofs(const WheelFeModes& w, const WheelSection& section) {
  std::vector<int> fixed;
  for (int node : fem::nodes_on_segments(w.mesh, section.bore_segments))
    for (int c = 0; c < 3; ++c) fixed.push_back(3 * node + c);
  return fixed;
}

}  // namespace

// Sylvester's law of inertia: the negative pivots of LDL^T(K - omega_max^2 M) count the modes
// below omega_max; exactly the count the shift-invert Lanczos keeps, order by order (tolerance:
// none, integers).
TEST(WheelFeParallelOrders, InertiaCountEqualsModesFound) {
  const WheelSection section = test_support::default_section();
  const WheelFeOptions o = coarse_options(1);
  const WheelFeModes w = wheel_fe_modes(section, o);
  const fem::AxisymmetricOrders orders(w.mesh, o.material);
  fem::LowestModesSolver solver(bore_dofs(w, section), 2 * rollnoise::kPi * o.f_max);
  for (int n = 0; n <= o.n_max; ++n) {
    const auto km = orders.matrices(n);
    const int counted = solver.count_below(km.stiffness, km.mass);
    const int found = static_cast<int>(solver.solve(km.stiffness, km.mass).omega.size());
    EXPECT_EQ(counted, found) << "order n = " << n;
    std::printf("  n = %d: %d modes below %.0f Hz, inertia count %d\n", n, found, o.f_max, counted);
  }
}

// The modes (frequencies, orders, families, nodal circles, full DOF vectors) on 2 and 3 threads
// equal the serial ones bit for bit.
TEST(WheelFeParallelOrders, ModesDoNotDependOnThreads) {
  const WheelSection section = test_support::default_section();
  const WheelFeModes serial = wheel_fe_modes(section, coarse_options(1));
  ASSERT_GT(serial.modes.size(), 10u);
  for (int threads : {2, 3}) {
    const WheelFeModes parallel = wheel_fe_modes(section, coarse_options(threads));
    ASSERT_EQ(parallel.modes.size(), serial.modes.size()) << threads << " threads";
    EXPECT_EQ(parallel.mass, serial.mass);
    for (std::size_t j = 0; j < serial.modes.size(); ++j) {
      const WheelFeMode &a = serial.modes[j], &b = parallel.modes[j];
      EXPECT_EQ(a.frequency, b.frequency) << "mode " << j << ", " << threads << " threads";
      EXPECT_EQ(a.n, b.n);
      EXPECT_EQ(a.family, b.family);
      EXPECT_EQ(a.nodal_circles, b.nodal_circles);
      EXPECT_TRUE(a.dofs == b.dofs) << "mode " << j << ", " << threads << " threads";
      EXPECT_TRUE(a.tread_shape == b.tread_shape) << "mode " << j;
    }
  }
}

// The orders a chain counts by inertia first (guess <= 1) and finds empty are skipped without the
// Lanczos: the modes of wheel_fe_modes equal, order by order and bit for bit, those of the plain
// chain that solves every order (each order's count the next one's guess). On the coarse mesh to
// 2 kHz with n <= 9 the top orders have no mode below f_max, so the skip is exercised (checked).
TEST(WheelFeParallelOrders, OrdersCountedEmptyByInertiaEqualTheSolvedChain) {
  const WheelSection section = test_support::default_section();
  WheelFeOptions o = coarse_options(1);
  o.f_max = 2000.0;
  o.n_max = 9;
  const WheelFeModes w = wheel_fe_modes(section, o);
  const fem::AxisymmetricOrders orders(w.mesh, o.material);
  fem::LowestModesSolver solver(bore_dofs(w, section), 2 * rollnoise::kPi * o.f_max);
  int guess = -1, empty = 0;
  std::size_t j = 0;  // w.modes: ascending in n, then frequency
  for (int n = 0; n <= o.n_max; ++n) {
    const auto km = orders.matrices(n);
    const fem::Modes chain = solver.solve(km.stiffness, km.mass, guess);
    guess = static_cast<int>(chain.omega.size());
    empty += guess == 0;
    for (int k = 0; k < guess; ++k, ++j) {
      ASSERT_LT(j, w.modes.size()) << "order n = " << n;
      EXPECT_EQ(w.modes[j].n, n);
      EXPECT_EQ(w.modes[j].frequency, chain.omega(k) / (2 * rollnoise::kPi)) << "order n = " << n;
      EXPECT_TRUE(w.modes[j].dofs == chain.shapes.col(k)) << "order n = " << n;
    }
  }
  EXPECT_EQ(j, w.modes.size());
  EXPECT_GE(empty, 2);  // orders without a mode below f_max: the inertia skip ran
}
