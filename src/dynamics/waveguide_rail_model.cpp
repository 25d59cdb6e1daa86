#include "dynamics/waveguide_rail_model.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "core/errors.hpp"
#include "dynamics/frequency_argument.hpp"
#include "dynamics/rail_model.hpp"
#include "dynamics/rail_section.hpp"
#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

Eigen::MatrixXd contact_loads_at(const RailWaveguide& section, const WaveguideRailOptions& options,
                                 const Eigen::Vector2d& point, const Eigen::Vector2d& normal) {
  return options.head_load
             ? section.head_loads(point, normal, options.head_bottom)
             : section.patch_loads(point, options.patch_half_width, normal, options.head_bottom);
}

RailMaterial rail_material(const TrackParameters& track, double poisson_ratio) {
  RailMaterial m;
  m.youngs_modulus = track.vertical.youngs_modulus;
  m.poisson_ratio = poisson_ratio;
  m.density = track.vertical.mass_per_length / track.vertical.area;
  m.loss_factor = track.vertical.loss_factor;
  return m;
}

namespace {

// Where a contact at (offset_y, contact_angle) loads the outline (outline_contact_point) and the
// rail's outward normal there, (-sin gamma, cos gamma) (noise::contact_frame).
std::pair<Eigen::Vector2d, Eigen::Vector2d> contact_point_and_normal(
    const std::vector<Eigen::Vector2d>& outline, const WaveguideRailOptions& options,
    double offset_y, double angle) {
  if (!std::isfinite(offset_y) || !std::isfinite(angle) || !(std::abs(angle) < 0.5 * M_PI))
    throw NumericalError(
        "waveguide rail: a contact needs a finite offset and |angle| < pi/2, got " +
        std::to_string(offset_y) + " m, " + std::to_string(angle) + " rad");
  return {outline_contact_point(outline, options.head_bottom, offset_y, angle),
          Eigen::Vector2d(-std::sin(angle), std::cos(angle))};
}

FootSupport foot_support(const TrackParameters& track) {
  return FootSupport{track.vertical_support, track.lateral_support, track.longitudinal_support,
                     track.sleeper_spacing};
}

RailWaveguide full_model(const TrackParameters& track, const WaveguideRailOptions& o) {
  const std::vector<Eigen::Vector2d> outline = o.outline.empty() ? uic60_outline() : o.outline;
  return RailWaveguide(fem::mesh_polygon(outline, o.mesh_size),
                       rail_material(track, o.poisson_ratio), foot_support(track));
}

// The crown: the highest point of the outline at the centre line (y = 0), or the highest vertex.
Eigen::Vector2d crown_of(const fem::QuadraticTriangleMesh& mesh) {
  double top = mesh.nodes.at(0).y();
  for (const auto& p : mesh.nodes) top = std::max(top, p.y());
  return Eigen::Vector2d(0.0, top);
}

}  // namespace

void check_waveguide_inputs(const TrackParameters& track, const WaveguideRailOptions& options) {
  if (!(options.mesh_size > 0.0) || !(options.patch_half_width > 0.0))
    throw InputError("track.model", "waveguide rail: mesh size and load patch must be > 0");
  if (!(options.seat_length >= 0.0) || !(options.seat_length < track.sleeper_spacing))
    throw InputError("track.model", "waveguide rail: the seat length must lie in [0, L)");
  if (options.sampling.per_octave < 0)
    throw InputError("track.model", "waveguide rail: grid points per octave must be >= 0");
  fem::check_outline(options.outline.empty() ? uic60_outline() : options.outline,
                     options.mesh_size);
  check_rail_inputs(rail_material(track, options.poisson_ratio), foot_support(track));
}

WaveguideRailModel::WaveguideRailModel(const TrackParameters& track,
                                       const WaveguideRailOptions& options)
    : GridSamplingRail(track, 0.0, options.archive,
                       "waveguide, continuous support\n" + options.archive_identity),
      options_(options),
      outline_(options.outline.empty() ? uic60_outline() : options.outline),
      section_([track, options] {
        RailWaveguide full = full_model(track, options);
        RailReductionModes modes = full.reduction_modes(options.contact_reduction);
        return Section{std::move(full), std::move(modes)};
      }),
      crown_([section = section_, options] {
        const Section& s = section.get();
        Eigen::MatrixXd loads =
            contact_loads_at(s.full, options, crown_of(s.full.mesh()), Eigen::Vector2d(0.0, 1.0));
        return Station{s.full.reduced(options.contact_reduction, loads, s.modes), std::move(loads)};
      }),
      head_([options] { return section_head_body(options); }) {
  check_waveguide_inputs(track, options);
}

