#include "pipeline/statespace.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace rollnoise::pipeline {

std::vector<Eigen::MatrixXcd> contact_transfer(const std::vector<nss::CreepMatrix>& f,
                                               const std::vector<nss::LoadVector>& g) {
  std::vector<Eigen::MatrixXcd> H;
  for (size_t k = 0; k < f.size(); ++k) {
    Eigen::MatrixXcd h(3, 4);
    h << -f[k], g[k];
    H.push_back(h);
  }
  return H;
}

std::vector<Eigen::MatrixXd> contact_markov_parameters(const nss::LinearContactModel& model) {
  const auto& hf = model.markov_parameters();
  const auto& hg = model.load_markov_parameters();
  if (hf.empty())
    throw NumericalError(
        "statespace: the fast sweep has no Markov parameters (it fell back to the Hessenberg "
        "form: the impulse response did not decay within 60 contact lengths)");
  std::vector<Eigen::MatrixXd> H(std::max(hf.size(), hg.size()), Eigen::MatrixXd::Zero(3, 4));
  for (size_t j = 0; j < hf.size(); ++j) H[j].leftCols(3) = hf[j];  // -f = sum_j h_j z^j
  for (size_t j = 0; j < hg.size(); ++j) H[j].col(3) = hg[j];
  return H;
}

StateSpaceResult run_statespace(ContactCase c, const std::vector<double>& freq,
                                const StateSpaceOptions& o, const std::string& frequency_key) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  StateSpaceResult r;
  r.band_min = *std::min_element(freq.begin(), freq.end());
  r.band_max = *std::max_element(freq.begin(), freq.end());
  if (!(r.band_max > 0))
    throw InputError(frequency_key, "the state-space fit needs a positive frequency");
  r.frequency = freq;
  std::sort(r.frequency.begin(), r.frequency.end());
  r.frequency.erase(std::unique(r.frequency.begin(), r.frequency.end()), r.frequency.end());
  if (r.frequency.front() > 0) r.frequency.insert(r.frequency.begin(), 0.0);  // the static gain
  r.creep = run_creep(std::move(c), r.frequency, false, frequency_key);
  const nss::LinearContactModel& model = *r.creep.state.model();
  r.dt = model.time_step();
  const std::vector<Eigen::MatrixXcd> H = contact_transfer(r.creep.f, r.creep.g);

  const auto t0 = Clock::now();
  linalg::RationalFitOptions fo;
  fo.target = o.tolerance;
  fo.max_poles = o.max_poles;
  r.fit = linalg::fit_rational(r.frequency, H, fo);
  const auto t1 = Clock::now();

  const std::vector<Eigen::MatrixXd> markov = contact_markov_parameters(model);
  r.markov_count = static_cast<int>(markov.size());
  r.discrete = linalg::eigensystem_realisation(markov, o.hankel_tolerance);
  // its response against the sweep's f and g with the creepage input of each sampling: xi~(t_k)
  // (factor 1), xi~(t_k - dt/2) (exp(-i w dt/2)) or the mean over [t_{k-1}, t_k] (exp(-i w dt/2)
  // sinc(w dt/2)); nss::LinearContactModel::apply_sampling. The closest names the input.
  r.discrete_error = std::numeric_limits<double>::infinity();
  for (const contact::CreepageSampling s : {contact::CreepageSampling::contact, contact::CreepageSampling::midstep,
                                            contact::CreepageSampling::average}) {
    std::vector<Eigen::MatrixXcd> Hs;
    for (double fr : r.frequency) {
      Hs.push_back(r.discrete.model.discrete_frequency_response(fr, r.dt));
      Hs.back().leftCols(3) *= contact::step_sampling_factor(s, fr, r.dt);
    }
    const double e = linalg::relative_response_error(H, Hs, r.fit.scaling);
    if (e < r.discrete_error) r.discrete_error = e, r.input_sampling = s;
  }
  r.input_delay_steps = r.input_sampling == contact::CreepageSampling::contact ? 0.0 : 0.5;
  r.seconds_fit = seconds(t0, t1);
  r.seconds_discrete = seconds(t1, Clock::now());
  return r;
}

}  // namespace rollnoise::pipeline
