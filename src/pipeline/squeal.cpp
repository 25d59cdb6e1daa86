#include "pipeline/squeal.hpp"

#include <chrono>
#include <memory>

#include "core/errors.hpp"
#include "noise/kalker_linear.hpp"

namespace rollnoise::pipeline {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

int SquealResult::unstable_count() const {
  int n = 0;
  for (const auto& r : roots) n += r.unstable ? 1 : 0;
  return n;
}

noise::LaplaceLoop squeal_loop(const ContactCase& c, const NoiseCase& nc, const CurveSetup& curve,
                               const ContactStage& stage, const noise::MarkovContact& contact, bool coupled) {
  noise::LaplaceLoop loop;
  loop.modes = noise::contact_frame_modes(*nc.wheel, curve.position);
  const Eigen::Matrix4d rigid = noise::rigid_flexibility(nc.wheel->wheelset(), curve.position);
  const noise::ContactPosition position = curve.position;
  const double kN = stage.normal_stiffness, V = c.speed;
  const dynamics::RailModel* rail = nc.rail.get();
  loop.rest = [=, &contact](dynamics::cdouble s) {
    const Eigen::Vector3cd g = coupled ? contact.load(s) : Eigen::Vector3cd::Zero();
    return noise::Receptance4(rigid.cast<dynamics::cdouble>() / (s * s) +
                              noise::rail_receptance_laplace(*rail, s, position) +
                              noise::contact_receptance_laplace(s, kN, V, contact.creep(s), g));
  };
  return loop;
}

SquealResult run_squeal(ContactCase c, const NoiseCase& nc, const noise::StabilityOptions& options) {
  const auto t0 = Clock::now();
  SquealResult r;
  // the band's modes, and the Nyquist limit, before anything is solved
  std::vector<double> in_band;
  for (const auto& m : nc.wheel->modes())
    if (m.frequency >= nc.band_min && m.frequency <= nc.band_max) in_band.push_back(m.frequency);
  if (in_band.empty())
    throw InputError("noise.band_max", "squeal: no wheel mode between noise.band_min and noise.band_max");
  r.curve = resolve_curve(c, nc);
  check_nyquist(c, in_band, "noise.band_max");
  r.contact = std::move(c);
  r.stage = contact_stage(r.contact, nc.use_nss);
  r.contact.grid = r.stage.patch->grid;
  std::unique_ptr<noise::MarkovContact> markov;
  if (nc.use_nss) {
    check_nyquist(r.contact, in_band, "noise.band_max");
    const nss::LinearContactModel& model = *r.stage.model;
    model.creep_coefficients({0.0});  // builds the Markov parameters (the sweep's model)
    r.coupled = nc.normal_coupling && model.has_normal_load_input();
    markov = std::make_unique<noise::MarkovContact>(model.markov_parameters(),
                                                    r.coupled ? model.load_markov_parameters() : std::vector<Eigen::Vector3d>{},
                                                    model.time_step());
  } else {  // Kalker's constant f: one Markov parameter h_0 = -f (any time step), g = 0
    const ContactCase& cc = r.contact;
    markov = std::make_unique<noise::MarkovContact>(
        std::vector<Eigen::Matrix3d>{-noise::kalker_creep_matrix(cc.a, cc.b, cc.material.shear_modulus(), cc.material.nu)},
        std::vector<Eigen::Vector3d>{}, 1.0);
  }
  const noise::MarkovContact& contact = *markov;
  r.min_sigma = contact.min_sigma();
  r.seconds_contact = seconds_since(t0);

  const auto t1 = Clock::now();
  noise::LaplaceLoop loop = squeal_loop(r.contact, nc, r.curve, r.stage, contact, r.coupled);
  auto inner = loop.rest;
  loop.rest = [&r, inner](dynamics::cdouble s) {  // count the evaluations
    ++r.evaluations;
    return inner(s);
  };
  noise::StabilityOptions o = options;
  o.band_min = nc.band_min;
  o.band_max = nc.band_max;
  r.roots = noise::mode_roots(loop, o);
  r.seconds_roots = seconds_since(t1);
  return r;
}

}  // namespace rollnoise::pipeline