const WaveguideRailModel::Station& WaveguideRailModel::crown() const {
  return crown_.get();
}

Receptance4 WaveguideRailModel::at(cdouble omega) const {
  const Station& c = crown();
  return c.model.point_transfer(omega, c.loads, c.loads);
}

Receptance4 WaveguideRailModel::receptance(double frequency) const {
  if (!std::isfinite(frequency) || !(frequency > 0.0))
    throw InputError("frequency", "rail receptance needs a finite frequency > 0 Hz");
  return at(cdouble(angular(frequency), 0.0));
}

Receptance4 WaveguideRailModel::receptance_laplace(cdouble s) const {
  if (!std::isfinite(s.real()) || !std::isfinite(s.imag()) || s == 0.0)
    throw InputError("frequency", "track receptance needs a finite, non-zero Laplace variable s");
  return at(cdouble(0.0, -1.0) * s);  // i omega = s
}

Eigen::Vector2d outline_contact_point(const std::vector<Eigen::Vector2d>& outline,
                                      double head_bottom, double offset_y, double contact_angle) {
  // The head's top edges (both ends at z >= head_bottom, outward normal upwards), in the outline's
  // counter-clockwise order (from +y over the crown to -y), each with its normal's angle
  // gamma_e = atan2(-n_y, n_z) (the loop's contact angle of that normal).
  struct Edge {
    Eigen::Vector2d a, b;
    double angle;
  };
  std::vector<Edge> top;
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = outline[i], b = outline[(i + 1) % n], d = b - a;
    if (d.norm() == 0.0 || a.y() < head_bottom || b.y() < head_bottom) continue;
    const Eigen::Vector2d normal = Eigen::Vector2d(d.y(), -d.x()).normalized();  // outward (CCW)
    if (normal.y() <= 0.0) continue;
    top.push_back({a, b, std::atan2(-normal.x(), normal.y())});
  }
  if (top.empty()) throw InputError("rail_section", "the rail outline has no head above it");
  // 1. The contact's own lateral offset, where the head's top spans it: the point of the top at
  //    y = offset_y (the highest, should two edges span it). The profiles placed the contact
  //    there; the outline is a coarser polyline of the same section, whose normals jump from edge
  //    to edge, so its normal would move the point to a vertex up to half an edge away.
  double best_z = -INFINITY;
  for (const Edge& e : top) {
    const double dy = e.b.x() - e.a.x();
    if (dy == 0.0 || (e.a.x() - offset_y) * (e.b.x() - offset_y) > 0.0) continue;
    best_z = std::max(best_z, e.a.y() + (offset_y - e.a.x()) / dy * (e.b.y() - e.a.y()));
  }
  if (std::isfinite(best_z)) return {offset_y, best_z};
  // 2. Off the top (a gauge-face or flange-root offset beyond the outline's head): where the
  //    outline's outward normal is the contact normal (the contact condition). Candidates: a
  //    point of an edge (the one nearest y = offset_y), cost |gamma - gamma_e|; a vertex shared by
  //    two consecutive edges whose normals bracket gamma, cost 0.
  double best_cost = INFINITY, best_distance = INFINITY;
  Eigen::Vector2d best(0.0, 0.0);
  auto consider = [&](const Eigen::Vector2d& p, double cost) {
    const double distance = std::abs(p.x() - offset_y);
    if (cost < best_cost - 1e-12 || (cost <= best_cost + 1e-12 && distance < best_distance))
      best = p, best_cost = std::min(cost, best_cost), best_distance = distance;
  };
  for (std::size_t i = 0; i < top.size(); ++i) {
    const Edge& e = top[i];
    const double dy = e.b.x() - e.a.x();
    const double t = dy != 0.0 ? std::clamp((offset_y - e.a.x()) / dy, 0.0, 1.0) : 0.5;
    consider(e.a + t * (e.b - e.a), std::abs(contact_angle - e.angle));
    if (i + 1 < top.size() && top[i + 1].a == e.b) {
      const double lo = std::min(e.angle, top[i + 1].angle),
                   hi = std::max(e.angle, top[i + 1].angle);
      if (contact_angle >= lo && contact_angle <= hi) consider(e.b, 0.0);
    }
  }
  return best;
}

Eigen::Vector2d WaveguideRailModel::contact_point(double offset_y, double contact_angle) const {
  return outline_contact_point(outline_, options_.head_bottom, offset_y, contact_angle);
}

std::shared_ptr<const WaveguideRailModel::Station> WaveguideRailModel::station(
    const Points& points) const {
  const Section& s = section_.get();
  Eigen::MatrixXd loads = contact_point_loads(s.full, outline_, options_, points);
  return std::make_shared<const Station>(
      Station{s.full.reduced(options_.contact_reduction, loads, s.modes), std::move(loads)});
}

