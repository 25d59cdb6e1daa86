// Checks of the adaptive frequency sampling of the waveguide rail's receptances
// (dynamics/waveguide_frequency_sampling.hpp) on analytic receptance-like functions: a damped
// resonance (smooth in ln f) and a wave's cut-on (the 1/sqrt(f - f_c) onset of a waveguide's
// point receptance, smoothed by a loss factor), on the noise case's kind of grid (1/3-octave bands
// 100 Hz - 5 kHz, 48 samples per band: 864 frequencies).
#include "support/memory_archive.hpp"
#include "dynamics/waveguide_frequency_sampling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace rd = rollnoise::dynamics;
using cd = std::complex<double>;

namespace {

// 1/3-octave bands from 100 Hz to 5 kHz, 48 logarithmically spaced samples per band.
std::vector<double> sampling_test_grid() {
  std::vector<double> f;
  const double lo = 100.0 / std::pow(2.0, 1.0 / 6.0), per = std::log(2.0) / 3.0 / 48.0;
  for (int i = 0; i < 18 * 48; ++i) f.push_back(lo * std::exp((i + 0.5) * per));
  return f;
}

// A 4x4 with a damped resonance at f0 (loss eta) on the diagonal and coupled off-diagonal terms,
// plus, if fc > 0, a cut-on at fc: 1 / sqrt(1 - (f / fc)^2 (1 - i eta)) (a propagating wave above
// fc, evanescent below).
rd::Receptance4 sampling_test_receptance(double f, double f0, double fc) {
  const double eta = 0.02;
  const cd resonance = 1e-9 / (1.0 - (f / f0) * (f / f0) + cd(0.0, eta));
  const cd onset = fc > 0.0
                       ? 2e-10 / std::sqrt(cd(1.0 - (f / fc) * (f / fc), (f / fc) * (f / fc) * eta))
                       : cd(0.0);
  rd::Receptance4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      r(i, j) = (i == j ? 1.0 : 0.2 / (1.0 + i + j)) * (resonance * (1.0 + 0.3 * i) + onset);
  return r;
}

// Eq. (F1): the largest entry error against the geometric mean of its diagonal terms.
double sampling_test_error(const rd::Receptance4& a, const rd::Receptance4& b) {
  double e = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      e = std::max(e,
                   std::abs(a(i, j) - b(i, j)) / std::sqrt(std::abs(b(i, i)) * std::abs(b(j, j))));
  return e;
}

}  // namespace

// A smooth resonance: a small part of the grid is computed, and the interpolation of the rest is
// within the tolerance everywhere (the check's estimate is of the coarser interpolant, so
// the final error is smaller than the tolerance); a tighter tolerance computes more and errs less.
TEST(WaveguideFrequencySampling, SmoothReceptanceWithinToleranceOnAFewSamples) {
  const std::vector<double> f = sampling_test_grid();
  auto evaluate = [](double fq) {
    return std::vector<rd::Receptance4>{sampling_test_receptance(fq, 250.0, 0.0)};
  };
  double previous_error = 1.0;
  int previous_points = 0;
  for (double tolerance : {1e-1, 1e-2, 1e-3}) {
    int points = 0;
    const std::vector<rd::Receptance4> r =
        rd::sample_receptances(f, evaluate, {6, tolerance}, &points).front();
    ASSERT_EQ(r.size(), f.size());
    double error = 0.0;
    for (std::size_t k = 0; k < f.size(); ++k)
      error = std::max(error, sampling_test_error(r[k], evaluate(f[k]).front()));
    EXPECT_LT(error, tolerance) << "tolerance " << tolerance;
    EXPECT_LT(error, previous_error);
    // not fewer (a resonance is a rational of low order: Eq. F2 may close the same intervals for
    // every tolerance here)
    EXPECT_GE(points, previous_points);
    EXPECT_LT(points, static_cast<int>(f.size()) / 3) << "tolerance " << tolerance;
    previous_error = error, previous_points = points;
  }
}

