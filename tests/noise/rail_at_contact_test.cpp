// The waveguide rail loaded at the contact inside the loop (WaveguideRailModel::contact_receptance*,
// noise::rail_contact_receptance, the loop's structural_receptances with the rail model): where a
// contact lands on the outline, the centred contact against the crown receptance, reciprocity and
// passivity at the 300 m curve's gauge-corner contact against the rigid move of the crown's
// receptance, and the interpolation of contact_receptances() on a coarse grid.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <complex>
#include <vector>

#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "noise/loop.hpp"
#include "noise/stability.hpp"
#include "noise_fixture.hpp"

using namespace noise_test;
using cd = std::complex<double>;

namespace {

double db(cd z) {
  return 20.0 * std::log10(std::abs(z));
}

// The leading outer wheel's contact of cases/curve_300m.toml (docs/noise_loop.md Sec. 7.2):
// 36.6 mm to the gauge side, contact angle 0.524 rad.
rn::ContactPosition curve_contact() {
  rn::ContactPosition p;
  p.rail_offset_y = -0.0366;
  p.contact_angle = 0.524;
  return p;
}

const rd::WaveguideRailModel& rail_40mm() {
  static const rd::WaveguideRailModel rail = [] {
    rd::WaveguideRailOptions o;
    o.mesh_size = 0.04;
    return rd::WaveguideRailModel(rd::uic60_ballasted(), o);
  }();
  return rail;
}

void expect_reciprocal_and_passive(const rd::Receptance4& R, const char* what) {
  EXPECT_LT((R - R.transpose()).norm(), 1e-8 * R.norm()) << what;
  const Eigen::Matrix4d dissipation = -0.5 * (R.imag() + R.imag().transpose());
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(dissipation).eigenvalues().minCoeff(),
            -1e-10 * R.norm())
      << what;
}

}  // namespace

// The contact lands at its own lateral offset on the head's top, where the top spans it: the
// crown contact (0, 0) on the crown (0, 172) mm, `tangent.toml`'s (-7.3 mm, 0.024 rad) at
// z = 172 - 7.3/12 x 0.2 mm on the crown's edge (not the -12 mm vertex its normal would pick), a
// 0.3 rad contact at -20 mm on the edge from (-12, 171.8) to (-25, 170.8) mm, mirrored at +20 mm.
// Beyond the top (the 300 m curve's flange-root contact at -36.6 mm, 0.524 rad; the outline's
// head is 72 mm wide) where the outline's normal is the contact normal: the gauge-corner vertex
// (-33, 166.5) mm between the edges of normal angle 0.49 and 1.23 rad. Exact to round-off.
TEST(RailContactPoint, AtTheContactsOffsetOnTheHeadElseWhereTheNormalsCoincide) {
  const std::vector<Eigen::Vector2d> outline = rd::uic60_outline();
  auto at = [&](double offset, double angle) {
    return rd::outline_contact_point(outline, rd::kUic60HeadBottom, offset, angle);
  };
  EXPECT_LT((at(0.0, 0.0) - Eigen::Vector2d(0.0, 0.172)).norm(), 1e-12);
  EXPECT_LT((at(-0.0073, 0.024) - Eigen::Vector2d(-0.0073, 0.172 - 0.0073 / 0.012 * 0.0002)).norm(),
            1e-12);
  EXPECT_LT((at(-0.02, 0.3) - Eigen::Vector2d(-0.02, 0.1718 - 8.0 / 13.0 * 0.001)).norm(), 1e-12);
  EXPECT_LT((at(0.02, -0.3) - Eigen::Vector2d(0.02, 0.1718 - 8.0 / 13.0 * 0.001)).norm(), 1e-12);
  EXPECT_LT((at(-0.0366, 0.524) - Eigen::Vector2d(-0.033, 0.1665)).norm(), 1e-12);
  // the normal no longer moves a point the top spans: -29 mm on the 0.49 rad edge whatever the
  // angle
  for (double angle : {std::atan2(4.3, 8.0), 0.0, 1.0})
    EXPECT_LT((at(-0.029, angle) - Eigen::Vector2d(-0.029, 0.16865)).norm(), 1e-9);
}

