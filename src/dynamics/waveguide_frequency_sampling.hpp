// Sampling the waveguide rail's receptances on a frequency grid with fewer direct evaluations
// (each one m x m wavenumber eigenproblem, rail_waveguide.hpp Eq. W5): the values are computed
// directly on a subset of the grid and interpolated by cubic Hermite in ln f
// (interpolate_receptances, waveguide_rail_model.hpp) or, where that fails its check, by a local
// rational (Eq. F2 below) at the others.
//
// The subset is chosen adaptively (docs/models.md Sec. 2.7, "The frequency grid"): a starting
// grid of `per_octave` points per octave (grid frequencies nearest to it, both ends included),
// then, pass by pass, every open interval between two neighbouring samples gets its point a third
// of the way in ln f (the nearest grid frequency strictly inside; not the midpoint, where the
// Hermite interpolant's error from equal slope errors at both ends cancels) evaluated directly and
// compared with the interpolation of the samples of the pass before; where the difference exceeds
// `tolerance`
//
//   max_ij |R_ij^interp - R_ij| / sqrt(|S_a,ii| |S_b,jj|)                                    (F1)
//
// (every entry of a pair (a, b) against the geometric mean of the point receptances' diagonal
// terms of its two points, S_a = R_aa at x = 0, so the small couplings and the transfers between
// distant points count on the scale of the point receptances, not their own; for a point
// receptance S_a = S_b = R) the two halves stay open,
// else they close. The new sample joins the samples either way. Refinement ends where an interval
// holds no grid frequency inside: there every frequency is computed directly, as near a wave's
// cut-on (the 1/sqrt(f - f_c) onset, smoothed only by the steel's loss), which no smooth
// interpolant resolves (the classic adaptive bisection with an interpolation error estimate: de
// Boor, A Practical Guide to Splines, 2001, Ch. XII; Press et al., Numerical Recipes, 3rd ed.
// 2007, Sec. 4.7 for the same idea in quadrature).
//
// Between two neighbouring samples of such an interval (the band refinement's added lines fall
// there, sampled_at) the values come from a rational instead, where it is checked: the set-valued
// AAA rational (linalg/aaa_rational.hpp) in ln f of every entry of every pair, fitted to the 2 W
// samples around the interval (W = 6 on each side) to a tenth of the tolerance in Eq. (F1)'s
// measure, is used if, for each of the four samples nearest the interval (two on each side), the
// same fit without that sample predicts it within a third of the tolerance (leave-one-out);
// otherwise the line is computed directly.                                               (F2)
// A resonance or a cut-on smoothed by the loss is a low-order rational locally, which the Hermite
// cubic is not; measured on the leading outer wheel's contact of curve_300m (discrete support,
// docs/record/performance_waveguide.md Sec. 7) the check held for 92 % of such lines, their
// largest error 0.003.
//
// The bisection uses Eq. (F2) too: a half of an interval whose cubic check failed closes if (F2)
// holds for it on the samples of that pass (the new third point among them) with the closer
// leave-one-out agreement of a tenth of the tolerance (the samples are still sparse there),
// instead of being bisected on to the grid's resolution. After the last pass (F2) is checked again
// on the final samples for every interval it closed; where it fails then, the interval's grid
// frequencies are computed, until it holds for all. The grid frequencies inside such an interval
// take (F2)'s rational of the final samples (the same as sampled_at gives there).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "dynamics/rail_contact.hpp"
#include "dynamics/receptance.hpp"
#include "linalg/aaa_rational.hpp"

