// The linear model's transfer function: f(omega) and g(omega) at many frequencies from the Markov
// series (Horner, O(J) per frequency) or the Hessenberg form, f(s) and g(s) at complex frequency,
// and the creepage sampling's factor on f.

#include <cmath>
#include <optional>

#include "contact/creepage_history.hpp"
#include "linalg/markov_series.hpp"
#include "nss/linear_model.hpp"
#include "nss/linear_model_parts.hpp"

namespace rollnoise::nss {

namespace {

// sum_j h_j z^j by Horner at z = e^{-i w dt} for each frequency (four frequencies per pass).
template <class Out, class Term>
std::vector<Out> horner(const std::vector<Term>& h, double dt, const std::vector<double>& frequencies) {
  std::vector<std::complex<double>> z;
  z.reserve(frequencies.size());
  for (double f : frequencies) z.push_back(std::polar(1.0, -2.0 * M_PI * f * dt));
  return linalg::horner_many<Out>(h, z);
}

// The Markov series is used at a complex z where its last weighted term is at most this fraction
// of the largest (linalg::horner_if_converged), else the exact Hessenberg form.
constexpr double kSeriesTolerance = 1e-12;

}  // namespace

void LinearContactModel::apply_sampling(std::vector<CreepMatrix>& f, const std::vector<double>& frequencies) const {
  // Every route above solves the recursion M0 Q_k = M1 Q_{k-1} + W xi_k with xi_k the creepage of
  // step k. CONTACT takes xi_k = xi(t_k); midstep takes xi_k = xi(t_k - dt/2), where the
  // displacement difference (A p_k - A0 p_{k-1})/dt of paper Eq. 2 is centred. For xi(t) = xi^
  // e^{i w t}: xi_k = (xi^ e^{-i w dt/2}) e^{i w t_k}, the same recursion with the input amplitude
  // xi^ e^{-i w dt/2}, so F^ = -f_contact xi^ e^{-i w dt/2}, i.e. f_midstep = f_contact e^{-i w dt/2}
  // (w dt/2 = pi f dx/V: pipeline::half_step_phase_correction). The outputs F_k stay at t_k. Checked:
  // the midstep f converges at second order at 1-5 kHz, f_contact at first (tests/nss).
  // Average takes xi_k = (1/dt) int_{t_k - dt}^{t_k} xi^ e^{i w t} dt
  //   = xi^ e^{i w t_k} (1 - e^{-i w dt})/(i w dt) = xi^ e^{i w t_k} e^{-i w dt/2} sin(w dt/2)/(w dt/2),
  // so f_average = f_contact e^{-i w dt/2} sinc(w dt/2) (sinc x = sin x / x, 1 at x = 0): the step
  // mean of the rigid slip, as (u_k - u_{k-1})/dt is the step mean of du/dt, whose harmonic form
  // i w u e^{-i w dt/2} sinc(w dt/2) carries the same factor (contact/creepage_history.hpp).
  if (sampling_ == contact::CreepageSampling::contact) return;
  // on the frequency axis the exact polar form (contact::step_sampling_factor); off it,
  // creepage_sampling_factor below (the same function continued).
  for (size_t i = 0; i < f.size(); ++i) f[i] *= contact::step_sampling_factor(sampling_, frequencies[i], dt_);
}

std::complex<double> creepage_sampling_factor(std::complex<double> s_dt, contact::CreepageSampling sampling) {
  // f_sampling(s) = f_contact(s) x factor(s dt) (apply_sampling; linear_model.hpp "Creepage
  // sampling"), continued analytically from s = i w:
  //   contact 1;  midstep e^{-s dt/2};
  //   average (1 - e^{-s dt})/(s dt) = e^{-s dt/2} sinh(s dt/2)/(s dt/2)  (-> 1 as s dt -> 0),
  // which at s = i w is e^{-i w dt/2} sinc(w dt/2), contact::step_sampling_factor.
  switch (sampling) {
    case contact::CreepageSampling::contact:
      return 1.0;
    case contact::CreepageSampling::midstep:
      return std::exp(-0.5 * s_dt);
    case contact::CreepageSampling::average: {
      const std::complex<double> y = 0.5 * s_dt;
      const std::complex<double> shc = std::abs(y) < 1e-8 ? std::complex<double>(1.0) : std::sinh(y) / y;
      return std::exp(-y) * shc;
    }
  }
  return 1.0;
}

const LinearContactModel::MarkovSeries& LinearContactModel::series(int max_contact_lengths) const {
  // Krylov, else the exact recursion, else (empty) the Hessenberg form; on the paper form (falling
  // friction) the Hessenberg form directly. Built once: the first caller's max_contact_lengths.
  std::call_once(built_->series_once, [this, max_contact_lengths] {
    auto series = std::make_unique<MarkovSeries>();
    if (route_ == Route::paper_form) {
      series->info.method = SweepInfo::Method::hessenberg;  // the paper form only (header)
    } else {
      SweepInfo info;
      std::optional<MarkovSeries> model = krylov_markov(max_contact_lengths, info);
      if (!model) {  // the exact recursion, and failing that the Hessenberg form
        info.krylov_failed = true;
        model = exact_markov(max_contact_lengths, info);
        if (!model) info.method = SweepInfo::Method::hessenberg;
      }
      if (model) series = std::make_unique<MarkovSeries>(std::move(*model));
      series->info = info;
    }
    built_->series = std::move(series);
  });
  return *built_->series;
}

std::vector<CreepMatrix> LinearContactModel::creep_from_markov(const std::vector<Eigen::Matrix3d>& h,
                                                               const std::vector<double>& frequencies) const {
  std::vector<CreepMatrix> f = horner<CreepMatrix>(h, dt_, frequencies);  // f = -sum_j h_j z^j
  for (auto& fk : f) fk = -fk;
  apply_sampling(f, frequencies);
  return f;
}

std::vector<CreepMatrix> LinearContactModel::creep_coefficients(const std::vector<double>& frequencies,
                                                                int max_contact_lengths) const {
  for (double f : frequencies) check_frequency(f);
  const MarkovSeries& h = series(max_contact_lengths);
  if (h.creep.empty()) return creep_coefficients_hessenberg(frequencies);
  return creep_from_markov(h.creep, frequencies);
}

std::vector<LoadVector> LinearContactModel::normal_load_coefficients(const std::vector<double>& frequencies,
                                                                     int max_contact_lengths) const {
  for (double f : frequencies) check_frequency(f);
  if (!has_normal_load_input()) return std::vector<LoadVector>(frequencies.size(), LoadVector::Zero());
  const MarkovSeries& h = series(max_contact_lengths);
  if (!h.creep.empty()) return horner<LoadVector>(h.load, dt_, frequencies);  // (G3)
  std::vector<LoadVector> g;
  hessenberg_sweep(frequencies, nullptr, &g);
  return g;
}

std::vector<CreepMatrix> LinearContactModel::creep_coefficients_markov(const std::vector<double>& frequencies,
                                                                       int max_contact_lengths) const {
  for (double f : frequencies) check_frequency(f);
  if (falling_) return creep_coefficients_hessenberg(frequencies);  // no reduced form (header)
  // Computed afresh (not cached), so that it stays an independent check of creep_coefficients.
  SweepInfo info;
  const std::optional<MarkovSeries> model = exact_markov(max_contact_lengths, info);
  if (!model) return creep_coefficients_hessenberg(frequencies);
  return creep_from_markov(model->creep, frequencies);
}

CreepMatrix LinearContactModel::creep_coefficients_laplace(std::complex<double> s) const {
  const std::complex<double> z = std::exp(-s * dt_);
  std::optional<CreepMatrix> f = linalg::horner_if_converged<CreepMatrix>(series().creep, z, kSeriesTolerance);
  if (f) {
    *f = -*f;  // f = -sum_j h_j z^j
  } else {
    f = CreepMatrix();
    hessenberg_at(z, &*f, nullptr);
  }
  return *f * creepage_sampling_factor(s * dt_, sampling_);
}

std::pair<CreepMatrix, LoadVector> LinearContactModel::coefficients_laplace(std::complex<double> s) const {
  if (!series().creep.empty() || !has_normal_load_input())  // the series (cheap), or no g
    return {creep_coefficients_laplace(s), normal_load_coefficients_laplace(s)};
  const std::complex<double> z = std::exp(-s * dt_);
  CreepMatrix f;
  LoadVector g;
  hessenberg_at(z, &f, &g);  // as the two calls take them, in one solve
  return {f * creepage_sampling_factor(s * dt_, sampling_), g};
}

LoadVector LinearContactModel::normal_load_coefficients_laplace(std::complex<double> s) const {
  if (!has_normal_load_input()) return LoadVector::Zero();
  const std::complex<double> z = std::exp(-s * dt_);
  const MarkovSeries& h = series();
  std::optional<LoadVector> g;
  if (!h.creep.empty()) g = linalg::horner_if_converged<LoadVector>(h.load, z, kSeriesTolerance);  // (G3)
  if (!g) {
    g = LoadVector();
    hessenberg_at(z, nullptr, &*g);
  }
  return *g;
}

}  // namespace rollnoise::nss
