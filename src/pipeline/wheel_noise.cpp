#include "pipeline/wheel_noise.hpp"

#include "noise/contact_receptance.hpp"
#include "noise/loop_variants.hpp"
#include "noise/roughness.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

WheelNoise wheel_noise(const ContactCase& base, const NoiseCase& nc, const noise::WheelContact& w,
                       const noise::StructureSpectra& spectra,
                       const std::vector<double>& frequency) {
  WheelNoise out = wheel_contact_noise(base, nc, w, frequency);
  // The bogie loop replaces the wheel's loop alone (its rail point receptance at 864 frequencies
  // was a quarter of a partial-adhesion wheel's cost, docs/performance.md Sec. 8).
  if (nc.contact_coupling != NoiseCase::ContactCoupling::kBogie)
    out.loop = wheel_loop_alone(out, nc, spectra);
  return out;
}

WheelNoise wheel_contact_noise(const ContactCase& base, const NoiseCase& nc,
                               const noise::WheelContact& w, const std::vector<double>& frequency) {
  WheelNoise out;
  out.state = w;
  out.mean = wheel_mean_contact(base, w, noise_contact_options(nc, frequency));
  const MeanContact& m = out.mean;
  out.mean_force = contact::total_forces(m.patch().grid, m.steady().px, m.steady().py);
  if (nc.use_nss) {
    out.adhesion_elements = m.model()->adhesion_elements();
    out.slip_elements = m.model()->slip_elements();
  }
  out.contact_receptance = wheel_contact_receptance(out, nc, frequency);
  out.position = w.position();
  return out;
}

std::vector<noise::Receptance4> wheel_contact_receptance(const WheelNoise& w, const NoiseCase& nc,
                                                         const std::vector<double>& frequency) {
  if (!nc.use_nss) return wheel_contact_receptance(w, nc, frequency, {});
  const nss::LinearContactModel& model = *w.mean.model();
  return wheel_contact_receptance(
      w, nc, frequency,
      {model.creep_coefficients(frequency), model.normal_load_coefficients(frequency)});
}

std::vector<noise::Receptance4> wheel_contact_receptance(const WheelNoise& w, const NoiseCase& nc,
                                                         const std::vector<double>& frequency,
                                                         const noise::ContactCoefficients& nss) {
  const MeanContact& m = w.mean;
  return main_contact_receptance(frequency, m.normal_stiffness(), m.contact().speed,
                                 nc.use_nss ? nss : kalker_coefficients(m.contact(), frequency.size()),
                                 nc.normal_coupling);
}

noise::LoopResult wheel_loop_alone(const WheelNoise& w, const NoiseCase& nc,
                                   const noise::StructureSpectra& spectra,
                                   const dynamics::RailModel* rail) {
  const noise::StructuralReceptances structures =
      noise::structural_receptances(*nc.wheel, rail ? *rail : *nc.rail, spectra, w.position);
  return noise::solve_loop(structures, w.contact_receptance);
}

std::vector<noise::Receptance4> main_contact_receptance(const std::vector<double>& frequency,
                                                        double normal_stiffness, double speed,
                                                        const noise::ContactCoefficients& model,
                                                        bool normal_coupling) {
  if (normal_coupling && !model.load.empty())
    return noise::contact_receptances(frequency, normal_stiffness, speed, model.creep, model.load);
  return noise::contact_receptances(frequency, normal_stiffness, speed, model.creep);
}

noise::ContactRoughness contact_roughness(const NoiseCase& nc, const MeanContact& m) {
  noise::ContactFilter filter;
  filter.model = nc.filter;
  filter.a = m.contact().a;
  filter.b = m.contact().b;
  return noise::ContactRoughness(nc.wheel_roughness, nc.rail_roughness, m.contact().speed, filter);
}

noise::BandLevels wheel_bands(const WheelNoise& w, const noise::LoopResult& loop,
                              const NoiseCase& nc, const std::vector<double>& centres) {
  return noise::band_levels(loop, centres, contact_roughness(nc, w.mean));
}

}  // namespace rollnoise::pipeline