// A cut-on inside the grid: where the cubic's checks fail near f_c the sampling closes the
// intervals by Eq. (F2)'s checked rational (it would otherwise refine down to the grid there), the
// grid frequencies next to the cut-on are within the tolerance, and so is the whole grid, where the
// fixed grid of 24 per octave (the former sampling) is off by more than 10 times as much.
TEST(WaveguideFrequencySampling, ClosesACutOnByTheCheckedRational) {
  const std::vector<double> f = sampling_test_grid();
  const double fc = 3400.0;
  std::vector<double> evaluated;
  auto evaluate = [&](double fq) {
    evaluated.push_back(fq);
    return std::vector<rd::Receptance4>{sampling_test_receptance(fq, 250.0, fc)};
  };
  int points = 0;
  const double tolerance = 1e-2;
  rd::SampledGrid kept;
  const std::vector<rd::Receptance4> r =
      rd::sample_receptances(f, evaluate, {6, tolerance}, &points, {}, &kept).front();
  EXPECT_EQ(points, static_cast<int>(evaluated.size()));
  EXPECT_NE(std::find(kept.checked.begin(), kept.checked.end(), 2), kept.checked.end())
      << "no interval closed by Eq. (F2)";
  const auto above = std::lower_bound(f.begin(), f.end(), fc);
  for (auto it = above - 2; it != above + 2; ++it) {
    const std::size_t k = static_cast<std::size_t>(it - f.begin());
    EXPECT_LT(sampling_test_error(r[k], sampling_test_receptance(*it, 250.0, fc)), tolerance)
        << *it << " Hz";
  }
  evaluated.clear();
  int fixed_points = 0;
  const std::vector<rd::Receptance4> fixed =
      rd::sample_receptances(f, evaluate, {24, 0.0}, &fixed_points).front();
  double error = 0.0, fixed_error = 0.0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    const rd::Receptance4 d = sampling_test_receptance(f[k], 250.0, fc);
    error = std::max(error, sampling_test_error(r[k], d));
    fixed_error = std::max(fixed_error, sampling_test_error(fixed[k], d));
  }
  EXPECT_LT(error, tolerance);
  EXPECT_GT(fixed_error, 10.0 * error);
  EXPECT_LT(points, static_cast<int>(f.size()) / 2);
}

// per_octave = 0: every frequency computed directly, in any order and with repeats, and the values
// returned in the order asked, for every pair.
TEST(WaveguideFrequencySampling, EveryFrequencyDirectlyInTheOrderAsked) {
  const std::vector<double> f = {800.0, 120.0, 800.0, 3000.0, 450.0, 120.0};
  int calls = 0;
  auto evaluate = [&](double fq) {
    ++calls;
    return std::vector<rd::Receptance4>{sampling_test_receptance(fq, 250.0, 0.0),
                                        2.0 * sampling_test_receptance(fq, 900.0, 0.0)};
  };
  int points = 0;
  const std::vector<std::vector<rd::Receptance4>> r =
      rd::sample_receptances(f, evaluate, {0, 1e-3}, &points);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(points, 4);
  EXPECT_EQ(calls, 4);
  for (std::size_t k = 0; k < f.size(); ++k) {
    EXPECT_EQ(r[0][k], sampling_test_receptance(f[k], 250.0, 0.0));
    EXPECT_EQ(r[1][k], 2.0 * sampling_test_receptance(f[k], 900.0, 0.0));
  }
}

// Frequencies off the grid from the grid's kept sampling (sampled_at; the refinement's added
// lines): the grid's own frequencies are sample_receptances's values to the bit; an added
// frequency inside an interval the sampling checked is interpolated, within the tolerance of the
// true function (Eq. F1, 0.03); one in an unchecked interval (the cut-on at 1.5 kHz, where the
// sampling computed every grid frequency) or outside the grid is computed (the function's value to
// the bit); and each value is the same bits whichever other frequencies are asked with it (no
// dependence on how a caller slices its lines).
TEST(WaveguideFrequencySampling, OffGridFrequenciesFromTheKeptSamplingAlone) {
  const std::vector<double> f = sampling_test_grid();
  auto evaluate = [](double x) {
    return std::vector<rd::Receptance4>{sampling_test_receptance(x, 640.0, 1500.0)};
  };
  const rd::FrequencySampling sampling;
  rd::SampledGrid kept;
  const auto on_grid = rd::sample_receptances(f, evaluate, sampling, nullptr, {}, &kept);
  ASSERT_EQ(kept.values.size(), 1u);
  ASSERT_EQ(kept.checked.size() + 1, kept.at.size());
  EXPECT_LT(kept.at.size(), f.size());
  const auto again = rd::sampled_at(kept, f, evaluate);
  for (std::size_t k = 0; k < f.size(); ++k) ASSERT_TRUE(again[0][k] == on_grid[0][k]) << f[k];

  // added lines: a third of the way between neighbours, and two outside the grid
  std::vector<double> added{0.9 * f.front(), 1.1 * f.back()};
  for (std::size_t k = 0; k + 1 < f.size(); ++k) added.push_back(f[k] + (f[k + 1] - f[k]) / 3.0);
  const auto all = rd::sampled_at(kept, added, evaluate);
  int interpolated = 0, computed = 0;
  double worst = 0.0;
  for (std::size_t k = 0; k < added.size(); ++k) {
    const rd::Receptance4 truth = evaluate(added[k])[0];
    if (all[0][k] == truth) {
      ++computed;
    } else {
      ++interpolated;
      worst = std::max(worst, sampling_test_error(all[0][k], truth));
    }
    const auto alone = rd::sampled_at(kept, {added[k]}, evaluate);  // asked alone
    ASSERT_TRUE(alone[0][0] == all[0][k]) << added[k];
  }
  std::printf("  %zu grid samples; %d added lines interpolated (largest error %.2e), %d computed\n",
              kept.at.size(), interpolated, worst, computed);
  EXPECT_GT(interpolated, 0);
  EXPECT_GE(computed, 2);  // at least the two outside the grid
  EXPECT_LT(worst, sampling.tolerance);
  // near the cut-on every grid frequency was sampled (unchecked intervals): the added lines there
  // come from Eq. (F2)'s checked rational, not computed, within the tolerance (counted above)
  int near_cut_on = 0;
  for (std::size_t k = 2; k < added.size(); ++k)
    if (std::abs(added[k] / 1500.0 - 1.0) < 0.002) {
      ++near_cut_on;
      EXPECT_FALSE(all[0][k] == evaluate(added[k])[0]) << added[k];
    }
  EXPECT_GT(near_cut_on, 0);
}

