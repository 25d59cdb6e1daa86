// The band limits of a case (noise.band_min/band_max, and frequency.spacing = "third-octave"
// between frequency.f_min and f_max) select 1/3-octave bands by nominal centre: the default
// band_max = 5000 Hz includes the 5 kHz band, whose exact base-10 centre is 5011.9 Hz.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "pipeline/frequency_axis.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;

// The paper's Hertzian case (34 x 25, V = 13.9 m/s): Nyquist V/(2 dx) = 14.5 kHz, above every band
// here.
pipeline::ContactCase fine_hertz_case() {
  return io::read_contact_case(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/hertz_paper.toml"));
}

double exact_centre(int n) {
  return 1000.0 * std::pow(10.0, n / 10.0);
}

TEST(BandAxis, DefaultLimitsIncludeTheFiveKilohertzBand) {
  const pipeline::NoiseCase nc;  // band_min = 100, band_max = 5000 Hz
  ASSERT_EQ(nc.band_max, 5000.0);
  const pipeline::BandAxis axis = pipeline::band_axis(fine_hertz_case(), nc);
  ASSERT_EQ(axis.centres.size(), 18u);  // nominal 100, 125, ..., 4000, 5000 Hz
  EXPECT_NEAR(axis.centres.front(), exact_centre(-10), 1e-9);
  EXPECT_NEAR(axis.centres.back(), exact_centre(7), 1e-9);  // 5011.9 Hz
  // the narrow-band frequencies fill the 5 kHz band up to its upper edge
  EXPECT_EQ(axis.frequency.size(), 18u * nc.points_per_band);
  EXPECT_GT(axis.frequency.back(), 5000.0);
  EXPECT_LT(axis.frequency.back(), exact_centre(7) * std::pow(10.0, 0.05));
}

TEST(BandAxis, NominalLimitsSelectTheirOwnBands) {
  pipeline::NoiseCase nc;
  nc.band_min = 400.0;   // exact centre 398.1 Hz
  nc.band_max = 1600.0;  // exact centre 1584.9 Hz
  const pipeline::BandAxis axis = pipeline::band_axis(fine_hertz_case(), nc);
  ASSERT_EQ(axis.centres.size(), 7u);  // 400, 500, 630, 800, 1000, 1250, 1600
  EXPECT_NEAR(axis.centres.front(), exact_centre(-4), 1e-9);
  EXPECT_NEAR(axis.centres.back(), exact_centre(2), 1e-9);
}

TEST(BandAxis, ThirdOctaveFrequencyAxisUsesTheSameRule) {
  pipeline::FrequencyAxis a;
  a.spacing = "third-octave";
  a.f_min = 400.0;
  a.f_max = 5000.0;
  const auto f = pipeline::frequencies(a);
  ASSERT_EQ(f.size(), 12u);
  EXPECT_NEAR(f.front(), exact_centre(-4), 1e-9);
  EXPECT_NEAR(f.back(), exact_centre(7), 1e-9);
  a.f_min = 0.0;  // from the lowest band of the axis, 0.1 Hz
  EXPECT_NEAR(pipeline::frequencies(a).front(), 0.1, 1e-12);
}

}  // namespace
