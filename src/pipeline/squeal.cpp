#include "pipeline/squeal.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "noise/kalker_linear.hpp"
#include "pipeline/squeal_hertz_wheels.hpp"
#include "pipeline/statespace.hpp"

namespace rollnoise::pipeline {

void check_contact_stability(double radius, double dt) {
  // The poles of f are the z_p with 1/z_p an eigenvalue of M0^{-1} M1; a radius rho >= 1 means the
  // contact's recursion grows by itself, at ln(rho)/dt in continuous time (docs/falling_friction.md
  // Sec. 3). The loop's roots are then meaningless (f(i w) is not the response of a stable contact).
  if (radius < 1.0) return;
  std::ostringstream m;
  m << "squeal: the linearised contact alone is unstable (spectral radius of M0^-1 M1 = " << radius
    << " >= 1: it grows at " << std::log(radius) / dt
    << " 1/s without wheel or rail). This is a limit of quasi-static falling friction "
       "(docs/falling_friction.md Sec. 3), not wheel squeal: lower friction.decay (or raise "
       "friction.kinetic_ratio), or use a smaller creepage";
  throw InputError("friction.decay", m.str());
}

MeanContactOptions squeal_contact_options(const NoiseCase& nc, const std::vector<double>& in_band) {
  MeanContactOptions o;
  o.with_model = nc.use_nss;
  o.with_transfer = true;
  o.normal_coupling = nc.normal_coupling;
  o.frequencies = in_band;
  o.frequency_key = "noise.band_max";
  return o;
}

int SquealResult::unstable_count() const {
  int n = 0;
  for (const auto& r : roots) n += r.unstable ? 1 : 0;
  return n;
}

noise::ContactPoint squeal_point(const NoiseCase& nc, const MeanContact& mean) {
  // the leading wheelset's outer wheel: side +1, the frame of the single loop
  noise::ContactPoint p;
  p.wheelset = 0;
  p.side = 1;
  p.position = mean.curve().position;
  p.rail_x = nc.rail->position();
  return p;
}

noise::LaplaceLoop squeal_loop(const NoiseCase& nc, const MeanContact& mean) {
  // contact.creep(s) carries the case's creepage sampling (LinearContactModel::creep_coefficients_laplace).
  const noise::SquealContact contact{squeal_point(nc, mean), mean.transfer().get(),
                                     mean.normal_stiffness()};
  return noise::laplace_loop(*nc.wheel, *nc.rail, {contact}, mean.contact().speed, mean.coupled(),
                             noise::CrossCoupling::none());
}

SquealResult run_squeal(ContactCase c, const NoiseCase& nc, const noise::StabilityOptions& options, bool route2) {
  const auto t0 = Clock::now();
  SquealResult r;
  // the band's modes before anything is solved
  std::vector<double> in_band;
  for (const auto& m : nc.wheel->modes())
    if (m.frequency >= nc.band_min && m.frequency <= nc.band_max) in_band.push_back(m.frequency);
  if (in_band.empty())
    throw InputError("noise.band_max", "squeal: no wheel mode between noise.band_min and noise.band_max");
  // the leading outer wheel's contact (squeal_hertz_wheels.hpp: its per-wheel Hertz state when the
  // per-wheel run computes those, so that both describe one contact)
  CurvePlacement p = resolve_curve(c, nc);
  r.curve_case = p.contact;
  r.mean_is_leading_outer_wheel = has_hertz_wheel_states(p, nc);
  if (r.mean_is_leading_outer_wheel) p = leading_outer_placement(p, nc);
  r.mean = solve_mean_contact(std::move(p.contact), std::move(p.curve),
                              squeal_contact_options(nc, in_band));
  // Falling friction: the contact's own stability was checked (no Markov parameters to prove it)
  r.contact_spectral_radius = r.mean.spectral_radius();
  if (r.mean.model()) check_contact_stability(r.mean.spectral_radius(), r.mean.model()->time_step());
  r.coupled = r.mean.coupled();
  r.min_sigma = r.mean.transfer()->min_sigma();
  r.seconds_contact = seconds_since(t0);

  const auto t1 = Clock::now();
  noise::LaplaceLoop loop = squeal_loop(nc, r.mean);
  auto inner = loop.rest;
  loop.rest = [&r, inner](dynamics::cdouble s) {  // count the evaluations
    ++r.evaluations;
    return inner(s);
  };
  noise::StabilityOptions o = options;
  o.band_min = nc.band_min;
  o.band_max = nc.band_max;
  if (route2) r.roots = noise::mode_roots(loop, o);
  r.seconds_roots = seconds_since(t1);
  return r;
}

}  // namespace rollnoise::pipeline

