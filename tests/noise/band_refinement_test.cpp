// Adaptive band means (src/noise/band_refinement.hpp): lines added where the case's lines do not
// resolve a lightly damped peak.
#include "noise/band_refinement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "noise/bands.hpp"

namespace rn = rollnoise::noise;

namespace {

// |H|^2 of a lightly damped single-degree-of-freedom receptance on a smooth background:
// H = 1/(f0^2 - f^2 + 2 i zeta f0 f) + b/f0^2, the wheel mode's shape in the loop's response.
struct Resonance {
  double f0, zeta, background;
  double operator()(double f) const {
    const std::complex<double> h =
        1.0 / std::complex<double>(f0 * f0 - f * f, 2.0 * zeta * f0 * f) + background / (f0 * f0);
    return std::norm(h);
  }
};

// The band mean by the midpoint rule on n equal cells (n large: the reference).
double fine_band_mean(const Resonance& p, double centre, long n) {
  const auto e = rn::third_octave_edges(centre);
  const double h = (e[1] - e[0]) / n;
  double sum = 0.0;
  for (long k = 0; k < n; ++k) sum += p(e[0] + (k + 0.5) * h);
  return sum / n;
}

// Refines the lines of band_frequencies(centres, 48) `levels` times, evaluating p exactly at the
// added lines; returns the lines.
std::vector<double> refined_lines(const Resonance& p, const std::vector<double>& centres,
                                  int levels) {
  std::vector<double> f = rn::band_frequencies(centres, 48);
  for (int level = 0; level < levels; ++level) {
    std::vector<double> values(f.size());
    for (std::size_t k = 0; k < f.size(); ++k) values[k] = p(f[k]);
    const std::vector<double> added = rn::refinement_frequencies(f, {values}, centres);
    if (added.empty()) break;
    f.insert(f.end(), added.begin(), added.end());
    std::sort(f.begin(), f.end());
  }
  return f;
}

}  // namespace

// A mode of zeta = 1e-4 (half-power width 0.25 Hz) in the 1250 Hz band (lines 6 Hz apart): the
// band mean on the 48 lines depends on where the peak falls between them and is off by more than
// 10 % at the frequencies drawn (seeded); with the added lines it is within 1 % (0.04 dB, the
// method's stated accuracy for a band one resonance dominates) of the mean on 2 million equal
// cells, for every draw.
TEST(BandRefinement, LightlyDampedPeakBetweenTheLinesConvergesToTheBandMean) {
  const std::vector<double> centres = {1000.0, 1250.0, 1600.0};
  std::mt19937_64 rng(38);
  const auto e = rn::third_octave_edges(1250.0);
  std::uniform_real_distribution<double> where(e[0] + 20.0, e[1] - 20.0);
  double worst_uniform = 0.0;
  for (int draw = 0; draw < 5; ++draw) {
    const Resonance p{where(rng), 1e-4, 0.3};
    const double reference = fine_band_mean(p, 1250.0, 2000000);
    std::vector<double> uniform = rn::band_frequencies(centres, 48);
    std::vector<double> v(uniform.size());
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = p(uniform[k]);
    worst_uniform =
        std::max(worst_uniform, std::abs(rn::band_mean(uniform, v, 1250.0) / reference - 1.0));

    const std::vector<double> f = refined_lines(p, centres, 6);
    std::vector<double> w(f.size());
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = p(f[k]);
    EXPECT_NEAR(rn::band_mean(f, w, 1250.0) / reference, 1.0, 1e-2)
        << "f0 = " << p.f0 << " Hz, " << f.size() << " lines";
    EXPECT_LT(f.size(), 1000u)
        << "uniform lines would need ~1e4 (spacing well below the half-power width)";
  }
  EXPECT_GT(worst_uniform, 0.1) << "the case's 48 lines alone";
}

// A response that varies by less than 3 dB between neighbouring lines gets no lines.
TEST(BandRefinement, SmoothResponseAddsNoLines) {
  const std::vector<double> centres = {500.0, 630.0, 800.0};
  const std::vector<double> f = rn::band_frequencies(centres, 48);
  std::vector<double> p(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) p[k] = 1.0 / (1.0 + std::pow(f[k] / 700.0, 4));
  EXPECT_TRUE(rn::refinement_frequencies(f, {p}, centres).empty());
}

// Added lines lie strictly between the case's first and last line and never on a line.
TEST(BandRefinement, AddedLinesStayInsideTheCaseLinesAndOffThem) {
  const std::vector<double> centres = {100.0, 125.0};
  const std::vector<double> f = rn::band_frequencies(centres, 8);
  std::vector<double> p(f.size(), 1.0);
  p.front() = 100.0;  // a step at both ends
  p.back() = 100.0;
  const std::vector<double> added = rn::refinement_frequencies(f, {p}, centres);
  ASSERT_FALSE(added.empty());
  for (double a : added) {
    EXPECT_GT(a, f.front());
    EXPECT_LT(a, f.back());
    EXPECT_EQ(std::count(f.begin(), f.end(), a), 0);
  }
}

// merged() interleaves two results by frequency, keeping each value with its frequency.
TEST(BandRefinement, MergedResultsAreSortedByFrequency) {
  rn::LoopResult a, b;
  a.frequency = {1.0, 3.0, 5.0};
  b.frequency = {2.0, 4.0};
  for (double f : a.frequency) a.force.push_back(rn::Vector4c::Constant(f));
  for (double f : b.frequency) b.force.push_back(rn::Vector4c::Constant(f));
  const rn::LoopResult m = rn::merged(a, b);
  ASSERT_EQ(m.frequency.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(m.frequency[k], double(k + 1));
    EXPECT_EQ(m.force[k](2).real(), double(k + 1));
  }
  EXPECT_TRUE(m.wheel_velocity.empty());
}
