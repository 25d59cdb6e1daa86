#include "pipeline/bogie_noise.hpp"

#include <algorithm>

#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "core/task_pool.hpp"
#include "dynamics/rail_model.hpp"
#include "noise/flange_patch.hpp"

namespace rollnoise::pipeline {
namespace {

noise::ContactPoint contact_point(const WheelNoise& w, const NoiseCase& nc) {
  noise::ContactPoint c;
  const bool leading = noise::is_leading(w.wheel);
  c.wheelset = leading ? 0 : 1;
  c.side = noise::is_outer(w.wheel) ? 1 : -1;
  c.position = w.position;  // its own frame (mirrored for an inner wheel), as its loop alone
  c.rail_x = nc.rail->position() + (leading ? 0.0 : nc.wheelbase);
  return c;
}

// The wheels, then the patches.
std::vector<const WheelNoise*> all_contacts(const std::vector<WheelNoise>& wheels,
                                            const std::vector<WheelNoise>& patches) {
  std::vector<const WheelNoise*> out;
  for (const WheelNoise& w : wheels) out.push_back(&w);
  for (const WheelNoise& p : patches) out.push_back(&p);
  return out;
}

}  // namespace

std::vector<noise::ContactPoint> bogie_contacts(const std::vector<WheelNoise>& wheels,
                                                const NoiseCase& nc,
                                                const std::vector<WheelNoise>& patches) {
  std::vector<noise::ContactPoint> out;
  for (const WheelNoise* w : all_contacts(wheels, patches)) out.push_back(contact_point(*w, nc));
  return out;
}

std::vector<WheelNoise> second_patches(const CurveSetup& curve, const ContactCase& base,
                                       const NoiseCase& nc, const std::vector<WheelNoise>& wheels,
                                       const std::vector<double>& frequency) {
  if (!nc.second_patch) return {};
  if (nc.contact_coupling != NoiseCase::ContactCoupling::kBogie)
    throw InputError("noise.second_patch",
                     "a second patch is a contact of the bogie loop: \"coupled\" needs "
                     "noise.contact_coupling = \"bogie\"");
  const bool leading_outer = std::any_of(wheels.begin(), wheels.end(), [](const WheelNoise& w) {
    return w.wheel == noise::WheelId::leading_outer;
  });
  if (!curve.state || !curve.state_input || !leading_outer) return {};
  const auto t0 = Clock::now();
  const std::optional<noise::WheelContact> flange =
      noise::flange_patch_contact(*curve.state_input, *curve.state);
  if (!flange) return {};
  WheelNoise patch = wheel_contact_noise(base, nc, *flange, frequency);
  patch.seconds = seconds_since(t0);
  return {std::move(patch)};
}

std::vector<bool> excited_contacts(std::size_t wheels, std::size_t patches, const NoiseCase& nc) {
  std::vector<bool> out(wheels, true);  // every tread contact its own source (Sec. 5.2)
  out.insert(out.end(), patches, nc.second_patch_roughness);
  return out;
}

noise::CrossCoupling loop_coupling(const NoiseCase& nc) {
  return nc.contact_coupling == NoiseCase::ContactCoupling::kBogie ? noise::CrossCoupling{}
                                                                   : noise::CrossCoupling::none();
}

noise::LoopVariants contact_loop(const std::vector<WheelNoise>& wheels, const NoiseCase& nc,
                                 const std::vector<double>& frequency,
                                 const std::vector<WheelNoise>& patches, int threads,
                                 const dynamics::RailModel* rail,
                                 const std::optional<noise::CrossCoupling>& cross) {
  const noise::ContactSetStructures s = noise::contact_set_structures(
      *nc.wheel, rail ? *rail : *nc.rail, bogie_contacts(wheels, nc, patches), frequency,
      cross.value_or(loop_coupling(nc)), threads);
  std::vector<noise::ContactVariants> alpha;
  for (const WheelNoise* w : all_contacts(wheels, patches)) alpha.push_back(w->receptance);
  return noise::solve_loop_variants(
      s, alpha, noise::independent_sources(excited_contacts(wheels.size(), patches.size(), nc)),
      threads);
}

std::vector<std::vector<double>> bogie_source_levels(const std::vector<WheelNoise>& wheels,
                                                     const NoiseCase& nc,
                                                     const std::vector<double>& centres,
                                                     const std::vector<WheelNoise>& patches,
                                                     int threads) {
  const std::vector<const WheelNoise*> contacts = all_contacts(wheels, patches);
  const std::vector<bool> excited = excited_contacts(wheels.size(), patches.size(), nc);
  std::vector<const WheelNoise*> sources;  // source e = the e-th excited contact
  for (std::size_t a = 0; a < contacts.size(); ++a)
    if (excited[a]) sources.push_back(contacts[a]);
  std::vector<std::vector<double>> levels(sources.size());
  parallel_for(sources.size(), threads, [&](std::size_t e, int) {
    levels[e] = contact_roughness(nc, sources[e]->mean).levels(centres);
  });
  return levels;
}

std::vector<noise::BandLevels> bogie_bands(const noise::ContactSetLoopResult& loop,
                                           const std::vector<double>& centres,
                                           const std::vector<std::vector<double>>& source_levels) {
  std::vector<noise::BandLevels> out;
  for (int a = 0; a < loop.contacts(); ++a)
    out.push_back(noise::contact_band_levels(loop, a, centres, source_levels));
  return out;
}

std::vector<noise::BandLevels> bogie_bands(const noise::ContactSetLoopResult& loop,
                                           const std::vector<WheelNoise>& wheels,
                                           const NoiseCase& nc, const std::vector<double>& centres,
                                           const std::vector<WheelNoise>& patches) {
  return bogie_bands(loop, centres, bogie_source_levels(wheels, nc, centres, patches));
}

}  // namespace rollnoise::pipeline