namespace rollnoise::pipeline {
namespace {

noise::StateSpace to_noise(const linalg::StateSpace& m) { return {m.A, m.B, m.C, m.D}; }

linalg::RationalFit fit(const std::vector<double>& freq, const std::vector<Eigen::MatrixXcd>& H, const Route1Options& o) {
  linalg::RationalFitOptions fo;
  fo.target = o.tolerance;
  fo.max_poles = o.max_poles;
  fo.pole_step = o.pole_step;
  return linalg::fit_rational(freq, H, fo);
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> x(n);
  for (int k = 0; k < n; ++k) x[k] = a + (b - a) * k / (n - 1);
  return x;
}

}  // namespace

Route1Result squeal_route1(const SquealResult& r, const NoiseCase& nc, const Route1Options& o) {
  const auto t0 = Clock::now();
  Route1Result out;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& m : nc.wheel->modes())
    if (m.frequency >= nc.band_min && m.frequency <= nc.band_max) lo = std::min(lo, m.frequency), hi = std::max(hi, m.frequency);
  out.fit_min = o.fit_min > 0 ? o.fit_min : 0.5 * lo;
  out.fit_max = o.fit_max > 0 ? o.fit_max : 2.0 * hi;
  const noise::ContactPosition& p = r.mean.curve().position;

  // rail: alpha_r at real frequencies in the contact frame (as the noise loop's stage 2)
  // uniform samples, and more around every mode of the band (+-4 %, where the roots lie), so that
  // the least squares of the fit weigh the modes' neighbourhoods most
  std::vector<double> fr = linspace(out.fit_min, out.fit_max, o.rail_samples);
  if (o.samples_per_mode > 0)
    for (const auto& m : nc.wheel->modes())
      if (m.frequency >= nc.band_min && m.frequency <= nc.band_max)
        for (double f : linspace(0.96 * m.frequency, 1.04 * m.frequency, o.samples_per_mode)) fr.push_back(f);
  std::sort(fr.begin(), fr.end());
  fr.erase(std::unique(fr.begin(), fr.end()), fr.end());
  const auto tr = Clock::now();
  std::vector<Eigen::MatrixXcd> Hr;
  for (const noise::Receptance4& h : noise::rail_contact_receptances(*nc.rail, fr, p)) Hr.push_back(h);
  out.seconds_rail = seconds_since(tr);
  out.rail = fit(fr, Hr, o);
  {
    std::vector<Eigen::MatrixXcd> exact, fitted;
    std::vector<double> at_modes;
    for (const auto& m : nc.wheel->modes())
      if (m.frequency >= nc.band_min && m.frequency <= nc.band_max) {
        at_modes.push_back(m.frequency);
        fitted.push_back(out.rail.model.frequency_response(m.frequency));
      }
    for (const noise::Receptance4& h : noise::rail_contact_receptances(*nc.rail, at_modes, p))
      exact.push_back(h);
    out.rail_error_at_modes = linalg::relative_response_error(exact, fitted, out.rail.scaling);
  }

