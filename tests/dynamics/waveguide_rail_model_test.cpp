// Checks of the reduced waveguide rail (RailWaveguide::reduced, the Ritz basis of cross-section
// modes and static load responses), of the load patch, and of the waveguide rail as the loop's
// RailModel (dynamics/waveguide_rail_model.hpp).
#include "dynamics/waveguide_rail_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/beam_rail_model.hpp"
#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "dynamics/track.hpp"
#include "dynamics/waveguide_discrete_support.hpp"
#include "fem/mesh.hpp"
#include "support/test_helpers.hpp"

namespace rd = rollnoise::dynamics;
namespace rf = rollnoise::fem;
using cd = std::complex<double>;

namespace {

using rollnoise::test_support::db;

rd::RailWaveguide supported_uic60(double h) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  return rd::RailWaveguide(rf::mesh_polygon(rd::uic60_outline(), h), rd::rail_material(t, 0.3),
                           rd::FootSupport{t.vertical_support, t.lateral_support,
                                           t.longitudinal_support, t.sleeper_spacing});
}

// The 300 m curve's gauge-corner contact (docs/models.md Sec. 2.7): 10 mm patch, 0.52 rad.
Eigen::MatrixXd gauge_patch(const rd::RailWaveguide& rail) {
  const double gamma = 0.52;
  return rail.patch_loads(Eigen::Vector2d(-0.0335, 0.1665), 0.01,
                          Eigen::Vector2d(-std::sin(gamma), std::cos(gamma)), rd::kUic60HeadBottom);
}

Eigen::MatrixXd crown_patch(const rd::RailWaveguide& rail) {
  return rail.patch_loads(Eigen::Vector2d(0.0, 0.172), 0.01, Eigen::Vector2d(0.0, 1.0),
                          rd::kUic60HeadBottom);
}

}  // namespace

// The reduced model (RailReduction's default basis: the cross-section modes below 20 kHz at seven
// wavenumbers 0-400 rad/m and the static responses to the loads; m = 187 coordinates against
// n = 621) gives the full model's 4x4 receptance of a 10 mm load patch, at the crown and at the
// curve's gauge-corner contact, within 0.25 dB on every diagonal term at 2 and 5 kHz (measured
// 0.14 dB at most, the gauge corner's normal term at 2 kHz; 0.02 dB below 1 kHz).
TEST(RailWaveguideReduced, ContactReceptanceWithinQuarterDecibelOfFullModel) {
  const rd::RailWaveguide full = supported_uic60(0.04);
  const Eigen::MatrixXd L = crown_patch(full), G = gauge_patch(full);
  Eigen::MatrixXd both(L.rows(), 8);
  both << L, G;
  const rd::RailWaveguide reduced = full.reduced(rd::RailReduction{}, both);
  EXPECT_LT(reduced.coordinates(), full.dofs() / 3);
  for (double f : {2000.0, 5000.0}) {
    const rd::RailWaves wf = full.waves(2.0 * M_PI * f), wr = reduced.waves(2.0 * M_PI * f);
    for (const Eigen::MatrixXd* P : {&L, &G}) {
      const rd::Receptance4 a = full.contact_receptance(wf, *P, *P, 0.0);
      const rd::Receptance4 b = reduced.contact_receptance(wr, *P, *P, 0.0);
      for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(db(b(i, i)), db(a(i, i)), 0.25) << "f = " << f << ", term " << i;
    }
  }
}

