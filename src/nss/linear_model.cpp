#include "nss/linear_model.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <stdexcept>
#include <thread>

#include "contact/element_operator.hpp"
#include "contact/halfspace_operator.hpp"
#include "core/errors.hpp"
#include "linalg/cholesky_solve.hpp"
#include "linalg/fft.hpp"

// Numerics of the fast sweep (creep_coefficients), in three steps.
//
// 1. The reduced, symmetric formulation. In the paper's unknowns Q (n = 2 per contact element) the
//    system is M(z) Q = W with M(z) = C - (A - z A0) B/dt. Only the tractions P = B Q enter the
//    elastic terms, and in a slip element P_e = B_e q_e = -t_e t_e' q_e lies along t_e. With the
//    traction amplitudes pi (adhesion: pi_e = P_e, 2 values; slip: pi_e = -t_e' q_e, 1 value) and
//    the n x r matrix Pi (identity blocks for adhesion, the column t_e for slip), P = Pi pi and:
//      adhesion rows:          0 = W_e + [(A - z A0) Pi pi]_e / dt,
//      slip rows (along t_e):  t_e' S_e = c_e t_e' q_e = -c_e pi_e = t_e' (W_e + [(A - z A0) Pi pi]_e/dt).
//    The slip rows along s_bar only give the other component of q_e, which nothing else needs.
//    Stacked: (K0 - z K1) pi = -Pi' W with
//      K0 = D + Pi' A Pi / dt,  K1 = Pi' A0 Pi / dt,  D = diag(0 for adhesion, c_e for slip),
//    and the outputs F = dx dy U' P = dx dy U' Pi pi. This is the same f as the paper's form (the
//    tests compare with creep_coefficients_direct, which solves the paper's form), of dimension
//    r = 2 n_adhesion + n_slip, and K0 is symmetric positive definite (A is the compliance of the
//    half-space: symmetric positive definite; D >= 0), so one Cholesky factorisation (n^3/3 flops,
//    half the memory of an LU) serves every solve. K1 is never assembled: A0 is block Toeplitz and
//    K1 x = Pi' A0 (Pi x)/dt is one FFT convolution on the grid (contact::HalfSpaceOperator, shift 1).
//
// 2. The block Krylov reduced model. With N = K0^{-1} K1 and X0 = K0^{-1} (-Pi' W), the Markov
//    parameters are h_j = L' N^j X0 (L = dx dy Pi' U) and f(z) = -sum_j h_j z^j = -L' (I - z N)^{-1} X0.
//    N is a rolling step: mostly a transport of the traction by one element (strongly non-normal),
//    and h_j decays only by ~0.13 per contact length (~600 steps to round-off on the coarse grid,
//    ~1100 on the fine one), but the transfer function itself has low order: the Hankel singular
//    values of the h_j fall below 1e-9 of the largest after ~65 (coarse). A block Arnoldi process on
//    N started from X0 (block size 3), orthonormal in the K0 inner product <u, v> = u' K0 v, builds
//    V (r x d, V' K0 V = I) with K0^{-1} K1 V_k = V H_k (H block upper Hessenberg). The Galerkin
//    projection of the pencil onto span V is
//      V'(K0 - z K1) V y = V'(-Pi' W)   <=>   (I - z H) y = e_1 R0   (X0 = V_0 R0),
//    f_k(z) = -(V' L)' (I - z H)^{-1} e_1 R0, and its Markov parameters h_j^(k) = (V'L)' H^j e_1 R0
//    equal the exact h_j for j < k (moment matching at z = 0; after k block steps) while the rest
//    of the sequence is extrapolated by the reduced dynamics. In the K0 inner product the
//    orthogonalisation is free: Y = K0 V is carried along (K0 X = K1 v for a new X = N v), so the
//    coefficients are Y' X; two passes of block classical Gram-Schmidt (CGS2). The block is
//    normalised by the Cholesky factor of its 3 x 3 K0-Gram matrix (R, the subdiagonal block of H).
//    Measured on the paper's coarse grid (mean creepage (0.001, 0.001, -0.053), Lc = 30 steps per
//    contact length): max relative error over the unit circle 2e-4 after Lc block steps, 3.5e-6
//    after 4/3 Lc, 2.7e-8 after 5/3 Lc, 2e-11 after 2 Lc, 1e-13 after 7/3 Lc; the same rate on the
//    fine grid (Lc = 60) and faster with more slip (full sliding: 4/3 Lc). One block step costs
//    one Cholesky solve with 3 right-hand sides and 3 FFT convolutions.
//    Why the Markov form: the reduced h_j^(k) are cheap (one (d x d)(d x 3) product each, H block
//    Hessenberg), and evaluating f by Horner costs O(J) per frequency for any number of
//    frequencies, with no conditioning issue (no eigendecomposition of the non-normal H). The
//    reduced model need not be stable in general (a Galerkin projection can move eigenvalues of N
//    out of the unit disk): such a model shows as h_j^(k) that do not decay, and is rejected.
//
// 3. The a-posteriori check. Every Lc/3 block steps (from Lc on) the Markov parameters of the
//    current model are computed until they decay (as for the exact ones: below 1e-15 of the largest
//    for a whole contact length) and f is evaluated by FFT on N >= 4J equispaced points of the unit
//    circle (2J + 1 frequencies over [0, Nyquist]; f is a trigonometric polynomial of degree J, so
//    this grid resolves it). The model of k block steps is accepted when it agrees with the model
//    of s = Lc/3 fewer steps: max_w |f_k - f_{k-s}| / |f_k| <= 1e-10 (Frobenius norms). With the
//    convergence above (two or more digits per s steps), |f - f_k| <= |f_k - f_{k-s}|; measured
//    against the exact recursion over [0, Nyquist] for mean states from full adhesion to full
//    sliding, the true error is 1e-15 to 6e-13 when the estimate is 1e-15 to 6e-11 (tests).
//    If no model passes (within 10 contact lengths of block steps), the block breaks down, or the
//    h_j do not decay within `max_contact_lengths`, creep_coefficients falls back to the exact
//    recursion (creep_coefficients_markov: J sequential solves), and from there to the Hessenberg
//    form.
//
// Cost (measured, one core, bench/nss_bench.cpp, sweep of 1000 frequencies with the model set-up):
// fine grid (68 x 50) at the paper's mean creepage (r = 3541, n = 4192): 2.0-2.3 s = K0 assembly
// and Cholesky 0.6-0.7 s + 140 block steps 1.2-1.4 s (a 3-column Cholesky solve ~7 ms, memory
// bound, linalg::cholesky_solve_in_place; FFTs ~1 ms; Gram-Schmidt ~2 ms at d = 420) + 5 checks
// 0.1 s + Horner at 1000 frequencies 0.02 s. Full adhesion is the slowest case: r = n = 4192 and
// 180 block steps, 4.1 s. Coarse grid (34 x 25): 0.08-0.13 s. The exact recursion needs 1132
// (fine) sequential steps instead of 140 (9-12 s), the paper's form a 4192 x 4192 LU per
// frequency (12 s).
//
// Matrix-free path (solver.linear_model = "matrix_free", or "auto" above kDenseReducedUnknowns =
// 11000 reduced unknowns, where the dense factor passes ~1 GB). K0 x = D x + Pi' A (Pi x)/dt is one
// FFT convolution (contact::ElementOperator with the shift-0 kernel, like K1 with shift 1), and
// K0 solves are preconditioned CG (Reduced::pcg). Preconditioner: M^{-1} = W Pi' (C/dt + cbar I)^{-1}
// Pi W, C the zero-padded circulant of the compliance, inverted 2 x 2 per Fourier bin
// (HalfSpaceOperator::inverse_circulant; its eigenvalues floored at 0.1 of the self-compliance:
// the truncated kernel's circulant has a few slightly negative bins, 17 of 6800 on 68 x 50, which
// unfloored took the iterations from 16 to 65). W = 1 on adhesion unknowns and
// sqrt((kappa_e + cbar)/(kappa_e + c_e)) on slip unknowns (kappa_e = t_e' A_ee t_e/dt), so that
// the preconditioner's diagonal ~ 1/(kappa_e + cbar) becomes that of K0, 1/(kappa_e + c_e): where
// c_e dominates (deep slip, pn -> 0 at the edges) K0 is nearly diagonal and the full-space inverse
// would overweight those rows. cbar (preconditioner_shift) is the median c_e of the slip elements
// times the slip unknowns' share of r: 0 in full adhesion, where R C^{-1} R' >= (R C R')^{-1}
// (Schur complement) is the restricted hypersingular-like inverse with log-type growth only; the
// median in full sliding, where K0 = D + Pi' A Pi/dt has c_e ~30 kappa_e and C^{-1} alone (which
// grows like |k| in the Fourier bins) spreads a nearly diagonal spectrum instead of compressing
// it. Measured PCG iterations per solve at tolerance 1e-12 (tests/nss/matrix_free_test.cpp, time
// responses) on 24x18, 34x25, 68x50 (100x100 from the stress test): full adhesion 14.3, 15.1,
// 16.7 (17.5); partial slip (paper state) 17.2, 18.2, 21.3 (27; with cbar = 0: 19.2, 21.7, 26.8,
// 32.5); full sliding 8.0, 8.3, 9.2 (10.4; with cbar = 0: 39 and 61 on 34x25 and 68x50, 87 on
// 100x100). The share weighting matters: cbar = the median in partial slip gives 26-29 (the
// adhesion rows then see a wrong diagonal); 0.1-0.3 of it 20-25. A block-Jacobi preconditioner
// (adhesion and slip elements each with their own symbol, the coupling dropped) gave 23-26 at
// twice the FFT cost. Without W: 85-95 in partial slip. Starting from the rolled traction
// (Pi' S Pi x_prev, S one element in x) saves ~5 % in the recursion and time_response and nothing
// in the Krylov steps (the orthonormalised block is not a traction history), so the Krylov
// solves start from zero.
// Tolerance: relative residual 1e-12. The Krylov process then runs with an inexact N (each
// block X = N V + E, |E|_K0 <~ 1e-12 cond-weighted), i.e. exactly for a perturbed rolling step; the
// Markov parameters move by O(1e-12) relative and the a-posteriori check (1e-10 between models
// s steps apart) still measures the truncation, which dominates: measured f against the dense path
// 2e-13 - 1e-11 over [0, Nyquist] (adhesion, partial slip, full sliding, spin), the same block
// steps as the dense path. Orthogonalisation uses K0 X = apply_K0(X) of the computed X (so X' Z is
// the exact K0-Gram matrix of the stored basis); Y = K0 V is kept while it takes < 256 MB,
// otherwise recomputed (memory r d instead of 2 r d: 200 x 200 partial slip, r ~ 41500, d ~ 1600,
// 0.53 GB instead of 1.06 GB).
// Threads (LinearModelInput::threads, solver.threads). The columns of a block (4: three creepages
// and the normal load) are independent in K1 X, K0 X and the PCG solves, so Reduced::for_columns
// shares them out among threads, each with its own copies of the FFT operators (an FFT
// operator's work arrays serve one caller). Every column goes through the same operations as in a
// serial run: the results are identical to the last bit for any thread count (tested). The dense
// path's Cholesky solve stays serial: it streams the factor once for all columns, and two threads
// with two columns each stream it twice (measured on r = 3541: 7.1 ms for 2 x 2 columns on two
// threads against 7.8 ms for 4 on one).
// Cost (bench --sweep-cost 34,68,100,200 on the paper state, unloaded 2-core machine, 2 threads,
// 1000 frequencies, f and g, set-up included): dense 0.09 s (34x25), 2.1 s (68x50), 12.4 s
// (100x74, 0.39 GB); matrix-free 0.38 s (34x25, 19.9 PCG iterations per solve), 5.0 s (68x50,
// 22.8), 12.8 s (100x74, 25.3), 168 s (200x147, r = 30477, 412 block steps, 30.7, peak 0.53 GB).
// (Before threads and the shifted preconditioner: 0.72, 9.7, 28.4 and 326 s.) One PCG iteration
// is two FFT convolutions (K0 and M^{-1}, 8 transforms of the padded grid); on 200x147 the sweep
// is ~50000 of them (4 columns x 412 steps x 30.7), ~95 % of its time; the a-posteriori checks
// take 3.6 s. So the matrix-free path is the memory-scalable one, and as fast as the dense one
// from ~100x74 up.
// Not reached: 68x50 in < 0.5 s and 200x200 in < 10 s (docs/accuracy.md, "Limits of the sweep's
// speed"). The cost is (K0 solves) x (cost of one), both measured:
//   - Solves: ~2 contact lengths of block steps, 4 columns each (560 on 68x50, 1648 on 200x147).
//     On 34x25 the model's error is 7.9e-5 after 1 Lc, 2.6e-9 after 5/3, 1.6e-12 after 2, and the
//     same on the requested band (10 Hz - 10 kHz) as on [0, Nyquist] at every step: a check on the
//     band alone would not stop earlier.
//   - The dense path cannot get there: each block step is a pass over the factor (forward and back
//     over the 50 MB triangle at r = 3541, ~7 ms at the measured ~14 GB/s): ~1 s for 140 steps,
//     plus the Cholesky factorisation (1.5e10 flops, 0.55 s).
//   - Matrix-free: a convolution on the padded grid is 4 real transforms, 0.23 ms (136 x 100) and
//     1.43 ms (400 x 294). The targets on 2 threads, less the K1 and K0 products, leave ~6
//     convolutions per solve: 3 PCG iterations to 1e-12, i.e. a preconditioned condition number
//     ~1.001; the measured rates (23 and 31 iterations) correspond to 3.5 - 5.4.
//   - Rational Krylov on the band (exact solves at shifts spread over 10 Hz - 10 kHz, real basis,
//     Galerkin): 68x50 needs 17 shifts (132 vectors) for 3.6e-7 (9 shifts: 6e-2); on 34x25 more
//     shifts made it worse (17: 1.1e-6, 33: 1.8e-3). At most 4x fewer vectors than the 560 here,
//     each a complex non-Hermitian solve of K0 - z K1 (whose preconditioner would have to carry
//     the transport): no net gain.
//   - Krylov at z = 1 (shift-invert with an LU of K0 - K1, for a band near omega = 0): on 34x25 over
//     10 Hz - 10 kHz (omega dt up to 2.2) 2.8e-7 after 80 block steps, against 5e-15 for the
//     polynomial Krylov at z = 0 used here: the noise band is not near z = 1 on these grids.
//   - A hierarchical-matrix Cholesky (hmat-oss 1.8, Debian libhmat-oss, ACA+, admissibility 2,
//     leaves of 64, on the dumped K0 of 68x50): at 1e-10 4.2 M entries (dense triangle 6.3 M),
//     8.1 s to factor, 20 ms per 4-column solve; at 1e-6 2.4 M, 1.9 s, 12 ms (dense 0.57 s and
//     7.8 ms). At r ~ 3500 a 2D patch's off-diagonal blocks do not compress enough to pay.
//   - FFTW_MEASURE plans transform the padded grids 1.3-1.5x faster than FFTW_ESTIMATE (e.g.
//     100 x 135: 43 against 60 us) but choose plans by timing, so the results would change in the
//     last bits from run to run; not taken.
// What would: a K0 solve to 1e-12 in ~3 convolutions, or a model with ~10x fewer vectors whose
// solves cost no more than these; neither is known for this operator.

