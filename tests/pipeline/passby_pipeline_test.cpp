// The train's axles (pipeline/passby.hpp (A1)), the pass-by pipeline against the same sources
// placed by hand through the acoustics core, its levels' consistency, the TSI normalisation and
// the CNOSSOS-EU transfer functions of a made-up bogie.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "acoustics/a_weighting.hpp"
#include "acoustics/tsi_noise.hpp"
#include "pipeline/cnossos.hpp"
#include "pipeline/passby.hpp"

namespace pl = rollnoise::pipeline;
namespace pac = rollnoise::acoustics;
using rollnoise::noise::WheelId;

namespace {

// A made-up bogie: one computed wheel (the leading outer), three bands, known powers and decays.
pl::SoundResult made_up_sound() {
  pl::SoundResult s;
  s.centre.assign({500.0, 1000.0, 2000.0});
  pl::SoundBands p;
  p.push_back({95.0, 100.0, 90.0, NAN});
  p.push_back({100.0, 102.0, 85.0, NAN});
  p.push_back({105.0, 98.0, 80.0, NAN});
  s.contact_power.push_back(p);
  s.decay_vertical.assign({3.0, 2.0, 4.0});
  s.decay_lateral.assign({1.0, 1.0, 2.0});
  return s;
}

double watts(double level) {
  return 1e-12 * std::pow(10.0, 0.1 * level);
}

}  // namespace

// Two coaches of 26.4 m, bogie centres 19 m apart, 2.5 m wheelbase: axles at 3.7 -+ 1.25 m and
// 22.7 -+ 1.25 m behind each vehicle's front, the leading one first (exact, 1e-12 m).
TEST(TrainGeometry, AxlesOfTwoCoachesLieAtTheBogieCentresPlusMinusHalfTheWheelbase) {
  const std::vector<pl::Vehicle> train(2, pl::Vehicle{26.4, 19.0, 2.5});
  const std::vector<pl::Axle> a = pl::train_axles(train);
  ASSERT_EQ(a.size(), 8u);
  const double expect[] = {2.45, 4.95, 21.45, 23.95, 28.85, 31.35, 47.85, 50.35};
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(a[i].from_front, expect[i], 1e-12) << i;
    EXPECT_EQ(a[i].leading, i % 2 == 0) << i;
  }
  EXPECT_NEAR(pl::train_length(train), 52.8, 1e-12);
}

