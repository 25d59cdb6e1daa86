#include "noise/contact_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "linalg/markov_series.hpp"
#include "noise/kalker_linear.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::noise {

ContactTransfer::~ContactTransfer() = default;

std::pair<Eigen::Matrix3cd, Eigen::Vector3cd> ContactTransfer::creep_and_load(cdouble s) const {
  return {creep(s), load(s)};
}

std::vector<Eigen::Matrix3cd> ContactTransfer::creep(const std::vector<double>& frequencies) const {
  std::vector<Eigen::Matrix3cd> f;
  f.reserve(frequencies.size());
  for (double x : frequencies) f.push_back(creep(cdouble(0.0, 2.0 * M_PI * x)));
  return f;
}

std::vector<LoadCoefficients> ContactTransfer::load(const std::vector<double>& frequencies) const {
  std::vector<LoadCoefficients> g;
  g.reserve(frequencies.size());
  for (double x : frequencies) g.push_back(load(cdouble(0.0, 2.0 * M_PI * x)));
  return g;
}

ConstantTransfer ConstantTransfer::kalker(double a, double b, double shear_modulus, double nu) {
  return ConstantTransfer(kalker_creep_matrix(a, b, shear_modulus, nu));
}

ConstantTransfer ConstantTransfer::kalker(double a, double b, const contact::Material& material) {
  return ConstantTransfer(kalker_creep_matrix(a, b, material));
}

namespace {

using linalg::max_abs_entry;

// Decay ratio per step of a Markov sequence: from the stretch where |h_j| falls from 1e-4 to 1e-10
// of its largest value (before the round-off floor), else over the whole sequence.
template <class T>
double decay_ratio(const std::vector<T>& h) {
  if (h.size() < 2) return 0.0;
  double big = 0.0;
  for (const auto& x : h) big = std::max(big, max_abs_entry(x));
  if (!(big > 0.0)) return 0.0;
  std::size_t j1 = 0, j2 = 0;
  for (std::size_t j = 0; j < h.size(); ++j) {
    const double n = max_abs_entry(h[j]);
    if (n > 1e-4 * big) j1 = j;
    if (n > 1e-10 * big) j2 = j;
  }
  if (j2 <= j1) j1 = 0;
  const double n1 = max_abs_entry(h[j1]), n2 = std::max(max_abs_entry(h[j2]), 1e-300);
  if (j2 == j1 || !(n1 > 0.0)) return 0.0;
  return std::min(1.0, std::pow(n2 / n1, 1.0 / double(j2 - j1)));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The contact at complex s
// ---------------------------------------------------------------------------------------------

MarkovContact::MarkovContact(std::vector<Eigen::Matrix3d> creep, std::vector<Eigen::Vector3d> load, double dt)
    : h_(std::move(creep)), gm_(std::move(load)), dt_(dt) {
  if (h_.empty())
    throw NumericalError("squeal: the contact model has no Markov parameters (its sweep fell back to the "
                         "Hessenberg form): f cannot be continued to complex frequency");
  set_guard();
}

void MarkovContact::set_guard() {
  // the model's time step dx/V: the grid and the speed are checked when the case is read
  ROLLNOISE_ASSERT(dt_ > 0.0, "squeal: the contact model's time step must be positive");
  if (h_.empty()) {
    min_sigma_ = -1e300;  // exact everywhere (an evaluator without a series): nothing to guard
    return;
  }
  const double rho = std::max(decay_ratio(h_), gm_.empty() ? 0.0 : decay_ratio(gm_));
  // |z| rho < 1 <=> sigma > ln(rho)/dt; 0.9 of it as the margin of the guard (the truncation
  // check in check() guards the accuracy near it).
  min_sigma_ = rho > 0.0 ? 0.9 * std::log(rho) / dt_ : -1e300;
}

void MarkovContact::check(cdouble s, double big, double last) const {
  if (s.real() < min_sigma_ || !(last <= 1e-6 * big)) {
    std::ostringstream m;
    m << "squeal: the contact's Markov series does not converge at s = " << s << " 1/s (growth rate "
      << s.real() << " 1/s below " << min_sigma_ << " 1/s, the limit set by the decay of the contact's memory)";
    throw NumericalError(m.str());
  }
}

MarkovContact::MarkovContact(std::vector<Eigen::Matrix3d> creep, std::vector<Eigen::Vector3d> load, double dt,
                             LaplaceEvaluator exact)
    : h_(std::move(creep)), gm_(std::move(load)), dt_(dt), exact_(std::move(exact)) {
  if (!exact_.creep) throw NumericalError("squeal: the contact's exact evaluator is missing");
  set_guard();
}

Eigen::Matrix3cd MarkovContact::creep(cdouble s) const {
  const cdouble z = std::exp(-s * dt_);
  if (!h_.empty()) {
    const auto [big, last] = linalg::weighted_terms(h_, std::abs(z));
    check(s, big, last);
  }
  if (exact_.creep) return exact_.creep(s);
  return -linalg::horner<Eigen::Matrix3cd>(h_, z);  // f = -sum h_j z^j
}

Eigen::Vector3cd MarkovContact::load(cdouble s) const {
  const cdouble z = std::exp(-s * dt_);
  if (!gm_.empty()) {
    const auto [big, last] = linalg::weighted_terms(gm_, std::abs(z));
    check(s, big, last);
  }
  if (exact_.load) return exact_.load(s);
  if (gm_.empty()) return Eigen::Vector3cd::Zero();
  return linalg::horner<Eigen::Vector3cd>(gm_, z);  // g = sum gm_j z^j (G3)
}

// ---------------------------------------------------------------------------------------------
// The linear NSS model
// ---------------------------------------------------------------------------------------------

namespace {

MarkovContact guard_of(const std::shared_ptr<const nss::LinearContactModel>& model, bool with_load) {
  // f(s), g(s) exactly, with the model's creepage sampling (nss::creepage_sampling_factor); the
  // Markov parameters, where they exist, keep their guard.
  const nss::LinearContactModel* m = model.get();
  LaplaceEvaluator exact;
  exact.creep = [m](cdouble s) { return m->creep_coefficients_laplace(s); };
  if (with_load) exact.load = [m](cdouble s) { return m->normal_load_coefficients_laplace(s); };
  return MarkovContact(m->markov_parameters(), with_load ? m->load_markov_parameters() : std::vector<Eigen::Vector3d>{},
                       m->time_step(), std::move(exact));
}

}  // namespace

NssTransfer::NssTransfer(std::shared_ptr<const nss::LinearContactModel> model, bool with_load)
    : model_(std::move(model)), with_load_(with_load), guarded_(guard_of(model_, with_load)) {}

std::pair<Eigen::Matrix3cd, Eigen::Vector3cd> NssTransfer::creep_and_load(cdouble s) const {
  // with Markov parameters the guarded series (MarkovContact); without them there is no guard and
  // the exact evaluators are the model's, which share one solve
  if (!with_load_ || !model_->markov_parameters().empty()) return {creep(s), load(s)};
  const auto [f, g] = model_->coefficients_laplace(s);
  return {f, g};
}

std::vector<Eigen::Matrix3cd> NssTransfer::creep(const std::vector<double>& frequencies) const {
  return model_->creep_coefficients(frequencies);
}

std::vector<LoadCoefficients> NssTransfer::load(const std::vector<double>& frequencies) const {
  if (!with_load_) return std::vector<LoadCoefficients>(frequencies.size(), LoadCoefficients::Zero());
  return model_->normal_load_coefficients(frequencies);
}

}  // namespace rollnoise::noise