namespace rollnoise::dynamics {

/// How contact_transfers samples a frequency grid (WaveguideRailOptions).
struct FrequencySampling {
  /// Starting grid, points per octave (0: every frequency directly).
  int per_octave = 4;
  /// Eq. (F1)'s bound for closing an interval; <= 0: no refinement (the starting grid alone, as
  /// the fixed grid of 24 per octave was before).
  double tolerance = 0.03;
  /// The direct evaluations of a pass (the starting grid, each pass's third points, the lines
  /// sampled_at computes) on up to this many threads (the case's solver.threads): each is on its
  /// own, so the values do not depend on it; `evaluate` must then be safe to call concurrently.
  int threads = 1;
};

/// The values of every pair (`evaluate(f)` returns one 4x4 per pair, always as many) at each of
/// `frequencies` (Hz, > 0, any order, repeats allowed): per pair, per frequency. `scales`: per
/// pair the indices of the two values whose diagonals are S_a and S_b of Eq. (F1) (the point
/// receptances of its two points); empty: each pair its own. `evaluations`, if given, receives the
/// number of direct evaluations.
struct SampledGrid;
/// `kept`, if given, receives the sampling (SampledGrid).
std::vector<std::vector<Receptance4>> sample_receptances(
    const std::vector<double>& frequencies,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling, int* evaluations = nullptr,
    const std::vector<std::pair<int, int>>& scales = {}, SampledGrid* kept = nullptr);

/// The adaptive sampling of a grid as sample_receptances makes it, kept so that frequencies off
/// the grid can be taken from it (sampled_at).
struct SampledGrid {
  std::vector<double> at;                        ///< frequencies evaluated directly, ascending (Hz)
  std::vector<std::vector<Receptance4>> values;  ///< per pair, one per `at`
  /// per interval (at[i], at[i + 1]): 1 closed by a check of Eq. (F1) (its third point agreed
  /// with the cubic interpolation), 2 closed by Eq. (F2) (its rational checked), 0 holds no grid
  /// frequency (every one there was evaluated)
  std::vector<char> checked;
  /// Eq. (F2)'s local rationals that sampled_at has fitted, by the interval's upper sample and
  /// the fit's tolerances, kept for its later calls (the refinement asks a grid's sampling once
  /// per loop variant and added line set): a fit depends on the samples and the sampling's scales
  /// alone, which do not change once the grid is made. Shared by copies.
  struct Fits {
    std::mutex mutex;
    std::map<std::tuple<std::size_t, double, double>, std::optional<linalg::BarycentricRational>>
        kept;
  };
  std::shared_ptr<Fits> fits = std::make_shared<Fits>();
};

/// Per pair, the values at `frequencies` (Hz, any order) from a grid's sampling: a sampled
/// frequency its value, a frequency inside an interval closed by Eq. (F1) the cubic interpolation
/// of the samples (interpolate_receptances, as on the grid), one inside an interval closed by Eq.
/// (F2) or unchecked (near a cut-on or a sharp resonance, where the sampling evaluated every grid
/// frequency) the rational of Eq. (F2) where its check holds, any other (and outside the grid)
/// evaluated directly. Each frequency's
/// value depends on the sampling and itself alone, not on the others asked for. Eq. (F2)'s
/// tolerance is sampling.tolerance, its scales `scales` (as sample_receptances'); the direct
/// evaluations on up to sampling.threads threads.
std::vector<std::vector<Receptance4>> sampled_at(
    const SampledGrid& grid, const std::vector<double>& frequencies,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling = {}, const std::vector<std::pair<int, int>>& scales = {});

/// What a rail model keeps of one grid: its sampling, and the values computed directly at the
/// frequencies the sampling does not give (sampled_at's, e.g. refinement lines near a cut-on or
/// off the grid), by frequency.
struct KeptSampling {
  SampledGrid grid;
  std::map<double, std::vector<Receptance4>> direct;
};

/// What a rail model keeps of one set of pairs at complex frequencies (squeal's continuation,
/// RailModel::laplace_transfers): the values (one 6x6 per pair) by s = (Re s, Im s).
struct KeptLaplace {
  std::map<std::pair<double, double>, std::vector<Receptance6>> values;
};

/// Keeps samplings (and values at complex frequencies) beyond the run (io/rail_sampling_cache.hpp:
/// files in the user's cache directory). read gives nothing for a key it does not hold; write is
/// best effort. All may be called from several threads.
class SamplingArchive {
 public:
  virtual ~SamplingArchive() = default;
  virtual std::optional<KeptSampling> read(const std::string& key) const = 0;
  virtual void write(const std::string& key, const KeptSampling& kept) const = 0;
  virtual std::optional<KeptLaplace> read_laplace(const std::string& key) const = 0;
  virtual void write_laplace(const std::string& key, const KeptLaplace& kept) const = 0;
};

/// The samplings a rail model keeps (sample_receptances' `kept`), by what they were made of: a
/// set of points on the section ((offset, angle) each), its pairs (any encoding of the values a
/// sampling holds: the points' indices and their positions along the rail) and the grid; with
/// each, the values computed directly beside it. Shared by the copies of a model, thread-safe; a
/// cache of values computed the same way whenever asked, so emptying it (at 64 entries) changes no
/// result. With an archive, a sampling not held is read from it, and each one made (or given more
/// direct values) is written to it, under the model's `identity` (everything its values depend
/// on besides the key) followed by the key's bytes.
class SamplingMemo {
 public:
  /// (points, pairs, grid, every frequency computed directly: a "sampling" with no interpolation)
  using Key = std::tuple<std::vector<std::pair<double, double>>, std::vector<double>,
                         std::vector<double>, bool>;
  SamplingMemo() = default;
  SamplingMemo(std::shared_ptr<const SamplingArchive> archive, std::string identity);
  /// Whether the samplings also go to an archive; the archive (may be null) and the identity.
  bool archived() const { return archive_ != nullptr; }
  const std::shared_ptr<const SamplingArchive>& archive() const { return archive_; }
  const std::string& identity() const { return identity_; }
  /// The sampling of `key`: held, else from the archive (with its direct values), else null.
  std::shared_ptr<const SampledGrid> recalled(const Key& key) const;
  /// Holds `grid` under `key` (and archives it); returns what is held.
  std::shared_ptr<const SampledGrid> remember(Key key, SampledGrid grid) const;
  /// The value computed directly at `f` beside `key`'s sampling, if held.
  std::optional<std::vector<Receptance4>> direct(const Key& key, double f) const;
  /// Holds a value computed directly at `f` beside `key`'s sampling (held: recalled or remembered).
  void keep_direct(const Key& key, double f, std::vector<Receptance4> value) const;
  /// Archives `key`'s entry again if it holds direct values the archive does not.
  void archive_direct(const Key& key) const;