namespace rollnoise::nss {

using contact::Component;
using contact::ElementState;
using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

namespace {
// Matrix-free path (top of the file): PCG tolerance, floor of the circulant symbol's eigenvalues
// (relative to the largest), and the shift of the rolled start (elements in x).
constexpr double kPcgTolerance = 1e-12;
constexpr double kSymbolFloor = 0.1;
constexpr int kRollShift = 1;

// The Krylov sweep's Y = K0 V is kept beside the basis V (as on the dense path) while it takes at
// most this many bytes (at the largest basis the sweep allocates, 1.5 times its first capacity);
// above, the matrix-free path recomputes K0 X instead (three more FFT products per column and
// step, against memory r d): 68 x 50 keeps it (~20 MB), 200 x 200 drops it (~0.7 GB).
constexpr double kKrylovYBudget = 256e6;

bool lean_krylov_basis(int r, int capacity) { return 8.0 * r * 1.5 * capacity > kKrylovYBudget; }
}  // namespace

// The paper's formulation, dense (for the reference solve and the Hessenberg sweep).
struct LinearContactModel::Dense {
  Eigen::MatrixXd M0, M1;
};

// The reduced symmetric formulation: K1 by FFT, and K0 either factored densely (its lower triangle,
// Cholesky in place) or applied by FFT and solved by preconditioned CG (the matrix-free path).
struct LinearContactModel::Reduced {
  explicit Reduced(contact::ElementOperator k1) : K1(std::move(k1)) {}
  // ---- dense path ----
  Eigen::MatrixXd K0;  // holds the Cholesky factor after construction
  std::unique_ptr<Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>>> llt;
  /// K1 X = Pi' A0 Pi X / dt column by column: the amplitudes expanded to tractions on the grid
  /// (adhesion elements free, slip elements along t_e), one FFT convolution with the shifted
  /// kernel (the model's A0_op_), projected back.
  contact::ElementOperator K1;
  // ---- matrix-free path ----
  bool matrix_free = false;
  std::unique_ptr<contact::ElementOperator> A;  ///< Pi' A Pi / dt (shift 0)
  std::unique_ptr<contact::ElementOperator> G;  ///< Pi' (dt C^{-1}) Pi, C the circulant of A
  Eigen::VectorXd d;                            ///< D: c_e on slip unknowns, 0 on adhesion ones
  Eigen::VectorXd w;                            ///< preconditioner scaling (1 for adhesion)
  double tolerance = 0.0;                       ///< PCG: relative residual |b - K0 x| / |b|
  double cbar = 0.0;                            ///< diagonal added to the preconditioner's symbol (as c_e)
  mutable std::atomic<long> solves{0}, iterations{0};

