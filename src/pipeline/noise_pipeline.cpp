#include "pipeline/noise_pipeline.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>

#include "contact/normal_solver.hpp"
#include "contact/steady_rolling.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "core/task_pool.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/kalker_linear.hpp"
#include "noise/roughness.hpp"
#include "pipeline/noise_sound.hpp"

namespace rollnoise::pipeline {

MeanContactOptions noise_contact_options(const NoiseCase& nc,
                                         const std::vector<double>& frequency) {
  MeanContactOptions o;
  // the model with the NSS contact, and for the quasi-steady baseline's f(0), g(0)
  o.with_model = nc.use_nss || nc.compare == NoiseCase::Baseline::kQuasiSteady;
  o.frequencies = frequency;
  o.frequency_key = "noise.band_max";
  return o;
}

namespace {

// The 1/3-octave centres of the case, their narrow-band samples checked against c.limits (cheap:
// run before the curve stage, so that a huge noise.points_per_band is refused at once).
std::vector<double> band_centres(const ContactCase& c, const NoiseCase& nc) {
  std::vector<double> centres = noise::third_octave_centres(nc.band_min, nc.band_max);
  if (centres.empty())
    throw InputError("noise.band_max", "no 1/3-octave band between band_min and band_max");
  const double count = double(centres.size()) * double(nc.points_per_band);
  check_size(c.limits, "noise.points_per_band", count, "narrow-band frequencies",
             frequency_bytes(count));
  return centres;
}

}  // namespace

BandAxis band_axis(const ContactCase& c, const NoiseCase& nc) {
  BandAxis a;
  a.centres = band_centres(c, nc);
  a.frequency = noise::band_frequencies(a.centres, nc.points_per_band);
  return a;
}

namespace {

// How many wheels curve.wheels names (as listed_wheel_ids, without its checks): more than one
// runs the further wheels in parallel.
std::size_t listed_wheel_count(const NoiseCase& nc) {
  if (!nc.wheels.empty()) return nc.wheels.size();
  return nc.curve_radius > 0.0 ? noise::kAllWheels.size() : 1;
}

// The wheels of curve.wheels other than the leading outer one (the main run's): their contact
// work (wheel_contact_noise: mean contact, NSS model, f(w), g(w)) on a pool of `threads`, started
// as soon as the curve state exists (the cases are placed from it), so that the
// pool's background threads work on them while the caller finishes the main wheel's loop; finish()
// lets the caller join in. Each wheel is one task with its result at its index: the results do not
// depend on the thread count. An exception of a wheel reaches finish()'s caller (TaskPool).
class FurtherWheels {
 public:
  FurtherWheels(const NoiseCase& nc, int threads) : nc_(nc), threads_(threads) {}

  // Each task also finds its wheel's contact state (noise::bogie_wheel_contacts of that wheel
  // alone: the wheels' states are independent given the curve state). `base`: the main wheel's
  // case as placed (each wheel's case is placed at its own contact from it: grid, a, b, N).
  void start(const ContactCase& base, const CurveSetup& curve,
             const std::vector<double>& frequency) {
    base_ = base;
    curve_ = curve;
    frequency_ = frequency;
    const std::vector<noise::WheelId> listed = curve_wheel_ids(curve_, nc_);
    if (listed.empty()) order_.push_back(-1);  // no curve contact state: the case's one contact
    for (noise::WheelId id : listed) {
      order_.push_back(id == noise::WheelId::leading_outer ? -1 : int(ids_.size()));
      if (id == noise::WheelId::leading_outer)
        main_state_ = curve_.state->wheel;
      else
        ids_.push_back(id);
    }
    results_.resize(ids_.size());
    // The outer wheels first: they carry the load transfer, so their patches are the larger ones
    // and their models the longest tasks (a long task started last would run on alone).
    schedule_.resize(ids_.size());
    for (std::size_t i = 0; i < ids_.size(); ++i) schedule_[i] = i;
    std::stable_partition(schedule_.begin(), schedule_.end(),
                          [this](std::size_t i) { return noise::is_outer(ids_[i]); });
    // Caller::busy: the caller's main wheel runs beside them (with one further wheel, too).
    pool_ = std::make_unique<TaskPool>(
        ids_.size(), threads_,
        [this](std::size_t task, int) {
          const std::size_t i = schedule_[task];
          const auto t0 = Clock::now();
          const noise::WheelContact w =
              noise::bogie_wheel_contacts(*curve_.state_input, *curve_.state, {ids_[i]}).front();
          results_[i] = wheel_contact_noise(base_, nc_, w, frequency_);
          results_[i].seconds = seconds_since(t0);
        },
        TaskPool::Caller::busy);
  }

