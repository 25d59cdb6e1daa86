// The fast sweep's Markov parameters (LinearContactModel::creep_coefficients), in three steps.
//
// 1. The reduced, symmetric formulation (linear_model.hpp): (K0 - z K1) pi = -Pi' W with
//    K0 = D + Pi' A Pi / dt symmetric positive definite, K1 = Pi' A0 Pi / dt (by FFT), F = dx dy U' Pi pi,
//    of dimension r = 2 n_adhesion + n_slip; the same f as the paper's form (the tests compare with
//    creep_coefficients_direct). K0 is solved by a StepSolver (step_solver.hpp).
//
// 2. The block Krylov reduced model. With N = K0^{-1} K1 and X0 = K0^{-1} (-Pi' W), the Markov
//    parameters are h_j = L' N^j X0 (L = dx dy Pi' U) and f(z) = -sum_j h_j z^j = -L' (I - z N)^{-1} X0.
//    N is a rolling step: mostly a transport of the traction by one element (strongly non-normal);
//    h_j decays slowly (hundreds of steps to round-off) but the transfer function has low order
//    (fast-decaying Hankel singular values). A block Arnoldi process on N started from X0 (block
//    size 3, 4 with the normal load), orthonormal in the K0 inner product (linalg/block_arnoldi.hpp),
//    builds V (r x d, V' K0 V = I) with K0^{-1} K1 V_k = V H_k. The Galerkin projection of the pencil
//    onto span V is (I - z H) y = e_1 R0 (X0 = V_0 R0), f_k(z) = -(V' L)' (I - z H)^{-1} e_1 R0, whose
//    Markov parameters (V'L)' H^j e_1 R0 equal the exact h_j for j < k after k block steps (moment
//    matching at z = 0); the rest of the sequence is extrapolated by the reduced dynamics. In the K0
//    inner product the orthogonalisation is free: Y = K0 V is carried along (K0 X = K1 v for a new
//    X = N v). The Markov form costs O(J) per frequency (Horner) with no eigendecomposition of the
//    non-normal H; a reduced model that is not stable shows as h_j that do not decay and is rejected.
//
// 3. The a-posteriori check. At checks k_1 < k_2 < ... the Markov parameters of the current
//    model are computed until they decay and f is evaluated by FFT on N >= 4J points of the unit
//    circle (f is a trigonometric polynomial of degree J, so this grid resolves it). The model of
//    k_n block steps is accepted when it agrees with the model of the check before:
//    e_n = max_w |f_{k_n} - f_{k_{n-1}}| / |f_{k_n}| <= 1e-10 (Frobenius norms); e_n estimates the
//    error of the older model, which the newer one improves on (the errors decay geometrically in
//    k, docs/record/linear_model_sweep.md). Check schedule (check_schedule below): the first
//    check after half a contact length, then every 4 block steps, or, where two estimates give the
//    decay rate rho per step (e_n / e_{n-1} = rho^{k_{n-1} - k_{n-2}}), at the step where the error
//    is predicted to reach the tolerance, at most Lc/3 steps on (until 2026-11 every Lc/3 steps
//    from Lc on: the same accepted accuracy, 20-45 % more block steps). If no model passes (within
//    10 contact lengths of block steps), the block breaks down, or the h_j do not decay within
//    `max_contact_lengths`, the sweep falls back to the exact recursion (exact_markov), and from
//    there to the Hessenberg form (transfer.cpp).
//
// Matrix-free path: the PCG solves run to a relative residual of 1e-12, i.e. the Krylov process
// runs exactly for a slightly perturbed rolling step; the Markov parameters move by O(1e-12)
// relative and the a-posteriori check (1e-10) still measures the truncation. Orthogonalisation
// uses K0 X = apply_K0(X) of the computed X; Y = K0 V is kept while it takes < 256 MB
// (lean_krylov_basis), otherwise recomputed. Every PCG solve starts from the previous block (or
// traction) rolled on by one element (solve_step).
// Measured convergence, costs and the alternatives tried: docs/record/linear_model_sweep.md.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "linalg/block_arnoldi.hpp"
#include "linalg/fft.hpp"
#include "linalg/markov_series.hpp"
#include "nss/linear_model.hpp"
#include "nss/linear_model_parts.hpp"