// The cubic Hermite interpolation in ln f of single-degree-of-freedom receptances
// 1 / (1 - (f/f0)^2 + i eta) with the pads' damping, eta = 0.25, f0 = 1, 1.1, 1.2, 1.3 kHz on
// the diagonal, on the loop's 89-5623 Hz range (864 frequencies): the error falls with the grid
// step at the scheme's order (>= 2.5 between 24 and 48 points per octave; measured 3.6), and is
// below 0.05 dB at 24 points per octave (measured 0.013 dB); the samples are returned exactly.
// (A steel resonance, eta = 0.02, is not resolved by 24 points per octave: 1.4 dB; the rail's
// own error is measured by bench/rail_contact_bench.cpp, docs/record/waveguide_rail.md Sec. 8.)
TEST(ReceptanceInterpolation, ConvergesAtThirdOrderOnAResonance) {
  const double f0 = 1000.0, eta = 0.25, lo = 89.1, hi = 5623.4;
  auto sdof = [&](double f) {
    rd::Receptance4 r = rd::Receptance4::Zero();
    for (int i = 0; i < 4; ++i)
      r(i, i) = 1e-9 / (1.0 - std::pow(f / (f0 * (1.0 + 0.1 * i)), 2) + cd(0.0, eta));
    return r;
  };
  std::vector<double> fine;
  for (int i = 0; i <= 864; ++i) fine.push_back(lo * std::pow(hi / lo, i / 864.0));
  auto max_error_db = [&](int per_octave) {
    const int n = static_cast<int>(std::ceil(per_octave * std::log2(hi / lo)));
    std::vector<double> grid;
    std::vector<rd::Receptance4> values;
    for (int i = 0; i <= n; ++i) {
      grid.push_back(i == n ? hi : lo * std::pow(hi / lo, double(i) / n));
      values.push_back(sdof(grid.back()));
    }
    const std::vector<rd::Receptance4> r = rd::interpolate_receptances(grid, values, fine);
    double e = 0.0;
    for (std::size_t k = 0; k < fine.size(); ++k)
      for (int i = 0; i < 4; ++i)
        e = std::max(e, std::abs(db(r[k](i, i)) - db(sdof(fine[k])(i, i))));
    const std::vector<rd::Receptance4> at_samples = rd::interpolate_receptances(grid, values, grid);
    for (std::size_t k = 0; k < grid.size(); ++k) EXPECT_EQ(at_samples[k], values[k]);
    return e;
  };
  const double e24 = max_error_db(24), e48 = max_error_db(48);
  EXPECT_GT(std::log2(e24 / e48), 2.5) << e24 << " dB, " << e48 << " dB";
  EXPECT_LT(e24, 0.05);
}

// A centred contact (offset 0, angle 0) is loaded at the crown with the crown's patch: its
// receptance is the crown receptance (RailModel::receptance) to round-off, at 1 kHz.
TEST(WaveguideRailAtContact, CentredContactEqualsTheCrownReceptance) {
  const rd::WaveguideRailModel& rail = rail_40mm();
  const rd::Receptance4 crown = rail.receptance(1000.0);
  const rd::Receptance4 centred = rail.contact_receptance(1000.0, 0.0, 0.0);
  EXPECT_LT((centred - crown).norm(), 1e-10 * crown.norm());
  // and the loop's rail in the contact frame is that receptance (the contact frame is the
  // global one at gamma = 0)
  EXPECT_LT((rn::rail_contact_receptance(rail, 1000.0, rn::ContactPosition{}) - crown).norm(),
            1e-10 * crown.norm());
}

// At the 300 m curve's gauge-corner contact the 4x4 the loop and squeal use is reciprocal
// (symmetric to 1e-8) and passive (-Im R positive semi-definite to 1e-10 |R|) at 500 Hz and
// 2 kHz; at s = i omega the continuation equals it (1e-9); it is not the crown's receptance moved
// rigidly (what the loop used before): a diagonal term differs by more than 1 dB at each
// frequency (measured on this 40 mm mesh: up to 2.6 dB at 500 Hz and 3.0 dB at 2 kHz,
// docs/models.md Sec. 2.7).
TEST(WaveguideRailAtContact, CurveContactReciprocalPassiveAndNotTheRigidMove) {
  const rd::WaveguideRailModel& rail = rail_40mm();
  const rn::ContactPosition p = curve_contact();
  for (double f : {500.0, 2000.0}) {
    const rd::Receptance4 R = rn::rail_contact_receptance(rail, f, p);
    expect_reciprocal_and_passive(R, f == 500.0 ? "500 Hz" : "2 kHz");
    const double w = 2.0 * M_PI * f;
    EXPECT_LT((rn::rail_receptance_laplace(rail, cd(0.0, w), p) - R).norm(), 1e-9 * R.norm());
    const rd::Receptance4 moved = rn::to_contact_frame(
        rd::move_point(rd::embed(rail.receptance(f)), Eigen::Vector3d(0.0, p.rail_offset_y, 0.0)),
        p.contact_angle);
    double largest = 0.0;
    for (int i = 0; i < 4; ++i) largest = std::max(largest, std::abs(db(R(i, i)) - db(moved(i, i))));
    EXPECT_GT(largest, 1.0) << "f = " << f;
  }
}