std::vector<Receptance4> WaveguideRailModel::between(
    const Station& s, cdouble omega, const std::vector<std::tuple<int, int, double>>& pairs) const {
  std::vector<Receptance4> out;
  // Point receptances only (each wheel's loop alone): Eq. (W6), no waves.
  if (std::all_of(pairs.begin(), pairs.end(),
                  [](const auto& p) { return std::get<2>(p) == 0.0; })) {
    const Eigen::MatrixXcd h = s.model.point_transfer(omega, s.loads, s.loads);
    for (const auto& [a, b, x] : pairs) out.push_back(h.block<4, 4>(4 * a, 4 * b));
    return out;
  }
  const RailWaves w = s.model.waves(omega);
  std::vector<std::pair<double, Eigen::MatrixXcd>> at_x;  // Eq. (W4) per distinct distance
  for (const auto& [a, b, x] : pairs) {
    auto it =
        std::find_if(at_x.begin(), at_x.end(), [x = x](const auto& e) { return e.first == x; });
    if (it == at_x.end())
      it = at_x.insert(at_x.end(), {x, s.model.transfer(w, s.loads, s.loads, x)});
    out.push_back(it->second.block<4, 4>(4 * a, 4 * b));
  }
  return out;
}

namespace {

// The pairs' points grouped into the sets that are coupled (a pair joins its two points): each
// set gets one Ritz basis, so a point asked for alone has the basis it has in the single-contact
// loop. Per pair: its set, and (point a, point b, x_a - x_b) with the points indexed in that set.
struct PointSets {
  std::vector<std::vector<std::pair<double, double>>> points;  // per set, sorted
  std::vector<int> set;                                        // per pair
  std::vector<std::tuple<int, int, double>> within;            // per pair
};

PointSets point_sets(const std::vector<RailContactPair>& pairs) {
  std::vector<std::pair<double, double>> all;
  auto key = [](const RailContact& c) { return std::make_pair(c.offset_y, c.contact_angle); };
  for (const auto& [a, b] : pairs) all.push_back(key(a)), all.push_back(key(b));
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  auto index = [&](const RailContact& c) {
    return static_cast<int>(std::lower_bound(all.begin(), all.end(), key(c)) - all.begin());
  };
  std::vector<int> root(all.size());  // union-find over the points
  for (std::size_t i = 0; i < all.size(); ++i) root[i] = static_cast<int>(i);
  auto find = [&](int i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (const auto& [a, b] : pairs) root[find(index(a))] = find(index(b));
  PointSets out;
  std::vector<int> set_of_root(all.size(), -1), position(all.size(), 0);
  for (std::size_t i = 0; i < all.size(); ++i) {  // all is sorted: each set's points too
    int& s = set_of_root[find(static_cast<int>(i))];
    if (s < 0) s = static_cast<int>(out.points.size()), out.points.emplace_back();
    position[i] = static_cast<int>(out.points[s].size());
    out.points[s].push_back(all[i]);
  }
  for (const auto& [a, b] : pairs) {
    out.set.push_back(set_of_root[find(index(a))]);
    out.within.emplace_back(position[index(a)], position[index(b)], a.x - b.x);
  }
  return out;
}

}  // namespace

std::vector<std::vector<Receptance6>> GridSamplingRail::contact_transfers(
    const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs,
    bool interpolate) const {
  return transfers(frequencies, pairs, interpolate, nullptr);
}

std::vector<std::vector<Receptance6>> GridSamplingRail::contact_transfers_from(
    const std::vector<double>& grid, const std::vector<double>& frequencies,
    const std::vector<RailContactPair>& pairs) const {
  for (double f : grid) checked_omega(f);
  return transfers(frequencies, pairs, true, &grid);
}

GridSamplingRail::GridSamplingRail(const TrackParameters& track, double contact_position,
                                   std::shared_ptr<const SamplingArchive> archive,
                                   std::string identity)
    : RailModel(track, contact_position),
      memo_(std::make_shared<const SamplingMemo>(std::move(archive), std::move(identity))) {}

namespace {

// The values at complex s of one set of pairs, read from the archive on construction and written
// back when they are destroyed if they grew (best effort).
class ArchivedLaplace {
 public:
  ArchivedLaplace(std::shared_ptr<const SamplingArchive> archive, std::string key)
      : archive_(std::move(archive)), key_(std::move(key)) {
    if (std::optional<KeptLaplace> k = archive_->read_laplace(key_)) kept_ = std::move(*k);
    read_ = kept_.values.size();
  }
  ~ArchivedLaplace() {
    if (kept_.values.size() <= read_) return;
    try {
      archive_->write_laplace(key_, kept_);
    } catch (...) {  // a destructor does not throw: the values are only not kept
    }
  }
  ArchivedLaplace(const ArchivedLaplace&) = delete;
  ArchivedLaplace& operator=(const ArchivedLaplace&) = delete;