  // ---- threads ("Threads" at the top of the file) ----
  /// The FFT operators one thread uses: an FFT operator's work arrays serve one caller at a time,
  /// so every further thread has its own copies (lane 0 is K1, A and G above).
  struct Lane {
    const contact::ElementOperator* K1 = nullptr;
    const contact::ElementOperator* A = nullptr;  ///< matrix-free path only
    const contact::ElementOperator* G = nullptr;  ///< matrix-free path only
  };
  std::vector<Lane> lanes;
  std::vector<std::unique_ptr<contact::ElementOperator>> copies;  ///< owns lanes 1..

  /// f(lane, j) for the columns j < n, shared out round-robin among min(lanes, n) threads (the
  /// caller is lane 0). Each column is computed by one thread with the same operations as in a
  /// serial run, so the results do not depend on the number of threads. The first exception of
  /// any thread is rethrown after all have finished.
  template <class F>
  void for_columns(Eigen::Index n, F&& f) const {
    const int T = static_cast<int>(std::min<Eigen::Index>(static_cast<Eigen::Index>(lanes.size()), n));
    if (T <= 1) {
      for (Eigen::Index j = 0; j < n; ++j) f(lanes.front(), j);
      return;
    }
    std::vector<std::exception_ptr> error(T);
    auto run = [&](int t) {
      try {
        for (Eigen::Index j = t; j < n; j += T) f(lanes[t], j);
      } catch (...) {
        error[t] = std::current_exception();
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < T; ++t) pool.emplace_back(run, t);
    run(0);
    for (auto& th : pool) th.join();
    for (const auto& e : error)
      if (e) std::rethrow_exception(e);
  }

  /// K1 X (both paths), the columns in parallel.
  Eigen::MatrixXd apply_K1(const Eigen::MatrixXd& X) const {
    Eigen::MatrixXd Y(X.rows(), X.cols());
    for_columns(X.cols(), [&](const Lane& l, Eigen::Index j) { l.K1->apply(X.col(j).data(), Y.col(j).data()); });
    return Y;
  }
  /// K0 X = D X + Pi' A Pi X / dt (matrix-free path), the columns in parallel.
  Eigen::MatrixXd apply_K0(const Eigen::MatrixXd& X) const {
    Eigen::MatrixXd Y(X.rows(), X.cols());
    for_columns(X.cols(), [&](const Lane& l, Eigen::Index j) { apply_K0(l, X.col(j), Y.col(j)); });
    return Y;
  }
  /// K0^{-1} B: the Cholesky factor (linalg::cholesky_solve_in_place: streams the factor once per
  /// pass for three right-hand sides, ~3x faster than LLT::solve for few columns), or PCG from
  /// `start` (zero if null) per column, the columns in parallel.
  Eigen::MatrixXd solve(Eigen::MatrixXd B, const Eigen::MatrixXd* start = nullptr) const {
    if (!matrix_free) {
      linalg::cholesky_solve_in_place(K0, B);
      return B;
    }
    Eigen::MatrixXd X = start ? *start : Eigen::MatrixXd::Zero(B.rows(), B.cols());
    for_columns(B.cols(), [&](const Lane& l, Eigen::Index j) { pcg(l, B.col(j), X.col(j)); });
    return X;
  }

 private:
  /// y = K0 x = Pi' A Pi x / dt + D x for one column, with the lane's FFT operator.
  void apply_K0(const Lane& lane, const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
    lane.A->apply(x.data(), y.data());
    y += d.cwiseProduct(x);
  }

  // Preconditioned conjugate gradients (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed.,
  // Alg. 9.1) for K0 x = b, M^{-1} = W G W; stops at |b - K0 x|_2 <= tolerance |b|_2.
  void pcg(const Lane& lane, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> x) const {
    ++solves;
    const double bnorm = b.norm();
    if (bnorm == 0.0) {
      x.setZero();
      return;
    }
    Eigen::VectorXd r(b.size()), q(b.size()), z(b.size()), wv(b.size());
    apply_K0(lane, x, q);
    r = b - q;
    auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
      wv = w.cwiseProduct(v);
      lane.G->apply(wv.data(), out.data());
      out.array() *= w.array();
    };
    if (r.norm() <= tolerance * bnorm) return;
    precondition(r, z);
    Eigen::VectorXd p = z;
    double rz = r.dot(z);
    const int max_iterations = 20000;
    for (int it = 1; it <= max_iterations; ++it) {
      ++iterations;
      apply_K0(lane, p, q);
      const double alpha = rz / p.dot(q);
      x += alpha * p;
      r -= alpha * q;
      if (r.norm() <= tolerance * bnorm) return;
      precondition(r, z);
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
    throw NumericalError("linear contact model: PCG on K0 did not converge (matrix-free path)");
  }
};

LinearContactModel::LinearContactModel(const contact::ContactPatch& patch,
                                       const contact::TangentialSolution& mean,
                                       const LinearModelInput& in)
    : dt_(patch.grid.dx / in.speed), speed_(in.speed), mu_(in.mu), solver_(in.solver), sampling_(in.sampling),
      table_(patch.influence) {
  contact::check_rolling_input(in.mu, in.speed, contact::Creepage{});
  if (in.threads < 0 || in.threads > kMaxThreads)
    throw InputError("solver.threads", "must be 0 (one per hardware thread) to " + std::to_string(kMaxThreads) +
                                           ", not " + std::to_string(in.threads));
  threads_ = in.threads > 0 ? in.threads
                            : std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxThreads);
  const contact::Grid& g = patch.grid;
  const contact::InfluenceTable& A = patch.influence;
  el_ = contact::sweep_order(g, patch.normal.pn);
  const int m = static_cast<int>(el_.size()), n = 2 * m;

  // Element data (scaled formulation, see the header): t_e and c_e for slip elements; c_e is
  // floored at 1e-12 times the self-compliance A_ee/dt so that the pencil stays regular.
  const double self = std::max(A(Component::xx, 0, 0), A(Component::yy, 0, 0)) / dt_;
  offset_.resize(m);
  t_.assign(m, Eigen::Vector2d::Zero());
  c_.assign(m, 0.0);
  kappa_.assign(m, 0.0);
  contact::check_falling_friction(in.falling);
  const contact::FrictionLaw law{in.mu, in.falling};
  std::vector<double> mu_bar(m, in.mu);  // mu(|s_bar|) at the slip elements
  slip_.assign(m, 0);
  for (int a = 0; a < m; ++a) {
    const int k = el_[a];
    offset_[a] = r_;
    if (mean.state[k] == static_cast<std::int8_t>(ElementState::slip)) {
      const double s1 = mean.sx[k], s2 = mean.sy[k], s = std::hypot(s1, s2);
      t_[a] = Eigen::Vector2d(s2 / s, -s1 / s);
      mu_bar[a] = law.mu(s);  // in.mu itself for constant friction
      c_[a] = std::max(s / (mu_bar[a] * patch.normal.pn[k]), 1e-12 * self);
      // radial term of K_e (header): kappa = mu'(|s|) |s| / mu(|s|)
      if (in.falling.active()) kappa_[a] = law.slope(s) * s / mu_bar[a];
      if (kappa_[a] != 0.0) falling_ = true;
      slip_[a] = 1;
      ++n_slip_;
      r_ += 1;
    } else {
      ++n_adhesion_;
      r_ += 2;
    }
  }

  // Inputs W (per unit creepage) and outputs L in the paper's form; -Pi' W and dx dy Pi' U reduced.
  W_.setZero(n, 3);
  L_.setZero(n, 3);
  Wr_.setZero(r_, 3);
  Lr_.setZero(r_, 3);
  const double area = g.element_area();
  for (int a = 0; a < m; ++a) {
    const double x = g.x(el_[a] % g.nx), y = g.y(el_[a] / g.nx);
    W_(2 * a, 0) = in.speed;
    W_(2 * a + 1, 1) = in.speed;
    W_(2 * a, 2) = -in.speed * y;
    W_(2 * a + 1, 2) = in.speed * (x + in.spin_offset * g.dx);
    Eigen::Matrix<double, 2, 3> U;  // U1, U2, Usp0 at this element
    U << 1, 0, -y, 0, 1, x;
    if (slip_[a]) {
      const Eigen::Matrix2d B = slip_traction_matrix(a);
      L_.block<2, 3>(2 * a, 0) = area * B.transpose() * U;
      Wr_.row(offset_[a]) = -t_[a].transpose() * W_.block<2, 3>(2 * a, 0);
      Lr_.row(offset_[a]) = area * t_[a].transpose() * U;
    } else {
      L_.block<2, 3>(2 * a, 0) = area * U;
      Wr_.block<2, 3>(offset_[a], 0) = -W_.block<2, 3>(2 * a, 0);
      Lr_.block<2, 3>(offset_[a], 0) = area * U;
    }
  }
  // A0 by FFT (shift 1): the rolling step of the sweeps (K1) and the delayed load input below.
  A0_op_ = std::make_shared<const contact::HalfSpaceOperator>(table_, contact::Problem::Tangential, 1);