// The loop's structures with the rail at the contact: the contact-frame rail is the model's
// contact_receptances() on the frequencies, and the global 6x6 the velocities use maps back to it
// (T^T (T R T^T) T = R, to round-off).
TEST(WaveguideRailAtContact, LoopStructuresCarryTheContactReceptance) {
  const rd::WaveguideRailModel& rail = rail_40mm();
  const rn::ContactPosition p = curve_contact();
  const std::vector<double> f{500.0, 2000.0};
  const rn::StructuralReceptances s = rn::structural_receptances(wheel(), rail, p, f);
  for (std::size_t k = 0; k < f.size(); ++k) {
    const rd::Receptance4 R = rail.contact_receptance(f[k], p.rail_offset_y, p.contact_angle);
    EXPECT_LT((s.rail_contact[k] - R).norm(), 1e-12 * R.norm());
    EXPECT_LT((rn::to_contact_frame(s.rail[k], p.contact_angle) - R).norm(), 1e-12 * R.norm());
  }
}

// The transfer between two contacts on one rail (the gauge-corner contact a and a crown contact b,
// e.g. the other axle's wheel): at x = 0 the two section points' 8x8 receptance
// [[R_aa, R_ab], [R_ba, R_bb]] is reciprocal (symmetric to 1e-8) and passive (-Im part positive
// semi-definite to 1e-10 |R|); the transfer is continuous at x -> 0 (1 mm: within 1 % of x = 0);
// R_ab(x) = R_ba(-x)^T; and the pair's transfer from a to itself is a's point receptance (1e-8:
// the same Ritz space). At 1 kHz, 40 mm mesh, with the former loads (the 10 mm patches): with the
// loop's loads (the head as a body, RailWaveguide::head_loads) two contacts at one x share the
// head's six rigid motions, so the 8x8 has rank 6 and its two zero eigenvalues are round-off of
// Eqs. W4 and W6 (which agree to ~1e-8): there the test asserts the rank and the symmetry.
TEST(WaveguideRailAtContact, TransferBetweenTwoContactsReciprocalPassiveAndContinuousAtZero) {
  static const rd::WaveguideRailModel former_rail = [] {
    rd::WaveguideRailOptions o;
    o.mesh_size = 0.04;
    o.head_load = false;
    return rd::WaveguideRailModel(rd::uic60_ballasted(), o);
  }();
  {
    const rd::WaveguideRailModel& rail = rail_40mm();
    const double f = 1000.0, oa = -0.0366, ga = 0.524;
    Eigen::Matrix<cd, 8, 8> R;
    R << rail.contact_receptance(f, oa, ga), rail.contact_transfer(f, oa, ga, 0.0, 0.0, 0.0),
        rail.contact_transfer(f, 0.0, 0.0, oa, ga, 0.0), rail.contact_receptance(f, 0.0, 0.0);
    EXPECT_LT((R - R.transpose()).norm(), 1e-8 * R.norm());
    const Eigen::JacobiSVD<Eigen::Matrix<cd, 8, 8>> svd(R);
    EXPECT_LT(svd.singularValues()(6), 1e-6 * svd.singularValues()(0)) << "head loads: rank 6";
    EXPECT_GT(svd.singularValues()(5), 1e-6 * svd.singularValues()(0));
  }
  const rd::WaveguideRailModel& rail = former_rail;
  const double f = 1000.0, oa = -0.0366, ga = 0.524, ob = 0.0, gb = 0.0;
  const rd::Receptance4 aa = rail.contact_transfer(f, oa, ga, oa, ga, 0.0);
  EXPECT_LT((aa - rail.contact_receptance(f, oa, ga)).norm(), 1e-8 * aa.norm());
  Eigen::Matrix<cd, 8, 8> R;
  R << rail.contact_receptance(f, oa, ga), rail.contact_transfer(f, oa, ga, ob, gb, 0.0),
      rail.contact_transfer(f, ob, gb, oa, ga, 0.0), rail.contact_receptance(f, ob, gb);
  EXPECT_LT((R - R.transpose()).norm(), 1e-8 * R.norm());
  const Eigen::Matrix<double, 8, 8> dissipation = -0.5 * (R.imag() + R.imag().transpose());
  using Solver8 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 8, 8>>;
  EXPECT_GE(Solver8(dissipation).eigenvalues().minCoeff(), -1e-10 * R.norm());
  const rd::Receptance4 ab0 = rail.contact_transfer(f, oa, ga, ob, gb, 0.0);
  EXPECT_LT((rail.contact_transfer(f, oa, ga, ob, gb, 1e-3) - ab0).norm(), 1e-2 * ab0.norm());
  const double wheelbase = 2.5;
  EXPECT_LT((rail.contact_transfer(f, oa, ga, ob, gb, wheelbase) -
             rail.contact_transfer(f, ob, gb, oa, ga, -wheelbase).transpose())
                .norm(),
            1e-12 * ab0.norm());
}
