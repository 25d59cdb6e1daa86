// Checks of the roughness spectra, their conversion to frequency and the contact filter
// (src/noise/roughness*.hpp); the spectrum files: tests/io/roughness_file_test.cpp.
#include "noise/roughness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <string>

#include "core/errors.hpp"

namespace rn = rollnoise::noise;

namespace {

rn::ContactFilter no_filter() {
  rn::ContactFilter f;
  f.model = rn::ContactFilterModel::kNone;
  return f;
}

rn::ContactFilter filter(rn::ContactFilterModel model, double a, double b,
                         rn::ContactWeighting w = rn::ContactWeighting::kElasticHalfSpace) {
  rn::ContactFilter f;
  f.model = model;
  f.weighting = w;
  f.a = a;
  f.b = b;
  return f;
}

}  // namespace

TEST(RoughnessSpectra, Iso3095LimitValuesAtSelectedBands) {
  const rn::RoughnessSpectrum iso = rn::iso3095_2013_rail_limit();
  ASSERT_EQ(iso.wavelength.size(), 35u);
  // (wavelength m, dB re 1 um) from the CNOSSOS-EU table of the EN ISO 3095:2013 limit
  const double expect[][2] = {{0.25, 13.0}, {0.1, 4.9},       {0.04, -3.2},   {0.0315, -5.0},
                              {0.01, -8.0}, {0.00315, -11.0}, {0.001, -14.0}, {1.0, 17.1}};
  for (const auto& e : expect) EXPECT_NEAR(iso.level_at(e[0]), e[1], 1e-12) << e[0] << " m";
  // Between band centres: linear in log(wavelength) -> 5 cm to 4 cm halfway in log is the mean.
  EXPECT_NEAR(iso.level_at(std::sqrt(0.05 * 0.04)), 0.5 * (-1.1 - 3.2), 1e-12);
  // Held constant beyond the table.
  EXPECT_EQ(iso.level_at(10.0), 17.1);
  EXPECT_EQ(iso.level_at(1e-5), -14.0);
}

TEST(RoughnessConversion, FrequencyIsSpeedOverWavelength) {
  const rn::RoughnessSpectrum iso = rn::iso3095_2013_rail_limit();
  rn::RoughnessSpectrum quiet{"quiet", {1.0, 1e-3}, {-80.0, -80.0}};  // negligible wheel
  const double V = 100.0 / 3.6;
  const rn::ContactRoughness r(quiet, iso, V, no_filter());
  for (double lambda : {0.25, 0.05, 0.008}) {
    const double f = V / lambda;
    EXPECT_NEAR(r.combined_level(f), iso.level_at(lambda), 1e-6) << lambda;
    EXPECT_NEAR(r.level(f), iso.level_at(lambda), 1e-6) << lambda;
  }
  // Doubling the speed moves the spectrum up by one octave in frequency.
  const rn::ContactRoughness fast(quiet, iso, 2.0 * V, no_filter());
  for (double f : {200.0, 630.0, 2000.0}) EXPECT_NEAR(fast.level(2.0 * f), r.level(f), 1e-6);
}

TEST(RoughnessConversion, WheelAndRailAddByEnergy) {
  EXPECT_NEAR(rn::energy_sum_db(0.0, 0.0), 10.0 * std::log10(2.0), 1e-12);
  EXPECT_NEAR(rn::energy_sum_db(5.0, -5.0), 5.0 + 10.0 * std::log10(1.1), 1e-12);
  EXPECT_NEAR(rn::energy_sum_db(400.0, 400.0), 400.0 + 10.0 * std::log10(2.0),
              1e-9);  // no overflow
  rn::RoughnessSpectrum a{"a", {1.0, 1e-3}, {3.0, 3.0}}, b{"b", {1.0, 1e-3}, {-7.0, -7.0}};
  const rn::ContactRoughness r(a, b, 20.0, no_filter());
  EXPECT_NEAR(r.level(500.0), 3.0 + 10.0 * std::log10(1.1), 1e-12);
}

TEST(ContactFilter, CorrelatedModelsAreClosedForms) {
  const rn::ContactFilter uniform =
      filter(rn::ContactFilterModel::kCorrelated, 6e-3, 4e-3, rn::ContactWeighting::kUniform);
  const rn::ContactFilter punch = filter(rn::ContactFilterModel::kCorrelated, 6e-3, 4e-3);
  for (double ka : {0.05, 0.5, 1.0, 2.5, 5.0, 12.0}) {
    const double h = 2.0 * std::cyl_bessel_j(1.0, ka) / ka;  // area average, Thompson 2009
    EXPECT_NEAR(uniform.squared(ka / 6e-3), h * h, 1e-12) << "ka = " << ka;
    const double p = std::sin(ka) / ka;  // rigid-punch weighting
    EXPECT_NEAR(punch.squared(ka / 6e-3), p * p, 1e-12) << "ka = " << ka;
  }
}