  // Normal-load input (G1): bN on the slip elements from the frozen-area sensitivity dpn/dN, then
  // A bN/dt and A0 bN/dt on the grid (two FFT products) and their reduced forms.
  if (n_slip_ > 0) {
    const contact::HalfSpaceOperator normal_op(A, contact::Problem::Normal);
    const contact::NormalLoadSensitivity sens =
        contact::normal_load_sensitivity(g, normal_op, patch.normal);
    const int N = g.size();
    std::vector<double> b(2 * N, 0.0), u0(2 * N), u1(2 * N);
    for (int a = 0; a < m; ++a) {
      if (!slip_[a]) continue;
      const int k = el_[a];
      const double s = std::hypot(mean.sx[k], mean.sy[k]);
      b[k] = -mu_bar[a] * sens.dpn_dN[k] * mean.sx[k] / s;
      b[N + k] = -mu_bar[a] * sens.dpn_dN[k] * mean.sy[k] / s;
      const double x = g.x(k % g.nx), y = g.y(k / g.nx);
      dN_ += area * Eigen::Vector3d(b[k], b[N + k], x * b[N + k] - y * b[k]);
    }
    contact::HalfSpaceOperator(A, contact::Problem::Tangential, 0).apply(b.data(), u0.data());
    A0_op_->apply(b.data(), u1.data());
    wN0_.resize(n);
    wN1_.resize(n);
    rN0_.setZero(r_);
    rN1_.setZero(r_);
    for (int a = 0; a < m; ++a) {
      const int k = el_[a];
      const Eigen::Vector2d v0(u0[k] / dt_, u0[N + k] / dt_), v1(u1[k] / dt_, u1[N + k] / dt_);
      wN0_.segment<2>(2 * a) = v0;
      wN1_.segment<2>(2 * a) = v1;
      if (slip_[a]) {
        rN0_(offset_[a]) = -t_[a].dot(v0);
        rN1_(offset_[a]) = t_[a].dot(v1);
      } else {
        rN0_.segment<2>(offset_[a]) = -v0;
        rN1_.segment<2>(offset_[a]) = v1;
      }
    }
    block_ = 4;
  } else {
    wN0_.setZero(n);
    wN1_.setZero(n);
    rN0_.setZero(r_);
    rN1_.setZero(r_);
  }

