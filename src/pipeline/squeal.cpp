#include "pipeline/squeal.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/errors.hpp"
#include "noise/kalker_linear.hpp"

namespace rollnoise::pipeline {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

void check_contact_stability(const nss::LinearContactModel& model, SquealResult& r) {
  // The poles of f are the z_p with 1/z_p an eigenvalue of M0^{-1} M1; a radius rho >= 1 means the
  // contact's recursion grows by itself, at ln(rho)/dt in continuous time (docs/falling_friction.md
  // Sec. 3). The loop's roots are then meaningless (f(i w) is not the response of a stable contact).
  r.contact_spectral_radius = model.spectral_radius();
  if (r.contact_spectral_radius < 1.0) return;
  std::ostringstream m;
  m << "squeal: the linearised contact alone is unstable (spectral radius of M0^-1 M1 = " << r.contact_spectral_radius
    << " >= 1: it grows at " << std::log(r.contact_spectral_radius) / model.time_step()
    << " 1/s without wheel or rail). This is a limit of quasi-static falling friction "
       "(docs/falling_friction.md Sec. 3), not wheel squeal: lower friction.decay (or raise "
       "friction.kinetic_ratio), or use a smaller creepage";
  throw InputError("friction.decay", m.str());
}

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
    // Falling friction: no Markov parameters (the paper form only); the contact's own stability is
    // checked first. Constant friction: the sweep's Markov parameters (their decay proves it stable).
    if (!model.falling_friction()) model.creep_coefficients({0.0});
    if (model.markov_parameters().empty()) check_contact_stability(model, r);
    r.coupled = nc.normal_coupling && model.has_normal_load_input();
    // f(s), g(s) exactly, with the case's creepage sampling (nss::creepage_sampling_factor); the
    // Markov parameters, where they exist, keep their guard.
    noise::LaplaceEvaluator exact;
    exact.creep = [&model](dynamics::cdouble s) { return model.creep_coefficients_laplace(s); };
    if (r.coupled)
      exact.load = [&model](dynamics::cdouble s) { return model.normal_load_coefficients_laplace(s); };
    markov = std::make_unique<noise::MarkovContact>(model.markov_parameters(),
                                                    r.coupled ? model.load_markov_parameters() : std::vector<Eigen::Vector3d>{},
                                                    model.time_step(), std::move(exact));
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
