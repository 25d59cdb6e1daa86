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

/// sum_j h_j z_k^j by Horner for many points z_k (h_j real and of fixed size: Eigen::Matrix3d,
/// Eigen::Vector3d; Out its complex type): the same recursion as horner() above, four points at a
/// time, each in a lane of a 4-wide vector (real and imaginary parts apart, GCC/Clang vector
/// extension), so that one pass over the h_j serves four points and the complex products vectorise.
/// Per step acc <- acc z + h_j with acc z = (ar zr - ai zi) + i (ar zi + ai zr): the rounding of a
/// complex product written out (not the library's, which may fuse differently), so the sums agree
/// with horner() to round-off, not to the bit.
template <class Out, class Term>
std::vector<Out> horner_many(const std::vector<Term>& h, const std::vector<std::complex<double>>& z) {
  using v4d = double __attribute__((vector_size(32)));
  constexpr int E = Term::SizeAtCompileTime;
  static_assert(E > 0 && E == Out::SizeAtCompileTime, "fixed-size terms of the output's size");
  std::vector<Out> out(z.size(), Out::Zero());
  for (std::size_t k0 = 0; k0 < z.size(); k0 += 4) {
    v4d zr, zi;
    for (int l = 0; l < 4; ++l) {
      const std::complex<double> zl = z[std::min(k0 + l, z.size() - 1)];  // the last batch padded
      zr[l] = zl.real();
      zi[l] = zl.imag();
    }
    v4d ar[E], ai[E];
    for (int e = 0; e < E; ++e) ar[e] = ai[e] = v4d{0.0, 0.0, 0.0, 0.0};
    for (auto it = h.rbegin(); it != h.rend(); ++it) {
      const double* hj = it->data();
      for (int e = 0; e < E; ++e) {
        const v4d r = ar[e] * zr - ai[e] * zi + hj[e];
        ai[e] = ar[e] * zi + ai[e] * zr;
        ar[e] = r;
      }
    }
    for (std::size_t l = 0; l < 4 && k0 + l < z.size(); ++l)
      for (int e = 0; e < E; ++e) out[k0 + l].data()[e] = std::complex<double>(ar[e][l], ai[e][l]);
  }
  return out;
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