TEST(ContactFilter, UnityAtLongWavelengthsStrongAttenuationBelowPatchSize) {
  const double a = 7.18e-3, b = 5.29e-3;  // the paper's Hertzian patch
  for (auto weighting : {rn::ContactWeighting::kElasticHalfSpace, rn::ContactWeighting::kUniform})
    for (auto model : {rn::ContactFilterModel::kCorrelated, rn::ContactFilterModel::kIsotropic}) {
      const rn::ContactFilter f = filter(model, a, b, weighting);
      EXPECT_GT(f.band_db(2.0 * M_PI / 1.0), -0.05);    // 1 m: 0 dB
      EXPECT_GT(f.band_db(2.0 * M_PI / 0.25), -0.2);    // 25 cm
      EXPECT_LT(f.band_db(2.0 * M_PI / 0.005), -15.0);  // 5 mm, shorter than the patch 2a
      // Band levels fall from octave to octave between 10 cm and 2 mm (within an octave they may
      // ripple: the zeros of W).
      for (double lambda = 0.1; lambda > 0.002; lambda /= std::pow(10.0, 0.1)) {
        const double here = f.band_db(2.0 * M_PI / lambda);
        const double octave_shorter = f.band_db(2.0 * M_PI / (0.5 * lambda));
        EXPECT_LT(octave_shorter, here - 0.01) << "lambda = " << lambda;
      }
    }
  // Lateral averaging of isotropic roughness attenuates more than the correlated model (first
  // lobe of W, ka < pi).
  const rn::ContactFilter iso = filter(rn::ContactFilterModel::kIsotropic, a, b);
  const rn::ContactFilter cor = filter(rn::ContactFilterModel::kCorrelated, a, b);
  for (double lambda : {0.04, 0.02}) {
    const double k = 2.0 * M_PI / lambda;
    EXPECT_LT(iso.band_db(k), cor.band_db(k) - 0.3) << lambda;
  }
}

TEST(ContactFilter, IsotropicTendsToCorrelatedForNarrowPatch) {
  for (auto weighting : {rn::ContactWeighting::kElasticHalfSpace, rn::ContactWeighting::kUniform}) {
    const rn::ContactFilter iso = filter(rn::ContactFilterModel::kIsotropic, 6e-3, 1e-7, weighting);
    const rn::ContactFilter cor = filter(rn::ContactFilterModel::kCorrelated, 6e-3, 0.0, weighting);
    for (double k : {50.0, 500.0, 3000.0}) EXPECT_NEAR(iso.squared(k), cor.squared(k), 1e-6);
  }
}

TEST(ContactFilter, DefaultModelWithin3dBOfCnossosTableFor920mmWheel) {
  // CNOSSOS-EU Appendix G Table G-3, wheel load 100 kN, wheel diameter 920 mm (dB), against the
  // default filter (elastic half-space weighting, isotropic roughness, n = 2) for the Hertzian
  // patch of the paper's 98.1 kN case. Agreement within 3 dB from 63 mm to 3.15 mm; below that the
  // table levels off at -25 ... -30 dB while the model keeps falling (docs/models.md).
  const double lambda_mm[] = {63, 50, 40, 31.5, 25, 20, 16, 12.5, 10, 8, 6.3, 5, 4, 3.15};
  const double cnossos[] = {-1.0,  -1.8,  -3.2,  -5.4,  -8.7,  -12.2, -16.7,
                            -17.7, -17.8, -20.7, -22.1, -22.8, -24.0, -24.5};
  rn::ContactFilter f;  // defaults
  f.a = 7.18e-3;
  f.b = 5.29e-3;
  for (int i = 0; i < 14; ++i)
    EXPECT_NEAR(f.band_db(2.0 * M_PI / (lambda_mm[i] * 1e-3)), cnossos[i], 3.0)
        << lambda_mm[i] << " mm";
}

