#include "io/squeal_output.hpp"

#include "io/contact_output.hpp"
#include "io/noise_output.hpp"

namespace rollnoise::io {

void write_squeal(Hdf5Writer& w, const CaseReader& reader, const pipeline::NoiseCase& nc,
                  const pipeline::SquealResult& r) {
  write_mean_state(w, case_as_run(reader, r.mean.contact(), r.mean.curve()), r.mean.patch(), r.mean.contact().creepage,
                   r.mean.steady());
  write_contact_state(w, "/squeal/contact", nc, r.mean.contact(), r.mean.curve(), r.mean.normal_stiffness());
  const std::size_t n = r.roots.size();
  std::vector<std::complex<double>> s, s0;
  std::vector<double> freq, zeta, fn, residual, singular;
  std::vector<int> unstable, iterations, converged;
  std::vector<int> same_root_as, found_again;
  std::vector<std::string> label;
  for (const auto& x : r.roots) {
    same_root_as.push_back(static_cast<int>(x.same_root_as));
    found_again.push_back(x.refined ? 1 : 0);
    s.push_back(x.s);
    s0.push_back(x.s0);
    freq.push_back(x.frequency);
    zeta.push_back(x.damping_ratio);
    fn.push_back(x.natural_frequency);
    residual.push_back(x.residual);
    singular.push_back(x.singular_ratio);
    unstable.push_back(x.unstable ? 1 : 0);
    iterations.push_back(x.iterations);
    converged.push_back(x.converged ? 1 : 0);
    label.push_back(x.label);
  }
  w.write("/squeal/eigenvalue", s, {n}, "1/s (s = sigma + i omega, growth e^{s t})");
  w.write("/squeal/frequency", freq, {n}, "Hz (Im s / 2 pi)");
  w.write("/squeal/damping_ratio", zeta, {n}, "- (-Re s / |s|; negative: growing)");
  w.write("/squeal/unstable", unstable, {n}, "- (1: Re s > 0)");
  w.write("/squeal/mode", label, "- (label of the wheel mode the root continues, from the modes file)");
  w.write("/squeal/natural_frequency", fn, {n}, "Hz (the uncoupled wheel mode)");
  w.write("/squeal/uncoupled_eigenvalue", s0, {n}, "1/s (the uncoupled wheel mode, start of the continuation)");
  w.write("/squeal/residual", residual, {n}, "- (|det M| / prod_i |row i of M|, M = diag(D_j/omega_j^2) + Psi^T R^{-1} Psi/(m_j omega_j^2) at s, Eq. S2 of docs/squeal.md; 0..1)");
  w.write("/squeal/singular_ratio", singular, {n}, "- (sigma_min / sigma_max of the equilibrated loop matrix at s)");
  w.write("/squeal/iterations", iterations, {n}, "- (Newton iterations over all continuation steps)");
  w.write("/squeal/converged", converged, {n}, "- (1: the continuation reached lambda = 1)");
  w.write(
      "/squeal/same_root_as", same_root_as, {n},
      "- (-1, or the wheel mode (index among the case's modes, the rows' order) whose root this "
      "mode's continuation reached too: counted once, there; this mode's own root not found, "
      "converged = 0)");
  w.write(
      "/squeal/found_again", found_again, {n},
      "- (1: the continuation reached another mode's root, and this mode's own root was found by "
      "Newton from its uncoupled root on (S2) deflated by the roots already found; docs/squeal.md "
      "Sec. 4.2)");
  w.write("/squeal/min_growth_rate", r.min_sigma, "1/s (the contact's Markov series converge for Re s above this)");
  w.write("/squeal/contact_spectral_radius", r.contact_spectral_radius,
          "- (of M0^-1 M1, the contact alone: < 1 stable; -1: not computed, the Markov parameters decayed)");
  w.attribute("/squeal", "route",
              r.route == 1 ? "1: eigenvalues of the rational (vector-fitted) rail and contact coupled with the wheel's "
                             "modal state space, nearest to each uncoupled wheel mode (docs/squeal.md)"
                           : "2: Newton with homotopy continuation from each wheel mode on det(alpha_w + alpha_r + "
                             "alpha_c) = 0 (docs/squeal.md)");
  w.attribute("/squeal", "contact_model", nc.use_nss ? "linear NSS model" : "Kalker's steady linear theory");
  w.attribute("/squeal", "normal_coupling", r.coupled ? "on" : "off");
}

void write_squeal_route1(Hdf5Writer& w, const pipeline::Route1Result& r1,
                         const std::vector<noise::ModeRoot>& roots,
                         const pipeline::RouteAgreement* agreement, const std::string& warning) {
  const std::size_t n = roots.size();
  std::vector<std::complex<double>> s;
  std::vector<double> freq, zeta;
  std::vector<int> unstable;
  for (const auto& x : roots) {
    s.push_back(x.s);
    freq.push_back(x.frequency);
    zeta.push_back(x.damping_ratio);
    unstable.push_back(x.unstable ? 1 : 0);
  }
  const std::string g = "/squeal/route1/";
  w.write(g + "eigenvalue", s, {n}, "1/s (route 1: the coupled rational model's eigenvalue nearest to each root of /squeal)");
  w.write(g + "frequency", freq, {n}, "Hz (Im s / 2 pi)");
  w.write(g + "damping_ratio", zeta, {n}, "- (-Re s / |s|; negative: growing)");
  w.write(g + "unstable", unstable, {n}, "- (1: Re s > 0)");
  w.write(g + "fit_error_rail", r1.rail.error, "- (max relative error of the rail's rational fit over its band, linalg::fit_rational's norm)");
  w.write(g + "fit_error_rail_at_modes", r1.rail_error_at_modes, "- (the rail fit's error, same norm, at the natural frequencies of the band's wheel modes)");
  w.write(g + "fit_error_contact", r1.contact.error, "- (max relative error of the contact's [-f | g] fit, as /statespace/fit_error)");
  w.write(g + "fit_band", std::vector<double>{r1.fit_min, r1.fit_max}, {2}, "Hz (the rail's fit band; the contact's from 0 Hz)");
  w.write(g + "poles_rail", static_cast<double>(r1.rail.poles.size()), "- (poles of the rail's fit)");
  w.write(g + "poles_contact", static_cast<double>(r1.contact.poles.size()), "- (poles of the contact's fit)");
  w.write(g + "all_eigenvalues", r1.eigenvalues, {r1.eigenvalues.size()}, "1/s (every finite eigenvalue of the coupled rational model)");
  if (agreement) {
    const std::vector<double> a{agreement->frequency, agreement->damping_relative, agreement->damping_absolute};
    w.write("/squeal/route_agreement", a, {3},
            "- (max over the modes of |f1 - f2|/f2, |zeta1 - zeta2|/|zeta2|, |zeta1 - zeta2|; "
            "route 1 against route 2, "
            "route 2's converged roots)");
    w.write("/squeal/route_agreement_within", agreement->within() ? 1.0 : 0.0,
            "- (1: f within 0.1 % and zeta within 5 % or 1e-5 at every compared mode, "
            "docs/squeal.md Sec. 4.2)");
    w.write(g + "within", agreement->mode_within, {agreement->mode_within.size()},
            "- (per root: 1 within the routes' target, 0 beyond it, -1 not compared: route 2 not "
            "converged)");
    w.attribute("/squeal", "route_warning", warning.empty() ? "none" : warning);
  }
}

}  // namespace rollnoise::io
