// noise.band_refinement: the loops on the lines the band means need (docs/noise_loop.md Sec. 6.1).
#include "pipeline/band_lines.hpp"

#include <algorithm>
#include <memory>

#include "core/assert.hpp"
#include "core/task_pool.hpp"
#include "dynamics/rail_model.hpp"
#include "noise/band_refinement.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/limits.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

namespace {

// A contact at other frequencies: what contact_loop reads of it (its wheel, position and the
// variants' alpha_c at f, from its own model).
WheelNoise contact_at(const WheelNoise& w, const NoiseCase& nc, const std::vector<double>& f) {
  WheelNoise out;
  out.wheel = w.wheel;
  out.position = w.position;
  out.receptance = contact_variants_at(w, nc, f);
  return out;
}

std::vector<WheelNoise> contacts_at(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                    const std::vector<double>& f) {
  std::vector<WheelNoise> out;
  for (const WheelNoise& w : wheels) out.push_back(contact_at(w, nc, f));
  return out;
}

// The loop of `r` computed at the frequencies f (as run_noise computes it on the case's lines).
// `rail`: the case's rail as the refinement takes it (RailModel::on_grid).
noise::LoopVariants loops_at(const NoiseResult& r, const NoiseCase& nc,
                             const std::vector<double>& f, const dynamics::RailModel& rail) {
  return contact_loop(contacts_at(r.wheels, nc, f), nc, f, contacts_at(r.patches, nc, f), 1, &rail);
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
  out.loops = r.loops;
  const std::size_t base = r.loops.main.frequency.size();
  // A rail that samples the grid it is given (the waveguide) takes the added lines from its
  // sampling of the case's lines (RailModel::on_grid): interpolated where that sampling checked
  // the interpolation, computed elsewhere; each line's value then depends on the case's lines and
  // itself alone. Other rails compute every line alone as they are.
  const std::unique_ptr<dynamics::RailModel> on_grid = nc.rail->on_grid(r.axis.frequency);
  const dynamics::RailModel& rail = on_grid ? *on_grid : *nc.rail;
  for (int level = 0; level < nc.band_refinement; ++level) {
    std::vector<std::vector<double>> powers = noise::sampled_powers(out.loops.main);
    if (out.loops.has_uncoupled()) append(powers, noise::sampled_powers(out.loops.uncoupled));
    if (out.loops.has_baseline()) append(powers, noise::sampled_powers(out.loops.baseline));
    const std::vector<double>& f = out.loops.main.frequency;
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
    std::vector<noise::LoopVariants> more(
        std::min<std::size_t>(std::max(threads, 1), added.size()));
    more.resize(
        for_slices(added.size(), threads, [&](std::size_t i, std::size_t lo, std::size_t hi) {
          more[i] =
              loops_at(r, nc, std::vector<double>(added.begin() + lo, added.begin() + hi), rail);
        }));
    for (noise::LoopVariants& m : more)
      out.loops = noise::merged(std::move(out.loops), std::move(m));
    ++out.levels;
    out.added_lines += static_cast<long>(added.size());
  }
  return out;
}

}  // namespace rollnoise::pipeline
