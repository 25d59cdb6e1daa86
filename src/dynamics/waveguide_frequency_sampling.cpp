#include "dynamics/waveguide_frequency_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "dynamics/waveguide_rail_model.hpp"
#include "linalg/aaa_rational.hpp"

namespace rollnoise::dynamics {

namespace {

// Eq. (F1)'s scale of each entry of a pair's value b: sqrt(|sa_ii| |sb_jj|), sa and sb the point
// receptances of its two points (the Frobenius norm of b where that vanishes; 0 if b is 0 too).
Eigen::Matrix4d sampling_scales(const Receptance4& b, const Receptance4& sa,
                                const Receptance4& sb) {
  Eigen::Matrix4d s;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double d = std::sqrt(std::abs(sa(i, i)) * std::abs(sb(j, j)));
      s(i, j) = d > 0.0 ? d : b.norm();
    }
  return s;
}

// The indices of the values whose diagonals scale pair p (sample_receptances' `scales`; none
// given: the pair's own).
std::pair<int, int> scale_points(const std::vector<std::pair<int, int>>& scales, std::size_t p) {
  return p < scales.size() ? scales[p]
                           : std::pair<int, int>(static_cast<int>(p), static_cast<int>(p));
}

// Eq. (F1): the largest entry of |a - b| against its sampling_scales.
double sampling_error(const Receptance4& a, const Receptance4& b, const Receptance4& sa,
                      const Receptance4& sb) {
  const Eigen::Matrix4d scale = sampling_scales(b, sa, sb);
  double err = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (scale(i, j) > 0.0) err = std::max(err, std::abs(a(i, j) - b(i, j)) / scale(i, j));
  return err;
}

// The indices of the starting grid: per octave `per_octave` points from the lowest to the highest
// of `x` = ln f (sorted, distinct), each the nearest grid point, both ends included.
std::vector<int> starting_samples(const std::vector<double>& x, int per_octave) {
  const int n = static_cast<int>(x.size());
  const int intervals =
      std::max(3, static_cast<int>(std::ceil(per_octave * (x.back() - x.front()) / std::log(2.0))));
  std::vector<int> out;
  for (int i = 0; i <= intervals; ++i) {
    const double target = x.front() + (x.back() - x.front()) * i / intervals;
    int j = static_cast<int>(std::lower_bound(x.begin(), x.end(), target) - x.begin());
    if (j >= n) j = n - 1;
    if (j > 0 && target - x[j - 1] < x[j] - target) --j;
    if (out.empty() || out.back() != j) out.push_back(j);
  }
  return out;
}

// The grid point strictly between samples a and b nearest the point a third of the way in ln f
// (b - a >= 2). Not the midpoint: there the Hermite interpolant's error from equal slope errors at
// both ends cancels (h10(1/2) = -h11(1/2)), so a midpoint check would miss it.
int split_sample(const std::vector<double>& x, int a, int b) {
  const double target = x[a] + (x[b] - x[a]) / 3.0;
  int j = static_cast<int>(std::lower_bound(x.begin() + a, x.begin() + b, target) - x.begin());
  if (j > a + 1 && target - x[j - 1] < x[j] - target) --j;
  return std::clamp(j, a + 1, b - 1);
}

// evaluate(at[i]) for every i, on up to `threads` threads (core/task_pool.hpp): each evaluation is
// on its own, so the values do not depend on the thread count; `evaluate` must be safe to call
// concurrently.
std::vector<std::vector<Receptance4>> evaluated(
    const std::vector<double>& at, const std::function<std::vector<Receptance4>(double)>& evaluate,
    int threads) {
  std::vector<std::vector<Receptance4>> out(at.size());
  parallel_for(at.size(), std::max(threads, 1),
               [&](std::size_t i, int) { out[i] = evaluate(at[i]); });
  return out;
}

// Eq. (F2) of the header: the samples around the open interval (at[j-1], at[j]) as the rows of a
// set of functions of ln f (every pair's 16 entries), each entry against its Eq. (F1) scale.
struct LocalSamples {
  Eigen::VectorXd x;
  Eigen::MatrixXcd values;
  Eigen::MatrixXd scale;
};
LocalSamples local_samples(const SampledGrid& g, std::size_t lo, std::size_t hi,
                           const std::vector<std::pair<int, int>>& scales) {
  const std::size_t pairs = g.values.size();
  LocalSamples s;
  s.x.resize(hi - lo);
  s.values.resize(hi - lo, 16 * pairs);
  s.scale.resize(hi - lo, 16 * pairs);
  for (std::size_t i = lo; i < hi; ++i) {
    const Eigen::Index row = static_cast<Eigen::Index>(i - lo);
    s.x(row) = std::log(g.at[i]);
    for (std::size_t p = 0; p < pairs; ++p) {
      const auto [sa, sb] = scale_points(scales, p);
      const Receptance4& v = g.values[p][i];
      const Eigen::Matrix4d scale = sampling_scales(v, g.values[sa][i], g.values[sb][i]);
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          const Eigen::Index col = static_cast<Eigen::Index>(16 * p + 4 * r + c);
          s.values(row, col) = v(r, c);
          s.scale(row, col) = scale(r, c) > 0.0 ? scale(r, c) : 1.0;  // v = 0: any scale
        }
    }
  }
  return s;
}