TEST(ContactRoughness, PsdIntegratesToBandMeanSquare) {
  const rn::ContactRoughness r(rn::wheel_roughness_cast_iron_block(), rn::iso3095_2013_rail_limit(),
                               80.0 / 3.6, no_filter());
  for (double fc : rn::third_octave_centres(100.0, 5000.0)) {
    // Integrate the PSD over the band (trapezoid in log f) and compare with r0^2 10^{L/10}.
    const double lo = fc * std::pow(10.0, -0.05), hi = fc * std::pow(10.0, 0.05);
    const int n = 200;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double f = lo * std::pow(hi / lo, double(i) / n);
      const double w = (i == 0 || i == n) ? 0.5 : 1.0;
      sum += w * r.psd(f) * f * std::log(hi / lo) / n;
    }
    const double band = 1e-12 * std::pow(10.0, r.level(fc) / 10.0);
    EXPECT_NEAR(10.0 * std::log10(sum / band), 0.0, 0.15) << "band " << fc << " Hz";
  }
  EXPECT_NEAR(r.line_amplitude(1000.0, 2.0), std::sqrt(2.0 * r.psd(1000.0) * 2.0), 1e-20);
  // With the filter the PSD carries the band-averaged filter of the band centred at f.
  const rn::ContactRoughness filtered(rn::wheel_roughness_cast_iron_block(),
                                      rn::iso3095_2013_rail_limit(), 80.0 / 3.6,
                                      filter(rn::ContactFilterModel::kCorrelated, 6e-3, 0.0));
  // (the correlated model is cheap; the isotropic one costs a quadrature per point)
  const double k = 2.0 * M_PI * 2000.0 / (80.0 / 3.6);
  EXPECT_NEAR(10.0 * std::log10(filtered.psd(2000.0) / r.psd(2000.0)), filtered.filter().band_db(k),
              1e-9);
}

TEST(ThirdOctaveBands, CentresAreExactBase10) {
  const auto c = rn::third_octave_centres(100.0, 5000.0);
  ASSERT_EQ(c.size(), 18u);  // 100 ... 5012 Hz: nominal 100 ... 5000 Hz
  EXPECT_DOUBLE_EQ(c.front(), 100.0);
  EXPECT_NEAR(c[10], 1000.0, 1e-9);
  for (std::size_t i = 1; i < c.size(); ++i)
    EXPECT_NEAR(c[i] / c[i - 1], std::pow(10.0, 0.1), 1e-12);
  EXPECT_NEAR(rn::third_octave_bandwidth(1000.0), 230.77, 0.01);
}

// The limits name bands by their nominal centres (IEC 61260-1: 100, 125, 160, 200, 250, 315, 400,
// 500, 630, 800, 1000, ..., 5000 Hz), whose exact base-10 centres lie up to 2.5 % away (398.1 for
// 400, 5011.9 for 5000): each limit selects the band that contains it.
TEST(ThirdOctaveBands, LimitsSelectBandsByNominalCentre) {
  const double nominal[] = {100, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000,
                            1250, 1600, 2000, 2500, 3150, 4000, 5000, 6300, 8000, 10000};
  const int n = static_cast<int>(std::size(nominal));
  for (int i = 0; i < n; ++i) {
    // the band of a nominal centre is the band whose exact centre 1000 10^{k/10} is within 3 %
    const auto one = rn::third_octave_centres(nominal[i], nominal[i]);
    ASSERT_EQ(one.size(), 1u) << nominal[i];
    EXPECT_NEAR(one[0] / nominal[i], 1.0, 0.03) << nominal[i];
    EXPECT_EQ(rn::nominal_centre(one[0]), nominal[i]);  // and back to its label
    for (int j = i; j < n; ++j)
      EXPECT_EQ(rn::third_octave_centres(nominal[i], nominal[j]).size(), std::size_t(j - i + 1))
          << nominal[i] << " ... " << nominal[j] << " Hz";
  }
  // a limit inside a band selects that band; the band edges are f_c 10^{+-1/20}
  const auto c = rn::third_octave_centres(400.0 * std::pow(10.0, -0.04), 5000.0 * std::pow(10.0, 0.04));
  ASSERT_EQ(c.size(), 12u);
  EXPECT_NEAR(c.front(), 1000.0 * std::pow(10.0, -0.4), 1e-9);
  EXPECT_NEAR(c.back(), 1000.0 * std::pow(10.0, 0.7), 1e-9);
  EXPECT_GT(c.back(), 5000.0);
  // the default noise band axis (noise.band_min = 100, band_max = 5000) reaches the 5 kHz band
  // and stops below the 6.3 kHz one
  EXPECT_EQ(rn::third_octave_index(5000.0), 7);
  EXPECT_EQ(rn::third_octave_index(5500.0), 7);
  EXPECT_EQ(rn::third_octave_index(6000.0), 8);
}
