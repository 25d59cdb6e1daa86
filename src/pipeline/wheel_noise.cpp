#include "pipeline/wheel_noise.hpp"

#include "noise/contact_receptance.hpp"
#include "noise/kalker_linear.hpp"
#include "noise/roughness.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

noise::ContactCoefficients kalker_coefficients(const ContactCase& c, std::size_t n) {
  noise::ContactCoefficients k = noise::constant_coefficients(
      noise::kalker_creep_matrix(c.a, c.b, c.material).cast<std::complex<double>>(),
      noise::LoadCoefficients::Zero(), n);
  k.load.clear();
  return k;
}

noise::ContactVariants contact_variants_at(const WheelNoise& w, const NoiseCase& nc,
                                           const std::vector<double>& frequency,
                                           const noise::ContactCoefficients* nss) {
  using Baseline = NoiseCase::Baseline;
  const MeanContact& m = w.mean;
  const ContactCase& c = m.contact();
  noise::LoopVariantsInput in;
  in.normal_stiffness = m.normal_stiffness();
  in.speed = c.speed;
  in.normal_coupling = nc.normal_coupling;
  const bool kalker_needed = !nc.use_nss || nc.compare == Baseline::kKalker;
  const noise::ContactCoefficients kalker =
      kalker_needed ? kalker_coefficients(c, frequency.size()) : noise::ContactCoefficients{};
  if (!nc.use_nss)
    in.model = kalker;
  else if (nss)
    in.model = *nss;
  else
    in.model = {m.model()->creep_coefficients(frequency),
                m.model()->normal_load_coefficients(frequency)};
  if (nc.compare == Baseline::kQuasiSteady) {  // the same mean state, frequency-independent
    const nss::LinearContactModel& model = *m.model();
    in.baseline = noise::quasi_steady_coefficients(model.creep_coefficients({0.0})[0],
                                                   model.normal_load_coefficients({0.0})[0],
                                                   frequency.size());
  } else if (nc.compare == Baseline::kKalker && nc.use_nss) {
    in.baseline = kalker;
  }
  return noise::contact_variants(frequency, in);
}

WheelNoise contact_noise(noise::WheelId wheel, std::optional<noise::WheelContact> state,
                         MeanContact m, const NoiseCase& nc, const std::vector<double>& frequency,
                         noise::ContactCoefficients coefficients) {
  WheelNoise out;
  out.wheel = wheel;
  out.position = state ? state->position() : m.curve().position;
  out.state = std::move(state);
  out.mean = std::move(m);
  const MeanContact& mean = out.mean;
  out.mean_force = contact::total_forces(mean.patch().grid, mean.steady().px, mean.steady().py);
  if (mean.model()) {
    out.adhesion_elements = mean.model()->adhesion_elements();
    out.slip_elements = mean.model()->slip_elements();
  }
  out.coefficients = std::move(coefficients);
  out.receptance =
      contact_variants_at(out, nc, frequency, nc.use_nss ? &out.coefficients : nullptr);
  return out;
}

WheelNoise wheel_contact_noise(const ContactCase& base, const NoiseCase& nc,
                               const noise::WheelContact& w, const std::vector<double>& frequency) {
  MeanContact m = wheel_mean_contact(base, w, noise_contact_options(nc, frequency));
  noise::ContactCoefficients f;
  if (nc.use_nss)
    f = {m.model()->creep_coefficients(frequency), m.model()->normal_load_coefficients(frequency)};
  return contact_noise(w.wheel, w, std::move(m), nc, frequency, std::move(f));
}

noise::ContactRoughness contact_roughness(const NoiseCase& nc, const MeanContact& m) {
  noise::ContactFilter filter;
  filter.model = nc.filter;
  filter.a = m.contact().a;
  filter.b = m.contact().b;
  return noise::ContactRoughness(nc.wheel_roughness, nc.rail_roughness, m.contact().speed, filter);
}

}  // namespace rollnoise::pipeline