  std::optional<std::vector<Receptance6>> find(cdouble s) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = kept_.values.find({s.real(), s.imag()});
    if (it == kept_.values.end()) return std::nullopt;
    return it->second;
  }
  void add(cdouble s, std::vector<Receptance6> v) {
    const std::lock_guard<std::mutex> lock(mutex_);
    kept_.values.emplace(std::make_pair(s.real(), s.imag()), std::move(v));
  }

 private:
  std::shared_ptr<const SamplingArchive> archive_;
  std::string key_;
  KeptLaplace kept_;
  std::size_t read_ = 0;
  mutable std::mutex mutex_;
};

}  // namespace

RailModel::LaplaceTransfers GridSamplingRail::laplace_transfers(
    const std::vector<RailContactPair>& pairs) const {
  if (!memo_->archived()) return direct_laplace_transfers(pairs);
  // the key: the identity, then each pair's two contacts (x, offset, angle) as raw doubles
  std::string key = memo_->identity() + "\nlaplace " + std::to_string(pairs.size()) + ":";
  for (const auto& [a, b] : pairs)
    for (double v : {a.x, a.offset_y, a.contact_angle, b.x, b.offset_y, b.contact_angle})
      key.append(reinterpret_cast<const char*>(&v), sizeof v);
  auto kept = std::make_shared<ArchivedLaplace>(memo_->archive(), std::move(key));
  // the model's bases only once a value is not in the archive
  const Lazy<LaplaceTransfers> direct([this, pairs] { return direct_laplace_transfers(pairs); });
  return [kept, direct](cdouble s) {
    if (std::optional<std::vector<Receptance6>> v = kept->find(s)) return std::move(*v);
    std::vector<Receptance6> v = direct.get()(s);
    kept->add(s, v);
    return v;
  };
}

std::vector<std::vector<Receptance6>> GridSamplingRail::transfers(
    const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs,
    bool interpolate, const std::vector<double>* grid) const {
  for (double f : frequencies) checked_omega(f);
  if (frequencies.empty()) return {};
  const std::vector<std::vector<Receptance4>> values =
      frame_values(frequencies, pairs, interpolate, grid);
  std::vector<std::vector<Receptance6>> out(frequencies.size(),
                                            std::vector<Receptance6>(pairs.size()));
  for (std::size_t k = 0; k < frequencies.size(); ++k)
    for (std::size_t p = 0; p < pairs.size(); ++p)
      out[k][p] = from_contact_frames(values[p][k], pairs[p].first.contact_angle,
                                      pairs[p].second.contact_angle);
  return out;
}

std::vector<std::vector<Receptance4>> GridSamplingRail::frame_values(
    const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs,
    bool interpolate, const std::vector<double>* grid) const {
  // The points of the query; the crown alone (the decay rates, the line) is sampled as it is.
  Points points;
  for (const auto& [a, b] : pairs)
    for (const RailContact& c : {a, b}) {
      const std::pair<double, double> at(c.offset_y, c.contact_angle);
      if (std::find(points.begin(), points.end(), at) == points.end()) points.push_back(at);
    }
  const bool crown_only = points.size() == 1 && points.front() == std::pair(0.0, 0.0);
  const std::optional<SpanningPoints> span =
      interpolate && !crown_only ? spanning_points(points) : std::nullopt;
  if (!span) return set_values(frequencies, pairs, interpolate, grid);
  // the spanning points' four pairs (i, j) at each distinct pair of positions (x_a, x_b)
  std::vector<RailContactPair> spanned;
  std::map<std::pair<double, double>, std::size_t> first;
  std::vector<std::size_t> at(pairs.size());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const std::pair<double, double> x(pairs[p].first.x, pairs[p].second.x);
    const auto [it, added] = first.emplace(x, spanned.size());
    at[p] = it->second;
    if (!added) continue;
    for (const auto& [oa, ga] : span->points)
      for (const auto& [ob, gb] : span->points)
        spanned.push_back({RailContact{x.first, oa, ga}, RailContact{x.second, ob, gb}});
  }
  const std::vector<std::vector<Receptance4>> v =
      set_values(frequencies, spanned, interpolate, grid);
  auto alpha = [&](const RailContact& c) -> const Eigen::Matrix<double, 8, 4>& {
    const auto it = std::find(points.begin(), points.end(), std::pair(c.offset_y, c.contact_angle));
    return span->combination[static_cast<std::size_t>(it - points.begin())];
  };
  std::vector<std::vector<Receptance4>> out(pairs.size(),
                                            std::vector<Receptance4>(frequencies.size()));
  Eigen::Matrix<cdouble, 8, 8> V;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const Eigen::Matrix<cdouble, 8, 4> a = alpha(pairs[p].first).cast<cdouble>();
    const Eigen::Matrix<cdouble, 8, 4> b = alpha(pairs[p].second).cast<cdouble>();
    for (std::size_t k = 0; k < frequencies.size(); ++k) {
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) V.block<4, 4>(4 * i, 4 * j) = v[at[p] + 2 * i + j][k];
      out[p][k] = a.transpose() * V * b;
    }
  }
  return out;
}