// The contact points' basis of the loop (near_field_reduction: the modes below 12 kHz at the
// seven wavenumbers, the static responses at 0, 100, 400 and 1200 rad/m), each patch with its own
// basis as the loop builds it: fewer coordinates than RailReduction's default and the full model's
// 4x4 diagonal at 2 and 5 kHz within 0.1 dB at the crown and the gauge corner (measured on this
// 40 mm mesh: 0.032 dB at most; the default basis for the two points together, above: 0.14 dB).
TEST(RailWaveguideReduced, NearFieldBasisIsSmallerAndCloserToTheFullModel) {
  const rd::RailWaveguide full = supported_uic60(0.04);
  const rd::RailReduction near = rd::near_field_reduction();
  const rd::RailReductionModes modes = full.reduction_modes(near);
  const std::vector<Eigen::MatrixXd> points = {crown_patch(full), gauge_patch(full)};
  std::vector<rd::RailWaveguide> reduced;
  for (const Eigen::MatrixXd& P : points) {
    reduced.push_back(full.reduced(near, P, modes));
    EXPECT_LT(reduced.back().coordinates(), full.reduced(rd::RailReduction{}, P).coordinates());
  }
  double worst = 0.0;
  for (double f : {2000.0, 5000.0}) {
    const rd::RailWaves wf = full.waves(2.0 * M_PI * f);
    for (std::size_t p = 0; p < points.size(); ++p) {
      const Eigen::MatrixXd& P = points[p];
      const rd::Receptance4 a = full.contact_receptance(wf, P, P, 0.0);
      const rd::Receptance4 b =
          reduced[p].contact_receptance(reduced[p].waves(2.0 * M_PI * f), P, P, 0.0);
      for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(db(b(i, i)) - db(a(i, i))));
    }
  }
  EXPECT_LT(worst, 0.1);
}

// The load patch's consistent nodal loads have the unit resultant of each force and no force
// in the other directions, and the moment column applies no net axial force (a pure moment).
TEST(RailWaveguidePatch, LoadsHaveUnitResultants) {
  const rd::RailWaveguide rail = supported_uic60(0.04);
  const Eigen::MatrixXd G = gauge_patch(rail);
  Eigen::Matrix<double, 3, 4> resultant = Eigen::Matrix<double, 3, 4>::Zero();
  for (int node = 0; node < rail.dofs() / 3; ++node)
    for (int d = 0; d < 3; ++d) resultant.row(d) += G.row(rd::RailWaveguide::dof(node, d));
  const double gamma = 0.52;
  EXPECT_NEAR(resultant(1, rd::kZ), -std::sin(gamma), 1e-12);  // normal (-sin, cos)
  EXPECT_NEAR(resultant(2, rd::kZ), std::cos(gamma), 1e-12);
  EXPECT_NEAR(resultant(0, rd::kX), 1.0, 1e-12);
  EXPECT_NEAR(resultant(1, rd::kY), std::cos(gamma), 1e-12);  // tangent (n_z, -n_y)
  EXPECT_NEAR(resultant(2, rd::kY), std::sin(gamma), 1e-12);
  EXPECT_NEAR(resultant(0, rd::kRotZ), 0.0, 1e-9);
}

// The waveguide rail as the loop's RailModel: reciprocal and passive at the crown; its Laplace
// form at s = i omega equals the receptance at omega (the continuation's consistency), and at
// s = -sigma + i omega with a small decay rate it stays close (continuity, 0.5 dB at 1 %);
// the vertical receptance at 200 Hz equals the Timoshenko beam's on the same continuous
// support within 1.5 dB (the section does not deform there; the patch's local compliance adds
// ~0.5 dB).
TEST(WaveguideRailModel, ReciprocalPassiveAndContinuedToComplexFrequency) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  rd::WaveguideRailOptions o;
  o.mesh_size = 0.04;
  const rd::WaveguideRailModel rail(t, o);
  const rd::BeamRailModel beam(t, rd::TrackSupport::kContinuous, 0.0);
  for (double f : {200.0, 2000.0}) {
    const rd::Receptance4 R = rail.receptance(f);
    EXPECT_LT((R - R.transpose()).norm(), 1e-8 * R.norm()) << "f = " << f;
    const Eigen::Matrix4d dissipation = -0.5 * (R.imag() + R.imag().transpose());
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(dissipation).eigenvalues().minCoeff(),
              -1e-10 * R.norm());
    const double w = 2.0 * M_PI * f;
    EXPECT_LT((rail.receptance_laplace(cd(0.0, w)) - R).norm(), 1e-9 * R.norm());
    const rd::Receptance4 D = rail.receptance_laplace(cd(-0.01 * w * 0.02, w));
    EXPECT_NEAR(db(D(rd::kZ, rd::kZ)), db(R(rd::kZ, rd::kZ)), 0.5);
  }
  EXPECT_NEAR(db(rail.receptance(200.0)(rd::kZ, rd::kZ)),
              db(beam.receptance(200.0)(rd::kZ, rd::kZ)), 1.5);
  // Its transfers on a grid interpolate between direct evaluations (the refinement then slices
  // its lines by count, pipeline/band_lines.cpp); every frequency directly with per_octave = 0,
  // and the beams always.
  EXPECT_TRUE(rail.samples_grid());
  rd::WaveguideRailOptions direct = o;
  direct.sampling.per_octave = 0;
  EXPECT_FALSE(rd::WaveguideRailModel(t, direct).samples_grid());
  EXPECT_FALSE(beam.samples_grid());
}

