// noise.band_refinement: the loops on the lines the band means need (docs/noise_loop.md Sec. 6.1).
#include "pipeline/band_lines.hpp"

#include <algorithm>
#include <memory>

#include "core/assert.hpp"
#include "core/task_pool.hpp"
#include "noise/band_refinement.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/limits.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

namespace {

// The f and g of the main run's model at the lines of a level, computed once: its loop variants
// and its contact in the bogie loop take them.
struct MainCoefficients {
  const nss::LinearContactModel* model;
  noise::ContactCoefficients at;
};

// A wheel's contact at other frequencies: what bogie_loop and wheel_loop_alone read of it. The
// contact of the main run's model (the leading outer wheel's tread patch; not its flange patch,
// which has a model of its own) from `main`.
WheelNoise contact_at(const WheelNoise& w, const NoiseCase& nc, const std::vector<double>& f,
                      const MainCoefficients& main) {
  WheelNoise out;
  out.state = w.state;
  out.position = w.position;
  out.contact_receptance = w.mean.model().get() == main.model
                               ? wheel_contact_receptance(w, nc, f, main.at)
                               : wheel_contact_receptance(w, nc, f);
  return out;
}

std::vector<WheelNoise> contacts_at(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                    const std::vector<double>& f, const MainCoefficients& main) {
  std::vector<WheelNoise> out;
  for (const WheelNoise& w : wheels) out.push_back(contact_at(w, nc, f, main));
  return out;
}

// Every loop of `r` computed at the frequencies f (as run_noise computes them on the case's lines).
struct LoopsAt {
  noise::LoopVariants variants;
  noise::ContactSetLoopResult bogie;
  std::vector<noise::LoopResult> wheel_loops;
};

// `rail`: the case's rail as the refinement takes it (RailModel::on_grid).
LoopsAt loops_at(const NoiseResult& r, const NoiseCase& nc, const std::vector<double>& f,
                 const dynamics::RailModel& rail) {
  LoopsAt out;
  const noise::StructureSpectra spectra = noise::structure_spectra(*nc.wheel, f);
  const nss::LinearContactModel& model = *r.mean.model();
  const MainCoefficients main{&model, {model.creep_coefficients(f), model.normal_load_coefficients(f)}};
  out.variants = loop_variants(r, nc, spectra, f, main.at.creep, main.at.load, &rail);
  if (r.bogie) {
    out.bogie = bogie_loop(contacts_at(r.wheels, nc, f, main), nc, f, {},
                           contacts_at(r.patches, nc, f, main), 1, &rail);
    return out;
  }
  for (const WheelNoise& w : r.wheels)
    out.wheel_loops.push_back(w.state.wheel == noise::WheelId::leading_outer
                                  ? noise::LoopResult{}
                                  : wheel_loop_alone(contact_at(w, nc, f, main), nc, spectra, &rail));
  return out;
}

void append(std::vector<std::vector<double>>& to, std::vector<std::vector<double>> more) {
  for (auto& p : more) to.push_back(std::move(p));
}

}  // namespace

RefinedLoops refined_loops(const NoiseResult& r, const NoiseCase& nc, int threads) {
  // At most 16 times the case's lines in all (768 per band for the default 48; the worst case of a
  // level is three lines for one), and within the case's limits.steps and limits.memory: a level
  // that would pass them is not taken (the band means keep the lines they have).
  constexpr std::size_t kMaxGrowth = 16;
  RefinedLoops out;
  out.variants = r.variants;
  noise::ContactSetLoopResult bogie = r.bogie ? *r.bogie : noise::ContactSetLoopResult{};
  if (!r.bogie)
    for (const WheelNoise& w : r.wheels)
      out.wheel_loops.push_back(w.state.wheel == noise::WheelId::leading_outer ? noise::LoopResult{}
                                                                               : w.loop);
  const std::size_t base = r.variants.main.frequency.size();
  // A rail that samples the grid it is given (the waveguide) takes the added lines from its
  // sampling of the case's lines (RailModel::on_grid): interpolated where that sampling checked
  // the interpolation, computed elsewhere; each line's value then depends on the case's lines and
  // itself alone. Other rails compute every line alone as they are.
  const std::unique_ptr<dynamics::RailModel> on_grid = nc.rail->on_grid(r.axis.frequency);
  const dynamics::RailModel& rail = on_grid ? *on_grid : *nc.rail;
  for (int level = 0; level < nc.band_refinement; ++level) {
    std::vector<std::vector<double>> powers = noise::sampled_powers(out.variants.main);
    if (out.variants.has_uncoupled()) append(powers, noise::sampled_powers(out.variants.uncoupled));
    if (out.variants.has_baseline()) append(powers, noise::sampled_powers(out.variants.baseline));
    if (r.bogie) append(powers, noise::sampled_powers(bogie));
    for (const auto& loop : out.wheel_loops)
      if (!loop.frequency.empty()) append(powers, noise::sampled_powers(loop));
    const std::vector<double>& f = out.variants.main.frequency;
    const std::vector<double> added = noise::refinement_frequencies(f, powers, r.axis.centres);
    if (added.empty()) break;
    const double total = double(f.size() + added.size());
    const Limits& limits = r.mean.contact().limits;
    if (total > double(kMaxGrowth * base) || total > double(limits.steps) ||
        frequency_bytes(total) > limits.memory_bytes()) {
      out.capped = true;
      break;
    }
    // The added lines in contiguous slices, one per thread (core/task_pool.hpp, for_slices).
    // Every line is computed on its own (spectra, f and g, the loops; a sampling rail through its
    // on_grid view above), so the band levels do not depend on the thread count; a rail that
    // interpolated on the grid of each call would make them depend on it (the waveguide's moved by
    // up to 0.06 dB between 1 and 2 threads before it had the view).
    ROLLNOISE_ASSERT(!rail.samples_grid(),
                     "refined_loops: a rail that samples its grid needs an on_grid view");
    std::vector<LoopsAt> more(std::min<std::size_t>(std::max(threads, 1), added.size()));
    more.resize(
        for_slices(added.size(), threads, [&](std::size_t i, std::size_t lo, std::size_t hi) {
          more[i] =
              loops_at(r, nc, std::vector<double>(added.begin() + lo, added.begin() + hi), rail);
        }));
    for (LoopsAt& m : more) {
      out.variants = noise::merged(std::move(out.variants), std::move(m.variants));
      if (r.bogie) bogie = noise::merged(std::move(bogie), std::move(m.bogie));
      for (std::size_t i = 0; i < out.wheel_loops.size(); ++i)
        if (!out.wheel_loops[i].frequency.empty())
          out.wheel_loops[i] = noise::merged(std::move(out.wheel_loops[i]), std::move(m.wheel_loops[i]));
    }
    ++out.levels;
    out.added_lines += static_cast<long>(added.size());
  }
  if (r.bogie) out.bogie = std::make_shared<const noise::ContactSetLoopResult>(std::move(bogie));
  return out;
}

}  // namespace rollnoise::pipeline
