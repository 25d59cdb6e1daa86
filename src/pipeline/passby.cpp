// The train's axles, its sources and the pass-by levels: (A1) and the source model of passby.hpp.
#include "pipeline/passby.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "acoustics/tsi_noise.hpp"
#include "core/stopwatch.hpp"

namespace rollnoise::pipeline {

namespace {

using acoustics::Directivity;
using acoustics::MovingLineSource;
using acoustics::MovingPointSource;
using noise::WheelId;

// The bogie wheel of an axle (leading or trailing) on a side (outer or inner).
WheelId bogie_wheel(bool leading, bool outer) {
  if (leading) return outer ? WheelId::leading_outer : WheelId::leading_inner;
  return outer ? WheelId::trailing_outer : WheelId::trailing_inner;
}

// The computed wheel whose powers `want` takes (passby.hpp): itself, the same axle's other
// wheel, the other axle's wheel on its side, the first computed.
std::size_t source_index(WheelId want, const std::vector<WheelId>& wheels) {
  const bool leading = want == WheelId::leading_outer || want == WheelId::leading_inner;
  const bool outer = want == WheelId::leading_outer || want == WheelId::trailing_outer;
  for (const WheelId w : {want, bogie_wheel(leading, !outer), bogie_wheel(!leading, outer)})
    for (std::size_t i = 0; i < wheels.size(); ++i)
      if (wheels[i] == w) return i;
  return 0;
}

// 10^{L/10} pW in W; a NaN level (an empty column) is no power.
double watts(double level) {
  return std::isfinite(level) ? 1e-12 * std::pow(10.0, 0.1 * level) : 0.0;
}

// The axial family's share of the wheel's power per band (empty without the families).
std::vector<double> axial_share(const std::vector<std::array<double, 3>>& family) {
  std::vector<double> share;
  for (const auto& f : family) {
    const double ax = watts(f[0]), sum = ax + watts(f[1]) + watts(f[2]);
    share.push_back(sum > 0.0 ? ax / sum : 0.0);
  }
  return share;
}

// The sources of the whole train, by kind.
struct TrainSources {
  std::vector<MovingPointSource> wheels;
  std::vector<MovingLineSource> rails, sleepers;
};

// The sources of one wheel (x0 along the track, y across) with the computed wheel k's powers.
void add_wheel(TrainSources& s, double x0, double y, std::size_t k, const SoundResult& sound,
               const PassbyCase& pc) {
  const SoundBands& p = sound.contact_power[k];
  const std::size_t nb = p.size();
  const std::vector<double> share = k < sound.contact_family.size()
                                        ? axial_share(sound.contact_family[k])
                                        : std::vector<double>{};
  MovingPointSource mono{{x0, y, pc.wheel_radius}, Directivity::kMonopole, {}};
  MovingPointSource dipole{{x0, y, pc.wheel_radius}, Directivity::kDipoleY, {}};
  MovingLineSource rail{{x0, y, kRailCentreHeight}, pc.rail_directivity, {}, sound.decay_vertical};
  MovingLineSource sleepers{
      {x0, y, pc.geometry.ground_level}, Directivity::kMonopole, {}, sound.decay_vertical};
  for (std::size_t b = 0; b < nb; ++b) {
    const double w = watts(p[b][0]), a = share.size() == nb ? share[b] : 0.0;
    mono.power.push_back((1.0 - a) * w);
    dipole.power.push_back(a * w);
    rail.power.push_back(watts(p[b][1]));
    sleepers.power.push_back(watts(p[b][2]));
  }
  s.wheels.push_back(mono);
  if (share.size() == nb) s.wheels.push_back(dipole);
  s.rails.push_back(rail);
  s.sleepers.push_back(sleepers);
}

// The levels of the summed histories: L_pAF(t), L_pAeq,Tp, TEL, L_pAFmax; the spectrum.
void add_levels(PassbyResult& r, const std::array<acoustics::PassbyHistory, 3>& h, double dt) {
  const double tp = r.passage_time;
  acoustics::PassbyHistory total = h[0];
  total.mean_square = h[0].mean_square + h[1].mean_square + h[2].mean_square;
  const std::vector<double> pa2 = acoustics::a_weighted_mean_square(total, r.centre);
  r.time = total.time;
  const std::vector<double> fast = acoustics::time_weighted(pa2, dt);
  for (double x : fast) r.level_a.push_back(acoustics::pressure_level(x));
  r.lmax_a = *std::max_element(r.level_a.begin(), r.level_a.end());
  r.leq_a = acoustics::equivalent_level(r.time, pa2, 0.0, tp);                               // (E1)
  r.tel = acoustics::equivalent_level(r.time, pa2, r.time.front(), r.time.back() + dt, tp);  // (E2)
  const auto column = [](const Eigen::MatrixXd& m, std::size_t b) {
    const Eigen::VectorXd c = m.col(static_cast<Eigen::Index>(b));
    return std::vector<double>(c.data(), c.data() + c.size());
  };
  for (std::size_t b = 0; b < r.centre.size(); ++b) {
    std::array<double, 4> row{};
    for (std::size_t s = 0; s < 3;
         ++s) {  // a source without power (the table wheel): NaN, not -inf
      const double l = acoustics::equivalent_level(r.time, column(h[s].mean_square, b), 0.0, tp);
      row[s] = std::isfinite(l) ? l : std::numeric_limits<double>::quiet_NaN();
    }
    row[3] = acoustics::equivalent_level(r.time, column(total.mean_square, b), 0.0, tp);
    r.spectrum.push_back(row);
  }
  r.spectrum_a = a_weighted_columns(r.centre, r.spectrum);
}

}  // namespace

std::array<std::size_t, 4> bogie_sources(const std::vector<WheelId>& wheels) {
  std::array<std::size_t, 4> k{};
  for (std::size_t i = 0; i < 4; ++i) k[i] = source_index(static_cast<WheelId>(i), wheels);
  return k;
}

std::vector<Axle> train_axles(const std::vector<Vehicle>& train) {
  std::vector<Axle> axles;
  double start = 0.0;  // s_k
  for (const Vehicle& v : train) {
    for (const double bogie : {start + 0.5 * (v.length - v.bogie_distance),
                               start + 0.5 * (v.length + v.bogie_distance)}) {
      axles.push_back({bogie - 0.5 * v.wheelbase, true});  // (A1)
      axles.push_back({bogie + 0.5 * v.wheelbase, false});
    }
    start += v.length;
  }
  return axles;
}

double train_length(const std::vector<Vehicle>& train) {
  double l = 0.0;
  for (const Vehicle& v : train) l += v.length;
  return l;
}

PassbyResult run_passby(const PassbyCase& pc, const SoundResult& sound,
                        const std::vector<WheelId>& wheels, double speed) {
  const Clock::time_point start = Clock::now();
  if (pc.train.empty()) throw std::invalid_argument("run_passby: a train needs a vehicle");
  if (wheels.empty() || sound.contact_power.size() < wheels.size())
    throw std::invalid_argument("run_passby: needs the sound power of every computed wheel");
  PassbyResult r;
  r.speed = speed;
  r.length = train_length(pc.train);
  r.passage_time = r.length / speed;
  r.axles = train_axles(pc.train);
  r.centre = sound.centre;
  const std::array<std::size_t, 4> source = bogie_sources(wheels);
  for (std::size_t i = 0; i < 4; ++i) r.source_wheel[i] = wheels[source[i]];
  r.wheel_split = !sound.contact_family.empty();
  TrainSources s;
  for (const Axle& a : r.axles)
    for (const bool outer : {true, false})
      add_wheel(s, -a.from_front, outer ? kRailHalfDistance : -kRailHalfDistance,
                source[static_cast<std::size_t>(bogie_wheel(a.leading, outer))], sound, pc);
  // the lead and tail of passby.hpp; the sleepers radiate into the half space (Q = 1)
  const double margin = std::max(10.0 * pc.geometry.distance, 50.0) / speed, dt = pc.time_step;
  const double t0 = -margin;
  const int steps = static_cast<int>(std::ceil((r.passage_time + 2.0 * margin) / dt)) + 1;
  acoustics::PassbyGeometry half_space = pc.geometry;
  half_space.reflection = 1.0;
  const std::array<acoustics::PassbyHistory, 3> h = {
      acoustics::passby_history(s.wheels, {}, pc.geometry, speed, t0, dt, steps),
      acoustics::passby_history({}, s.rails, pc.geometry, speed, t0, dt, steps, {}, pc.threads),
      acoustics::passby_history({}, s.sleepers, half_space, speed, t0, dt, steps, {}, pc.threads)};
  add_levels(r, h, dt);
  r.leq_a_80 = acoustics::tsi_normalised_80(r.leq_a, speed);
  r.limit_a = pc.category.empty() ? std::numeric_limits<double>::quiet_NaN()
                                  : acoustics::tsi_passby_limit(pc.category);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace rollnoise::pipeline