std::vector<std::vector<Receptance4>> GridSamplingRail::set_values(
    const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs,
    bool interpolate, const std::vector<double>* grid) const {
  const RailPointSets sets = rail_point_sets(pairs);
  const bool invariant = along_rail_invariant();
  // the contact-frame 4x4 of each pair at every frequency, one basis per set of points
  std::vector<std::vector<Receptance4>> values(pairs.size());
  for (std::size_t s = 0; s < sets.points.size(); ++s) {
    // the set's pairs as (a, b, x_a, x_b); (a, b, x_a - x_b, 0) where only the distance matters
    SetPairs within;
    std::vector<std::size_t> which;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (sets.set[p] != static_cast<int>(s)) continue;
      const auto [a, b, x] = sets.within[p];
      within.emplace_back(a, b, invariant ? x : pairs[p].first.x,
                          invariant ? 0.0 : pairs[p].second.x);
      which.push_back(p);
    }
    // Eq. (F1)'s scales: each point's receptance at its own position where asked for, else at the
    // same place in the first span, x mod L (a scale: the point receptance of the periodic track
    // there; the response along the rail for the sound asks for hundreds of positions, which
    // then share a few scales), appended
    const std::size_t asked = within.size();
    const double L = track().sleeper_spacing;
    auto point_value = [&](int a, double x) {
      SetPairs::value_type key(a, a, invariant ? 0.0 : x, invariant ? 0.0 : x);
      auto it = std::find(within.begin(), within.end(), key);
      if (it != within.end()) return static_cast<int>(it - within.begin());
      if (!invariant) {
        double in_span = std::round((x - std::floor(x / L) * L) * 1e9) / 1e9;  // to 1 nm
        if (in_span >= L) in_span = 0.0;
        key = SetPairs::value_type(a, a, in_span, in_span);
        it = std::find(within.begin(), within.end(), key);
        if (it != within.end()) return static_cast<int>(it - within.begin());
      }
      within.push_back(key);
      return static_cast<int>(within.size()) - 1;
    };
    std::vector<std::pair<int, int>> scales;
    for (std::size_t i = 0; i < asked; ++i) {
      const std::size_t p = which[i];
      const int sa = point_value(std::get<0>(within[i]), pairs[p].first.x);
      const int sb = point_value(std::get<1>(within[i]), pairs[p].second.x);
      scales.emplace_back(sa, sb);
    }
    std::vector<double> code;  // the memo's key for the pairs
    for (const auto& [a, b, xa, xb] : within)
      code.insert(code.end(), {double(a), double(b), xa, xb});
    std::vector<std::vector<Receptance4>> v =
        sampled_values(frequencies, grid, interpolate, evaluator(sets.points[s], within),
                       sampling(), scales, *memo_, sets.points[s], code);
    for (std::size_t i = 0; i < which.size(); ++i) values[which[i]] = std::move(v[i]);
  }
  return values;
}

GridSamplingRail::Evaluator WaveguideRailModel::evaluator(const Points& points,
                                                          const SetPairs& pairs) const {
  // The points' basis on the first direct evaluation (none where a kept sampling serves all; the
  // sampling may evaluate on several threads); the pairs as (a, b, x_a - x_b).
  std::vector<std::tuple<int, int, double>> within;
  for (const auto& [a, b, x, unused] : pairs) within.emplace_back(a, b, x);
  const Lazy<std::shared_ptr<const Station>> st([this, points] { return station(points); });
  return
      [this, within, st](double f) { return between(*st.get(), checked_complex_omega(f), within); };
}

std::unique_ptr<RailModel> GridSamplingRail::on_grid(std::vector<double> grid) const {
  if (!samples_grid()) return nullptr;
  return std::make_unique<WaveguideOnGrid>(*this, std::move(grid));
}