// The continuation to decaying s (Re s < 0, Im omega > 0) follows each wave from the real
// frequency (RailWaveguide::continued_branch): along the vertical path s = -zeta W + i W, zeta = 0
// ... 0.1 in steps of 0.0025, the crown receptance is smooth, every second difference within 1e-3
// of the value (measured <= 8e-6 at 361, 1006 and 2500 Hz; with the plain rule Im k < 0 the
// receptance jumped where a wave crosses the real k axis: second differences 0.85-1.2 at zeta =
// 0.015-0.043, the sheet change that stopped squeal's root continuation for roots with zeta above
// ~1 %). At zeta = 0 it is the frequency-domain receptance.
TEST(WaveguideRailModel, ContinuedToDecayingRootsWithoutJumpingSheets) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  rd::WaveguideRailOptions o;
  o.mesh_size = 0.04;
  const rd::WaveguideRailModel rail(t, o);
  for (double f : {361.0, 1006.0, 2500.0}) {
    const double W = 2.0 * M_PI * f;
    std::vector<rd::Receptance4> R;
    for (int i = 0; i <= 40; ++i) R.push_back(rail.receptance_laplace(cd(-0.0025 * i * W, W)));
    EXPECT_LT((R.front() - rail.receptance(f)).norm(), 1e-9 * R.front().norm()) << "f = " << f;
    double worst = 0.0;
    for (int i = 1; i < 40; ++i)
      worst = std::max(worst, (R[i + 1] - 2.0 * R[i] + R[i - 1]).norm() / R[i].norm());
    std::printf("  %6.0f Hz: largest relative second difference along the path %.2e\n", f, worst);
    EXPECT_LT(worst, 1e-3) << "f = " << f;
  }
}

namespace {

// An archive in memory for the waveguide model's values at complex s and its samplings.
class LaplaceArchive : public rd::SamplingArchive {
 public:
  std::optional<rd::KeptSampling> read(const std::string& key) const override {
    const auto it = samplings.find(key);
    return it == samplings.end() ? std::nullopt : std::optional<rd::KeptSampling>(it->second);
  }
  void write(const std::string& key, const rd::KeptSampling& kept) const override {
    samplings[key] = kept;
  }
  std::optional<rd::KeptLaplace> read_laplace(const std::string& key) const override {
    const auto it = laplace.find(key);
    return it == laplace.end() ? std::nullopt : std::optional<rd::KeptLaplace>(it->second);
  }
  void write_laplace(const std::string& key, const rd::KeptLaplace& kept) const override {
    laplace[key] = kept;
  }
  mutable std::map<std::string, rd::KeptSampling> samplings;
  mutable std::map<std::string, rd::KeptLaplace> laplace;
};

}  // namespace

