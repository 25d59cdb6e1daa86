// Checks of the waveguide rail's point receptance by the matrix function of Eq. (W6)
// (RailWaveguide::point_transfer, rail_waveguide_point.cpp) against the residue sum of Eq. (W4)
// over the waves (RailWaveguide::transfer at x = 0): the same G'(0), two ways.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "fem/mesh.hpp"

namespace rd = rollnoise::dynamics;
namespace rf = rollnoise::fem;
using cd = std::complex<double>;

namespace {

rd::RailWaveguide uic60(double h, double eta, bool supported) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  rd::RailMaterial m = rd::rail_material(t, 0.3);
  m.loss_factor = eta;
  std::optional<rd::FootSupport> support;
  if (supported)
    support = rd::FootSupport{t.vertical_support, t.lateral_support, t.longitudinal_support,
                              t.sleeper_spacing};
  return rd::RailWaveguide(rf::mesh_polygon(rd::uic60_outline(), h), m, support);
}

// Two contacts' load patches (crown and the 300 m curve's gauge corner), dofs() x 8.
Eigen::MatrixXd two_patches(const rd::RailWaveguide& rail) {
  const double gamma = 0.52;
  Eigen::MatrixXd l(rail.dofs(), 8);
  l.leftCols(4) = rail.patch_loads(Eigen::Vector2d(0.0, 0.172), 0.01, Eigen::Vector2d(0.0, 1.0),
                                   rd::kUic60HeadBottom);
  l.rightCols(4) =
      rail.patch_loads(Eigen::Vector2d(-0.0335, 0.1665), 0.01,
                       Eigen::Vector2d(-std::sin(gamma), std::cos(gamma)), rd::kUic60HeadBottom);
  return l;
}

}  // namespace

// The loop's model (UIC60 on the ballasted track's support, 30 mm mesh, the near-field basis of
// both contacts: m ~ 90): Eq. (W6) equals Eq. (W4) at x = 0 to 1e-8 of the 8x8's largest entry,
// at real frequencies 50 Hz-5 kHz and at complex ones on the squeal continuation's side
// (omega = -i s, s = -0.005 omega_0 + i omega_0: slightly decaying). Both are G'(0) of the same
// Y, so they differ by round-off amplified by Y's conditioning: measured 3.8e-9 at 50 Hz (the
// eigenvalues k^2 spread over the most decades), 1.5e-10 at 400 Hz, < 1e-10 from 1 kHz up.
// (Without the diagonal scaling of Y the 50 Hz difference was 1.3e-7.)
TEST(RailWaveguidePoint, SchurPointReceptanceEqualsResidueSumOfWaves) {
  const rd::RailWaveguide full = uic60(0.03, 0.02, true);
  const Eigen::MatrixXd loads = two_patches(full);
  const rd::RailWaveguide rail = full.reduced(rd::near_field_reduction(), loads);
  for (double f : {50.0, 400.0, 1000.0, 2500.0, 5000.0}) {
    const double w0 = 2.0 * M_PI * f;
    for (cd omega : {cd(w0, 0.0), cd(0.0, -1.0) * cd(-0.005 * w0, w0)}) {
      const Eigen::MatrixXcd ref = rail.transfer(rail.waves(omega), loads, loads, 0.0);
      const Eigen::MatrixXcd h = rail.point_transfer(omega, loads, loads);
      EXPECT_LT((h - ref).cwiseAbs().maxCoeff(), 1e-8 * ref.cwiseAbs().maxCoeff())
          << "f = " << f << " Hz, omega = " << omega;
    }
  }
}

// Response and load distributions that differ (the crown's response to the gauge corner's
// loads, a 4x4 block of the above) and the unreduced model (n = 3 x nodes, 60 mm mesh): the
// same agreement, 1e-8 of the largest entry (measured 3.6e-9 at 300 Hz, < 1e-10 at 3 kHz).
TEST(RailWaveguidePoint, SchurTransferBetweenTwoPatchesOfUnreducedModelEqualsWaves) {
  const rd::RailWaveguide rail = uic60(0.06, 0.02, true);
  const Eigen::MatrixXd loads = two_patches(rail);
  for (double f : {300.0, 3000.0}) {
    const cd omega(2.0 * M_PI * f, 0.0);
    const Eigen::MatrixXcd ref =
        rail.transfer(rail.waves(omega), loads.leftCols(4), loads.rightCols(4), 0.0);
    const Eigen::MatrixXcd h = rail.point_transfer(omega, loads.leftCols(4), loads.rightCols(4));
    EXPECT_LT((h - ref).cwiseAbs().maxCoeff(), 1e-8 * ref.cwiseAbs().maxCoeff()) << f;
  }
}

// The undamped free rail at a real frequency has real wavenumbers (propagating waves, Y's
// eigenvalues on the negative real axis, where Eq. (W6)'s principal root does not choose the
// direction of travel): point_transfer hands over to the residue sum, which takes the group
// velocity's direction; the two agree to round-off (1e-12 of the largest entry).
TEST(RailWaveguidePoint, UndampedFreeRailFallsBackToWavesWithGroupVelocity) {
  const rd::RailWaveguide full = uic60(0.04, 0.0, false);
  const Eigen::MatrixXd loads = two_patches(full);
  const rd::RailWaveguide rail = full.reduced(rd::near_field_reduction(), loads);
  const cd omega(2.0 * M_PI * 1000.0, 0.0);
  const Eigen::MatrixXcd ref = rail.transfer(rail.waves(omega), loads, loads, 0.0);
  const Eigen::MatrixXcd h = rail.point_transfer(omega, loads, loads);
  EXPECT_LT((h - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.cwiseAbs().maxCoeff());
}