// The pipeline's L_pAeq,Tp equals that of the same sources placed by hand (every axle's two wheels
// monopoles at the wheel centre, rails and sleepers lines of the vertical decay, the sleepers with
// their image) through the acoustics core, to 1e-9 dB; the spectrum's A-weighted total is
// L_pAeq,Tp (1e-9 dB: both over the same T_p); L_pAFmax >= L_pAeq,Tp; the energy mean of the
// F-weighted history over T_p is L_pAeq,Tp within 0.5 dB (the 0.125 s lag only shifts energy).
TEST(PassbyPipeline, EqualsTheHandPlacedSourcesAndItsLevelsAgree) {
  const pl::SoundResult s = made_up_sound();
  pl::PassbyCase pc;
  pc.train.assign(2, pl::Vehicle{26.4, 19.0, 2.5});
  pc.time_step = 0.01;
  const double V = 80.0 / 3.6;
  const pl::PassbyResult r = pl::run_passby(pc, s, {WheelId::leading_outer}, V);

  std::vector<pac::MovingPointSource> wheels;
  std::vector<pac::MovingLineSource> rails, sleepers;
  for (const pl::Axle& a : pl::train_axles(pc.train))
    for (const double y : {0.75, -0.75}) {
      pac::MovingPointSource w{{-a.from_front, y, 0.46}, pac::Directivity::kMonopole, {}};
      pac::MovingLineSource rl{
          {-a.from_front, y, -0.08}, pac::Directivity::kMonopole, {}, s.decay_vertical};
      pac::MovingLineSource sl{
          {-a.from_front, y, -0.3}, pac::Directivity::kMonopole, {}, s.decay_vertical};
      for (const auto& row : s.contact_power[0]) {
        w.power.push_back(watts(row[0]));
        rl.power.push_back(watts(row[1]));
        sl.power.push_back(watts(row[2]));
      }
      wheels.push_back(w), rails.push_back(rl), sleepers.push_back(sl);
    }
  const double t0 = r.time.front();
  const int steps = static_cast<int>(r.time.size());
  pac::PassbyHistory h = pac::passby_history(wheels, rails, pc.geometry, V, t0, 0.01, steps);
  h.mean_square += pac::passby_history({}, sleepers, pc.geometry, V, t0, 0.01, steps).mean_square;
  const std::vector<double> pa2 = pac::a_weighted_mean_square(h, s.centre);
  EXPECT_NEAR(r.leq_a, pac::equivalent_level(h.time, pa2, 0.0, r.passage_time), 1e-9);

  double sum = 0.0;
  for (std::size_t b = 0; b < r.centre.size(); ++b)
    sum += std::pow(10.0, 0.1 * (r.spectrum[b][3] + pac::a_weighting(r.centre[b])));
  EXPECT_NEAR(10.0 * std::log10(sum), r.leq_a, 1e-9);
  EXPECT_GE(r.lmax_a, r.leq_a);
  double energy = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < r.time.size(); ++k)
    if (r.time[k] >= 0.0 && r.time[k] < r.passage_time)
      energy += std::pow(10.0, 0.1 * r.level_a[k]), ++n;
  EXPECT_NEAR(10.0 * std::log10(energy / n), r.leq_a, 0.5);
  EXPECT_GE(r.tel, r.leq_a);  // the whole event's energy over T_p
  for (const WheelId w : r.source_wheel) EXPECT_EQ(w, WheelId::leading_outer);
  EXPECT_TRUE(std::isnan(r.limit_a));
}

// passby.rail_directivity: the receiver (7.5 m out, 1.2 m up: the rails' centre lines 9-10 deg
// below it) hears the rails' vertical dipole below their monopole, and the lateral dipole above it
// by at most 10 lg 3 = 4.8 dB (the dipole's on-axis gain); the wheels' and sleepers' columns do
// not move (1e-12 dB).
TEST(PassbyPipeline, RailDirectivityOrdersTheRailsLevel) {
  const pl::SoundResult s = made_up_sound();
  pl::PassbyCase pc;
  pc.train.assign(2, pl::Vehicle{26.4, 19.0, 2.5});
  const double V = 80.0 / 3.6;
  std::vector<pl::PassbyResult> r;
  for (const pac::Directivity d :
       {pac::Directivity::kMonopole, pac::Directivity::kDipoleZ, pac::Directivity::kDipoleY}) {
    pc.rail_directivity = d;
    r.push_back(pl::run_passby(pc, s, {WheelId::leading_outer}, V));
  }
  std::printf("  rail L_eq,A: monopole %.2f, vertical dipole %.2f, lateral dipole %.2f dB(A)\n",
              r[0].spectrum_a[1], r[1].spectrum_a[1], r[2].spectrum_a[1]);
  EXPECT_LT(r[1].spectrum_a[1], r[0].spectrum_a[1] - 6.0);
  EXPECT_GT(r[2].spectrum_a[1], r[0].spectrum_a[1]);
  EXPECT_LT(r[2].spectrum_a[1], r[0].spectrum_a[1] + 10 * std::log10(3.0));
  for (const std::size_t c : {0u, 2u})
    for (std::size_t k = 1; k < 3; ++k) EXPECT_NEAR(r[k].spectrum_a[c], r[0].spectrum_a[c], 1e-12);
}