// The rows of `s` without row `drop`.
LocalSamples samples_without(const LocalSamples& s, Eigen::Index drop) {
  const Eigen::Index n = s.x.size();
  LocalSamples o;
  o.x.resize(n - 1);
  o.values.resize(n - 1, s.values.cols());
  o.scale.resize(n - 1, s.scale.cols());
  for (Eigen::Index i = 0, k = 0; i < n; ++i) {
    if (i == drop) continue;
    o.x(k) = s.x(i);
    o.values.row(k) = s.values.row(i);
    o.scale.row(k) = s.scale.row(i);
    ++k;
  }
  return o;
}

// Eq. (F2): the rational of the kLocalWindow samples on each side of the open interval (at[j-1],
// at[j]), fitted to a tenth of the tolerance, if each of the two samples nearest either end is
// predicted within `agreement` (a third of the tolerance) by the same fit without it; else none.
// An infinite `agreement` skips that check (an interval the sampling closed by it: the same
// samples, so the same outcome).
constexpr std::size_t kLocalWindow = 6;
// The bisection closes an interval by Eq. (F2) only on a closer leave-one-out agreement (its
// samples are still sparse there), this fraction of the tolerance.
constexpr double kClosingAgreement = 0.1;
std::optional<linalg::BarycentricRational> local_rational(
    const SampledGrid& g, std::size_t j, double tolerance,
    const std::vector<std::pair<int, int>>& scales, double agreement) {
  const std::size_t n = g.at.size();
  const std::size_t lo = j >= kLocalWindow ? j - kLocalWindow : 0,
                    hi = std::min(n, j + kLocalWindow);
  if (!(tolerance > 0.0) || hi - lo < 6) return std::nullopt;
  const LocalSamples s = local_samples(g, lo, hi, scales);
  const int terms = static_cast<int>(hi - lo) - 1;
  for (std::size_t q = j >= 2 ? j - 2 : 0; std::isfinite(agreement) && q < std::min(n, j + 2);
       ++q) {
    const Eigen::Index row = static_cast<Eigen::Index>(q - lo);
    const LocalSamples rest = samples_without(s, row);
    const linalg::BarycentricRational r =
        linalg::aaa_fit(rest.x, rest.values, rest.scale, 0.1 * tolerance, terms - 1);
    const double err =
        ((r(s.x(row)) - s.values.row(row)).cwiseAbs().array() / s.scale.row(row).array())
            .maxCoeff();
    if (!(err <= agreement)) return std::nullopt;
  }
  return linalg::aaa_fit(s.x, s.values, s.scale, 0.1 * tolerance, terms);
}

// The samples (grid index -> every pair's value) as a SampledGrid (no intervals marked), for
// Eq. (F2)'s fits.
SampledGrid grid_of(const std::map<int, std::vector<Receptance4>>& samples,
                    const std::vector<double>& f) {
  SampledGrid g;
  const std::size_t pairs = samples.empty() ? 0 : samples.begin()->second.size();
  g.values.assign(pairs, {});
  for (const auto& [i, v] : samples) {
    g.at.push_back(f[i]);
    for (std::size_t p = 0; p < pairs; ++p) g.values[p].push_back(v.at(p));
  }
  return g;
}

