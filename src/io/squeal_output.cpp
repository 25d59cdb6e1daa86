#include "io/squeal_output.hpp"

#include "io/contact_output.hpp"
#include "io/noise_output.hpp"

namespace rollnoise::io {

void write_squeal(Hdf5Writer& w, const CaseReader& reader, const pipeline::NoiseCase& nc,
                  const pipeline::SquealResult& r) {
  write_mean_state(w, case_as_run(reader, r.contact, r.curve), *r.stage.patch, r.contact.creepage, r.stage.steady);
  write_contact_state(w, "/squeal/contact", nc, r.contact, r.curve, r.stage.normal_stiffness);
  const std::size_t n = r.roots.size();
  std::vector<std::complex<double>> s, s0;
  std::vector<double> freq, zeta, fn, residual, singular;
  std::vector<int> unstable, iterations, converged;
  std::vector<std::string> label;
  for (const auto& x : r.roots) {
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
  w.write("/squeal/residual", residual, {n}, "- (|det(diag(D_j/omega_j^2) + Psi^T R^{-1} Psi/(m_j omega_j^2))| at s, Eq. S2 of docs/squeal.md)");
  w.write("/squeal/singular_ratio", singular, {n}, "- (sigma_min / sigma_max of the equilibrated loop matrix at s)");
  w.write("/squeal/iterations", iterations, {n}, "- (Newton iterations over all continuation steps)");
  w.write("/squeal/converged", converged, {n}, "- (1: the continuation reached lambda = 1)");
  w.write("/squeal/min_growth_rate", r.min_sigma, "1/s (the contact's Markov series converge for Re s above this)");
  w.attribute("/squeal", "route",
              "2: Newton with homotopy continuation from each wheel mode on det(alpha_w + alpha_r + alpha_c) = 0 "
              "(docs/squeal.md)");
  w.attribute("/squeal", "contact_model", nc.use_nss ? "linear NSS model" : "Kalker's steady linear theory");
  w.attribute("/squeal", "normal_coupling", r.coupled ? "on" : "off");
}

}  // namespace rollnoise::io