 private:
  struct Entry {
    std::shared_ptr<const SampledGrid> grid;
    std::map<double, std::vector<Receptance4>> direct;
    std::size_t archived = 0;  ///< direct values the archive holds
  };
  std::string archive_key(const Key& key) const;
  void archive(const Key& key, const Entry& e) const;  // with mutex_ held
  std::shared_ptr<const SamplingArchive> archive_;
  std::string identity_;
  mutable std::mutex mutex_;
  mutable std::map<Key, Entry> entries_;
};

/// One set of points' values, per pair at each of `frequencies`, as a rail model that samples its
/// grid gives them (the waveguide on either support):
///  * `interpolate` false, or sampling.per_octave = 0: every frequency by `evaluate` (with an
///    archive in `memo`, kept as a sampling of the frequencies that interpolates nothing);
///  * else from the sampling of `*grid` (`frequencies` themselves where `grid` is null: the values
///    sample_receptances gives), kept in `memo` (key: `points`, `pairs`, the grid) or made now and
///    kept: sampled_at, so that each frequency's value depends on the grid and itself alone, and a
///    second query on the same grid evaluates nothing.
/// `scales` as sample_receptances'.
std::vector<std::vector<Receptance4>> sampled_values(
    const std::vector<double>& frequencies, const std::vector<double>* grid, bool interpolate,
    const std::function<std::vector<Receptance4>(double)>& evaluate,
    const FrequencySampling& sampling, const std::vector<std::pair<int, int>>& scales,
    const SamplingMemo& memo, const std::vector<std::pair<double, double>>& points,
    const std::vector<double>& pairs);

}  // namespace rollnoise::dynamics