// Eq. (F2) where its check fails: a ripple on the cut-on function with a period of about two grid
// spacings (0.3 % in f: no smooth function of ln f, so the sampling evaluates every grid frequency
// there, and no low-order rational predicts a left-out sample). Added lines in the intervals the
// cubic did not close (closed by Eq. F2, or unchecked) are then mostly computed (the function's
// value to the bit); without the ripple none is, and all are within the tolerance.
TEST(WaveguideFrequencySampling, OpenIntervalsFromACheckedRationalElseComputed) {
  const std::vector<double> f = sampling_test_grid();
  const double spacing = std::log(f[1] / f[0]);
  for (const double ripple : {0.0, 0.3}) {
    auto evaluate = [&](double x) {
      const double phase = std::log(x) / (2.0 * spacing) * 2.0 * M_PI;
      const double bump = x > 1400.0 && x < 1600.0 ? ripple * std::sin(phase) : 0.0;
      return std::vector<rd::Receptance4>{sampling_test_receptance(x, 640.0, 1500.0) *
                                          (1.0 + bump)};
    };
    const rd::FrequencySampling sampling;
    rd::SampledGrid kept;
    rd::sample_receptances(f, evaluate, sampling, nullptr, {}, &kept);
    std::vector<double> added;  // a third of the way into each interval the cubic did not close
    for (std::size_t i = 0; i + 1 < kept.at.size(); ++i)
      if (kept.checked[i] != 1) added.push_back(kept.at[i] + (kept.at[i + 1] - kept.at[i]) / 3.0);
    ASSERT_GT(added.size(), 5u) << ripple;
    const auto v = rd::sampled_at(kept, added, evaluate, sampling);
    int computed = 0;
    double worst = 0.0;
    for (std::size_t k = 0; k < added.size(); ++k) {
      const rd::Receptance4 truth = evaluate(added[k])[0];
      if (v[0][k] == truth)
        ++computed;
      else
        worst = std::max(worst, sampling_test_error(v[0][k], truth));
    }
    std::printf(
        "  ripple %.1f: %zu lines in intervals the cubic did not close, %d computed, the others' "
        "largest "
        "error %.2e\n",
        ripple, added.size(), computed, worst);
    EXPECT_LT(worst, sampling.tolerance) << ripple;
    if (ripple == 0.0)
      EXPECT_EQ(computed, 0);
    else
      EXPECT_GT(computed, static_cast<int>(added.size()) / 2);
  }
}