  // steps per contact length: the extent of the contact area in x, in elements
  int ix_min = g.nx, ix_max = -1;
  for (int k : el_) ix_min = std::min(ix_min, k % g.nx), ix_max = std::max(ix_max, k % g.nx);
  steps_per_contact_length_ = std::max(1, ix_max - ix_min + 1);
}

LinearContactModel::~LinearContactModel() = default;
LinearContactModel::LinearContactModel(LinearContactModel&&) noexcept = default;
LinearContactModel& LinearContactModel::operator=(LinearContactModel&&) noexcept = default;

const LinearContactModel::Dense& LinearContactModel::dense() const {
  if (dense_) return *dense_;
  // M0 = C - A B/dt, M1 = -A0 B/dt on the contact elements, interleaved (x, y) per element,
  // assembled column by column (contiguous writes in the column-major matrices).
  auto d = std::make_unique<Dense>();
  const contact::Grid& g = table_.grid();
  const int m = static_cast<int>(el_.size()), n = 2 * m;
  d->M0.resize(n, n);
  d->M1.resize(n, n);
  for (int b = 0; b < m; ++b) {
    const int ixb = el_[b] % g.nx, iyb = el_[b] / g.nx;
    const Eigen::Matrix2d B = slip_[b] ? slip_traction_matrix(b) : Eigen::Matrix2d::Identity();
    double* c0x = d->M0.col(2 * b).data();
    double* c0y = d->M0.col(2 * b + 1).data();
    double* c1x = d->M1.col(2 * b).data();
    double* c1y = d->M1.col(2 * b + 1).data();
    for (int a = 0; a < m; ++a) {
      const int di = el_[a] % g.nx - ixb, dj = el_[a] / g.nx - iyb;
      const double xx = table_(Component::xx, di, dj), xy = table_(Component::xy, di, dj),
                   yy = table_(Component::yy, di, dj);
      const double xx0 = table_(Component::xx, di + 1, dj), xy0 = table_(Component::xy, di + 1, dj),
                   yy0 = table_(Component::yy, di + 1, dj);
      // -[xx xy; xy yy] B / dt, column by column
      c0x[2 * a] = -(xx * B(0, 0) + xy * B(1, 0)) / dt_;
      c0x[2 * a + 1] = -(xy * B(0, 0) + yy * B(1, 0)) / dt_;
      c0y[2 * a] = -(xx * B(0, 1) + xy * B(1, 1)) / dt_;
      c0y[2 * a + 1] = -(xy * B(0, 1) + yy * B(1, 1)) / dt_;
      c1x[2 * a] = -(xx0 * B(0, 0) + xy0 * B(1, 0)) / dt_;
      c1x[2 * a + 1] = -(xy0 * B(0, 0) + yy0 * B(1, 0)) / dt_;
      c1y[2 * a] = -(xx0 * B(0, 1) + xy0 * B(1, 1)) / dt_;
      c1y[2 * a + 1] = -(xy0 * B(0, 1) + yy0 * B(1, 1)) / dt_;
    }
    d->M0(2 * b, 2 * b) += c_[b];
    d->M0(2 * b + 1, 2 * b + 1) += c_[b];
  }
  dense_ = std::move(d);
  return *dense_;
}

Eigen::Matrix2d LinearContactModel::slip_traction_matrix(int a) const {
  // B_e = -t t' - kappa s^ s^' (header, "Falling friction"); s^ = (-t2, t1) as t = (s2, -s1)/|s|
  Eigen::Matrix2d B = -t_[a] * t_[a].transpose();
  if (kappa_[a] != 0.0) {
    const Eigen::Vector2d sh(-t_[a](1), t_[a](0));
    B -= kappa_[a] * sh * sh.transpose();
  }
  return B;
}

const LinearContactModel::Reduced& LinearContactModel::reduced() const {
  return matrix_free() ? reduced_matrix_free() : reduced_factor();
}

const LinearContactModel::Reduced& LinearContactModel::reduced_factor() const {
  if (reduced_) return *reduced_;
  if (falling_)
    throw std::logic_error(
        "linear contact model: the reduced form K0 (Cholesky) does not hold falling friction (linear_model.hpp)");
  const contact::Grid& g = table_.grid();
  auto red = std::make_unique<Reduced>(contact::ElementOperator(A0_op_, g, el_, slip_, t_, dt_));
  const int m = static_cast<int>(el_.size());
  // K0 = D + Pi' A Pi / dt: only the lower triangle (element a >= b) is written and read. The
  // block of elements (a, b) is Pi_a' A_ab Pi_b / dt with A_ab = [xx xy; xy yy](di, dj).
  red->K0.resize(r_, r_);
  for (int b = 0; b < m; ++b) {
    const int ixb = el_[b] % g.nx, iyb = el_[b] / g.nx, ob = offset_[b];
    const int nb = slip_[b] ? 1 : 2;
    for (int cb = 0; cb < nb; ++cb) {
      // column (ob + cb) of K0 = Pi' A (Pi e_{ob+cb}) / dt; traction direction of that column
      const Eigen::Vector2d pb = slip_[b] ? t_[b] : Eigen::Vector2d(cb == 0 ? 1.0 : 0.0, cb == 1 ? 1.0 : 0.0);
      double* col = red->K0.col(ob + cb).data();
      for (int a = b; a < m; ++a) {
        const int di = el_[a] % g.nx - ixb, dj = el_[a] / g.nx - iyb;
        const double xx = table_(Component::xx, di, dj), xy = table_(Component::xy, di, dj),
                     yy = table_(Component::yy, di, dj);
        const double ux = (xx * pb(0) + xy * pb(1)) / dt_, uy = (xy * pb(0) + yy * pb(1)) / dt_;
        const int oa = offset_[a];
        if (slip_[a]) {
          col[oa] = t_[a](0) * ux + t_[a](1) * uy;
        } else {
          col[oa] = ux;
          col[oa + 1] = uy;
        }
      }
    }
    if (slip_[b]) red->K0(ob, ob) += c_[b];
  }
  add_lanes(*red);
  red->llt = std::make_unique<Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>>>(red->K0);
  if (red->llt->info() != Eigen::Success)
    throw NumericalError("linear contact model: the reduced matrix K0 = D + Pi' A Pi/dt is not positive definite");
  reduced_ = std::move(red);
  return *reduced_;
}

const LinearContactModel::Reduced& LinearContactModel::reduced_matrix_free() const {
  if (reduced_mf_) return *reduced_mf_;
  const contact::Grid& g = table_.grid();
  auto red = std::make_unique<Reduced>(contact::ElementOperator(A0_op_, g, el_, slip_, t_, dt_));
  red->matrix_free = true;
  red->A = reduced_operator(ReducedOperator::compliance);
  // Preconditioner (see "Matrix-free path" at the top of the file): M^{-1} = W Pi' (C/dt + cbar I)^{-1}
  // Pi W, cbar = 0 with adhesion elements, else the median c_e.
  red->cbar = preconditioner_shift();
  red->G = reduced_operator(ReducedOperator::preconditioner, red->cbar);
  red->d = step_matrix_slip_diagonal();
  red->w = Eigen::VectorXd::Ones(r_);
  const Eigen::Matrix2d self = (Eigen::Matrix2d() << table_(Component::xx, 0, 0), table_(Component::xy, 0, 0),
                                table_(Component::xy, 0, 0), table_(Component::yy, 0, 0))
                                   .finished() /
                               dt_;
  for (size_t a = 0; a < el_.size(); ++a)
    if (slip_[a]) {
      const double kappa = t_[a].dot(self * t_[a]);
      red->w(offset_[a]) = std::sqrt((kappa + red->cbar) / (kappa + c_[a]));
    }
  red->tolerance = kPcgTolerance;
  add_lanes(*red);
  reduced_mf_ = std::move(red);
  return *reduced_mf_;
}

double LinearContactModel::preconditioner_shift() const {
  // The median c_e of the slip elements weighted by the slip unknowns' share of r ("Matrix-free
  // path" at the top of the file): 0 in full adhesion, the median in full sliding.
  if (n_slip_ == 0) return 0.0;
  std::vector<double> c;
  for (size_t a = 0; a < el_.size(); ++a)
    if (slip_[a]) c.push_back(c_[a]);
  std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
  return double(n_slip_) / double(r_) * c[c.size() / 2];
}

std::unique_ptr<contact::ElementOperator> LinearContactModel::reduced_operator(ReducedOperator which,
                                                                              double cbar) const {
  const contact::Grid& g = table_.grid();
  auto on_elements = [&](contact::HalfSpaceOperator op, double divisor) {
    return std::make_unique<contact::ElementOperator>(std::make_shared<const contact::HalfSpaceOperator>(std::move(op)),
                                                      g, el_, slip_, t_, divisor);
  };
  switch (which) {
    case ReducedOperator::rolling_step:
      return on_elements(contact::HalfSpaceOperator(table_, contact::Problem::Tangential, 1), dt_);
    case ReducedOperator::compliance:
      return on_elements(contact::HalfSpaceOperator(table_, contact::Problem::Tangential, 0), dt_);
    case ReducedOperator::preconditioner:
      return on_elements(contact::HalfSpaceOperator::inverse_circulant(table_, kSymbolFloor, cbar * dt_), 1.0 / dt_);
  }
  throw std::logic_error("reduced_operator: unknown operator");
}

void LinearContactModel::add_lanes(Reduced& red) const {
  // Lane 0 is the operators red holds; every further lane builds its own FFT operators (the kernel
  // spectra again: a few FFTs of the padded grid, ~1 MB on 100 x 100).
  red.lanes.assign(1, Reduced::Lane{&red.K1, red.A.get(), red.G.get()});
  auto own = [&red](std::unique_ptr<contact::ElementOperator> op) {
    red.copies.push_back(std::move(op));
    return red.copies.back().get();
  };
  for (int t = 1; t < threads_; ++t) {
    Reduced::Lane lane;
    lane.K1 = own(reduced_operator(ReducedOperator::rolling_step));
    if (red.matrix_free) {
      lane.A = own(reduced_operator(ReducedOperator::compliance));
      lane.G = own(reduced_operator(ReducedOperator::preconditioner, red.cbar));
    }
    red.lanes.push_back(lane);
  }
}

Eigen::MatrixXd LinearContactModel::rolled(const Eigen::MatrixXd& X) const {
  // Element a takes the traction of the element kRollShift columns upstream (zero if that is not
  // a contact element), projected on its own unknowns: Pi_a' Pi_b x_b.
  const contact::Grid& g = table_.grid();
  std::vector<int> position(g.size(), -1);
  for (size_t a = 0; a < el_.size(); ++a) position[el_[a]] = static_cast<int>(a);
  Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(X.rows(), X.cols());
  for (size_t a = 0; a < el_.size(); ++a) {
    const int ix = el_[a] % g.nx - kRollShift;
    if (ix < 0 || ix >= g.nx) continue;
    const int b = position[el_[a] + (ix - el_[a] % g.nx)];
    if (b < 0) continue;
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
      const Eigen::Vector2d p = slip_[b] ? Eigen::Vector2d(t_[b] * X(offset_[b], j))
                                         : Eigen::Vector2d(X.block<2, 1>(offset_[b], j));
      if (slip_[a])
        Y(offset_[a], j) = t_[a].dot(p);
      else
        Y.block<2, 1>(offset_[a], j) = p;
    }
  }
  return Y;
}

long LinearContactModel::inner_solves() const { return reduced_mf_ ? reduced_mf_->solves.load() : 0L; }
long LinearContactModel::inner_iterations() const { return reduced_mf_ ? reduced_mf_->iterations.load() : 0L; }

double linear_model_bytes(LinearSolver solver, int r, int grid_elements, int Lc) {
  const double p = 4.0, d = 1.5 * p * std::min(10 * Lc, 2 * Lc + 2);  // the largest Krylov basis
  const double basis = 8.0 * r * d, projection = 3 * 8.0 * d * d;     // V; H and its copies
  // FFT operators (A, A0, C^{-1}, the normal one): zero-padded grid of ~4 N values, a few real and
  // complex arrays each (kernel spectra 4 per tangential operator).
  const double fft = 4 * 12 * 16.0 * 4.0 * grid_elements;
  if (!uses_matrix_free(solver, r)) return 8.0 * r * r + 2 * basis + projection + fft;
  return (lean_krylov_basis(r, int(d / 1.5)) ? basis : 2 * basis) + projection + fft + 64.0 * r;
}

bool uses_matrix_free(LinearSolver solver, int reduced_unknowns) {
  if (solver == LinearSolver::automatic) return reduced_unknowns > kDenseReducedUnknowns;
  return solver == LinearSolver::matrix_free;
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Markov parameters h_j = Lh' S_j (3 x p), S_{j+1} = H S_j (S_0 given), until |h_j| < 1e-15 max
// |h| for a whole contact length (`quiet_steps`); false if that does not happen within max_steps.
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

}  // namespace

void LinearContactModel::check_frequency(double f) const {
  if (!std::isfinite(f) || f < 0.0) {
    std::ostringstream msg;
    msg << "frequency " << f << " Hz: must be finite and non-negative";
    throw InputError("frequency", msg.str());
  }
  if (f > nyquist_frequency() * (1 + 1e-12)) {
    std::ostringstream msg;
    msg << "frequency " << f << " Hz is above the grid's Nyquist limit V/(2 dx) = "
        << nyquist_frequency() << " Hz: refine the grid in x (grid.nx) or lower the frequency";
    throw InputError("frequency", msg.str());
  }
}

CreepMatrix LinearContactModel::creep_coefficients_direct(double frequency) const {
  check_frequency(frequency);
  const Dense& d = dense();
  const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * frequency * dt_);
  const Eigen::MatrixXcd M = d.M0.cast<std::complex<double>>() - z * d.M1.cast<std::complex<double>>();
  const Eigen::MatrixXcd Q = M.partialPivLu().solve(W_.cast<std::complex<double>>());
  std::vector<CreepMatrix> f = {-(L_.transpose().cast<std::complex<double>>() * Q)};
  apply_sampling(f, {frequency});
  return f[0];
}