// Eq. (F2)'s values at the frequencies `at` (Hz, inside one interval) from the rational `r`.
std::vector<std::vector<Receptance4>> rational_values(const linalg::BarycentricRational& r,
                                                      const std::vector<double>& at,
                                                      std::size_t pairs) {
  std::vector<std::vector<Receptance4>> out(at.size(), std::vector<Receptance4>(pairs));
  for (std::size_t k = 0; k < at.size(); ++k) {
    const Eigen::RowVectorXcd v = r(std::log(at[k]));
    for (std::size_t p = 0; p < pairs; ++p)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          out[k][p](a, b) = v(static_cast<Eigen::Index>(16 * p + 4 * a + b));
  }
  return out;
}
}  // namespace

std::vector<std::vector<Receptance4>> sample_receptances(
    const std::vector<double>& frequencies,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling, int* evaluations,
    const std::vector<std::pair<int, int>>& scales, SampledGrid* kept) {
  std::vector<double> f = frequencies;  // the distinct frequencies, ascending
  std::sort(f.begin(), f.end());
  f.erase(std::unique(f.begin(), f.end()), f.end());
  if (!f.empty() && !(f.front() > 0.0))
    throw NumericalError("sample_receptances: frequencies must be > 0 Hz");
  const int n = static_cast<int>(f.size());
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = std::log(f[i]);
  std::map<int, std::vector<Receptance4>> samples;  // grid index -> every pair's value
  std::vector<int> start;
  if (sampling.per_octave > 0 && n > 4) start = starting_samples(x, sampling.per_octave);
  if (start.empty() || start.size() + 1 >= static_cast<std::size_t>(n)) {
    start.resize(n);  // as many samples as frequencies: every one directly
    for (int i = 0; i < n; ++i) start[i] = i;
  }
  {
    std::vector<double> at;
    for (int i : start) at.push_back(f[i]);
    std::vector<std::vector<Receptance4>> v = evaluated(at, evaluate, sampling.threads);
    for (std::size_t k = 0; k < start.size(); ++k) samples.emplace(start[k], std::move(v[k]));
  }
  std::size_t pairs = samples.empty() ? 0 : samples.begin()->second.size();
  // The interpolation of the current samples, per pair, at grid points `at`.
  auto interpolated = [&](const std::vector<int>& at) {
    std::vector<double> grid, where;
    for (const auto& s : samples) grid.push_back(f[s.first]);
    for (int i : at) where.push_back(f[i]);
    std::vector<std::vector<Receptance4>> out(pairs);
    for (std::size_t p = 0; p < pairs; ++p) {
      std::vector<Receptance4> v;
      for (const auto& s : samples) v.push_back(s.second.at(p));
      out[p] = interpolate_receptances(grid, v, where);
    }
    return out;
  };
  std::vector<std::pair<int, int>> open;
  std::set<std::pair<int, int>> checked;   // sample intervals closed by the cubic's check (F1)
  std::set<std::pair<int, int>> rational;  // ... by Eq. (F2) instead (grid indices)
  if (sampling.tolerance > 0.0 && samples.size() < static_cast<std::size_t>(n))
    for (std::size_t i = 0; i + 1 < start.size(); ++i)
      if (start[i + 1] - start[i] >= 2) open.emplace_back(start[i], start[i + 1]);
  while (!open.empty()) {  // one pass: every open interval's third point against the samples before
    std::vector<int> mid;
    for (const auto& [a, b] : open) mid.push_back(split_sample(x, a, b));
    const std::vector<std::vector<Receptance4>> predicted = interpolated(mid);
    std::vector<std::pair<int, int>> still_open;
    std::vector<double> at;
    for (int i : mid) at.push_back(f[i]);
    std::vector<std::vector<Receptance4>> values_at_mid = evaluated(at, evaluate, sampling.threads);
    std::vector<std::pair<int, std::vector<Receptance4>>> added;
    std::vector<std::pair<int, int>> failed;  // the halves of the intervals whose check failed
    for (std::size_t k = 0; k < open.size(); ++k) {
      added.emplace_back(mid[k], std::move(values_at_mid[k]));
      const std::vector<Receptance4>& direct = added.back().second;
      double err = 0.0;
      for (std::size_t p = 0; p < pairs; ++p) {
        const auto [sa, sb] = scale_points(scales, p);
        err = std::max(err,
                       sampling_error(predicted[p][k], direct.at(p), direct.at(sa), direct.at(sb)));
      }
      if (err <= sampling.tolerance) {
        checked.emplace(open[k].first, mid[k]);
        checked.emplace(mid[k], open[k].second);
        continue;
      }
      // the cubic's check failed:
      failed.emplace_back(open[k].first, mid[k]);
      failed.emplace_back(mid[k], open[k].second);
    }
    for (auto& s : added) samples.emplace(s.first, std::move(s.second));
    // a half whose cubic check failed closes where Eq. (F2) holds on the samples now (the rational
    // of the samples around it); else it stays open while it holds a grid frequency
    const SampledGrid now = failed.empty() ? SampledGrid{} : grid_of(samples, f);
    for (const auto& [a, b] : failed) {
      if (b - a < 2) continue;  // no grid frequency inside: unchecked
      const auto j = static_cast<std::size_t>(std::distance(samples.begin(), samples.find(b)));
      if (local_rational(now, j, sampling.tolerance, scales,
                         kClosingAgreement * sampling.tolerance))
        rational.emplace(a, b);
      else
        still_open.emplace_back(a, b);
    }
    open = std::move(still_open);
  }
  // Eq. (F2) once more on the final samples for each interval it closed (more samples around it
  // since); where it fails now, the interval's grid frequencies are computed (samples themselves),
  // until it holds for every one left.
  std::map<std::pair<int, int>, linalg::BarycentricRational> fits;
  while (!rational.empty()) {
    const SampledGrid now = grid_of(samples, f);
    fits.clear();
    std::vector<int> fill;
    for (auto it = rational.begin(); it != rational.end();) {
      const auto [a, b] = *it;
      const auto j = static_cast<std::size_t>(std::distance(samples.begin(), samples.find(b)));
      if (std::optional<linalg::BarycentricRational> r =
              local_rational(now, j, sampling.tolerance, scales, sampling.tolerance / 3.0)) {
        fits.emplace(*it, std::move(*r));
        ++it;
        continue;
      }
      for (int i = a + 1; i < b; ++i) fill.push_back(i);
      it = rational.erase(it);
    }
    if (fill.empty()) break;
    std::vector<double> at;
    for (int i : fill) at.push_back(f[i]);
    std::vector<std::vector<Receptance4>> v = evaluated(at, evaluate, sampling.threads);
    for (std::size_t k = 0; k < fill.size(); ++k) samples.emplace(fill[k], std::move(v[k]));
  }
  if (evaluations) *evaluations = static_cast<int>(samples.size());
  // per interval between neighbouring samples: 1 closed by the cubic's check, 2 by Eq. (F2), 0 not
  // checked (no grid frequency inside)
  std::vector<char> closed_by;
  {
    int before = -1;
    for (const auto& s : samples) {
      if (before >= 0) {
        const std::pair<int, int> ab(before, s.first);
        closed_by.push_back(checked.count(ab) ? 1 : rational.count(ab) ? 2 : 0);
      }
      before = s.first;
    }
  }
  if (kept) {
    *kept = grid_of(samples, f);
    kept->checked = closed_by;
  }
  // every requested frequency: its sample, the cubic of the samples, or Eq. (F2)'s rational
  std::vector<std::vector<Receptance4>> out(pairs);
  const bool all = samples.size() == static_cast<std::size_t>(n);
  std::vector<int> every(n);
  for (int i = 0; i < n; ++i) every[i] = i;
  std::vector<std::vector<Receptance4>> values =
      all ? std::vector<std::vector<Receptance4>>{} : interpolated(every);
  for (const auto& [ab, r] : fits) {
    std::vector<double> at(f.begin() + ab.first + 1, f.begin() + ab.second);
    const std::vector<std::vector<Receptance4>> v = rational_values(r, at, pairs);
    for (std::size_t k = 0; k < at.size(); ++k)
      for (std::size_t p = 0; p < pairs; ++p) values[p][ab.first + 1 + k] = v[k][p];
  }
  for (double fq : frequencies) {
    const int i = static_cast<int>(std::lower_bound(f.begin(), f.end(), fq) - f.begin());
    for (std::size_t p = 0; p < pairs; ++p)
      out[p].push_back(all ? samples.at(i).at(p) : values[p][i]);
  }
  return out;
}