// The direct evaluations of a pass on several threads (FrequencySampling::threads, the case's
// solver.threads): the same samples, the same number of evaluations and the same values to the
// bit as on one thread, on the grid (sample_receptances) and off it (sampled_at), with a cut-on
// (1.5 kHz) where every grid frequency is evaluated.
TEST(WaveguideFrequencySampling, ThreadsGiveTheSerialSamplingToTheBit) {
  const std::vector<double> f = sampling_test_grid();
  std::atomic<int> calls{0};
  auto evaluate = [&](double x) {
    ++calls;
    return std::vector<rd::Receptance4>{sampling_test_receptance(x, 640.0, 1500.0),
                                        sampling_test_receptance(x, 900.0, 0.0)};
  };
  std::vector<double> added{0.9 * f.front()};
  for (std::size_t k = 0; k + 1 < f.size(); k += 5) added.push_back(f[k] + (f[k + 1] - f[k]) / 3.0);
  std::vector<std::vector<std::vector<rd::Receptance4>>> on_grid, off_grid;
  std::vector<int> evaluations;
  for (int threads : {1, 2, 3}) {
    rd::FrequencySampling sampling;
    sampling.threads = threads;
    rd::SampledGrid kept;
    int points = 0;
    calls = 0;
    on_grid.push_back(rd::sample_receptances(f, evaluate, sampling, &points, {}, &kept));
    EXPECT_EQ(calls.load(), points);
    evaluations.push_back(points);
    off_grid.push_back(rd::sampled_at(kept, added, evaluate, sampling));
  }
  EXPECT_LT(evaluations[0], static_cast<int>(f.size()));
  for (std::size_t t = 1; t < on_grid.size(); ++t) {
    EXPECT_EQ(evaluations[t], evaluations[0]);
    for (std::size_t p = 0; p < 2; ++p) {
      for (std::size_t k = 0; k < f.size(); ++k)
        ASSERT_TRUE(on_grid[t][p][k] == on_grid[0][p][k]) << f[k];
      for (std::size_t k = 0; k < added.size(); ++k)
        ASSERT_TRUE(off_grid[t][p][k] == off_grid[0][p][k]) << added[k];
    }
  }
}

using rollnoise_test::MemoryArchive;

// Samplings kept beyond the run (SamplingMemo with an archive; track.sampling_cache): a second
// memo on the same archive and identity (a later run) computes nothing, neither the grid's sampling
// nor the lines beside it (an unchecked interval at the cut-on, outside the grid), and gives the
// first run's values to the bit; another identity (another track) or another grid computes anew.
TEST(WaveguideFrequencySampling, ArchivedSamplingServesALaterRunWithoutEvaluating) {
  const std::vector<double> f = sampling_test_grid();
  std::atomic<int> calls{0};
  auto evaluate = [&](double x) {
    ++calls;
    return std::vector<rd::Receptance4>{sampling_test_receptance(x, 640.0, 1500.0)};
  };
  std::vector<double> added{0.9 * f.front(), 1.1 * f.back()};
  for (std::size_t k = 0; k + 1 < f.size(); k += 3) added.push_back(f[k] + (f[k + 1] - f[k]) / 3.0);
  const rd::FrequencySampling sampling;
  const std::vector<std::pair<double, double>> points{{-0.0366, 0.52}};
  const std::vector<double> pairs{0, 0, 0, 0};
  auto archive = std::make_shared<const MemoryArchive>();
  auto run = [&](const std::string& identity, const std::vector<double>& grid) {
    const rd::SamplingMemo memo(archive, identity);  // a run's memo
    calls = 0;
    auto on_grid =
        rd::sampled_values(grid, nullptr, true, evaluate, sampling, {}, memo, points, pairs);
    auto off_grid =
        rd::sampled_values(added, &grid, true, evaluate, sampling, {}, memo, points, pairs);
    return std::make_tuple(on_grid, off_grid, calls.load());
  };
  const auto [grid1, added1, first] = run("track A", f);
  EXPECT_GT(first, 0);
  EXPECT_EQ(archive->kept_.size(), 1u);
  const auto [grid2, added2, second] = run("track A", f);
  EXPECT_EQ(second, 0);  // the sampling and its direct lines from the archive
  for (std::size_t k = 0; k < f.size(); ++k) ASSERT_TRUE(grid2[0][k] == grid1[0][k]) << f[k];
  for (std::size_t k = 0; k < added.size(); ++k)
    ASSERT_TRUE(added2[0][k] == added1[0][k]) << added[k];
  const int writes = archive->writes;
  run("track A", f);
  EXPECT_EQ(archive->writes, writes);  // nothing new: nothing written
  // another identity, another grid: computed and kept apart
  EXPECT_EQ(std::get<2>(run("track B", f)), first);
  std::vector<double> other(f.begin(), f.begin() + 400);
  EXPECT_GT(std::get<2>(run("track A", other)), 0);
  EXPECT_EQ(archive->kept_.size(), 3u);
}