void LinearContactModel::apply_sampling(std::vector<CreepMatrix>& f, const std::vector<double>& frequencies) const {
  // Every route above solves the recursion M0 Q_k = M1 Q_{k-1} + W xi_k with xi_k the creepage of
  // step k. CONTACT takes xi_k = xi(t_k); midstep takes xi_k = xi(t_k - dt/2), where the
  // displacement difference (A p_k - A0 p_{k-1})/dt of paper Eq. 2 is centred. For xi(t) = xi^
  // e^{i w t}: xi_k = (xi^ e^{-i w dt/2}) e^{i w t_k}, the same recursion with the input amplitude
  // xi^ e^{-i w dt/2}, so F^ = -f_contact xi^ e^{-i w dt/2}, i.e. f_midstep = f_contact e^{-i w dt/2}
  // (w dt/2 = pi f dx/V: nss::half_step_phase_correction). The outputs F_k stay at t_k. Checked:
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

LoadVector LinearContactModel::normal_load_coefficients_direct(double frequency) const {
  check_frequency(frequency);
  if (!has_normal_load_input()) return LoadVector::Zero();
  const Dense& d = dense();
  // (G2): M(z) Q = (A - z A0) bN / dt = wN0 - z wN1,  g = dx dy U' bN + L' Q
  const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * frequency * dt_);
  const Eigen::MatrixXcd M = d.M0.cast<std::complex<double>>() - z * d.M1.cast<std::complex<double>>();
  const Eigen::VectorXcd rhs = wN0_.cast<std::complex<double>>() - z * wN1_.cast<std::complex<double>>();
  const Eigen::VectorXcd Q = M.partialPivLu().solve(rhs);
  return dN_.cast<std::complex<double>>() + L_.transpose().cast<std::complex<double>>() * Q;
}

void LinearContactModel::reduce() const {
  if (hessenberg_) return;
  const Dense& d = dense();
  // (M0 - z M1)^{-1} = (I - z N)^{-1} M0^{-1},  N = M0^{-1} M1 = Q H Q' (real Hessenberg form)
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu0(d.M0);
  const Eigen::MatrixXd N = lu0.solve(d.M1);
  const Eigen::HessenbergDecomposition<Eigen::MatrixXd> hd(N);
  H_ = hd.matrixH();
  const Eigen::MatrixXd Q = hd.matrixQ();
  Eigen::MatrixXd inputs(W_.rows(), 5);  // the creepages, then wN0 and wN1 of (G2)
  inputs << W_, wN0_, wN1_;
  Rhat_ = Q.transpose() * lu0.solve(inputs);
  Lhat_ = Q.transpose() * L_;
  hessenberg_ = true;
}