namespace rollnoise::nss {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// sum_j h_j e^{-i j theta_k} on theta_k = 2 pi k / N, k = 0..N/2 (N >= 4 J, a power of two), by
// one real-to-complex FFT per entry of the 3 x p blocks h_j (the check of the Krylov models).
std::vector<Eigen::MatrixXcd> transfer_on_grid(const std::vector<Eigen::MatrixXd>& h, int N) {
  const int rows = static_cast<int>(h.front().rows()), cols = static_cast<int>(h.front().cols());
  std::vector<Eigen::MatrixXcd> f(N / 2 + 1, Eigen::MatrixXcd::Zero(rows, cols));
  const linalg::RealFft fft(N);
  double* in = fft.real();
  const std::complex<double>* out = fft.spectrum();
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      std::fill(in, in + N, 0.0);
      for (size_t j = 0; j < h.size(); ++j) in[j] = h[j](r, c);
      fft.forward();  // out_k = sum_j in_j e^{-2 pi i jk/N}
      for (int k = 0; k <= N / 2; ++k) f[k](r, c) = out[k];
    }
  return f;
}


// The a-posteriori check (step 3 at the top of the file): max over N >= 4J equispaced points of
// the unit circle of |f_a - f_b| / |f_b| (Frobenius norms) for the transfer functions of two
// Markov sequences.
double max_relative_difference(const std::vector<Eigen::MatrixXd>& ha, const std::vector<Eigen::MatrixXd>& hb) {
  const size_t J = std::max(hb.size(), ha.size());
  int N = 64;
  while (N < 4 * static_cast<int>(J)) N *= 2;
  const auto fa = transfer_on_grid(ha, N), fb = transfer_on_grid(hb, N);
  double err = 0.0;
  for (size_t i = 0; i < fa.size(); ++i) err = std::max(err, (fb[i] - fa[i]).norm() / std::max(fb[i].norm(), 1e-300));
  return err;
}

// The block step of the next a-posteriori check (step 3 at the top of the file) after the check
// at block step k. The checks before it were at k1 and k2 < k1; `estimate` (made at k) is the
// error of the model of k1, `estimate_before` (made at k1) that of the model of k2 (< 0: none).
int next_check(int k, int k1, int k2, double estimate, double estimate_before, int Lc,
               double tolerance) {
  constexpr int kMinStride = 4;
  const int max_stride = std::max(kMinStride, Lc / 6);
  if (!(estimate > 0.0) || !(estimate_before > estimate) || k1 <= k2) return k + kMinStride;
  // Geometric decay of the error in the block steps m: err(m) ~ estimate rho^(m - k1) with
  // rho^(k1 - k2) = estimate / estimate_before. The check at the first m with err(m) <= tolerance
  // is followed by the one that accepts (its estimate is err(m)).
  const double log_rho = std::log(estimate / estimate_before) / double(k1 - k2);
  const double steps = std::log(tolerance / estimate) / log_rho;
  const int converged_at = k1 + static_cast<int>(std::ceil(std::min(steps, 1e6)));
  return std::clamp(converged_at, k + kMinStride, k + max_stride);
}

}  // namespace

LinearContactModel::StartBlock LinearContactModel::start_block() const {
  // X = K0^{-1} [-Pi' W, s y], Z = K0 X; y = K0^{-1}(K1 x0 + rN1), x0 = K0^{-1} rN0 (G3).
  const StepSolver& red = step();
  StartBlock b;
  b.Z.resize(r_, block_);
  b.Z.leftCols(3) = Wr_;
  b.g0 = dN_;
  if (block_ == 4) b.Z.col(3) = rN0_;
  b.X = red.solve(b.Z);
  if (block_ == 3) return b;
  const Eigen::VectorXd x0 = b.X.col(3);
  b.g0 += Lr_.transpose() * x0;
  b.Z.col(3) = red.apply_K1(x0) + rN1_;
  b.X.col(3) = red.solve(b.Z.col(3));
  // Scale y to the creepage columns (same K0-norm as the largest), so that the block's Gram
  // matrix, the decay test and the a-posteriori check weigh both inputs alike.
  const double creep_norm = (b.X.leftCols(3).transpose() * b.Z.leftCols(3)).diagonal().maxCoeff();
  const double load_norm = b.X.col(3).dot(b.Z.col(3));
  b.load_scale = load_norm > 0.0 ? std::sqrt(creep_norm / load_norm) : 1.0;
  b.X.col(3) *= b.load_scale;
  b.Z.col(3) *= b.load_scale;
  return b;
}

LinearContactModel::MarkovSeries LinearContactModel::markov_model(const std::vector<Eigen::MatrixXd>& h,
                                                                 const StartBlock& start) const {
  MarkovSeries model;
  model.load.assign(1, start.g0);
  for (const auto& hj : h) {
    model.creep.push_back(hj.leftCols(3));
    if (block_ == 4) model.load.push_back(hj.col(3) / start.load_scale);
  }
  return model;
}

