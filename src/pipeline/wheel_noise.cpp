#include "pipeline/wheel_noise.hpp"

#include "noise/contact_receptance.hpp"
#include "noise/loop_variants.hpp"
#include "noise/roughness.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

WheelNoise wheel_noise(const ContactCase& base, const NoiseCase& nc, const noise::WheelContact& w,
                       const noise::StructureSpectra& spectra,
                       const std::vector<double>& frequency) {
  WheelNoise out;
  out.state = w;
  ContactCase c = base;
  // The wheel's contact point (this side's frame: the patch of the inner wheel is computed in the
  // mirror image and reads like an outer wheel's), its normal force and creepages.
  place_contact_at(c, w.contact, w.normal_force());
  c.creepage = {w.creepage(0), w.creepage(1), w.creepage(2)};
  const ContactStage stage = contact_stage(c, nc.use_nss);
  c.grid = stage.patch->grid;  // the grid may have been enlarged
  check_nyquist(c, frequency, "noise.band_max");
  out.normal_stiffness = stage.normal_stiffness;
  out.mean_force = contact::total_forces(stage.patch->grid, stage.steady.px, stage.steady.py);
  noise::LoopVariantsInput in;
  in.normal_stiffness = stage.normal_stiffness;
  in.speed = c.speed;
  in.normal_coupling = nc.normal_coupling;
  if (nc.use_nss) {
    out.adhesion_elements = stage.model->adhesion_elements();
    out.slip_elements = stage.model->slip_elements();
    in.model = {stage.model->creep_coefficients(frequency),
                stage.model->normal_load_coefficients(frequency)};
  } else {
    in.model = kalker_coefficients(c, frequency.size());
  }
  const noise::StructuralReceptances structures =
      noise::structural_receptances(*nc.wheel, *nc.rail, spectra, w.position());
  out.contact_receptance = main_contact_receptance(frequency, in.normal_stiffness, in.speed, in.model,
                                                   in.normal_coupling);
  out.position = w.position();
  out.loop = noise::solve_loop(structures, out.contact_receptance);
  out.contact = std::move(c);
  return out;
}

std::vector<noise::Receptance4> main_contact_receptance(const std::vector<double>& frequency,
                                                        double normal_stiffness, double speed,
                                                        const noise::ContactCoefficients& model,
                                                        bool normal_coupling) {
  if (normal_coupling && !model.load.empty())
    return noise::contact_receptances(frequency, normal_stiffness, speed, model.creep, model.load);
  return noise::contact_receptances(frequency, normal_stiffness, speed, model.creep);
}

noise::BandLevels wheel_bands(const WheelNoise& w, const NoiseCase& nc,
                              const std::vector<double>& centres) {
  noise::ContactFilter filter;
  filter.model = nc.filter;
  filter.a = w.contact.a;
  filter.b = w.contact.b;
  const noise::ContactRoughness roughness(nc.wheel_roughness, nc.rail_roughness, w.contact.speed,
                                          filter);
  return noise::band_levels(w.loop, centres, roughness);
}

}  // namespace rollnoise::pipeline