std::vector<std::vector<Receptance4>> sampled_at(
    const SampledGrid& g, const std::vector<double>& frequencies,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling, const std::vector<std::pair<int, int>>& scales) {
  const std::size_t pairs = g.values.size(), n = g.at.size();
  std::vector<std::vector<Receptance4>> out(pairs, std::vector<Receptance4>(frequencies.size()));
  std::vector<double> inside;        // frequencies in checked intervals, interpolated together
  std::vector<std::size_t> inside_k;  // their places in `frequencies`
  std::vector<double> computed;       // frequencies evaluated directly (on `threads` threads)
  std::vector<std::size_t> computed_k;
  std::map<std::size_t, std::vector<std::size_t>> open;  // open interval j -> places inside it
  for (std::size_t k = 0; k < frequencies.size(); ++k) {
    const double fq = frequencies[k];
    const std::size_t j = static_cast<std::size_t>(std::lower_bound(g.at.begin(), g.at.end(), fq) - g.at.begin());
    if (j < n && g.at[j] == fq) {  // a sample
      for (std::size_t p = 0; p < pairs; ++p) out[p][k] = g.values[p][j];
    } else if (j > 0 && j < n && g.checked[j - 1] == 1) {  // inside (at[j-1], at[j]) closed by F1
      inside.push_back(fq);
      inside_k.push_back(k);
    } else if (j > 0 &&
               j < n) {  // closed by Eq. (F2), or unchecked (every grid frequency a sample)
      open[j].push_back(k);
    } else {  // outside the grid
      computed.push_back(fq);
      computed_k.push_back(k);
    }
  }
  for (const auto& [j, places] : open) {
    const double agreement =
        g.checked[j - 1] == 2 ? std::numeric_limits<double>::infinity() : sampling.tolerance / 3.0;
    const std::tuple<std::size_t, double, double> key(j, sampling.tolerance, agreement);
    std::optional<std::optional<linalg::BarycentricRational>> kept;
    {
      const std::lock_guard<std::mutex> lock(g.fits->mutex);
      if (const auto it = g.fits->kept.find(key); it != g.fits->kept.end()) kept = it->second;
    }
    if (!kept) {
      kept = local_rational(g, j, sampling.tolerance, scales, agreement);
      const std::lock_guard<std::mutex> lock(g.fits->mutex);
      g.fits->kept.emplace(key, *kept);
    }
    const std::optional<linalg::BarycentricRational>& r = *kept;
    for (std::size_t k : places) {
      if (!r) {
        computed.push_back(frequencies[k]);
        computed_k.push_back(k);
        continue;
      }
      const std::vector<std::vector<Receptance4>> v = rational_values(*r, {frequencies[k]}, pairs);
      for (std::size_t p = 0; p < pairs; ++p) out[p][k] = v[0][p];
    }
  }
  const std::vector<std::vector<Receptance4>> direct =
      evaluated(computed, evaluate, sampling.threads);
  for (std::size_t i = 0; i < computed.size(); ++i)
    for (std::size_t p = 0; p < pairs; ++p) out[p][computed_k[i]] = direct[i].at(p);
  if (!inside.empty())
    for (std::size_t p = 0; p < pairs; ++p) {
      const std::vector<Receptance4> v = interpolate_receptances(g.at, g.values[p], inside);
      for (std::size_t i = 0; i < inside.size(); ++i) out[p][inside_k[i]] = v[i];
    }
  return out;
}

