// The sound stage (pipeline/sound_power.hpp, docs/sound.md): the rail's integral along x against the
// closed form of the continuously supported beam, the energy bound, the columns' sums, the table
// wheel's empty column.
#include "pipeline/sound_power.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "acoustics/a_weighting.hpp"
#include "core/constants.hpp"
#include "dynamics/track.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;
using cdouble = std::complex<double>;

io::NoiseInputs sound_case(const std::string& name, const std::vector<std::string>& overrides) {
  std::vector<std::string> o = {"noise.points_per_band=6", "noise.band_max=2500.0",
                                "noise.compare=\"none\"", "grid.nx=24", "wheel.mesh_size=0.02",
                                "wheel.f_max=3500", "wheel.mode_cache=\"off\""};
  o.insert(o.end(), overrides.begin(), overrides.end());
  return io::read_noise_inputs(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/" + name, o));
}

// Int_{-inf}^{inf} |w/F(x)|^2 dx of the rail on a continuous support in closed form: with
// w/F(x) = sum_j a_j e^{-i k_j |x|} (InfiniteBeam::wave_amplitudes, Im k_j < 0),
//   Int = 2 sum_{j,l} a_j conj(a_l) / (i (k_j - conj(k_l))).
double closed_form_square_integral(const dynamics::BeamSection& beam, const dynamics::Support& s,
                                   double spacing, double frequency) {
  const double omega = 2 * kPi * frequency;
  const dynamics::InfiniteBeam b(beam, omega, s.dynamic_stiffness(omega) / spacing);
  const auto a = b.wave_amplitudes().wF;
  const auto& k = b.wavenumbers();
  cdouble sum = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int l = 0; l < 2; ++l) sum += a[j] * std::conj(a[l]) / (cdouble(0, 1) * (k[j] - std::conj(k[l])));
  return 2 * sum.real();
}

// (S2)'s integral along the rail (Gauss points a span over the window, the tails closed as
// geometric series) against the closed form of the continuously supported Timoshenko beam, from
// 100 Hz to 5 kHz: within 0.5 % (0.02 dB). The vertical direction at a contact on the centre line
// with contact angle 0, so that G_z(0, 0) is Int |w/F|^2 dx.
TEST(SoundPower, RailIntegralAlongXMatchesTheContinuousBeamsClosedForm) {
  const dynamics::TrackParameters track = dynamics::uic60_ballasted();
  const dynamics::RailModel rail(track, dynamics::TrackSupport::kContinuous, 0.3);
  noise::ContactPoint c;
  c.rail_x = 0.3;
  const std::vector<double> grid = {100, 250, 500, 1000, 2000, 3500, 5000};
  const pipeline::RailGram g = pipeline::rail_gram(pipeline::rail_line_gram(rail, {0.3}, grid, 12), {c}, 1);
  ASSERT_EQ(g.z.size(), grid.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const double exact =
        closed_form_square_integral(track.vertical, track.vertical_support, track.sleeper_spacing, grid[k]);
    const double numeric = g.z[k](0, 0).real();
    worst = std::max(worst, std::abs(numeric / exact - 1.0));
    std::printf("  %6.0f Hz: Int |w/F|^2 dx = %.4e (closed form %.4e) m^3/N^2\n", grid[k], numeric, exact);
  }
  EXPECT_LT(worst, 5e-3);
}

// The energy bound (S5) and the columns: on the 300 m curve's bogie (FE wheel, coarse mesh, bands
// to 2.5 kHz) the radiated total lies below the mechanical power the contact forces put in, in every
// band; the total column is the power sum of wheel, rail and sleepers (0.01 dB); the A-weighted
// totals follow from the bands (0.01 dB); and the wheels' radiation efficiencies stay in (0, 1.5].
TEST(SoundPower, RadiatedPowerStaysBelowTheMechanicalInputInEveryBand) {
  const io::NoiseInputs in = sound_case("curve_300m.toml", {});
  const pipeline::NoiseResult r = pipeline::run_noise(in.contact, in.noise);
  ASSERT_TRUE(r.sound);
  const pipeline::SoundResult& s = *r.sound;
  ASSERT_EQ(s.power.size(), r.axis.centres.size());
  ASSERT_TRUE(s.wheel);
  for (std::size_t b = 0; b < s.power.size(); ++b) {
    const auto& p = s.power[b];
    for (double v : p) EXPECT_TRUE(std::isfinite(v)) << "band " << b;
    const double sum = 10 * std::log10(std::pow(10, p[0] / 10) + std::pow(10, p[1] / 10) + std::pow(10, p[2] / 10));
    EXPECT_NEAR(p[3], sum, 0.01) << "band " << b;
    EXPECT_LT(p[3], s.input_power[b]) << "band " << s.centre[b] << " Hz radiates more than is put in";
    std::printf("  %6.0f Hz: wheel %5.1f rail %5.1f sleepers %5.1f total %5.1f, input %5.1f dB re 1 pW\n",
                s.centre[b], p[0], p[1], p[2], p[3], s.input_power[b]);
  }
  for (int c = 0; c < 4; ++c) {
    std::vector<double> column;
    for (const auto& p : s.power) column.push_back(p[static_cast<std::size_t>(c)]);
    EXPECT_NEAR(s.power_a[static_cast<std::size_t>(c)], acoustics::a_weighted_total(s.centre, column), 0.01);
  }
  ASSERT_EQ(s.contact_power.size(), r.wheels.size());
  for (const auto& sigma : s.wheel->efficiency)
    for (double v : sigma) {
      EXPECT_GT(v, 0.0);
      EXPECT_LT(v, 1.5);
    }
}

// The table wheel has no surface: its sound column is NaN and the note names wheel.model; the rail
// and the sleepers are still computed.
TEST(SoundPower, TableWheelLeavesTheWheelColumnEmptyNamingWheelModel) {
  const io::NoiseInputs in = sound_case("curve_300m_table.toml", {"curve.wheels=[\"leading_outer\"]"});
  const pipeline::NoiseResult r = pipeline::run_noise(in.contact, in.noise);
  ASSERT_TRUE(r.sound);
  EXPECT_NE(r.sound->wheel_note.find("wheel.model"), std::string::npos);
  for (const auto& p : r.sound->power) {
    EXPECT_TRUE(std::isnan(p[0]));
    EXPECT_TRUE(std::isfinite(p[1]));
    EXPECT_TRUE(std::isfinite(p[2]));
  }
}

}  // namespace