std::optional<LinearContactModel::MarkovSeries> LinearContactModel::exact_markov(int max_contact_lengths,
                                                                                SweepInfo& info) const {
  // h_j = L' X_j, X_0 = K0^{-1}(-Pi' W), X_{j+1} = K0^{-1} K1 X_j (the same h_j as
  // L' (M0^{-1} M1)^j M0^{-1} W in the paper's form), until |h_j| < 1e-15 max |h| for a whole
  // contact length; the normal-load column started from y (G3).
  const StepSolver& red = step();
  const StartBlock start = start_block();
  std::vector<Eigen::MatrixXd> h;
  const bool ok = linalg::markov_sequence(
      Lr_, start.X,
      [&](const Eigen::MatrixXd& X) { return solve_step(red, red.apply_K1(X), X); },
      steps_per_contact_length_, max_contact_lengths * steps_per_contact_length_, h);
  if (!ok) return std::nullopt;
  info.method = SweepInfo::Method::markov;
  info.block_steps = static_cast<int>(h.size());
  return markov_model(h, start);
}

std::optional<LinearContactModel::MarkovSeries> LinearContactModel::krylov_markov(int max_contact_lengths,
                                                                                 SweepInfo& info) const {
  info = SweepInfo{};
  auto t0 = std::chrono::steady_clock::now();
  const StepSolver& red = step();
  info.factor_seconds = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const int Lc = steps_per_contact_length_;
  const int max_markov = max_contact_lengths * Lc;
  const int p = block_;  // block size: 3 creepages (+ 1 normal load, G3)
  // Block steps: at most 10 contact lengths, and never more than the dimension allows.
  const int max_blocks = std::min(10 * Lc, r_ / p - 1);
  const double tolerance = 1e-10;

  const StartBlock start = start_block();
  const int capacity = p * std::min(max_blocks + 2, 2 * Lc + 2);
  linalg::BlockArnoldi::Product k0;  // matrix-free: K0 products instead of Y = K0 V where Y does not fit
  if (red.matrix_free() && lean_krylov_basis(r_, capacity)) k0 = [&red](const Eigen::MatrixXd& X) { return red.apply_K0(X); };
  linalg::BlockArnoldi arnoldi(r_, p, capacity, k0);
  // Matrix-free: Z = K0 X for the computed X (the PCG solution, not the exact one).
  if (!arnoldi.start(start.X, red.matrix_free() ? red.apply_K0(start.X) : start.Z)) return std::nullopt;
  const long solves0 = red.solves(), iterations0 = red.iterations();
  info.matrix_free = red.matrix_free();

  std::vector<Eigen::MatrixXd> h_prev, h_cur;  // Markov parameters of the last two checked models
  bool have_prev = false;
  int check_at = std::max(4, Lc / 2), k1 = 0, k2 = 0;  // the next check; the last two (0: none)
  double estimate_before = -1.0;                       // the estimate made at k1 (< 0: none)
  for (int k = 1; k <= max_blocks; ++k) {
    // Block step k: X = N V_{k-1} = K0^{-1} K1 V_{k-1}, with Z = K0 X = K1 V_{k-1}.
    Eigen::MatrixXd Z = red.apply_K1(arnoldi.last_block());
    Eigen::MatrixXd X = solve_step(red, Z, arnoldi.last_block());
    if (red.matrix_free()) Z = red.apply_K0(X);
    const bool ok = arnoldi.extend(std::move(X), std::move(Z));
    info.inner_solves = red.solves() - solves0;
    info.inner_iterations = red.iterations() - iterations0;
    if (k < check_at && ok && k < max_blocks) continue;
    // Check: after k steps the square model uses blocks 0..k-1 (d = p k); its H is complete.
    info.krylov_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    ++info.checks;
    const int d = arnoldi.model_dimension();
    double estimate = -1.0;
    if (!arnoldi.markov_parameters(d, Lr_, Lc, max_markov, h_cur)) {
      have_prev = false;  // not decayed (yet): no usable model at this size
    } else if (have_prev) {
      estimate = info.error_estimate = max_relative_difference(h_prev, h_cur);
      if (info.error_estimate <= tolerance) {
        info.check_seconds += seconds_since(t0);
        info.method = SweepInfo::Method::krylov;
        info.block_steps = k;
        info.reduced_dimension = d;
        return markov_model(h_cur, start);
      }
    }
    if (!ok) return std::nullopt;  // breakdown without a verified model
    std::swap(h_prev, h_cur);
    have_prev = !h_prev.empty() && h_prev.size() < static_cast<size_t>(max_markov);
    check_at = next_check(k, k1, k2, estimate, estimate_before, Lc, tolerance);
    k2 = k1;
    k1 = k;
    estimate_before = estimate;
    info.check_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
  }
  return std::nullopt;
}

}  // namespace rollnoise::nss