SamplingMemo::SamplingMemo(std::shared_ptr<const SamplingArchive> archive, std::string identity)
    : archive_(std::move(archive)), identity_(std::move(identity)) {}

std::string SamplingMemo::archive_key(const Key& key) const {
  // the identity, then the points, the pairs and the grid as counts and raw doubles (the key is
  // compared in full by the archive)
  std::string out = identity_;
  auto append = [&out](const double* v, std::size_t n) {
    out += "\n" + std::to_string(n) + ":";
    out.append(reinterpret_cast<const char*>(v), n * sizeof(double));
  };
  const auto& [points, pairs, grid, every] = key;
  std::vector<double> flat;
  for (const auto& [offset, angle] : points) flat.insert(flat.end(), {offset, angle});
  append(flat.data(), flat.size());
  append(pairs.data(), pairs.size());
  append(grid.data(), grid.size());
  out += every ? "\nevery frequency directly" : "\nsampled";
  return out;
}

void SamplingMemo::archive(const Key& key, const Entry& e) const {
  archive_->write(archive_key(key), KeptSampling{*e.grid, e.direct});
}

std::shared_ptr<const SampledGrid> SamplingMemo::recalled(const Key& key) const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = entries_.find(key);
    if (it != entries_.end()) return it->second.grid;
  }
  if (!archive_) return nullptr;
  std::optional<KeptSampling> kept = archive_->read(archive_key(key));
  if (!kept) return nullptr;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.size() >= 64) entries_.clear();
  Entry& e = entries_[key];
  if (!e.grid) {
    e.grid = std::make_shared<const SampledGrid>(std::move(kept->grid));
    e.direct = std::move(kept->direct);
    e.archived = e.direct.size();
  }
  return e.grid;
}