WaveguideOnGrid::WaveguideOnGrid(const GridSamplingRail& rail, std::vector<double> grid)
    : RailModel(rail.track(), rail.position()), rail_(rail), grid_(std::move(grid)) {}

std::vector<std::vector<Receptance6>> WaveguideOnGrid::contact_transfers(
    const std::vector<double>& frequencies, const std::vector<RailContactPair>& pairs,
    bool interpolate) const {
  return interpolate ? rail_.contact_transfers_from(grid_, frequencies, pairs)
                     : rail_.contact_transfers(frequencies, pairs, false);
}

RailModel::LaplaceTransfers WaveguideRailModel::direct_laplace_transfers(
    const std::vector<RailContactPair>& pairs) const {
  const PointSets sets = point_sets(pairs);
  std::vector<std::shared_ptr<const Station>> stations;
  for (const auto& points : sets.points) stations.push_back(station(points));
  return [this, pairs, sets, stations](cdouble s) {
    const cdouble omega = checked_laplace(s);
    std::vector<Receptance6> out(pairs.size());
    for (std::size_t k = 0; k < stations.size(); ++k) {
      std::vector<std::tuple<int, int, double>> within;
      std::vector<std::size_t> which;
      for (std::size_t p = 0; p < pairs.size(); ++p)
        if (sets.set[p] == static_cast<int>(k))
          within.push_back(sets.within[p]), which.push_back(p);
      const std::vector<Receptance4> r = between(*stations[k], omega, within);
      for (std::size_t i = 0; i < which.size(); ++i)
        out[which[i]] = from_contact_frames(r[i], pairs[which[i]].first.contact_angle,
                                            pairs[which[i]].second.contact_angle);
    }
    return out;
  };
}

std::vector<Receptance4> WaveguideRailModel::line_transfers(
    double frequency, const std::vector<std::pair<double, double>>& pairs) const {
  const Station& c = crown();
  const RailWaves w = c.model.waves(checked_complex_omega(frequency));
  std::vector<Receptance4> out;
  for (const auto& [xr, xe] : pairs)
    out.push_back(c.model.contact_receptance(w, c.loads, c.loads, xr - xe));
  return out;
}

Receptance4 WaveguideRailModel::line_transfer_laplace(cdouble s, double x_response,
                                                      double x_load) const {
  const Station& c = crown();
  return c.model.contact_receptance(c.model.waves(checked_laplace(s)), c.loads, c.loads,
                                    x_response - x_load);
}

Receptance4 WaveguideRailModel::contact_receptance(double frequency, double offset_y,
                                                   double contact_angle) const {
  return between(*station({{offset_y, contact_angle}}), checked_complex_omega(frequency),
                 {{0, 0, 0.0}})
      .front();
}

Receptance4 WaveguideRailModel::contact_receptance_laplace(cdouble s, double offset_y,
                                                           double contact_angle) const {
  return between(*station({{offset_y, contact_angle}}), checked_laplace(s), {{0, 0, 0.0}}).front();
}

Receptance4 WaveguideRailModel::contact_transfer(double frequency, double offset_a, double angle_a,
                                                 double offset_b, double angle_b, double x) const {
  // one basis per unordered pair: (b, a) at -x is the transpose of (a, b) at x
  const std::pair<double, double> a(offset_a, angle_a), b(offset_b, angle_b);
  if (b < a)
    return contact_transfer(frequency, offset_b, angle_b, offset_a, angle_a, -x).transpose();
  return between(*station({a, b}), checked_complex_omega(frequency), {{0, 1, x}}).front();
}

Receptance4 WaveguideRailModel::contact_transfer_laplace(cdouble s, double offset_a, double angle_a,
                                                         double offset_b, double angle_b,
                                                         double x) const {
  const std::pair<double, double> a(offset_a, angle_a), b(offset_b, angle_b);
  if (b < a)
    return contact_transfer_laplace(s, offset_b, angle_b, offset_a, angle_a, -x).transpose();
  return between(*station({a, b}), checked_laplace(s), {{0, 1, x}}).front();
}

std::vector<Receptance4> WaveguideRailModel::contact_receptances(
    const std::vector<double>& frequencies, double offset_y, double contact_angle) const {
  const RailContact c{0.0, offset_y, contact_angle};
  const std::vector<std::vector<Receptance6>> six = contact_transfers(frequencies, {{c, c}});
  std::vector<Receptance4> out;
  const Eigen::Matrix<cdouble, 6, 4> T = contact_frame(contact_angle).cast<cdouble>();
  for (const auto& r : six) out.push_back(T.transpose() * r.front() * T);
  return out;
}

