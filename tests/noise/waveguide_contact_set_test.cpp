// The bogie's contacts with the waveguide rail (noise/contact_set.hpp with
// RailModel::contact_transfers of dynamics/waveguide_rail_model.hpp and of the discretely
// supported waveguide): the assembled multi-contact receptance reciprocal and passive, and with
// every cross term off each contact equal to its single-contact loop (as for the beam,
// contact_set_loop_test.cpp). Coarse 40 mm section mesh; four wheels and a flange patch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_discrete_support.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "noise/contact_set.hpp"
#include "noise/contact_set_loop.hpp"
#include "noise/loop.hpp"
#include "noise_fixture.hpp"

using namespace noise_test;
using cd = std::complex<double>;

namespace {

// A bogie in a curve: the leading outer wheel at the gauge corner (cases/curve_300m.toml: 36.6 mm,
// 0.524 rad) with a flange patch on the gauge face (1.25 rad, ~72 deg, the flank of the outline
// below the corner), the other wheels near the crown; 2.5 m wheelbase. (A flange patch at 1.0 rad
// lands on the same outline point as the tread contact: the UIC60 outline's gauge-corner vertex
// carries every normal from 0.49 to 1.23 rad, dynamics::outline_contact_point; the two patches are
// then one point and the rail block is singular.)
std::vector<rn::ContactPoint> waveguide_bogie_contacts() {
  return {point(0, 1, -5e-3, -0.0366, 0.524, 0.3), point(0, -1, 2e-3, -1e-3, 0.02, 0.3),
          point(1, 1, 1e-3, -0.01, 0.1, 2.8), point(1, -1, 0.0, 2e-3, 0.025, 2.8),
          point(0, 1, -30e-3, -0.036, 1.25, 0.3)};
}

rd::WaveguideRailOptions coarse() {
  rd::WaveguideRailOptions o;
  o.mesh_size = 0.04;
  return o;
}

const rd::WaveguideRailModel& continuous_rail() {
  static const rd::WaveguideRailModel rail(rd::uic60_ballasted(), coarse());
  return rail;
}

// The former loads (the 10 mm patches): with the loop's (the head as a body) the tread and the
// flange patch of one wheel, at one x, share the head's six rigid motions and the rail's 20 x 20
// has two zero eigenvalues, whose sign is round-off (-3e-10 of the largest at 500 Hz).
const rd::WaveguideRailModel& continuous_rail_patches() {
  static const rd::WaveguideRailModel rail = [] {
    rd::WaveguideRailOptions o = coarse();
    o.head_load = false;
    return rd::WaveguideRailModel(rd::uic60_ballasted(), o);
  }();
  return rail;
}

const rd::DiscreteWaveguideRailModel& discrete_rail() {
  static const rd::DiscreteWaveguideRailModel rail = [] {
    rd::TrackParameters t = rd::uic60_ballasted();
    t.supports_each_side = 10;  // cheap; the symmetry does not depend on it
    return rd::DiscreteWaveguideRailModel(t, coarse(), 0.3);
  }();
  return rail;
}

// The eigenvalues of the dissipation -(A - A^H) / 2i of A scaled by its diagonal (as
// relative_min_dissipation), ascending, over the largest's magnitude.
Eigen::VectorXd relative_dissipations(const Eigen::MatrixXcd& A) {
  Eigen::VectorXd d(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    d(i) = std::abs(A(i, i)) > 0 ? 1.0 / std::sqrt(std::abs(A(i, i))) : 1.0;
  const Eigen::MatrixXcd Ds = d.cast<std::complex<double>>().asDiagonal();
  const Eigen::MatrixXcd D = Ds * (-(A - A.adjoint()) / std::complex<double>(0.0, 2.0)) * Ds;
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(D).eigenvalues();
  return ev / ev.cwiseAbs().maxCoeff();
}

// `structural_zeros`: the rail's dissipation has that many zero eigenvalues (contacts at one x
// loading the head through its six rigid motions: a tread and a flange patch give 8 columns on 6),
// whose computed sign is round-off; they must be zero within 1e-9, every other one >= -1e-10.
void expect_reciprocal_and_passive(const rd::RailModel& rail, double f,
                                   const std::vector<rn::ContactPoint>& cs,
                                   int structural_zeros = 0) {
  const rn::ContactSetReceptance r = rn::contact_set_receptance(wheel(), rail, cs, f);
  EXPECT_LE((r.rail - r.rail.transpose()).norm(), 1e-8 * r.rail.norm()) << f;
  EXPECT_LE((r.wheel - r.wheel.transpose()).norm(), 1e-8 * r.wheel.norm()) << f;
  EXPECT_GT(r.rail.block(0, 8, 4, 4).norm(), 0.0) << f;  // the rail between the axles
  if (cs.size() > 4) {                                   // tread, flange
    EXPECT_GT(r.rail.block(0, 16, 4, 4).norm(), 0.0) << f;
  }
  EXPECT_EQ(r.rail.block(0, 4, 4, 4).norm(), 0.0) << f;  // the two rails are uncoupled
  const Eigen::VectorXd rail_dissipation = relative_dissipations(r.rail);
  if (structural_zeros > 0)
    std::printf("  %.0f Hz: rail dissipation's smallest %.2e, %.2e, next %.2e\n", f,
                rail_dissipation(0), rail_dissipation(1), rail_dissipation(structural_zeros));
  for (int i = 0; i < structural_zeros; ++i) EXPECT_LE(std::abs(rail_dissipation(i)), 1e-9) << f;
  EXPECT_GE(rail_dissipation(structural_zeros), -1e-10) << f;
  EXPECT_GE(relative_min_dissipation(r.wheel + r.rail), -1e-10) << f;
}

}  // namespace

// Four wheels and a flange patch on the continuously supported waveguide at 500 Hz and 2 kHz:
// the 20 x 20 rail receptance symmetric to 1e-8 relative (reciprocity of Eq. W4) and passive
// (dissipation >= -1e-10 of its largest eigenvalue), with its cross terms present; with the
// former patch loads, where the tread and the flange patch are distinct points of the section
// (continuous_rail_patches). With the head loads: symmetric, and wheel plus rail passive.
TEST(WaveguideBogie, AssembledReceptanceIsReciprocalAndPassive) {
  for (double f : {500.0, 2000.0}) {
    expect_reciprocal_and_passive(continuous_rail_patches(), f, waveguide_bogie_contacts());
    const rn::ContactSetReceptance r =
        rn::contact_set_receptance(wheel(), continuous_rail(), waveguide_bogie_contacts(), f);
    EXPECT_LE((r.rail - r.rail.transpose()).norm(), 1e-8 * r.rail.norm()) << f;
    EXPECT_GE(relative_min_dissipation(r.wheel + r.rail), -1e-10) << f;
  }
}

// The same on discrete supports (N = 10), the four wheels and the flange patch, 500 Hz and 1.5 kHz:
// the section is loaded at each contact's own point
// (DiscreteWaveguideRailModel::contact_transfers), so tread and flange patch are two points of the
// head, not the crown's four degrees of freedom moved rigidly to both. Through the head as a body
// (the default) their 8 columns act on the head's 6 rigid motions: the rail's dissipation has two
// zero eigenvalues (within 1e-9; measured +-1.7e-10 at 500 Hz, the next 5.4e-4), the rest
// >= -1e-10.
TEST(WaveguideBogie, AssembledReceptanceOnDiscreteSupportsIsReciprocalAndPassive) {
  for (double f : {500.0, 1500.0})
    expect_reciprocal_and_passive(discrete_rail(), f, waveguide_bogie_contacts(), 2);
}

// With every cross term off, each contact's forces and velocities equal the single-contact loop's
// with the same rail model and contact receptance, to 1e-10 relative: the contact set asks the
// waveguide for each point alone, so each gets the basis the single-contact loop gives it.
TEST(WaveguideBogie, WithoutCrossTermsEachContactIsTheSingleContactLoop) {
  const std::vector<double> f = {300.0, 1200.0, 3500.0};
  // the leading outer wheel at the gauge corner, its flange patch, the trailing inner wheel
  const std::vector<rn::ContactPoint> all = waveguide_bogie_contacts();
  const std::vector<rn::ContactPoint> cs = {all[0], all[4], all[3]};
  const rd::WaveguideRailModel& rail = continuous_rail();
  const rn::ContactSetStructures s =
      rn::contact_set_structures(wheel(), rail, cs, f, rn::CrossCoupling::none());
  const rn::CreepFunction creep = spring_creep();
  std::vector<std::vector<rn::Receptance4>> alpha(cs.size());
  for (std::size_t a = 0; a < cs.size(); ++a)
    for (double fk : f)
      alpha[a].push_back(rn::contact_receptance(fk, hertz().normal_stiffness(), kSpeed, creep(fk),
                                                rn::LoadCoefficients::Zero()));
  const rn::ContactSetLoopResult r =
      rn::solve_contact_set_loop(s, alpha, rn::independent_sources({1, 1, 1}));
  double worst = 0.0;
  for (std::size_t a = 0; a < cs.size(); ++a) {
    const rn::LoopResult ref =
        rn::solve_loop(rn::structural_receptances(wheel(), rail, cs[a].position, f), alpha[a]);
    for (std::size_t k = 0; k < f.size(); ++k) {
      auto rel = [](const rn::Vector4c& x, const rn::Vector4c& y) {
        return (x - y).norm() / y.norm();
      };
      worst = std::max({worst, rel(r.force[k].block(4 * a, a, 4, 1), ref.force[k]),
                        rel(r.wheel_velocity[k].block(4 * a, a, 4, 1), ref.wheel_velocity[k]),
                        rel(r.rail_velocity[k].block(4 * a, a, 4, 1), ref.rail_velocity[k])});
    }
  }
  EXPECT_LT(worst, 1e-10);
}