namespace {

// Solve (I - z H) X = R for upper Hessenberg H: Gaussian elimination with row interchanges between
// neighbouring rows (the only candidates for a pivot in a Hessenberg matrix), then back substitution.
Eigen::MatrixXcd solve_shifted_hessenberg(const RowMajorMatrix& H, std::complex<double> z, const Eigen::MatrixXd& R) {
  using cd = std::complex<double>;
  const int n = static_cast<int>(H.rows());
  Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> T = (-z) * H.cast<cd>();
  T.diagonal().array() += 1.0;
  Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> X = R.cast<cd>();
  for (int k = 0; k + 1 < n; ++k) {
    if (std::abs(T(k + 1, k)) > std::abs(T(k, k))) {
      T.row(k).tail(n - k).swap(T.row(k + 1).tail(n - k));
      X.row(k).swap(X.row(k + 1));
    }
    const cd mult = T(k + 1, k) / T(k, k);
    if (mult != cd(0.0)) {
      T.row(k + 1).tail(n - k - 1) -= mult * T.row(k).tail(n - k - 1);
      X.row(k + 1) -= mult * X.row(k);
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    if (k + 1 < n) X.row(k) -= T.row(k).tail(n - k - 1) * X.bottomRows(n - k - 1);
    X.row(k) /= T(k, k);
  }
  return X;
}

}  // namespace

LinearContactModel::StartBlock LinearContactModel::start_block() const {
  // X = K0^{-1} [-Pi' W, s y], Z = K0 X; y = K0^{-1}(K1 x0 + rN1), x0 = K0^{-1} rN0 (G3).
  const Reduced& red = reduced();
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

LinearContactModel::MarkovModel LinearContactModel::markov_model(const std::vector<Eigen::MatrixXd>& h,
                                                                 const StartBlock& start) const {
  MarkovModel model;
  model.load.assign(1, start.g0);
  for (const auto& hj : h) {
    model.creep.push_back(hj.leftCols(3));
    if (block_ == 4) model.load.push_back(hj.col(3) / start.load_scale);
  }
  return model;
}

std::optional<LinearContactModel::MarkovModel> LinearContactModel::exact_markov(int max_contact_lengths,
                                                                                SweepInfo& info) const {
  // h_j = L' X_j, X_0 = K0^{-1}(-Pi' W), X_{j+1} = K0^{-1} K1 X_j (the same h_j as
  // L' (M0^{-1} M1)^j M0^{-1} W in the paper's form), until |h_j| < 1e-15 max |h| for a whole
  // contact length; the normal-load column started from y (G3).
  const Reduced& red = reduced();
  const StartBlock start = start_block();
  std::vector<Eigen::MatrixXd> h;
  const bool ok = markov_sequence(
      Lr_, start.X,
      [&](const Eigen::MatrixXd& X) {
        if (!red.matrix_free) return Eigen::MatrixXd(red.solve(red.apply_K1(X)));
        const Eigen::MatrixXd guess = rolled(X);  // N X is nearly X rolled on by one element
        return red.solve(red.apply_K1(X), &guess);
      },
      steps_per_contact_length_, max_contact_lengths * steps_per_contact_length_, h);
  if (!ok) return std::nullopt;
  info.method = SweepInfo::Method::markov;
  info.block_steps = static_cast<int>(h.size());
  return markov_model(h, start);
}

namespace {

// Orthonormalise the block X (K0 X = Z) in the K0 inner product: X' Z = R' R (Cholesky), X <- X R^{-1},
// Z <- Z R^{-1}. Returns false when the block has (numerically) lost rank (smallest eigenvalue of
// X' Z below 1e-24 `scale`): a breakdown of the block process.
bool normalise_in_K0(Eigen::MatrixXd& X, Eigen::MatrixXd& Z, double scale, Eigen::MatrixXd& R) {
  Eigen::MatrixXd G = X.transpose() * Z;
  G = 0.5 * (G + G.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(G, Eigen::EigenvaluesOnly);
  if (!(es.eigenvalues()(0) > 1e-24 * scale)) return false;
  const Eigen::LLT<Eigen::MatrixXd> g(G);
  if (g.info() != Eigen::Success) return false;
  R = g.matrixU();
  X = R.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(X);
  Z = R.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(Z);
  return true;
}

// The block Arnoldi process on N = K0^{-1} K1 in the K0 inner product (step 2 at the top of the
// file): the basis V (r x d, V' K0 V = I) grows by blocks of p columns, Y = K0 V alongside, and H
// holds the Gram-Schmidt coefficients (the projection V' K1 V, block upper Hessenberg with upper
// triangular subdiagonal blocks R). The caller forms the new block X = N V_{k-1} (K1 products and
// K0 solves); this class only orthonormalises, stores and projects.
class BlockArnoldi {
 public:
  using Product = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;
  /// With `k0` (K0 X for a block X), Y = K0 V is not stored: the Gram-Schmidt coefficients are
  /// V' (K0 X) and K0 X is recomputed after each pass (memory r d instead of 2 r d).
  BlockArnoldi(int rows, int block, int capacity, Product k0 = nullptr)
      : r_(rows), p_(block), cap_(capacity), k0_(std::move(k0)), V_(rows, capacity),
        Y_(rows, k0_ ? 0 : capacity), H_(Eigen::MatrixXd::Zero(capacity, capacity)) {}

  /// The first block from X0 = K0^{-1} B (Z0 = B): X0 = V_0 R0. False on a breakdown.
  bool start(Eigen::MatrixXd X, Eigen::MatrixXd Z) {
    const Eigen::MatrixXd G0 = X.transpose() * Z;
    if (!normalise_in_K0(X, Z, G0.diagonal().maxCoeff(), R0_)) return false;
    V_.leftCols(p_) = X;
    if (!k0_) Y_.leftCols(p_) = Z;
    d_ = p_;
    return true;
  }

  /// The newest block V_{k-1} of the basis (k - 1 steps done).
  Eigen::Ref<const Eigen::MatrixXd> last_block() const { return V_.middleCols(d_ - p_, p_); }

  /// Block step k: orthogonalise X = N V_{k-1} (Z = K0 X = K1 V_{k-1}) against the basis, normalise
  /// it and append it. The column block k-1 of H is complete either way, so the square model of
  /// the first k blocks (model_dimension()) exists; false on a breakdown (nothing appended).
  bool extend(Eigen::MatrixXd X, Eigen::MatrixXd Z) {
    const Eigen::VectorXd norm0 = (X.transpose() * Z).diagonal();  // squared K0-norms
    const double scale = norm0.maxCoeff();
    const int d = d_;
    grow(d + p_);
    const Eigen::MatrixXd C = gram_schmidt(X, Z, norm0);
    Eigen::MatrixXd R;
    const bool ok = normalise_in_K0(X, Z, scale, R);
    H_.block(0, d - p_, d, p_) = C;
    if (ok) {
      H_.block(d, d - p_, p_, p_) = R;
      V_.middleCols(d, p_) = X;
      if (!k0_) Y_.middleCols(d, p_) = Z;
      d_ += p_;
    }
    model_d_ = d;
    return ok;
  }

  /// Dimension of the square reduced model after the last step (p k after k steps).
  int model_dimension() const { return model_d_; }

  /// Markov parameters of the reduced model of the first dk basis vectors: h_j = (V' L)' H^j e_1 R0
  /// (exact for j < dk / p), until they decay (markov_sequence); false if they do not.
  bool markov_parameters(int dk, const Eigen::MatrixXd& L, int quiet_steps, int max_steps,
                         std::vector<Eigen::MatrixXd>& h) const {
    const int p = p_;
    const Eigen::MatrixXd Hk = H_.topLeftCorner(dk, dk);
    Eigen::MatrixXd S0 = Eigen::MatrixXd::Zero(dk, p);
    S0.topRows(p) = R0_;
    const Eigen::MatrixXd Lh = V_.leftCols(dk).transpose() * L;
    // S -> H S with H block upper Hessenberg whose subdiagonal blocks R are upper triangular:
    // column c has non-zeros in rows <= c + p only, so columns q..q+3 in rows < q + p + 4.
    return markov_sequence(
        Lh, S0,
        [&](const Eigen::MatrixXd& S) {
          Eigen::MatrixXd next = Eigen::MatrixXd::Zero(dk, p);
          linalg::subtract_product(Hk, dk, dk, -S, next, [p](int q) { return q + p + 4; });
          return next;
        },
        quiet_steps, max_steps, h);
  }

 private:
  // Block classical Gram-Schmidt in the K0 inner product against the d_ basis vectors, repeated
  // once when a column lost more than half of its squared norm ("twice is enough", Kahan-Parlett):
  // one pass leaves the new column orthogonal to O(eps / ratio); away from cancellation one pass
  // is as good as two. The rolling step mostly transports the traction into new directions
  // (ratios ~0.9-1), with strong cancellation about once per contact length. Returns the
  // coefficients C = V' K0 X (the new column block of H).
  Eigen::MatrixXd gram_schmidt(Eigen::MatrixXd& X, Eigen::MatrixXd& Z, const Eigen::VectorXd& norm0) const {
    const int d = d_;
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(d, p_);
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::MatrixXd Ci = k0_ ? linalg::transposed_product(V_, d, Z)   // V' K0 X
                                     : linalg::transposed_product(Y_, d, X);  // Y' X
      linalg::subtract_product(V_, r_, d, Ci, X);                             // X -= V Ci
      if (k0_)
        Z = k0_(X);
      else
        linalg::subtract_product(Y_, r_, d, Ci, Z);  // Z -= Y Ci
      C += Ci;
      const Eigen::VectorXd norm1 = (X.transpose() * Z).diagonal();
      if (pass == 0 && (norm1.array() > 0.5 * norm0.array()).all()) break;
    }
    return C;
  }

  void grow(int need) {
    if (need <= cap_) return;
    const int c = std::max(need, p_ * ((cap_ / p_) * 3 / 2 + 1));
    V_.conservativeResize(Eigen::NoChange, c);
    if (!k0_) Y_.conservativeResize(Eigen::NoChange, c);
    H_.conservativeResize(c, c);
    H_.rightCols(c - cap_).setZero();
    H_.bottomRows(c - cap_).setZero();
    cap_ = c;
  }

  int r_, p_, cap_;
  Product k0_;
  int d_ = 0;        // basis vectors so far
  int model_d_ = 0;  // dimension of the square model after the last step
  Eigen::MatrixXd V_, Y_, H_, R0_;
};

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

}  // namespace

std::optional<LinearContactModel::MarkovModel> LinearContactModel::krylov_markov(int max_contact_lengths,
                                                                                 SweepInfo& info) const {
  info = SweepInfo{};
  auto t0 = std::chrono::steady_clock::now();
  const Reduced& red = reduced();
  info.factor_seconds = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const int Lc = steps_per_contact_length_;
  const int max_markov = max_contact_lengths * Lc;
  const int p = block_;  // block size: 3 creepages (+ 1 normal load, G3)
  // Block steps: at most 10 contact lengths, and never more than the dimension allows.
  const int max_blocks = std::min(10 * Lc, r_ / p - 1);
  const int stride = std::max(4, (Lc + 2) / 3);  // block steps between checks
  const double tolerance = 1e-10;

  const StartBlock start = start_block();
  const int capacity = p * std::min(max_blocks + 2, 2 * Lc + 2);
  BlockArnoldi::Product k0;  // matrix-free: K0 products instead of Y = K0 V where Y does not fit
  if (red.matrix_free && lean_krylov_basis(r_, capacity)) k0 = [&red](const Eigen::MatrixXd& X) { return red.apply_K0(X); };
  BlockArnoldi arnoldi(r_, p, capacity, k0);
  // Matrix-free: Z = K0 X for the computed X (the PCG solution, not the exact one).
  if (!arnoldi.start(start.X, red.matrix_free ? red.apply_K0(start.X) : start.Z)) return std::nullopt;
  const long solves0 = red.solves, iterations0 = red.iterations;
  info.matrix_free = red.matrix_free;

  std::vector<Eigen::MatrixXd> h_prev, h_cur;  // Markov parameters of the last two checked models
  bool have_prev = false;
  int next_check = Lc;
  for (int k = 1; k <= max_blocks; ++k) {
    // Block step k: X = N V_{k-1} = K0^{-1} K1 V_{k-1}, with Z = K0 X = K1 V_{k-1}.
    Eigen::MatrixXd Z = red.apply_K1(arnoldi.last_block());
    Eigen::MatrixXd X;
    if (red.matrix_free) {
      const Eigen::MatrixXd guess = rolled(arnoldi.last_block());
      X = red.solve(Z, &guess);
      Z = red.apply_K0(X);
    } else {
      X = red.solve(Z);
    }
    const bool ok = arnoldi.extend(std::move(X), std::move(Z));
    info.inner_solves = red.solves - solves0;
    info.inner_iterations = red.iterations - iterations0;
    if (k < next_check && ok && k < max_blocks) continue;
    // Check: after k steps the square model uses blocks 0..k-1 (d = p k); its H is complete.
    info.krylov_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    ++info.checks;
    const int d = arnoldi.model_dimension();
    if (!arnoldi.markov_parameters(d, Lr_, Lc, max_markov, h_cur)) {
      have_prev = false;  // not decayed (yet): no usable model at this size
    } else if (have_prev) {
      info.error_estimate = max_relative_difference(h_prev, h_cur);
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
    next_check = k + stride;
    info.check_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
  }
  return std::nullopt;
}

namespace {

// sum_j h_j z^j by Horner at z = e^{-i w dt} for each frequency.
template <class Out, class Term>
std::vector<Out> horner(const std::vector<Term>& h, double dt, const std::vector<double>& frequencies) {
  std::vector<Out> out;
  out.reserve(frequencies.size());
  for (double f : frequencies) {
    const std::complex<double> z = std::polar(1.0, -2.0 * M_PI * f * dt);
    Out acc = Out::Zero();
    for (auto it = h.rbegin(); it != h.rend(); ++it) acc = acc * z + it->template cast<std::complex<double>>();
    out.push_back(acc);
  }
  return out;
}

}  // namespace

std::vector<CreepMatrix> LinearContactModel::creep_from_markov(const std::vector<Eigen::Matrix3d>& h,
                                                               const std::vector<double>& frequencies) const {
  std::vector<CreepMatrix> f = horner<CreepMatrix>(h, dt_, frequencies);  // f = -sum_j h_j z^j
  for (auto& fk : f) fk = -fk;
  apply_sampling(f, frequencies);
  return f;
}

bool LinearContactModel::build_markov(int max_contact_lengths) const {
  if (!markov_.empty()) return true;
  if (markov_failed_) return false;
  SweepInfo info;
  std::optional<MarkovModel> model = krylov_markov(max_contact_lengths, info);
  if (!model) {  // the exact recursion, and failing that the Hessenberg form
    info.krylov_failed = true;
    model = exact_markov(max_contact_lengths, info);
    if (!model) {
      info.method = SweepInfo::Method::hessenberg;
      markov_failed_ = true;
    }
  }
  info_ = info;
  if (!model) return false;
  markov_ = std::move(model->creep);
  load_markov_ = std::move(model->load);
  return true;
}

std::vector<CreepMatrix> LinearContactModel::creep_coefficients(const std::vector<double>& frequencies,
                                                                int max_contact_lengths) const {
  for (double f : frequencies) check_frequency(f);
  if (falling_) info_.method = SweepInfo::Method::hessenberg;  // the paper form only (header)
  if (falling_ || !build_markov(max_contact_lengths)) return creep_coefficients_hessenberg(frequencies);
  return creep_from_markov(markov_, frequencies);
}

std::vector<LoadVector> LinearContactModel::normal_load_coefficients(const std::vector<double>& frequencies,
                                                                     int max_contact_lengths) const {
  for (double f : frequencies) check_frequency(f);
  if (!has_normal_load_input()) return std::vector<LoadVector>(frequencies.size(), LoadVector::Zero());
  if (!falling_ && build_markov(max_contact_lengths))
    return horner<LoadVector>(load_markov_, dt_, frequencies);  // (G3)
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
  const std::optional<MarkovModel> model = exact_markov(max_contact_lengths, info);
  if (!model) return creep_coefficients_hessenberg(frequencies);
  return creep_from_markov(model->creep, frequencies);
}

std::vector<CreepMatrix> LinearContactModel::creep_coefficients_hessenberg(
    const std::vector<double>& frequencies) const {
  for (double f : frequencies) check_frequency(f);
  std::vector<CreepMatrix> f;
  hessenberg_sweep(frequencies, &f, nullptr);
  apply_sampling(f, frequencies);
  return f;
}

void LinearContactModel::hessenberg_sweep(const std::vector<double>& frequencies, std::vector<CreepMatrix>* f,
                                          std::vector<LoadVector>* g) const {
  // (M0 - z M1)^{-1} = (I - z N)^{-1} M0^{-1}: f = -L' X(:, 0:3), g = dN + L' (X(:, 3) - z X(:, 4))
  // with (I - z H) X = Q' M0^{-1} [W, wN0, wN1] (G2).
  for (double fr : frequencies) {
    CreepMatrix fk;
    LoadVector gk;
    hessenberg_at(std::polar(1.0, -2.0 * M_PI * fr * dt_), f ? &fk : nullptr, g ? &gk : nullptr);
    if (f) f->push_back(fk);
    if (g) g->push_back(gk);
  }
}

void LinearContactModel::hessenberg_at(std::complex<double> z, CreepMatrix* f, LoadVector* g) const {
  // Any complex z (the shifted Hessenberg solve does not need |z| = 1).
  reduce();
  const int first = f ? 0 : 3, count = (f ? 3 : 0) + (g ? 2 : 0);
  const Eigen::MatrixXcd X = solve_shifted_hessenberg(H_, z, Rhat_.middleCols(first, count));
  const Eigen::MatrixXcd LX = Lhat_.transpose().cast<std::complex<double>>() * X;
  if (f) *f = -LX.leftCols(3);
  if (g) *g = dN_.cast<std::complex<double>>() + LX.col(count - 2) - z * LX.col(count - 1);
}

namespace {

double max_abs(const Eigen::Matrix3d& m) { return m.cwiseAbs().maxCoeff(); }
double max_abs(const Eigen::Vector3d& m) { return m.cwiseAbs().maxCoeff(); }

// sum_j h_j z^j by Horner at one complex z, if the series has converged to round-off there: the
// last weighted term |h_J| |z|^J at most 1e-12 of the largest (the h_j are kept until they decay
// to ~1e-15 of their largest, so for |z| > 1 this bounds the amplified truncation).
template <class Out, class Term>
std::optional<Out> horner_if_converged(const std::vector<Term>& h, std::complex<double> z) {
  if (h.empty()) return std::nullopt;
  double w = 1.0, big = 0.0, last = 0.0;
  for (const auto& x : h) {
    last = max_abs(x) * w;
    big = std::max(big, last);
    w *= std::abs(z);
  }
  if (!(last <= 1e-12 * big)) return std::nullopt;
  Out acc = Out::Zero();
  for (auto it = h.rbegin(); it != h.rend(); ++it) acc = acc * z + it->template cast<std::complex<double>>();
  return acc;
}

}  // namespace

CreepMatrix LinearContactModel::creep_coefficients_laplace(std::complex<double> s) const {
  const std::complex<double> z = std::exp(-s * dt_);
  std::optional<CreepMatrix> f;
  if (!falling_ && build_markov(60)) f = horner_if_converged<CreepMatrix>(markov_, z);
  if (f) {
    *f = -*f;  // f = -sum_j h_j z^j
  } else {
    f = CreepMatrix();
    hessenberg_at(z, &*f, nullptr);
  }
  return *f * creepage_sampling_factor(s * dt_, sampling_);
}

LoadVector LinearContactModel::normal_load_coefficients_laplace(std::complex<double> s) const {
  if (!has_normal_load_input()) return LoadVector::Zero();
  const std::complex<double> z = std::exp(-s * dt_);
  std::optional<LoadVector> g;
  if (!falling_ && build_markov(60)) g = horner_if_converged<LoadVector>(load_markov_, z);  // (G3)
  if (!g) {
    g = LoadVector();
    hessenberg_at(z, nullptr, &*g);
  }
  return *g;
}

double LinearContactModel::spectral_radius() const {
  // The eigenvalues of M0^{-1} M1 = Q H Q' are those of H (real Schur of the Hessenberg form).
  if (spectral_radius_ < 0.0) {
    reduce();
    const Eigen::EigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(H_), false);
    spectral_radius_ = es.eigenvalues().cwiseAbs().maxCoeff();
  }
  return spectral_radius_;
}

Eigen::MatrixXd LinearContactModel::step_matrix_cholesky_factor() const {
  // K0 holds the factor in its lower triangle; its strict upper triangle was never written.
  return reduced_factor().K0.triangularView<Eigen::Lower>();
}

double LinearContactModel::step_matrix_rcond() const {
  return reduced_factor().llt->rcond();
}

Eigen::VectorXd LinearContactModel::step_matrix_slip_diagonal() const {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(r_);
  for (size_t a = 0; a < el_.size(); ++a)
    if (slip_[a]) d(offset_[a]) = c_[a];
  return d;
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response(const std::vector<Eigen::Vector3d>& xi) const {
  return time_response(xi, std::vector<double>(xi.size(), 0.0));
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response(const std::vector<Eigen::Vector3d>& xi,
                                                               const std::vector<double>& dN) const {
  // K0 pi_k = K1 pi_{k-1} - Pi' W xi_k + rN0 N~_k + rN1 N~_{k-1} (the reduced form of M0 Q_k =
  // M1 Q_{k-1} + W xi_k + (A bN N~_k - A0 bN N~_{k-1})/dt, G2), F_k = dx dy U' (Pi pi_k + bN N~_k).
  if (dN.size() != xi.size())
    throw InputError("excitation", "time_response: the normal-load and creepage histories differ in length");
  if (falling_) return time_response_dense(xi, dN);
  const Reduced& red = reduced();
  std::vector<Eigen::Vector3d> F;
  F.reserve(xi.size());
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(r_, 1);
  double previous = 0.0;
  for (size_t k = 0; k < xi.size(); ++k) {
    Eigen::MatrixXd rhs = red.apply_K1(p) + Wr_ * xi[k];
    if (block_ == 4) rhs += rN0_ * dN[k] + rN1_ * previous;
    if (red.matrix_free) {
      const Eigen::MatrixXd guess = rolled(p);
      p = red.solve(rhs, &guess);
    } else {
      p = red.solve(rhs);
    }
    F.push_back(Lr_.transpose() * p + dN_ * dN[k]);
    previous = dN[k];
  }
  return F;
}

std::vector<Eigen::Vector3d> LinearContactModel::time_response_dense(const std::vector<Eigen::Vector3d>& xi,
                                                                     const std::vector<double>& dN) const {
  // The paper form in time (G2 with z the one-step delay): M0 Q_k = M1 Q_{k-1} + W xi_k +
  // wN0 N~_k - wN1 N~_{k-1},  F_k = L' Q_k + dN N~_k; one LU factorisation of M0.
  const Dense& d = dense();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(d.M0);
  std::vector<Eigen::Vector3d> F;
  F.reserve(xi.size());
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(W_.rows());
  double previous = 0.0;
  for (size_t k = 0; k < xi.size(); ++k) {
    Eigen::VectorXd rhs = d.M1 * Q + W_ * xi[k];
    if (block_ == 4) rhs += wN0_ * dN[k] - wN1_ * previous;
    Q = lu.solve(rhs);
    F.push_back(L_.transpose() * Q + dN_ * dN[k]);
    previous = dN[k];
  }
  return F;
}

}  // namespace rollnoise::nss