std::vector<Receptance4> interpolate_receptances(const std::vector<double>& grid,
                                                 const std::vector<Receptance4>& values,
                                                 const std::vector<double>& frequencies) {
  const int n = static_cast<int>(grid.size());
  if (n < 3 || static_cast<int>(values.size()) != n)
    throw NumericalError("interpolate_receptances: at least 3 samples, one value per sample");
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = std::log(grid[i]);
  // Slopes dR/dx at the samples: the derivative of the parabola through (i-1, i, i+1) at i
  // (one-sided parabola at the ends); cubic Hermite between samples (de Boor, A Practical Guide
  // to Splines, 2001, Ch. IV, Eq. (7)).
  std::vector<Receptance4> slope(n);
  for (int i = 0; i < n; ++i) {
    const int j = std::clamp(i, 1, n - 2);
    const double h0 = x[j] - x[j - 1], h1 = x[j + 1] - x[j];
    const Receptance4 d0 = (values[j] - values[j - 1]) / h0, d1 = (values[j + 1] - values[j]) / h1;
    if (i == j)
      slope[i] = (h1 * d0 + h0 * d1) / (h0 + h1);
    else if (i == 0)
      slope[i] = d0 - h0 * (d1 - d0) / (h0 + h1);
    else
      slope[i] = d1 + h1 * (d1 - d0) / (h0 + h1);
  }
  std::vector<Receptance4> out;
  out.reserve(frequencies.size());
  for (double f : frequencies) {
    const double xf = std::log(f);
    if (!(xf >= x.front() - 1e-12 && xf <= x.back() + 1e-12))
      throw NumericalError("interpolate_receptances: frequency outside the sampled grid");
    const int i = std::clamp(
        static_cast<int>(std::upper_bound(x.begin(), x.end(), xf) - x.begin()) - 1, 0, n - 2);
    const double h = x[i + 1] - x[i], t = (xf - x[i]) / h;
    const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t),
                 h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
    out.push_back(h00 * values[i] + h10 * h * slope[i] + h01 * values[i + 1] +
                  h11 * h * slope[i + 1]);
  }
  return out;
}

Eigen::MatrixXd contact_point_loads(const RailWaveguide& section,
                                    const std::vector<Eigen::Vector2d>& outline,
                                    const WaveguideRailOptions& options,
                                    const std::vector<std::pair<double, double>>& points) {
  Eigen::MatrixXd loads(section.dofs(), 4 * static_cast<int>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [point, normal] =
        contact_point_and_normal(outline, options, points[i].first, points[i].second);
    loads.middleCols(4 * i, 4) = contact_loads_at(section, options, point, normal);
  }
  return loads;
}

LoadPointColumns load_point_columns(const std::vector<RailLoadPoint>& points) {
  LoadPointColumns out;
  for (const RailLoadPoint& p : points) {
    const std::pair<double, double> at(p.offset_y, p.contact_angle);
    const auto it = std::find(out.distinct.begin(), out.distinct.end(), at);
    out.which.push_back(static_cast<int>(it - out.distinct.begin()));
    if (it == out.distinct.end()) out.distinct.push_back(at);
    out.x.insert(out.x.end(), 4, p.x);
  }
  return out;
}

Eigen::MatrixXd LoadPointColumns::columns(const Eigen::MatrixXd& distinct_loads) const {
  Eigen::MatrixXd out(distinct_loads.rows(), 4 * static_cast<Eigen::Index>(which.size()));
  for (std::size_t i = 0; i < which.size(); ++i)
    out.middleCols(4 * static_cast<Eigen::Index>(i), 4) =
        distinct_loads.middleCols(4 * which[i], 4);
  return out;
}

HeadBody section_head_body(const WaveguideRailOptions& options) {
  const std::vector<Eigen::Vector2d> outline =
      options.outline.empty() ? uic60_outline() : options.outline;
  return head_body(fem::mesh_polygon(outline, options.mesh_size), options.head_bottom);
}

namespace {

// A contact's four columns on the head's six distributions (HeadBody::at at its point and normal).
Eigen::Matrix<double, 6, 4> head_columns(const HeadBody& head,
                                         const std::vector<Eigen::Vector2d>& outline,
                                         const WaveguideRailOptions& options, double offset_y,
                                         double angle) {
  const auto [point, normal] = contact_point_and_normal(outline, options, offset_y, angle);
  return head.at(point, normal);
}

}  // namespace