// TSI Noise (Regulation (EU) No 1304/2014 Annex 6.2.2.3): at 80 km/h the normalised level is the
// level; at 160 km/h it is 30 lg 2 = 9.03 dB lower (1e-12); Table 4's coach limit is 79 dB; an
// unknown category is refused.
TEST(TsiNoise, NormalisationToEightyAndTheCoachLimit) {
  EXPECT_NEAR(pac::tsi_normalised_80(80.0, 80.0 / 3.6), 80.0, 1e-12);
  EXPECT_NEAR(pac::tsi_normalised_80(80.0, 160.0 / 3.6), 80.0 - 30.0 * std::log10(2.0), 1e-12);
  EXPECT_EQ(pac::tsi_passby_limit("coach"), 79.0);
  EXPECT_THROW(pac::tsi_passby_limit("tram"), std::invalid_argument);
}

// The made-up bogie's transfer functions (cnossos.hpp (C1)): every wheel of the bogie takes the
// leading outer wheel's powers, so per axle the vehicle's power is two wheels', the track's two
// rails' and sleepers'; minus the effective roughness (1e-9 dB). The bands below 500 Hz and above
// 2 kHz hold the nearest computed band's values, marked not computed.
TEST(CnossosTransfer, MadeUpBogiePerAxleMinusTheRoughness) {
  const pl::SoundResult s = made_up_sound();
  const std::vector<double> roughness{1.0, -2.0, -5.0};
  const pl::CnossosTransfer t = pl::cnossos_transfer(s, {WheelId::leading_outer}, roughness);
  const std::size_t i1000 = 13;  // 1 kHz is the 14th of the 24 bands
  ASSERT_EQ(pl::cnossos_centres()[i1000], 1000.0);
  EXPECT_NEAR(t.vehicle[i1000], 10.0 * std::log10(2.0 * std::pow(10.0, 10.0)) + 2.0, 1e-9);
  EXPECT_NEAR(t.track[i1000],
              10.0 * std::log10(2.0 * (std::pow(10.0, 10.2) + std::pow(10.0, 8.5))) + 2.0, 1e-9);
  EXPECT_TRUE(t.computed[i1000]);
  EXPECT_FALSE(t.computed[0]);
  EXPECT_EQ(t.vehicle[0], t.vehicle[10]);  // 50 Hz filled from 500 Hz
  EXPECT_EQ(t.track[23], t.track[16]);     // 10 kHz filled from 2 kHz
}

// The Directive's equations by hand (Directive (EU) 2015/996 Annex II 2.3.2, 2.3.8-2.3.10) for
// a made-up flat transfer (L_H,TR = 100 dB, L_H,VEH = 95 dB, L_R,TOT = -3 dB re 1 um), N_a = 4,
// Q = 10 vehicles/h, v = 80 km/h, equal the pipeline's per band and A-weighted (1e-9 dB).
TEST(CnossosLinePower, DirectiveEquationsByHand) {
  pl::CnossosTransfer t;
  t.track.fill(100.0), t.vehicle.fill(95.0), t.roughness.fill(-3.0), t.computed.fill(true);
  const pl::CnossosLinePower p = pl::cnossos_line_power(t, 4.0, 10.0, 80.0);
  const double tr = -3.0 + 100.0 + 10.0 * std::log10(4.0),
               veh = -3.0 + 95.0 + 10.0 * std::log10(4.0);
  const double line = 10.0 * std::log10(std::pow(10.0, tr / 10.0) + std::pow(10.0, veh / 10.0)) +
                      10.0 * std::log10(10.0 / (1000.0 * 80.0));
  double a = 0.0;
  for (std::size_t i = 0; i < pl::kCnossosBands; ++i) {
    EXPECT_NEAR(p.band[i], line, 1e-9);
    a += std::pow(10.0, 0.1 * (line + pac::a_weighting(pl::cnossos_centres()[i])));
  }
  EXPECT_NEAR(p.total_a, 10.0 * std::log10(a), 1e-9);
}