std::shared_ptr<const SampledGrid> SamplingMemo::remember(Key key, SampledGrid grid) const {
  auto kept = std::make_shared<const SampledGrid>(std::move(grid));
  const std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.size() >= 64) entries_.clear();
  Entry& e = entries_[key];
  if (e.grid) return e.grid;
  e.grid = kept;
  if (archive_) archive(key, e);
  return e.grid;
}

std::optional<std::vector<Receptance4>> SamplingMemo::direct(const Key& key, double f) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end()) return std::nullopt;
  const auto v = it->second.direct.find(f);
  if (v == it->second.direct.end()) return std::nullopt;
  return v->second;
}

void SamplingMemo::keep_direct(const Key& key, double f, std::vector<Receptance4> value) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  if (it != entries_.end()) it->second.direct.emplace(f, std::move(value));
}

void SamplingMemo::archive_direct(const Key& key) const {
  if (!archive_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end() || it->second.direct.size() == it->second.archived) return;
  archive(key, it->second);
  it->second.archived = it->second.direct.size();
}

namespace {

// The sampling of `key`'s grid as `memo` holds it (or its archive), else made now and kept.
std::shared_ptr<const SampledGrid> kept_sampling(
    const SamplingMemo& memo, const SamplingMemo::Key& key,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling, const std::vector<std::pair<int, int>>& scales) {
  if (std::shared_ptr<const SampledGrid> g = memo.recalled(key)) return g;
  SampledGrid kept;
  sample_receptances(std::get<2>(key), evaluate, sampling, nullptr, scales, &kept);
  return memo.remember(key, std::move(kept));
}

}  // namespace

std::vector<std::vector<Receptance4>> sampled_values(
    const std::vector<double>& frequencies, const std::vector<double>* grid, bool interpolate,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling, const std::vector<std::pair<int, int>>& scales,
    const SamplingMemo& memo, const std::vector<std::pair<double, double>>& points,
    const std::vector<double>& pairs) {
  if (!interpolate || sampling.per_octave <= 0) {
    FrequencySampling direct = sampling;
    direct.per_octave = 0;
    if (!memo.archived()) return sample_receptances(frequencies, evaluate, direct, nullptr, scales);
    // kept for later runs: every distinct frequency a sample, no interval checked
    std::vector<double> distinct = frequencies;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const std::shared_ptr<const SampledGrid> g =
        kept_sampling(memo, {points, pairs, distinct, true}, evaluate, direct, scales);
    return sampled_at(*g, frequencies, evaluate, sampling, scales);
  }
  // The sampling of the grid (`frequencies` themselves where no grid is given), kept or made now
  // and kept; every frequency from it (on the grid sampled itself: the values sample_receptances
  // gave, to the bit).
  const std::vector<double>& on = grid ? *grid : frequencies;
  const SamplingMemo::Key key{points, pairs, on, false};
  const std::shared_ptr<const SampledGrid> g = kept_sampling(memo, key, evaluate, sampling, scales);
  // the frequencies the sampling does not give: computed once, then kept beside it (the same
  // bits as computing them again)
  const auto direct = [&](double f) {
    if (std::optional<std::vector<Receptance4>> v = memo.direct(key, f)) return std::move(*v);
    std::vector<Receptance4> v = evaluate(f);
    memo.keep_direct(key, f, v);
    return v;
  };
  std::vector<std::vector<Receptance4>> out = sampled_at(*g, frequencies, direct, sampling, scales);
  memo.archive_direct(key);
  return out;
}

}  // namespace rollnoise::dynamics