std::optional<RailLoadBasis> head_load_basis(const HeadBody& head,
                                             const std::vector<Eigen::Vector2d>& outline,
                                             const WaveguideRailOptions& options,
                                             const std::vector<RailLoadPoint>& points) {
  if (!options.head_load) return std::nullopt;
  RailLoadBasis out;
  out.per_position = static_cast<int>(head.loads.cols());
  for (const RailLoadPoint& p : points) out.x.push_back(p.x);
  std::sort(out.x.begin(), out.x.end());  // the same basis for the same positions, in any order
  out.x.erase(std::unique(out.x.begin(), out.x.end()), out.x.end());
  out.combination = Eigen::MatrixXd::Zero(out.per_position * Eigen::Index(out.x.size()),
                                          4 * Eigen::Index(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const RailLoadPoint& p = points[i];
    const Eigen::Index at = std::find(out.x.begin(), out.x.end(), p.x) - out.x.begin();
    out.combination.block(out.per_position * at, 4 * Eigen::Index(i), out.per_position, 4) =
        head_columns(head, outline, options, p.offset_y, p.contact_angle);
  }
  return out;
}

std::optional<SpanningPoints> head_spanning_points(
    const HeadBody& head, const std::vector<Eigen::Vector2d>& outline,
    const WaveguideRailOptions& options, const std::vector<std::pair<double, double>>& points) {
  if (!options.head_load) return std::nullopt;
  SpanningPoints out;
  // the crown, and a point 25 mm off it with its normal at 0.3 rad: the two points' lever arms
  // and tangents differ, so their forces and moments span the head's six (HeadBody::at)
  out.points = {{0.0, 0.0}, {0.025, 0.3}};
  auto columns = [&](const std::pair<double, double>& p) {
    return head_columns(head, outline, options, p.first, p.second);
  };
  Eigen::Matrix<double, 6, 8> span;
  span << columns(out.points[0]), columns(out.points[1]);
  // rows equilibrated (forces, moments and the axial planes' slopes differ by 1e6)
  const Eigen::Matrix<double, 6, 1> scale = span.rowwise().lpNorm<Eigen::Infinity>().cwiseInverse();
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 6, 8>> cod(scale.asDiagonal() *
                                                                                span);
  if (cod.rank() < 6) return std::nullopt;
  for (const auto& p : points) {
    const Eigen::Matrix<double, 6, 4> C = scale.asDiagonal() * columns(p);
    const Eigen::Matrix<double, 8, 4> alpha = cod.solve(C);
    if ((scale.asDiagonal() * span * alpha - C).norm() > 1e-10 * C.norm()) return std::nullopt;
    out.combination.push_back(alpha);
  }
  return out;
}

std::optional<RailLoadBasis> WaveguideRailModel::load_basis(
    const std::vector<RailLoadPoint>& points) const {
  return head_load_basis(head_.get(), outline_, options_, points);
}

SurfaceSpectra WaveguideRailModel::basis_surface_spectra(const std::vector<double>& x,
                                                         const std::vector<OutlinePiece>& pieces,
                                                         const Eigen::MatrixXd& patterns) const {
  if (!options_.head_load) return nullptr;
  const Section& s = section_.get();
  const Eigen::MatrixXd head = s.full.head_body(options_.head_bottom).loads;
  auto model = std::make_shared<const RailWaveguide>(
      s.full.reduced(options_.contact_reduction, head, s.modes));
  auto response = std::make_shared<const Eigen::MatrixXd>(
      outline_normal_distributions(model->mesh(), pieces) * patterns);
  auto placed = std::make_shared<const PlacedLoads>(placed_at(head, x));
  return [model, response, placed](double frequency) {
    return surface_spectrum(*model, angular(frequency), *response, placed->load, placed->x);
  };
}

SurfaceSpectra WaveguideRailModel::surface_spectra(const std::vector<RailLoadPoint>& points,
                                                   const std::vector<OutlinePiece>& pieces,
                                                   const Eigen::MatrixXd& patterns) const {
  if (std::optional<RailLoadBasis> basis = load_basis(points))
    return combined(basis_surface_spectra(basis->x, pieces, patterns),
                    std::move(basis->combination));
  const LoadPointColumns at = load_point_columns(points);
  const std::shared_ptr<const Station> st = station(at.distinct);
  auto response = std::make_shared<const Eigen::MatrixXd>(
      outline_normal_distributions(st->model.mesh(), pieces) * patterns);
  auto load = std::make_shared<const Eigen::MatrixXd>(at.columns(st->loads));
  return [st, response, load, x = at.x](double frequency) {
    return surface_spectrum(st->model, angular(frequency), *response, *load, x);
  };
}

RailPointSets rail_point_sets(const std::vector<RailContactPair>& pairs) {
  PointSets s = point_sets(pairs);
  return RailPointSets{std::move(s.points), std::move(s.set), std::move(s.within)};
}

}  // namespace rollnoise::dynamics
