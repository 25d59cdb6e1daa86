// The creepage of a rolling step in each sampling (contact/creepage_history.hpp): the exact step
// average of every history kind against an independent quadrature of at(), and the harmonic factor
// e^{-i w dt/2} sinc(w dt/2) that the linear model's f carries for "average".
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "contact/creepage_history.hpp"

using namespace rollnoise::contact;

namespace {

// (1/(t1 - t0)) int_{t0}^{t1} at(t) dt by composite Gauss-Legendre (3 points on n panels): exact to
// rounding for the trigonometric histories at these step sizes; for samples the panels are cut to
// hold the kinks at the sample times inside a panel to an O(panel^2) error.
Creepage quadrature(const CreepageHistory& h, double t0, double t1, int n) {
  const double x[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  Creepage s{0, 0, 0};
  const double p = (t1 - t0) / n;
  for (int i = 0; i < n; ++i)
    for (int q = 0; q < 3; ++q) {
      const Creepage c = h.at(t0 + p * (i + 0.5 + 0.5 * x[q]));
      s.xi_x += 0.5 * w[q] * c.xi_x / n, s.xi_y += 0.5 * w[q] * c.xi_y / n, s.phi += 0.5 * w[q] * c.phi / n;
    }
  return s;
}

void expect_near(const Creepage& a, const Creepage& b, double tol, const char* what) {
  EXPECT_NEAR(a.xi_x, b.xi_x, tol) << what;
  EXPECT_NEAR(a.xi_y, b.xi_y, tol) << what;
  EXPECT_NEAR(a.phi, b.phi, 1e2 * tol) << what;
}

}  // namespace

TEST(StepAverage, HarmonicAndMultiharmonicStepMeansEqualTheQuadratureOfTheHistory) {
  const auto h = CreepageHistory::harmonic({0.001, 0.002, -0.05}, {5e-5, 1e-5, 0.003}, 4700.0, {0.3, 1.9, -2.2});
  const auto m = CreepageHistory::multiharmonic({0.001, 0, -0.05}, {1e-6, 2e-6, 5e-6}, 100, 5000, 40, 11);
  const double dt = 7.18e-3 * 34 / 30 / 17 / 13.8888888888889;  // one element of 17 at 50 km/h
  for (long k : {0L, 1L, 37L, 1234L}) {
    const double t0 = (k - 1) * dt, t1 = k * dt;
    expect_near(h.step_average(t0, t1), quadrature(h, t0, t1, 64), 1e-17, "harmonic");
    expect_near(m.step_average(t0, t1), quadrature(m, t0, t1, 64), 1e-17, "multiharmonic");
  }
  // over whole periods the cosine averages out
  const Creepage whole = h.step_average(0.1, 0.1 + 3 / 4700.0);
  EXPECT_NEAR(whole.xi_x, 0.001, 1e-18);
  EXPECT_NEAR(whole.phi, -0.05, 1e-16);
}

TEST(StepAverage, SampledSeriesStepMeansIntegrateTheInterpolantExactly) {
  // samples at uneven times; steps inside one interval, across several samples, and reaching
  // before the first and after the last sample (held constant there)
  const std::vector<double> t = {0.0, 0.3e-4, 1.0e-4, 1.1e-4, 2.5e-4};
  const std::vector<Creepage> v = {{1e-3, 0, -0.05}, {2e-3, -1e-3, 0.01}, {0.5e-3, 1e-3, 0.02},
                                   {-1e-3, 2e-3, -0.03}, {1e-3, 0, 0.0}};
  const auto h = CreepageHistory::samples({1e-3, 0, 0}, t, v);
  for (auto [t0, t1] : {std::pair{0.1e-4, 0.2e-4}, {0.2e-4, 1.05e-4}, {-0.5e-4, 0.2e-4}, {0.9e-4, 3.1e-4},
                        {2.6e-4, 2.9e-4}, {-1e-4, 4e-4}}) {
    // the interpolant is linear between breakpoints: an exact reference cut at them by hand
    std::vector<double> b = {t0};
    for (double s : t)
      if (s > t0 && s < t1) b.push_back(s);
    b.push_back(t1);
    Creepage ref{0, 0, 0};
    for (size_t i = 1; i < b.size(); ++i) {
      const Creepage q = quadrature(h, b[i - 1], b[i], 1);
      const double w = (b[i] - b[i - 1]) / (t1 - t0);
      ref.xi_x += w * q.xi_x, ref.xi_y += w * q.xi_y, ref.phi += w * q.phi;
    }
    expect_near(h.step_average(t0, t1), ref, 1e-18, "samples");
    // and against a quadrature that does not know the breakpoints (panel-size error at the kinks)
    expect_near(h.step_average(t0, t1), quadrature(h, t0, t1, 20000), 1e-9, "samples, blind");
  }
}

TEST(StepAverage, StepCreepageTakesEachSamplingsInstantOrMean) {
  const auto h = CreepageHistory::harmonic({0.001, 0.002, -0.05}, {5e-5, 1e-5, 0.003}, 1000.0, {0.1, 0.2, 0.3});
  const auto c = CreepageHistory::constant({0.001, 0.002, -0.05});
  const double dt = 2.3e-5;
  for (long k : {0L, 5L, 300L}) {
    const Creepage a = h.step_creepage(CreepageSampling::contact, k, dt), b = h.at(k * dt);
    EXPECT_EQ(a.xi_x, b.xi_x);
    EXPECT_EQ(a.xi_y, b.xi_y);
    EXPECT_EQ(a.phi, b.phi);  // bit for bit
    const Creepage m = h.step_creepage(CreepageSampling::midstep, k, dt), mb = h.at((k - 0.5) * dt);
    EXPECT_EQ(m.xi_x, mb.xi_x);
    EXPECT_EQ(m.phi, mb.phi);
    const Creepage v = h.step_creepage(CreepageSampling::average, k, dt), vb = h.step_average((k - 1) * dt, k * dt);
    EXPECT_EQ(v.xi_x, vb.xi_x);
    EXPECT_EQ(v.phi, vb.phi);
    for (CreepageSampling s : {CreepageSampling::contact, CreepageSampling::midstep, CreepageSampling::average}) {
      const auto d = h.step_variation(s, k, dt);
      const Creepage x = h.step_creepage(s, k, dt);
      EXPECT_NEAR(d[0], x.xi_x - 0.001, 1e-18);
      EXPECT_NEAR(d[2], x.phi + 0.05, 1e-16);
      const Creepage y = c.step_creepage(s, k, dt);  // constant: the mean in every sampling
      EXPECT_EQ(y.xi_x, 0.001);
    EXPECT_EQ(y.phi, -0.05);
    }
  }
}

TEST(StepAverage, HarmonicStepCreepageCarriesTheSamplingFactor) {
  // e^{i w t} = cos(w t) + i cos(w t - pi/2): the step creepage of xi^ e^{i w t} is
  // xi^ e^{i w t_k} step_sampling_factor, here from the histories themselves (up to Nyquist)
  const double dt = 1e-4;
  for (double f : {0.0, 130.0, 2100.0, 4999.0}) {
    const double fr = f > 0 ? f : 1e-9;
    const auto re = CreepageHistory::harmonic({0, 0, 0}, {1, 0, 0}, fr, {0, 0, 0});
    const auto im = CreepageHistory::harmonic({0, 0, 0}, {1, 0, 0}, fr, {-M_PI / 2, 0, 0});
    for (CreepageSampling s : {CreepageSampling::contact, CreepageSampling::midstep, CreepageSampling::average})
      for (long k : {1L, 17L}) {
        const std::complex<double> x(re.step_variation(s, k, dt)[0], im.step_variation(s, k, dt)[0]);
        const std::complex<double> expect = std::polar(1.0, 2 * M_PI * fr * k * dt) * step_sampling_factor(s, fr, dt);
        EXPECT_LT(std::abs(x - expect), 1e-14) << f << " Hz, " << sampling_name(s);
      }
  }
  EXPECT_EQ(step_sampling_factor(CreepageSampling::average, 0.0, dt), 1.0);
  EXPECT_NEAR(std::abs(step_sampling_factor(CreepageSampling::average, 5000.0, dt)), 2 / M_PI, 1e-15);
}