  // contact: [-f | g] with the model's creepage sampling (g = 0 when the loop is not coupled)
  if (r.mean.model()) {
    const nss::LinearContactModel& model = *r.mean.model();
    const double top = std::min(out.fit_max, model.nyquist_frequency());
    const std::vector<double> fc = linspace(0.0, top, o.contact_samples);
    std::vector<nss::LoadVector> g = r.coupled ? model.normal_load_coefficients(fc)
                                               : std::vector<nss::LoadVector>(fc.size(), nss::LoadVector::Zero());
    out.contact = fit(fc, contact_transfer(model.creep_coefficients(fc), g), o);
  } else {  // Kalker: the constant -f, no states
    linalg::StateSpace& m = out.contact.model;
    m.A.resize(0, 0), m.B.resize(0, 4), m.C.resize(3, 0);
    m.D = Eigen::MatrixXd::Zero(3, 4);
    const ContactCase& cc = r.mean.contact();
    m.D.leftCols(3) = -noise::kalker_creep_matrix(cc.a, cc.b, cc.material);
  }
  out.seconds_fit = seconds_since(t0);

  const auto t1 = Clock::now();
  // the wheel as route 2's loop of one contact has it (squeal_loop)
  const std::vector<noise::ContactPoint> point{squeal_point(nc, r.mean)};
  out.eigenvalues = noise::coupled_eigenvalues(
      noise::rigid_flexibility(nc.wheel->wheelset(), point),
      noise::loop_modes(*nc.wheel, point).modes, to_noise(out.rail.model),
      to_noise(out.contact.model), r.mean.normal_stiffness(), r.mean.contact().speed);
  out.seconds_eigen = seconds_since(t1);
  return out;
}

Route1Deviation route1_deviation(const Route1Result& r1, const SquealResult& r, const NoiseCase& nc,
                                 const std::vector<dynamics::cdouble>& s) {
  Route1Deviation d;
  const nss::LinearContactModel* m = r.mean.model().get();
  const std::function<noise::Receptance4(dynamics::cdouble)> rail =
      noise::rail_laplace_at_contact(*nc.rail, r.mean.curve().position);  // set up once
  for (const dynamics::cdouble x : s) {
    const Eigen::MatrixXcd ar = rail(x);
    d.rail.push_back(linalg::relative_response_error({ar}, {r1.rail.model.response(x)}, r1.rail.scaling));
    if (!m) {
      d.contact.push_back(0.0);
      continue;
    }
    // the exact contact at s, with the case's creepage sampling (as route 2 takes it)
    Eigen::MatrixXcd h(3, 4);
    h << -m->creep_coefficients_laplace(x),
        r.coupled ? m->normal_load_coefficients_laplace(x) : Eigen::Vector3cd::Zero();
    d.contact.push_back(linalg::relative_response_error({h}, {r1.contact.model.response(x)}, r1.contact.scaling));
  }
  return d;
}

std::vector<noise::ModeRoot> uncoupled_roots(const NoiseCase& nc) {
  std::vector<noise::ModeRoot> u;
  const std::vector<dynamics::WheelMode>& modes = nc.wheel->modes();
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const dynamics::WheelMode& m = modes[k];
    if (m.frequency < nc.band_min || m.frequency > nc.band_max) continue;
    noise::ModeRoot x;
    x.mode = k;
    x.label = m.label;
    x.natural_frequency = m.frequency;
    const double w = 2.0 * M_PI * m.frequency, z = m.damping_ratio;
    x.s0 = x.s = dynamics::cdouble(-z * w, w * std::sqrt(1.0 - z * z));
    u.push_back(x);
  }
  return u;
}