  // Every wheel in the order of curve.wheels, the main one from the run.
  std::vector<WheelNoise> finish(const NoiseResult& r) {
    if (pool_) pool_->finish();
    std::vector<WheelNoise> out;
    for (int k : order_) out.push_back(k >= 0 ? std::move(results_[k]) : main_wheel(r));
    return out;
  }

 private:
  WheelNoise main_wheel(const NoiseResult& r) const {
    WheelNoise m = contact_noise(
        noise::WheelId::leading_outer, main_state_, r.mean, nc_, r.axis.frequency,
        nc_.use_nss ? noise::ContactCoefficients{r.creep, r.load} : noise::ContactCoefficients{});
    m.seconds = r.seconds_contact - r.seconds_curve;
    return m;
  }

  const NoiseCase& nc_;
  int threads_;
  ContactCase base_;
  CurveSetup curve_;
  std::vector<double> frequency_;
  std::optional<noise::WheelContact> main_state_;
  std::vector<noise::WheelId> ids_;    // the further wheels
  std::vector<int> order_;             // curve.wheels: index into ids_, -1 the main wheel
  std::vector<std::size_t> schedule_;  // task -> index into ids_ (the order the tasks start in)
  std::vector<WheelNoise> results_;
  std::unique_ptr<TaskPool> pool_;  // last: joined before the members its tasks use go
};

using CurveHook =
    std::function<void(const ContactCase&, const CurveSetup&, const std::vector<double>&)>;

// Stages 2-3 of the case's main contact (the leading outer wheel's placement, or the case's one
// contact) on the frequencies of `axis`, calling `on_curve` with the placed case and the curve
// state as soon as they exist (before the main contact's mean contact): the further wheels start
// from there.
NoiseResult main_contact(ContactCase c, const NoiseCase& nc, BandAxis axis,
                         const CurveHook& on_curve);

}  // namespace

const noise::LoopVariants& NoiseResult::band_loops() const {
  return refined ? refined->loops : loops;
}

namespace {

// The wheel the top-level outputs report: the leading outer wheel if it is a contact, else the
// first.
std::size_t reported_wheel(const std::vector<WheelNoise>& wheels) {
  for (std::size_t i = 0; i < wheels.size(); ++i)
    if (wheels[i].wheel == noise::WheelId::leading_outer) return i;
  return 0;
}

}  // namespace

NoiseResult run_noise(ContactCase c, const NoiseCase& nc) {
  const auto t0 = Clock::now();
  BandAxis axis = band_axis(c, nc);  // 1, the sizes before any work
  const int threads = resolved_threads(c.threads, nss::kMaxThreads);
  NoiseResult r = run_noise_loop(std::move(c), nc, std::move(axis));
  if (nc.band_refinement > 0)
    r.refined = std::make_shared<const RefinedLoops>(refined_loops(r, nc, threads));
  add_bands(r, nc, threads);
  r.seconds_total = seconds_since(t0);
  return r;
}

NoiseResult run_noise_loop(ContactCase c, const NoiseCase& nc, BandAxis axis) {
  const auto t0 = Clock::now();
  // solver.threads: the wheels share the threads, so each wheel's model (the main one's too) runs
  // on one while there are several (the model checks the key's range itself)
  const int threads = resolved_threads(c.threads, nss::kMaxThreads);
  const bool parallel = threads > 1 && listed_wheel_count(nc) > 1;
  if (parallel && c.threads >= 0 && c.threads <= nss::kMaxThreads) c.threads = 1;
  FurtherWheels further(nc, parallel ? threads : 1);
  NoiseResult r = main_contact(
      std::move(c), nc, std::move(axis),
      [&](const ContactCase& base, const CurveSetup& curve, const std::vector<double>& frequency) {
        further.start(base, curve, frequency);
      });
  // r.seconds_wheels: what the wheels took after the main wheel's contact (their work overlaps it)
  const auto t1 = Clock::now();
  r.wheels = further.finish(r);
  r.patches = second_patches(r.mean.curve(), r.mean.contact(), nc, r.wheels, r.axis.frequency);
  r.reported = reported_wheel(r.wheels);
  r.loops = contact_loop(r.wheels, nc, r.axis.frequency, r.patches, threads);
  r.coupled_contacts = nc.contact_coupling == NoiseCase::ContactCoupling::kBogie;
  r.seconds_wheels = seconds_since(t1);
  r.seconds_total = seconds_since(t0);
  return r;
}

namespace {

NoiseResult main_contact(ContactCase c, const NoiseCase& nc, BandAxis axis,
                         const CurveHook& on_curve) {
  const auto t0 = Clock::now();
  NoiseResult r;
  r.axis = std::move(axis);
  const std::vector<double>& freq = r.axis.frequency;

  // 2.-3. the mean contact (the model always: the quasi-steady baseline and the sweep's f(0), g(0))
  MeanContactOptions options = noise_contact_options(nc, freq);
  options.with_model = true;
  CurvePlacement placed = resolve_curve(c, nc);  // as curve_mean_contact
  r.seconds_curve = seconds_since(t0);
  on_curve(placed.contact, placed.curve, freq);  // the further wheels from here on
  r.mean = solve_mean_contact(std::move(placed.contact), std::move(placed.curve), options);
  const nss::LinearContactModel& model = *r.mean.model();
  r.creep = model.creep_coefficients(freq);
  r.load = model.normal_load_coefficients(freq);  // g, the same sweep
  r.f0 = model.creep_coefficients({0.0})[0];
  r.g0 = model.normal_load_coefficients({0.0})[0];
  r.coupled = nc.normal_coupling && nc.use_nss && !r.load.empty();
  r.baseline_name = nc.compare == NoiseCase::Baseline::kQuasiSteady ? "quasi_steady" : "kalker";
  r.mean_force = contact::total_forces(r.mean.patch().grid, r.mean.steady().px, r.mean.steady().py);
  r.seconds_contact = seconds_since(t0);
  return r;
}

}  // namespace

void add_bands(NoiseResult& r, const NoiseCase& nc, int threads) {
  // 5. roughness and bands
  const std::vector<double>& centres = r.axis.centres;
  // The band means on the refined lines where noise.band_refinement added some (band_lines.hpp).
  const noise::LoopVariants& loops = r.band_loops();
  // The sources' effective roughness once each (the contact filter's band means are quadratures).
  r.source_levels = bogie_source_levels(r.wheels, nc, centres, r.patches, threads);
  auto set = [&](const noise::ContactSetLoopResult& loop, noise::BandLevels WheelNoise::*bands) {
    const std::vector<noise::BandLevels> b = bogie_bands(loop, centres, r.source_levels);
    for (std::size_t i = 0; i < r.wheels.size(); ++i) r.wheels[i].*bands = b[i];
    for (std::size_t k = 0; k < r.patches.size(); ++k) r.patches[k].*bands = b[r.wheels.size() + k];
  };
  set(loops.main, &WheelNoise::bands);
  if (loops.has_uncoupled()) set(loops.uncoupled, &WheelNoise::uncoupled_bands);
  if (loops.has_baseline()) set(loops.baseline, &WheelNoise::baseline_bands);
  // 6. the sound powers (they follow the roughness too: a study's cases that share stages 1-4
  // get their own)
  r.sound =
      nc.sound.on ? std::make_shared<const SoundResult>(noise_sound(r, nc, threads)) : nullptr;
}

ReceptanceResult run_receptance(ContactCase c, const NoiseCase& nc,
                                const std::vector<double>& freq) {
  for (double f : freq)  // before any work
    if (!(f > 0.0)) throw InputError("frequency.f_min", "receptances need positive frequencies");
  ReceptanceResult r;
  MeanContactOptions options;
  options.with_model = nc.use_nss;
  if (nc.use_nss) options.frequencies = freq, options.frequency_key = "frequency.f_max";
  r.mean = curve_mean_contact(c, nc, options);
  const ContactCase& cc = r.mean.contact();
  r.frequency = freq;
  const double kN = r.mean.normal_stiffness();
  if (nc.use_nss) {
    const nss::LinearContactModel& model = *r.mean.model();
    const auto f = model.creep_coefficients(freq);
    r.contact_receptance = nc.normal_coupling
                               ? noise::contact_receptances(freq, kN, cc.speed, f,
                                                            model.normal_load_coefficients(freq))
                               : noise::contact_receptances(freq, kN, cc.speed, f);
  } else {
    r.contact_receptance = noise::contact_receptances(
        freq, kN, cc.speed,
        noise::steady_creep(noise::kalker_creep_matrix(cc.a, cc.b, cc.material)));
  }
  r.structures = noise::structural_receptances(*nc.wheel, *nc.rail, r.mean.curve().position, freq);
  return r;
}

}  // namespace rollnoise::pipeline