// The values at complex s kept beyond the run (GridSamplingRail::laplace_transfers with an
// archive, squeal's continuation; track.sampling_cache): the first run's function computes them
// (the same bits as without the archive) and leaves them in the archive when it goes; a later
// run's function takes them from the archive, not from the model (a value altered in the archive
// comes back altered), and computes only the s it does not hold. Frequencies computed directly
// (contact_transfers without interpolation, squeal's route 1) are kept the same way.
TEST(WaveguideRailModel, ValuesAtComplexFrequencyKeptForALaterRun) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  rd::WaveguideRailOptions o;
  o.mesh_size = 0.04;
  auto archive = std::make_shared<LaplaceArchive>();
  rd::WaveguideRailOptions kept = o;
  kept.archive = archive;
  kept.archive_identity = "test track";
  const rd::RailContact c{0.3, -0.0366, 0.52};
  const std::vector<rd::RailContactPair> pairs{{c, c}};
  const std::vector<cd> s{cd(-20.0, 2.0 * M_PI * 800.0), cd(-5.0, 2.0 * M_PI * 1500.0)};
  const rd::WaveguideRailModel plain(t, o);
  const auto reference = plain.laplace_transfers(pairs);
  {
    const rd::WaveguideRailModel first(t, kept);
    const auto at = first.laplace_transfers(pairs);
    for (const cd& z : s) ASSERT_TRUE(at(z).front() == reference(z).front());
  }
  ASSERT_EQ(archive->laplace.size(), 1u);
  ASSERT_EQ(archive->laplace.begin()->second.values.size(), s.size());
  for (auto& [z, v] : archive->laplace.begin()->second.values) v.front() *= 2.0;  // marked
  const rd::WaveguideRailModel later(t, kept);
  const auto at = later.laplace_transfers(pairs);
  for (const cd& z : s) EXPECT_TRUE(at(z).front() == 2.0 * reference(z).front());
  const cd other(-10.0, 2.0 * M_PI * 1000.0);  // not held: computed
  EXPECT_TRUE(at(other).front() == reference(other).front());

  // every frequency directly (no interpolation): kept as a sampling with no checked interval
  const std::vector<double> f{300.0, 700.0, 300.0};
  const auto direct = plain.contact_transfers(f, pairs, false);
  const auto stored = later.contact_transfers(f, pairs, false);
  ASSERT_EQ(archive->samplings.size(), 1u);
  for (std::size_t k = 0; k < f.size(); ++k) ASSERT_TRUE(stored[k].front() == direct[k].front());
  for (auto& [key, sampling] : archive->samplings)
    for (auto& v : sampling.grid.values.front()) v *= 2.0;  // marked
  const rd::WaveguideRailModel third(t, kept);
  const auto again = third.contact_transfers(f, pairs, false);
  for (std::size_t k = 0; k < f.size(); ++k)
    EXPECT_TRUE(again[k].front() == 2.0 * direct[k].front());  // (scaling by 2 is exact)
}

