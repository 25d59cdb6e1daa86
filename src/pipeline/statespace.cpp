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

linalg::StateSpace sampling_filter(const std::vector<double>& frequency,
                                   const std::vector<std::complex<double>>& factor, double dt,
                                   const StateSpaceOptions& o) {
  linalg::StateSpace R;
  R.A.resize(0, 0), R.B.resize(0, 1), R.C.resize(1, 0), R.D = Eigen::MatrixXd::Ones(1, 1);
  if (std::all_of(factor.begin(), factor.end(), [](std::complex<double> c) { return c == 1.0; }))
    return R;  // contact: the samples are the step creepages
  // R(z) = R'(s'), s' = (2/dt)(z - 1)/(z + 1): at z = e^{i w dt}, s' = 2 pi i f' with the warped
  // frequency f' = tan(pi f dt)/(pi dt) (finite below the Nyquist limit, which run_creep checked)
  std::vector<double> warped;
  std::vector<Eigen::MatrixXcd> S;
  for (size_t k = 0; k < frequency.size(); ++k) {
    warped.push_back(std::tan(M_PI * frequency[k] * dt) / (M_PI * dt));
    S.push_back(Eigen::MatrixXcd::Constant(1, 1, factor[k]));
  }
  linalg::RationalFitOptions fo;
  fo.target = o.tolerance;  // as the model (|S| <= 1: an absolute error of the same size)
  fo.max_poles = o.max_poles;
  return linalg::bilinear_discretisation(linalg::fit_rational(warped, S, fo).model, dt);
}

linalg::StateSpace with_sampling_filter(const linalg::StateSpace& m, const linalg::StateSpace& R) {
  // u = (xi~, N~) -> v = (R xi~_x, R xi~_y, R phi~, N~) -> m. With the filters' state xf
  // (block diagonal, one R per creepage): xf+ = Af xf + Bf xi~, v_c = Cf xf + Df xi~, so
  //   [x; xf]+ = [[A, Bc Cf], [0, Af]] [x; xf] + [[Bc Df, Bn], [Bf, 0]] u,
  //   y = [C, Dc Cf] [x; xf] + [Dc Df, Dn] u.
  const Eigen::Index n = m.A.rows(), r = R.A.rows(), nf = 3 * r;
  Eigen::MatrixXd Af = Eigen::MatrixXd::Zero(nf, nf), Bf = Eigen::MatrixXd::Zero(nf, 3),
                  Cf = Eigen::MatrixXd::Zero(3, nf);
  for (int j = 0; j < 3; ++j) {
    Af.block(j * r, j * r, r, r) = R.A;
    Bf.block(j * r, j, r, 1) = R.B;
    Cf.block(j, j * r, 1, r) = R.C;
  }
  const double Df = R.D(0, 0);
  const Eigen::MatrixXd Bc = m.B.leftCols(3), Dc = m.D.leftCols(3);
  linalg::StateSpace s;
  s.A = Eigen::MatrixXd::Zero(n + nf, n + nf);
  s.A.topLeftCorner(n, n) = m.A;
  s.A.topRightCorner(n, nf) = Bc * Cf;
  s.A.bottomRightCorner(nf, nf) = Af;
  s.B = Eigen::MatrixXd::Zero(n + nf, 4);
  s.B.topLeftCorner(n, 3) = Df * Bc;
  s.B.topRightCorner(n, 1) = m.B.col(3);
  s.B.bottomLeftCorner(nf, 3) = Bf;
  s.C.resize(3, n + nf);
  s.C << m.C, Dc * Cf;
  s.D = m.D;
  s.D.leftCols(3) *= Df;
  return s;
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
  r.recursion = linalg::eigensystem_realisation(markov, o.hankel_tolerance);
  r.input_sampling = model.sampling();
  std::vector<std::complex<double>> factor;  // S(w dt) at the fitted frequencies
  for (double fr : r.frequency)
    factor.push_back(contact::step_sampling_factor(r.input_sampling, fr, r.dt));
  std::vector<Eigen::MatrixXcd> Hs;
  for (size_t k = 0; k < r.frequency.size(); ++k) {
    Hs.push_back(r.recursion.model.discrete_frequency_response(r.frequency[k], r.dt));
    Hs.back().leftCols(3) *= factor[k];
  }
  r.recursion_error = linalg::relative_response_error(H, Hs, r.fit.scaling);
  r.sampling_filter = sampling_filter(r.frequency, factor, r.dt, o);
  for (size_t k = 0; k < r.frequency.size(); ++k)
    r.sampling_filter_error = std::max(
        r.sampling_filter_error,
        std::abs(r.sampling_filter.discrete_frequency_response(r.frequency[k], r.dt)(0, 0) -
                 factor[k]));
  const double nyquist = 0.5 / r.dt;
  for (int k = 0; k <= 400; ++k) {  // above the band: 401 points to the Nyquist limit
    const double fr = r.band_max + (nyquist - r.band_max) * k / 400.0;
    r.sampling_filter_peak_gain =
        std::max(r.sampling_filter_peak_gain,
                 std::abs(r.sampling_filter.discrete_frequency_response(fr, r.dt)(0, 0)));
  }
  r.discrete = with_sampling_filter(r.recursion.model, r.sampling_filter);
  std::vector<Eigen::MatrixXcd> Hd;
  for (double fr : r.frequency) Hd.push_back(r.discrete.discrete_frequency_response(fr, r.dt));
  r.discrete_error = linalg::relative_response_error(H, Hd, r.fit.scaling);
  r.seconds_fit = seconds(t0, t1);
  r.seconds_discrete = seconds(t1, Clock::now());
  return r;
}

}  // namespace rollnoise::pipeline