std::vector<noise::ModeRoot> match_route1(const Route1Result& r1, const std::vector<noise::ModeRoot>& reference) {
  // one eigenvalue per reference root, the closest pairs first (a greedy assignment): two
  // references never take the same eigenvalue (sin/cos partners have one uncoupled root s0)
  struct Pair {
    double d;
    std::size_t ref, eig;
  };
  std::vector<Pair> pairs;
  for (std::size_t k = 0; k < reference.size(); ++k)
    for (std::size_t e = 0; e < r1.eigenvalues.size(); ++e)
      if (r1.eigenvalues[e].imag() >= 0.0) pairs.push_back({std::abs(r1.eigenvalues[e] - reference[k].s), k, e});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d < b.d; });
  std::vector<long> taken_by(r1.eigenvalues.size(), -1), of(reference.size(), -1);
  for (const Pair& p : pairs)
    if (of[p.ref] < 0 && taken_by[p.eig] < 0) of[p.ref] = static_cast<long>(p.eig), taken_by[p.eig] = static_cast<long>(p.ref);
  std::vector<noise::ModeRoot> m;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const noise::ModeRoot& ref = reference[k];
    noise::ModeRoot x;
    x.mode = ref.mode;
    x.label = ref.label;
    x.natural_frequency = ref.natural_frequency;
    x.s0 = ref.s0;
    x.converged = of[k] >= 0;
    x.s = x.converged ? r1.eigenvalues[static_cast<std::size_t>(of[k])] : dynamics::cdouble(std::nan(""), std::nan(""));
    x.frequency = x.s.imag() / (2.0 * M_PI);
    x.damping_ratio = -x.s.real() / std::abs(x.s);
    x.unstable = x.s.real() > 0.0;
    x.residual = x.singular_ratio = std::nan("");
    m.push_back(x);
  }
  return m;
}

RouteAgreement route_agreement(const std::vector<noise::ModeRoot>& a, const std::vector<noise::ModeRoot>& b) {
  RouteAgreement g;
  g.mode_within.assign(std::min(a.size(), b.size()), -1);
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    if (!a[k].converged) g.distinct = false;
    if (!b[k].converged) continue;
    ++g.compared;
    const double df = std::abs(a[k].frequency - b[k].frequency) / std::abs(b[k].frequency);
    const double dz = std::abs(a[k].damping_ratio - b[k].damping_ratio);
    const double rz = dz / std::abs(b[k].damping_ratio);
    if (df > g.frequency) g.frequency = df, g.worst_frequency_mode = k;
    g.damping_relative = std::max(g.damping_relative, rz);
    g.damping_absolute = std::max(g.damping_absolute, dz);
    const double beyond = std::min(rz / 0.05, dz / 1e-5);  // the squeal routes' acceptance: <= 1
    if (beyond > g.damping_beyond) g.damping_beyond = beyond, g.worst_damping_mode = k;
    g.mode_within[k] = df <= 1e-3 && beyond <= 1.0 ? 1 : 0;
  }
  return g;
}

std::string route_warning(const RouteAgreement& g, const std::vector<noise::ModeRoot>& r2,
                          const std::vector<noise::ModeRoot>& r1, const Route1Deviation& dev) {
  if (g.within()) return {};
  const std::size_t k = g.damping_beyond > 1.0 ? g.worst_damping_mode : g.worst_frequency_mode;
  const int beyond = static_cast<int>(std::count(g.mode_within.begin(), g.mode_within.end(), 0));
  const bool known = k < dev.rail.size() && k < dev.contact.size();
  const bool rail = known && dev.rail[k] >= dev.contact[k];
  char text[640];
  std::snprintf(
      text, sizeof text,
      "the routes disagree beyond their tolerance (f 0.1 %%, zeta 5 %% or 1e-5) at %d of %d "
      "modes, worst %s (f %.3f / %.3f Hz, zeta %.3e / %.3e, route 1 / route 2); likely cause: "
      "route 1's %s fit at that root (deviation %.1e, the %s's %.1e; docs/squeal.md Sec. 4.2)",
      beyond, g.compared, r2[k].label.c_str(), r1[k].frequency, r2[k].frequency,
      r1[k].damping_ratio, r2[k].damping_ratio, rail ? "rail" : "contact",
      known ? (rail ? dev.rail[k] : dev.contact[k]) : std::nan(""), rail ? "contact" : "rail",
      known ? (rail ? dev.contact[k] : dev.rail[k]) : std::nan(""));
  std::string w = text;
  if (std::abs(r2[k].damping_ratio) >= 1e-2)
    w += "; a heavily damped root: off the axis the rail's continuation (hysteretic damping as a "
         "constant) is not converged on a discrete track beyond zeta ~ eta_rail / 2";
  return w;
}

}  // namespace rollnoise::pipeline
