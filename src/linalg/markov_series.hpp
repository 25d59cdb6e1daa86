// Markov series of a discrete-time system, T(z) = sum_j h_j z^j (h_j real matrices or vectors, the
// impulse response): the sequence built until it decays, its sum by Horner, and the truncation
// guard for |z| != 1. Used by the linear contact model (nss/linear_model.hpp: f = -sum h_j z^j,
// g = sum gm_j z^j) and by the contact at complex frequency (noise/stability.hpp).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <optional>
#include <utility>
#include <vector>

namespace rollnoise::linalg {

/// The largest magnitude of the entries of a Markov parameter.
template <class T>
double max_abs_entry(const T& h) {
  return h.cwiseAbs().maxCoeff();
}

/// Markov parameters h_j = Lh' S_j, S_{j+1} = step(S_j) (S_0 given), until |h_j| < 1e-15 max |h|
/// (Frobenius) for `quiet_steps` steps in a row; false if that does not happen within max_steps.
template <class Step>
bool markov_sequence(const Eigen::MatrixXd& Lh, Eigen::MatrixXd S, const Step& step, int quiet_steps,
                     int max_steps, std::vector<Eigen::MatrixXd>& h) {
  h.clear();
  double h_max = 0.0;
  int quiet = 0;
  for (int j = 0; j < max_steps; ++j) {
    h.push_back(Lh.transpose() * S);
    const double norm = h.back().norm();
    h_max = std::max(h_max, norm);
    quiet = norm < 1e-15 * h_max ? quiet + 1 : 0;
    if (quiet >= quiet_steps) return true;
    S = step(S);
  }
  return false;
}

/// sum_j h_j z^j by Horner (Out: the complex type of the sum, e.g. Eigen::Matrix3cd).
template <class Out, class Term>
Out horner(const std::vector<Term>& h, std::complex<double> z) {
  Out acc = Out::Zero();
  for (auto it = h.rbegin(); it != h.rend(); ++it) acc = acc * z + it->template cast<std::complex<double>>();
  return acc;
}

/// The truncation guard's terms: the largest weighted term max_j |h_j|_max |z|^j and the last one.
template <class Term>
std::pair<double, double> weighted_terms(const std::vector<Term>& h, double abs_z) {
  double w = 1.0, big = 0.0, last = 0.0;
  for (const auto& x : h) {
    last = max_abs_entry(x) * w;
    big = std::max(big, last);
    w *= abs_z;
  }
  return {big, last};
}

/// sum_j h_j z^j if the series has converged at z: the last weighted term |h_J| |z|^J at most
/// `tolerance` of the largest (the h_j are kept until they decay to ~1e-15 of their largest, so for
/// |z| > 1 this bounds the amplified truncation); nothing otherwise or for an empty series.
template <class Out, class Term>
std::optional<Out> horner_if_converged(const std::vector<Term>& h, std::complex<double> z, double tolerance) {
  if (h.empty()) return std::nullopt;
  const auto [big, last] = weighted_terms(h, std::abs(z));
  if (!(last <= tolerance * big)) return std::nullopt;
  return horner<Out>(h, z);
}

}  // namespace rollnoise::linalg