// Below the section's first cut-on (1.2 kHz) a vertical load at the crown sees the rail the beam
// sees: the waveguide's vertical point receptance at the crown (the loop's model: 30 mm mesh, the
// head loaded as a body, the seats spread over 0.15 m) equals the Timoshenko beam's (RailModel,
// the track file's A, I, kappa = 0.4) within 1.5 dB at 100-500 Hz (1/6 octave) on the continuous
// support and at mid-span on the sleepers (measured 0.86 and 1.05 dB). The 1.5 dB leave room for
// what the beam has not: the section squashed between the head and the pads (the head's mean
// moves ~2e-10 m/N more than the foot's, ~0.8 dB at the 300 Hz trough), the mesh's A and I
// (-2.7 %, -1.2 %) and a seat of finite length against the beam's point seats. Over a sleeper
// the seat below the load squashes the section more (head minus foot 4-5e-10 m/N, real), and
// there the bound is 2.5 dB (measured 2.33 dB at 356 Hz). The former loads (the 10 mm patch, the
// seats at one x) fail it by their local compliance: > 2 dB at 315 Hz on both supports.
TEST(WaveguideAndBeam, WaveguideAndBeamAgreeForACentredVerticalLoadBelowCutOn) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  const rd::WaveguideRailOptions o;  // head_load, seat_length = 0.15 m
  rd::WaveguideRailOptions former = o;
  former.head_load = false;
  former.seat_length = 0.0;
  const rd::WaveguideRailModel continuous(t, o);
  const rd::BeamRailModel beam_continuous(t, rd::TrackSupport::kContinuous, 0.0);
  double worst[3] = {0.0, 0.0, 0.0};  // continuous, mid-span, over a sleeper
  for (double x : {0.3, 0.0}) {
    const rd::DiscreteWaveguideRailModel discrete(t, o, x);
    const rd::BeamRailModel beam(t, rd::TrackSupport::kDiscrete, x);
    for (int i = 0; i <= 14; ++i) {
      const double f = 100.0 * std::pow(2.0, i / 6.0);
      const double d =
          db(discrete.receptance(f)(rd::kZ, rd::kZ)) - db(beam.receptance(f)(rd::kZ, rd::kZ));
      EXPECT_LT(std::abs(d), x == 0.0 ? 2.5 : 1.5) << "discrete, x = " << x << " m, f = " << f;
      double& w = worst[x == 0.0 ? 2 : 1];
      w = std::max(w, std::abs(d));
      if (x == 0.0) continue;
      const double c = db(continuous.receptance(f)(rd::kZ, rd::kZ)) -
                       db(beam_continuous.receptance(f)(rd::kZ, rd::kZ));
      EXPECT_LT(std::abs(c), 1.5) << "continuous, f = " << f << " Hz";
      worst[0] = std::max(worst[0], std::abs(c));
    }
  }
  std::printf(
      "  largest |waveguide - beam| at 100-500 Hz: continuous %.2f dB, mid-span %.2f dB, "
      "over a sleeper %.2f dB\n",
      worst[0], worst[1], worst[2]);
  // the former loads at 315 Hz (the trough of the rail-pad-sleeper-ballast system)
  const double f = 315.0;
  const double c_former = db(rd::WaveguideRailModel(t, former).receptance(f)(rd::kZ, rd::kZ)) -
                          db(beam_continuous.receptance(f)(rd::kZ, rd::kZ));
  const double d_former =
      db(rd::DiscreteWaveguideRailModel(t, former, 0.3).receptance(f)(rd::kZ, rd::kZ)) -
      db(rd::BeamRailModel(t, rd::TrackSupport::kDiscrete, 0.3).receptance(f)(rd::kZ, rd::kZ));
  std::printf("  former loads at 315 Hz: continuous %+.2f dB, discrete (mid-span) %+.2f dB\n",
              c_former, d_former);
  EXPECT_GT(c_former, 2.0);
  EXPECT_GT(d_former, 2.0);
}

// Off the centre line the eccentric normal force twists the rail, which the beam has not: at
// `tangent.toml`'s contact (-7.3 mm on the rail profile, gamma = 0.024 rad), loaded at that
// offset on the head's top (outline_contact_point), the continuous waveguide's normal receptance
// is still the beam's within 1.5 dB at 250-500 Hz (1/12 octave; measured 1.21 dB at 348 Hz on a
// finer sweep, docs/models.md Sec. 2.11). Moved to the crown polyline's -12 mm vertex (where the
// contact's normal would put it), the torsion is (12 / 7.3)^2 = 2.7 times larger and the bar
// fails (measured 1.94 dB at 357 Hz).
TEST(WaveguideAndBeam, AgreeAtTheTangentContactOffTheCentreBelowCutOn) {
  const rd::TrackParameters t = rd::uic60_ballasted();
  const rd::WaveguideRailModel waveguide(t, rd::WaveguideRailOptions{});
  const rd::BeamRailModel beam(t, rd::TrackSupport::kContinuous, 0.0);
  double at_offset = 0.0, at_vertex = 0.0;
  for (int i = 0; i <= 12; ++i) {
    const double f = 250.0 * std::pow(2.0, i / 12.0);
    const double b = db(beam.receptance(f)(rd::kZ, rd::kZ));
    at_offset = std::max(
        at_offset, std::abs(db(waveguide.contact_receptance(f, -0.0073, 0.024)(rd::kZ, rd::kZ)) - b));
    at_vertex = std::max(
        at_vertex, std::abs(db(waveguide.contact_receptance(f, -0.012, 0.024)(rd::kZ, rd::kZ)) - b));
  }
  std::printf("  largest |waveguide - beam| at 250-500 Hz: at -7.3 mm %.2f dB, at -12 mm %.2f dB\n",
              at_offset, at_vertex);
  EXPECT_LT(at_offset, 1.5);
  EXPECT_GT(at_vertex, 1.5);
}
