#include "pipeline/noise_pipeline.hpp"

#include <chrono>
#include <cmath>

#include "contact/normal_solver.hpp"
#include "contact/steady_rolling.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "noise/contact_receptance.hpp"
#include "noise/kalker_linear.hpp"
#include "noise/roughness.hpp"

namespace rollnoise::pipeline {
namespace {


}  // namespace

noise::ContactCoefficients kalker_coefficients(const ContactCase& c, std::size_t n) {
  noise::ContactCoefficients k = noise::constant_coefficients(
      noise::kalker_creep_matrix(c.a, c.b, c.material).cast<std::complex<double>>(),
      noise::LoadCoefficients::Zero(), n);
  k.load.clear();
  return k;
}

MeanContactOptions noise_contact_options(const NoiseCase& nc, const std::vector<double>& frequency) {
  MeanContactOptions o;
  o.with_model = nc.use_nss;
  o.frequencies = frequency;
  o.frequency_key = "noise.band_max";
  return o;
}

namespace {

// The 1/3-octave centres of the case, their narrow-band samples checked against c.limits (cheap:
// run before the curve stage, so that a huge noise.points_per_band is refused at once).
std::vector<double> band_centres(const ContactCase& c, const NoiseCase& nc) {
  std::vector<double> centres = noise::third_octave_centres(nc.band_min, nc.band_max);
  if (centres.empty()) throw InputError("noise.band_max", "no 1/3-octave band between band_min and band_max");
  const double count = double(centres.size()) * double(nc.points_per_band);
  check_size(c.limits, "noise.points_per_band", count, "narrow-band frequencies", frequency_bytes(count));
  return centres;
}

}  // namespace

BandAxis band_axis(const ContactCase& c, const NoiseCase& nc) {
  BandAxis a;
  a.centres = band_centres(c, nc);
  a.frequency = noise::band_frequencies(a.centres, nc.points_per_band);
  return a;
}

std::shared_ptr<const noise::StructureSpectra> NoiseReuse::spectra(const NoiseCase& nc,
                                                                   const std::vector<double>& frequency) {
  if (nc.structures_id.empty()) {
    ++computed_;
    return std::make_shared<const noise::StructureSpectra>(noise::structure_spectra(*nc.wheel, frequency));
  }
  // the key: the models' id and the frequencies' bits
  std::string key = nc.structures_id;
  key.append(reinterpret_cast<const char*>(frequency.data()), frequency.size() * sizeof(double));
  auto it = spectra_.find(key);
  if (it != spectra_.end()) {
    ++reused_;
    return it->second;
  }
  ++computed_;
  if (spectra_.size() >= 64) spectra_.clear();  // a bound on memory (about 1 MB each)
  auto s = std::make_shared<const noise::StructureSpectra>(noise::structure_spectra(*nc.wheel, frequency));
  spectra_.emplace(std::move(key), s);
  return s;
}

namespace {

// curve.wheels: every wheel's contact state, and its loop alone; the leading outer wheel is the
// main run's (its state, patch, loop), the others run on the shared spectra.
std::vector<WheelNoise> wheel_loops(const NoiseResult& r, const NoiseCase& nc, const noise::StructureSpectra& spectra) {
  std::vector<WheelNoise> out;
  for (const noise::WheelContact& w : curve_wheels(r.mean.curve(), nc)) {
    if (w.wheel != noise::WheelId::leading_outer) {
      out.push_back(wheel_noise(r.mean.contact(), nc, w, spectra, r.axis.frequency));
      continue;
    }
    WheelNoise m;
    m.state = w;
    m.mean = r.mean;
    m.mean_force = r.mean_force;
    if (r.mean.model()) {
      m.adhesion_elements = r.mean.model()->adhesion_elements();
      m.slip_elements = r.mean.model()->slip_elements();
    }
    m.loop = r.variants.main;
    const noise::ContactCoefficients model =
        nc.use_nss ? noise::ContactCoefficients{r.creep, r.load}
                   : kalker_coefficients(r.mean.contact(), r.axis.frequency.size());
    m.contact_receptance = main_contact_receptance(r.axis.frequency, r.mean.normal_stiffness(),
                                                   r.mean.contact().speed, model, nc.normal_coupling);
    m.position = r.mean.curve().position;
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace

NoiseResult run_noise(ContactCase c, const NoiseCase& nc, NoiseReuse* reuse) {
  const auto t0 = Clock::now();
  NoiseResult r = run_noise_loop(std::move(c), nc, reuse);
  const auto t1 = Clock::now();
  r.wheels = wheel_loops(r, nc, *r.spectra);
  r.patches = second_patches(r.mean.curve(), r.mean.contact(), nc, r.wheels, *r.spectra, r.axis.frequency);
  if (!r.wheels.empty() && nc.contact_coupling == NoiseCase::ContactCoupling::kBogie)
    r.bogie = std::make_shared<const noise::ContactSetLoopResult>(
        bogie_loop(r.wheels, nc, r.axis.frequency, {}, r.patches));
  r.seconds_wheels = seconds_since(t1);
  add_bands(r, nc);
  r.seconds_total = seconds_since(t0);
  return r;
}


NoiseResult run_noise_loop(ContactCase c, const NoiseCase& nc, NoiseReuse* reuse) {
  const auto t0 = Clock::now();
  NoiseResult r;
  r.axis = band_axis(c, nc);  // 1, the sizes before any work
  const std::vector<double>& freq = r.axis.frequency;

  // 2.-3. the mean contact (the model always: the quasi-steady baseline and the sweep's f(0), g(0))
  MeanContactOptions options = noise_contact_options(nc, freq);
  options.with_model = true;
  r.mean = curve_mean_contact(c, nc, options);
  const ContactCase& cc = r.mean.contact();
  const nss::LinearContactModel& model = *r.mean.model();
  r.creep = model.creep_coefficients(freq);
  r.load = model.normal_load_coefficients(freq);  // g, the same sweep
  r.f0 = model.creep_coefficients({0.0})[0];
  r.g0 = model.normal_load_coefficients({0.0})[0];
  r.seconds_contact = seconds_since(t0);

  // 4. structures once, then the loop per contact model
  const auto t1 = Clock::now();
  const std::shared_ptr<const noise::StructureSpectra> spectra =
      reuse ? reuse->spectra(nc, freq)
            : std::make_shared<const noise::StructureSpectra>(noise::structure_spectra(*nc.wheel, freq));
  const noise::StructuralReceptances structures =
      noise::structural_receptances(*nc.wheel, *nc.rail, *spectra, r.mean.curve().position);
  r.seconds_structures = seconds_since(t1);
  using Baseline = NoiseCase::Baseline;
  noise::LoopVariantsInput in;
  in.normal_stiffness = r.mean.normal_stiffness();
  in.speed = cc.speed;
  in.normal_coupling = nc.normal_coupling;
  const bool kalker_needed = !nc.use_nss || nc.compare == Baseline::kKalker;
  const noise::ContactCoefficients kalker = kalker_needed ? kalker_coefficients(cc, freq.size()) : noise::ContactCoefficients{};
  in.model = nc.use_nss ? noise::ContactCoefficients{r.creep, r.load} : kalker;
  if (nc.compare == Baseline::kQuasiSteady)  // the same mean state, frequency-independent
    in.baseline = noise::quasi_steady_coefficients(r.f0, r.g0, freq.size());
  else if (nc.compare == Baseline::kKalker && nc.use_nss)
    in.baseline = kalker;
  r.coupled = nc.normal_coupling && !in.model.load.empty();
  r.variants = noise::solve_loop_variants(structures, in);
  r.baseline_name = nc.compare == Baseline::kQuasiSteady ? "quasi_steady" : "kalker";
  r.mean_force = contact::total_forces(r.mean.patch().grid, r.mean.steady().px, r.mean.steady().py);
  r.lateral_to_normal_db = 20 * std::log10(std::abs(r.mean_force.Fy / cc.normal_force));
  r.spectra = spectra;
  r.seconds_total = seconds_since(t0);
  return r;
}

void add_bands(NoiseResult& r, const NoiseCase& nc) {
  // 5. roughness and bands
  const ContactCase& cc = r.mean.contact();
  noise::ContactFilter filter;
  filter.model = nc.filter;
  filter.a = cc.a;
  filter.b = cc.b;
  const noise::ContactRoughness roughness(nc.wheel_roughness, nc.rail_roughness, cc.speed, filter);
  const std::vector<double>& centres = r.axis.centres;
  r.bands = noise::band_levels(r.variants.main, centres, roughness);
  const std::vector<double> rough_levels = roughness.levels(centres);
  if (r.variants.has_uncoupled()) {
    r.uncoupled_bands = noise::band_levels(r.variants.uncoupled, centres, rough_levels);
    r.coupling_difference = noise::force_level_difference(r.bands, r.uncoupled_bands);
  }
  if (r.variants.has_baseline()) r.baseline_bands = noise::band_levels(r.variants.baseline, centres, rough_levels);
  if (r.bogie) {
    const std::vector<noise::BandLevels> b = bogie_bands(*r.bogie, r.wheels, nc, centres, r.patches);
    for (std::size_t i = 0; i < r.wheels.size(); ++i) r.wheels[i].bands = b[i];
    for (std::size_t k = 0; k < r.patches.size(); ++k) r.patches[k].bands = b[r.wheels.size() + k];
    return;
  }
  for (WheelNoise& w : r.wheels)
    w.bands = w.state.wheel == noise::WheelId::leading_outer ? r.bands : wheel_bands(w, nc, centres);
}

ReceptanceResult run_receptance(ContactCase c, const NoiseCase& nc, const std::vector<double>& freq) {
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
                               ? noise::contact_receptances(freq, kN, cc.speed, f, model.normal_load_coefficients(freq))
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
