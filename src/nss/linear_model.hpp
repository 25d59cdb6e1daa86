// The linear non-steady-state (NSS) tangential contact model (Baeza, Bruni, Giner-Navarro, Liu;
// paper Eqs. 6-30; docs/conventions.md Sec. 3).
//
// Around a steady solution (p_bar, s_bar) at the mean creepage, with the adhesion and slip areas
// frozen, small creepage variations xi~ e^{i w t} give
//
//   S~ = W~ + (A - z A0) P~ / dt,   z = e^{-i w dt},  dt = dx / V                (paper Eq. 11)
//
// with W~ = V (xi~x U1 + xi~y U2 + phi~ Usp), Usp_e = (-y_e, x_e + spin_offset dx) (Eq. 20-21).
// Adhesion elements: S~_e = 0, unknown P~_e. Slip elements: P~_e = K_e S~_e with the derivative of
// -mu pn s/|s| (paper Eq. 9), K_e = -(mu pn/|s_bar|) t t^T, t = (s2, -s1)/|s_bar|.
//
// Unknowns and scaling. The paper's unknowns are P~ (adhesion) and S~ (slip). K_e grows like
// 1/|s_bar|, which blows up for slip elements next to the adhesion area. We scale the slip unknown to
// a traction, q_e = (mu pn_e/|s_bar_e|) S~_e, so that P~_e = B_e q_e with B_e = -t t^T (bounded) and
// S~_e = c_e q_e with c_e = |s_bar_e|/(mu pn_e). This is a column scaling of the paper's system (the
// same solution) that keeps every column of the order of the elastic compliance; as |s_bar| -> 0 the
// element tends continuously to adhesion across t. c_e is floored at 1e-12 times the self-compliance
// A_ee/dt so that the pencil stays regular when |s_bar| underflows.
//
// With Q = (p~ for adhesion, q for slip), P~ = B Q, S~ = C Q:
//   M(z) Q = W~,  M(z) = M0 - z M1,  M0 = C - A B/dt,  M1 = -A0 B/dt.
// (The paper prints "+" in Eqs. 14, 22, 24, which with its own Eqs. 9 and 11 gives -f; this sign
// is the consistent one, checked against CONTACT: docs/conventions.md Sec. 3.)
// Outputs F~x = dx dy U1' P~, F~y = dx dy U2' P~, M~z = dx dy Usp0' P~ with Usp0_e = (-y_e, x_e): the
// spin offset belongs to the input only. Creep coefficients: F~ = -f xi~ (Eqs. 28-30), rows Fx, Fy,
// Mz, columns xi_x, xi_y, phi.
//
// The reduced, symmetric form used by the fast paths (markov_sweep.cpp and reduced_form.cpp explain it in full). Only
// P~ = B Q propagates, and P~_e lies along t_e in a slip element, so the traction amplitudes
// pi (2 per adhesion element, pi_e = -t_e' q_e per slip element; P~ = Pi pi) are the state. The
// t_e-component of the slip equations and both adhesion equations give
//   (K0 - z K1) pi = -Pi' W~,  K0 = D + Pi' A Pi/dt (symmetric positive definite),
//   K1 = Pi' A0 Pi/dt (applied by FFT),  D = diag(0 adhesion, c_e slip),  F~ = dx dy U' Pi pi,
// of dimension r = 2 (adhesion elements) + (slip elements) instead of n = 2 (contact elements).
//
// Normal-load input (docs/nss_normal_load.md, Eqs. G1-G6). A normal-load variation N~ changes the
// pressure on the frozen contact area by pn~ = (dpn/dN) N~ (contact::normal_load_sensitivity: the
// normal problem's own derivative, not a Hertz formula). Adhesion elements are unchanged; in a
// slip element the traction -mu pn s/|s| gains -mu pn~ s_bar/|s_bar|, so P~ = B Q + bN N~ with
//   bN_e = -mu (dpn_e/dN) s_bar_e/|s_bar_e|  (slip),  0 (adhesion),                        (G1)
// and the pencil gets one more input, with a one-step delay through A0 (the traction of the
// previous step rolls on):
//   M(z) Q = W xi~ + (A - z A0) bN N~ / dt,  F~ = L' Q + dx dy U' bN N~ = -f xi~ + g N~.    (G2)
// g = (g_x, g_y, g_z) (-, -, m) for (Fx, Fy, Mz): at omega -> 0 and full sliding without spin
// g = F_bar / N_bar; in full adhesion g = 0. Reduced form: (K0 - z K1) pi = -Pi' W xi~ + (rN0 +
// z rN1) N~, rN0 = -Pi' A bN/dt, rN1 = Pi' A0 bN/dt. Its Markov parameters need ONE more vector
// in the Krylov block: with x0 = K0^{-1} rN0 and y = K0^{-1}(K1 x0 + rN1) = N x0 + K0^{-1} rN1,
//   g(z) = dx dy U' bN + L' x0 + z sum_j z^j L' N^j y                                       (G3)
// so the block of 3 creepage vectors becomes a block of 4 (one more column per Cholesky pass of
// the factor, which is streamed once for all of them).
//
// Falling friction (contact/friction_law.hpp, docs/falling_friction.md Sec. 2). With mu = mu(|s|) the slip
// element law p = -mu(|s|) pn s/|s| linearises to (sign convention: P~ = K_e S~, K_e negative
// semi-definite for constant friction)
//   K_e = -(mu pn/|s_bar|) t t' - mu'(|s_bar|) pn s^ s^',   s^ = s_bar/|s_bar|,  mu = mu(|s_bar|),
// Eq. 9 plus a radial term (a positive, i.e. negative-stiffness, entry along s^ for mu' < 0). In
// the scaled unknowns S~_e = c_e q_e (c_e = |s_bar|/(mu pn), mu at the mean slip speed):
//   P~_e = B_e q_e,  B_e = -t t' - kappa_e s^ s^',  kappa_e = mu'(|s_bar|) |s_bar| / mu(|s_bar|),
// so the slip element carries a second, radial traction amplitude; bN_e uses mu(|s_bar|). The
// paper form (Dense: creep_coefficients_direct, normal_load_coefficients_direct, the Hessenberg
// sweep) takes B_e as it is. The reduced form above does not (its K0 would get the radial unknown
// with the diagonal entry 1/(mu' pn) < 0: symmetric indefinite), so with falling friction every
// route uses the paper form: creep_coefficients / normal_load_coefficients / creep_coefficients_markov
// the Hessenberg sweep, time_response an LU recursion of M0, and the K0 diagnostics throw.
//
// Creepage sampling (LinearModelInput::sampling, contact/creepage_history.hpp). Everything above is
// the recursion with the creepage of step k taken at t_k (CONTACT's convention). With midstep the
// creepage is taken at t_k - dt/2: for xi~(t) = xi^ e^{i w t} the recursion sees xi~_k = xi^
// e^{-i w dt/2} e^{i w t_k}, so f_midstep(w) = f_contact(w) e^{-i w dt/2} exactly, on every f route
// (the factor is applied in one place, transfer.cpp). With average the creepage of step k is its
// mean over [t_{k-1}, t_k], xi~_k = xi^ e^{-i w dt/2} sinc(w dt/2) e^{i w t_k}, so f_average(w) =
// f_contact(w) e^{-i w dt/2} sinc(w dt/2). g is the same in every sampling (the load is taken at t_k
// with the traction it bounds). time_response() takes the creepages of the steps as the sampling
// defines them (contact::CreepageHistory::step_variation): the callers sample them.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "contact/creepage_history.hpp"
#include "contact/friction_law.hpp"
#include "contact/halfspace_operator.hpp"
#include "contact/influence.hpp"
#include "contact/patch.hpp"
#include "contact/tangential_solver.hpp"
#include "nss/step_solver.hpp"

namespace rollnoise::contact {
class ElementOperator;
}  // namespace rollnoise::contact

namespace rollnoise::nss {

using CreepMatrix = Eigen::Matrix3cd;
/// Normal-load coefficients g = (g_x, g_y, g_z) (-, -, m): F~ = -f xi~ + g N~ (docs/nss_normal_load.md).
using LoadVector = Eigen::Vector3cd;

/// How K0 is solved (solver.linear_model; reduced_form.cpp, "Matrix-free path"): a dense Cholesky
/// factor, or K0 applied by FFT and solved by preconditioned CG; automatic: dense up to
/// kDenseReducedUnknowns reduced unknowns.
enum class LinearSolver { automatic, dense, matrix_free };

/// The largest r for which `automatic` takes the dense path (measured, docs/accuracy.md).
constexpr int kDenseReducedUnknowns = 11000;
/// The most threads the linear model uses (LinearModelInput::threads): one per column of a block.
constexpr int kMaxThreads = 4;

struct LinearModelInput {
  // A constructor rather than an aggregate: {mu, speed, spin_offset} stays valid (see
  // contact::SteadyRollingInput).
  LinearModelInput(double mu_ = 0.3, double speed_ = 0.0, double spin_offset_ = 0.0,
                   contact::FallingFriction falling_ = {},
                   LinearSolver solver_ = LinearSolver::automatic,
                   contact::CreepageSampling sampling_ = contact::CreepageSampling::average)
      : mu(mu_), speed(speed_), spin_offset(spin_offset_), falling(falling_), solver(solver_),
        sampling(sampling_) {}
  /// {mu, speed, spin_offset, sampling}: constant friction, the automatic solver.
  LinearModelInput(double mu_, double speed_, double spin_offset_, contact::CreepageSampling sampling_)
      : mu(mu_), speed(speed_), spin_offset(spin_offset_), sampling(sampling_) {}
  double mu = 0.3;           ///< friction coefficient
  double speed = 0.0;        ///< rolling speed V (m/s)
  double spin_offset = 0.0;  ///< as in the steady solution (grid.spin_offset)
  /// Falling friction mu(|s|) = mu [(1 - A) e^{-B|s|} + A] as in the steady solution (constant
  /// by default; see "Falling friction" above).
  contact::FallingFriction falling;
  LinearSolver solver = LinearSolver::automatic;  ///< solver.linear_model
  /// how the creepage of step k is taken (by default its mean over [t_{k-1}, t_k]; midstep: at
  /// t_k - dt/2; contact: at t_k, as CONTACT)
  contact::CreepageSampling sampling = contact::CreepageSampling::average;
  /// Threads of the fast sweep, the recursion and time_response (solver.threads): the columns of
  /// a block (K1 and K0 products, PCG solves) are shared out among them; 0: one per hardware
  /// thread, at most 4 (the block size). The results do not depend on it (step_solver.hpp).
  int threads = 0;
};

/// Whether a model with r reduced unknowns takes the matrix-free path under `solver`.
bool uses_matrix_free(LinearSolver solver, int reduced_unknowns);

/// Estimated peak memory (bytes) of the linear model and its fast sweep on the path taken, for
/// r reduced unknowns, `grid_elements` elements of the potential contact area and Lc steps per
/// contact length: dense, the factor (8 r^2) and the Krylov basis with K0 times it; matrix-free,
/// the basis alone (or with K0 times it where that fits: markov_sweep.cpp) and the FFT work
/// arrays. An upper bound of the measured peak (bench: `rollnoise bench --sweep-cost`).
double linear_model_bytes(LinearSolver solver, int reduced_unknowns, int grid_elements, int steps_per_contact_length);

/// How creep_coefficients() obtained its Markov parameters (for benchmarks and tests).
struct SweepInfo {
  enum class Method { none, krylov, markov, hessenberg };
  Method method = Method::none;
  int block_steps = 0;           ///< block Krylov steps (3 vectors each), or Markov recursion steps
  int reduced_dimension = 0;     ///< dimension of the Krylov reduced model
  int checks = 0;                ///< a-posteriori checks made
  double error_estimate = 0.0;   ///< max over the check grid of |f_k - f_{k-s}| / |f_k| (krylov)
  bool krylov_failed = false;    ///< the Krylov model failed its checks (fell back)
  double factor_seconds = 0.0;   ///< assembling K0 and its Cholesky factorisation
  double krylov_seconds = 0.0;   ///< block steps (or recursion steps), checks excluded
  double check_seconds = 0.0;    ///< Markov parameters of the trial models and their comparison
  bool matrix_free = false;      ///< K0 solved by preconditioned CG (else by its Cholesky factor)
  long inner_solves = 0;         ///< matrix-free: K0 solves (columns) of the sweep
  long inner_iterations = 0;     ///< matrix-free: their PCG iterations in all
};

/// The creepage sampling's factor on f, f_sampling = f_contact * factor, as an analytic function of
/// s dt (s the complex frequency; s = i w on the real axis), so that f(s) at complex s carries the
/// sampling exactly: contact 1, midstep e^{-s dt/2} (the creepage of step k taken at t_k - dt/2;
/// on the real axis e^{-i w dt/2}, see "Creepage sampling" above), average (the step mean of the
/// creepage) (1 - e^{-s dt})/(s dt) (= e^{-i w dt/2} sinc(w dt/2) on the real axis; entire, 1 at
/// s = 0). Used by creep_coefficients_laplace; on the real axis apply_sampling takes the same factor
/// in its polar form (contact::step_sampling_factor).
std::complex<double> creepage_sampling_factor(std::complex<double> s_dt, contact::CreepageSampling sampling);

class LinearContactModel {
 public:
  /// `mean` is the steady solution at the mean creepage on `patch` (same mu, speed, spin offset).
  LinearContactModel(const contact::ContactPatch& patch, const contact::TangentialSolution& mean,
                     const LinearModelInput& in);
  ~LinearContactModel();
  LinearContactModel(LinearContactModel&&) noexcept;
  LinearContactModel& operator=(LinearContactModel&&) noexcept;

  /// Unknowns of the paper's formulation, 2 per contact element.
  int unknowns() const { return 2 * (n_adhesion_ + n_slip_); }
  /// Unknowns of the reduced symmetric formulation: 2 per adhesion element, 1 per slip element.
  int reduced_unknowns() const { return r_; }
  /// Whether K0 is applied by FFT and solved by preconditioned CG (LinearModelInput::solver).
  bool matrix_free() const { return uses_matrix_free(solver_, r_); }
  /// Steps per contact length (the extent of the contact area in x, in elements).
  int steps_per_contact_length() const { return steps_per_contact_length_; }
  /// Threads the model uses (LinearModelInput::threads resolved: 1 to kMaxThreads).
  int threads() const { return threads_; }
  int adhesion_elements() const { return n_adhesion_; }
  int slip_elements() const { return n_slip_; }
  double time_step() const { return dt_; }
  /// When the creepage of step k is taken (f's phase, the instants time_response expects).
  contact::CreepageSampling sampling() const { return sampling_; }
  /// Highest frequency the grid resolves: V / (2 dx) (w dt = pi) (Hz).
  double nyquist_frequency() const { return 0.5 / dt_; }

  /// f(omega) by a fresh complex LU of M(z) (the reference; O(n^3) per frequency, in the paper's
  /// formulation, independent of the reduced one).
  CreepMatrix creep_coefficients_direct(double frequency) const;

  /// f at many frequencies (the default, fast):  f(w) = -sum_j h_j z^j  with the Markov parameters
  /// (impulse response) h_j = L' (M0^{-1} M1)^j M0^{-1} W of the discrete-time system, O(J) per
  /// frequency. The h_j come from a block Krylov reduced model built with 4/3 to 3 contact lengths
  /// of block steps (3 vectors each; exact for j below the number of steps, the rest extrapolated
  /// by the reduced dynamics; f checked a posteriori to 1e-10 relative over [0, Nyquist]: see
  /// markov_sweep.cpp); if that check fails, from the exact recursion
  /// (creep_coefficients_markov); if the h_j have not decayed within `max_contact_lengths`, from
  /// creep_coefficients_hessenberg(). The model is built on the first call and kept.
  /// Throws InputError above the Nyquist limit.
  std::vector<CreepMatrix> creep_coefficients(const std::vector<double>& frequencies,
                                              int max_contact_lengths = 60) const;

  /// f at the complex frequency s (1/s; s = i w on the real axis), with the model's sampling:
  /// f(s) = -sum_j h_j z^j, z = e^{-s dt}, times creepage_sampling_factor(s dt) (the sums of
  /// creep_coefficients continued analytically). Exact: from the Markov parameters when they exist
  /// (constant friction) and their series converges at z to round-off (the last weighted term
  /// |h_J| |z|^J below 1e-12 of the largest), else from the Hessenberg form at the complex z
  /// (falling friction, or s far in the left half plane; builds it on first use, O(n^3)). Poles: the
  /// z with 1/z an eigenvalue of M0^{-1} M1 (spectral_radius()).
  CreepMatrix creep_coefficients_laplace(std::complex<double> s) const;
  /// g at the complex frequency s, the same way (G3 continued; no sampling factor: the load is
  /// taken at t_k in every sampling).
  LoadVector normal_load_coefficients_laplace(std::complex<double> s) const;
  /// Both at one s: the same values; without Markov parameters (falling friction) from ONE shifted
  /// Hessenberg solve with the five input columns instead of one for f and one for g (squeal's
  /// loop takes both at every s).
  std::pair<CreepMatrix, LoadVector> coefficients_laplace(std::complex<double> s) const;
  /// The spectral radius of M0^{-1} M1 (the discrete-time contact's largest pole |z_p|; paper
  /// form, from the Hessenberg form: O(n^3) on the first call, then kept). Below 1 the contact's
  /// recursion M0 Q_k = M1 Q_{k-1} + ... decays (a stable contact); above 1 it grows at the rate
  /// ln(radius)/dt (1/s) by itself, which falling friction can cause (docs/falling_friction.md Sec. 3).
  double spectral_radius() const;

  /// g(omega) at one frequency by a fresh complex LU of the paper's form (the reference).
  LoadVector normal_load_coefficients_direct(double frequency) const;

  /// g at many frequencies from the same Markov parameters as creep_coefficients() (one more
  /// input column of the same pencil; built together with f on the first call of either).
  std::vector<LoadVector> normal_load_coefficients(const std::vector<double>& frequencies,
                                                   int max_contact_lengths = 60) const;

  /// f at many frequencies from the exact Markov parameters: the recursion
  /// K0 X_{j+1} = K1 X_j (one Cholesky factorisation, K1 by FFT) until the h_j have decayed to
  /// round-off (|h_j| falls by ~1e-14 in 16 contact lengths on the paper's grid), then O(J) per
  /// frequency. Falls back to creep_coefficients_hessenberg() if they do not decay within
  /// `max_contact_lengths`. Slower than creep_coefficients() on fine grids (one sequential solve
  /// per step); kept as its fallback and as an independent check.
  std::vector<CreepMatrix> creep_coefficients_markov(const std::vector<double>& frequencies,
                                                     int max_contact_lengths = 60) const;

  /// f at many frequencies by the reduced pencil: one Hessenberg reduction of M0^{-1} M1 (real),
  /// then an O(n^2) Hessenberg solve per frequency. Exact (no truncation), slow (O(n^3) set-up).
  std::vector<CreepMatrix> creep_coefficients_hessenberg(const std::vector<double>& frequencies) const;

  /// The Markov parameters h_j behind creep_coefficients() (built on the first call of either,
  /// once; empty when the sweep uses the Hessenberg form: falling friction, or both Markov routes
  /// failed): exact ones from the recursion, or those of the Krylov reduced model (see
  /// sweep_info()). They are those of the creepage at t_k: f = -e^{-i w dt/2} sum_j h_j z^j with
  /// midstep sampling, -e^{-i w dt/2} sinc(w dt/2) sum_j h_j z^j with average
  /// (contact::step_sampling_factor).
  const std::vector<Eigen::Matrix3d>& markov_parameters() const { return series().creep; }
  /// The Markov parameters of g, g(z) = sum_j gm_j z^j (G3), built with markov_parameters().
  const std::vector<Eigen::Vector3d>& load_markov_parameters() const { return series().load; }
  /// dx dy U' bN of (G2): the instantaneous part of g (the frozen-slip-direction response, -, -, m).
  const Eigen::Vector3d& load_direct_term() const { return dN_; }
  /// Whether falling friction enters the model (some slip element has mu' != 0); then every sweep
  /// uses the exact paper form (Hessenberg), see "Falling friction" above.
  bool falling_friction() const { return falling_; }
  /// Whether there is a normal-load input at all (slip elements exist); without it g = 0.
  bool has_normal_load_input() const { return block_ == 4; }
  /// How the fast sweep built its Markov parameters (builds them, as markov_parameters()).
  const SweepInfo& sweep_info() const { return series().info; }

  /// Force variations (Fx, Fy, Mz) at t_k = k dt for the creepage variations of step k, taken as
  /// sampling() defines them (CreepageHistory::step_variation(sampling(), k, dt), k = 0, 1, ...), by the discrete-time recursion
  /// K0 pi_k = K1 pi_{k-1} - Pi' W~_k, pi_{-1} = 0 (one Cholesky factorisation of K0, or PCG started
  /// from the previous step rolled on by one element; K1 by FFT).
  std::vector<Eigen::Vector3d> time_response(const std::vector<Eigen::Vector3d>& creepage_variation) const;
  /// The same with a normal-load variation N~_k (N) at t_k (in both samplings) as well (same length
  /// as the creepages).
  std::vector<Eigen::Vector3d> time_response(const std::vector<Eigen::Vector3d>& creepage_variation,
                                             const std::vector<double>& normal_load_variation) const;

  /// The traction and slip variations of every contact element (element_fields.cpp): the impulse
  /// response of the fields, step by step. Inputs at step 0: a unit creepage (columns xi_x, xi_y,
  /// phi, taken at t_0 as with CONTACT's sampling) and a unit normal load N~_0 = 1 N (column 3);
  /// for k = 0, 1, ... `visit(k, P, S)` receives P~_k (traction, Pa) and S~_k (slip velocity, m/s),
  /// each 2 m x 4 (rows 2a, 2a + 1: x and y of elements()[a]):
  ///   K0 pi_k = K1 pi_{k-1} + [-Pi' W, rN0] d_k0 + [0, rN1] d_k1,  P~_k = Pi pi_k + [0, bN] d_k0,
  ///   S~_k = W xi_k + (A P~_k - A0 P~_{k-1}) / dt      (paper Eq. 11 in the time domain; G2).
  /// The response at frequency w is sum_k z^k P~_k (z = e^{-i w dt}; the creepage columns times
  /// creepage_sampling_factor for the model's sampling). Stops when |P~_k| stayed below
  /// `tolerance` times its largest value for a whole contact length (at most max_contact_lengths
  /// of steps); returns the number of steps visited. Constant friction only (std::domain_error on
  /// the paper form: falling friction).
  using FieldVisitor =
      std::function<void(int k, const Eigen::MatrixXd& P, const Eigen::MatrixXd& S)>;
  int element_impulse_response(const FieldVisitor& visit, double tolerance = 1e-12,
                               int max_contact_lengths = 60) const;
  /// The same for pressure changes on the frozen contact area at step 0: column c of the fields
  /// answers the pressure change patterns[c] (Pa per unit input, on the grid; zero outside the
  /// contact area), which enters as the normal load's dpn/dN N~ does (G1-G2: bN_e = -mu dpn_e
  /// s_bar_e/|s_bar_e| on the slip elements, the pressure alone changes no adhesion element):
  ///   K0 pi_k = K1 pi_{k-1} + r0 d_k0 + r1 d_k1,  P~_k = Pi pi_k + b d_k0,
  ///   S~_k = (A P~_k - A0 P~_{k-1}) / dt.
  /// E.g. the pressure a rail roughness makes within the patch at a given load (wear_transfer.hpp
  /// W7). Constant friction only.
  int element_pressure_response(const std::vector<contact::GridField>& patterns,
                                const FieldVisitor& visit, double tolerance = 1e-12,
                                int max_contact_lengths = 60) const;
  /// The contact elements (grid indices) in the model's order: element a of the field rows.
  const std::vector<int>& elements() const { return el_; }
  /// Whether element a (model order) slips in the steady state the model linearises.
  bool slip_element(int a) const { return slip_[a] != 0; }
  /// The grid of the frozen patch.
  const contact::Grid& grid() const { return table_.grid(); }

  /// Throw InputError (key "frequency") unless 0 <= f <= Nyquist.
  void check_frequency(double frequency) const;

  /// PCG statistics of the matrix-free path so far (all solves: sweep, recursion, time response):
  /// columns solved and iterations in all.
  long inner_solves() const;
  long inner_iterations() const;

  // ---- diagnostics (read-only; they build and factorise K0 densely, whatever the path) ----

  /// The Cholesky factor L of the reduced step matrix, K0 = D + Pi' A Pi/dt = L L' (lower
  /// triangular, r x r, a copy), for exact condition numbers: cond_2(K0) = cond_2(L)^2 and, for a
  /// diagonal scaling S, cond_2(S K0 S) = cond_2(S L)^2 (docs/stability.md).
  Eigen::MatrixXd step_matrix_cholesky_factor() const;
  /// Estimate of the reciprocal condition number 1/(|K0|_1 |K0^{-1}|_1) from the Cholesky factor
  /// (Eigen's LLT::rcond, Hager-Higham 1-norm estimator, O(r^2)).
  double step_matrix_rcond() const;
  /// The diagonal D of K0: c_e = |s_bar_e|/(mu pn_e) (floored, see above) for slip unknowns, 0 for
  /// adhesion unknowns (r values, reduced order).
  Eigen::VectorXd step_matrix_slip_diagonal() const;

 private:
  /// How the model solves: the reduced form with K0 factored densely or solved by PCG, or the
  /// paper's form (falling friction: the reduced K0 would be indefinite, see above). Decided once,
  /// in the constructor.
  enum class Route { reduced_dense, reduced_matrix_free, paper_form };
  struct Dense;           // the paper's formulation, assembled densely (paper_form.cpp)
  struct HessenbergForm;  // M0^{-1} M1 = Q H Q' and the projected inputs and outputs (paper_form.cpp)
  /// The parts built on first use, each exactly once (std::call_once: a model shared by threads
  /// does not race): the step solver of the route, the paper form, its Hessenberg form and
  /// spectral radius, and the Markov series of the fast sweep.
  struct Built;
  /// The Markov parameters of f and g with how they were obtained (transfer.cpp).
  struct MarkovSeries {
    std::vector<Eigen::Matrix3d> creep;
    std::vector<Eigen::Vector3d> load;
    SweepInfo info;
  };

  // ---- the frozen patch (linear_model.cpp; constructor steps) ----
  /// Element data of the scaled formulation (t_e, c_e, kappa_e, the offsets, r); returns
  /// mu(|s_bar|) per element.
  std::vector<double> freeze_elements(const contact::ContactPatch& patch, const contact::TangentialSolution& mean,
                                      const LinearModelInput& in);
  /// The inputs W and outputs L per unit creepage, and their reduced forms.
  void set_inputs_and_outputs(const contact::Grid& grid, const LinearModelInput& in);
  /// The normal-load input (G1-G2): bN, A bN/dt, A0 bN/dt and their reduced forms (needs A0_op_).
  void set_normal_load_input(const contact::ContactPatch& patch, const contact::TangentialSolution& mean,
                             const std::vector<double>& mu_bar);
  /// The inputs of traction changes b on the slip elements (columns of B, grid layout 2N: x then
  /// y): b in model order (n), A b/dt and A0 b/dt (n), and the reduced r0 = -Pi' A b/dt,
  /// r1 = Pi' A0 b/dt (G2).
  struct TractionInput {
    Eigen::MatrixXd b, w0, w1, r0, r1;
  };
  TractionInput traction_input(const Eigen::MatrixXd& B) const;
  /// The recursion of element_impulse_response with the step-0 inputs r0 and the step-1 inputs
  /// r1 (r x c), the traction b added at step 0 and the slip w added at step 0 (n x c).
  int impulse_response(const TractionInput& in, const Eigen::MatrixXd& w, const FieldVisitor& visit,
                       double tolerance, int max_contact_lengths) const;
  /// B_e of a slip element: -t t' (constant friction) - kappa s^ s^' (falling friction).
  Eigen::Matrix2d slip_traction_matrix(int a) const;

  // ---- the paper form (paper_form.cpp) ----
  const Dense& dense() const;  // built once, on first use
  std::unique_ptr<Dense> assemble_paper_form() const;
  const HessenbergForm& hessenberg() const;  // built once, on first use (O(n^3))
  std::unique_ptr<HessenbergForm> hessenberg_form() const;
  /// f and/or g by the Hessenberg form (either pointer may be null).
  void hessenberg_sweep(const std::vector<double>& frequencies, std::vector<CreepMatrix>* f,
                        std::vector<LoadVector>* g) const;
  /// The same at one complex z = e^{-s dt} (f without the sampling factor).
  void hessenberg_at(std::complex<double> z, CreepMatrix* f, LoadVector* g) const;
  /// time_response in the paper form (falling friction).
  std::vector<Eigen::Vector3d> time_response_dense(const std::vector<Eigen::Vector3d>& xi,
                                                   const std::vector<double>& dN) const;

  // ---- the step solvers of the reduced form (reduced_form.cpp) ----
  /// The step solver of the route (built on first use); throws std::logic_error on the paper form.
  const StepSolver& step() const;
  /// K0 = D + Pi' A Pi / dt, its lower triangle, assembled densely.
  Eigen::MatrixXd assemble_K0() const;
  /// The Cholesky step with `threads` operator sets (throws std::logic_error with falling friction).
  std::unique_ptr<DenseCholeskyStep> make_dense_step(int threads) const;
  std::unique_ptr<PcgStep> make_pcg_step() const;
  /// Builds the FFT operator sets of the step solvers, one per thread (the first shares A0_op_).
  OperatorFactory operator_factory(bool matrix_free, double cbar) const;
  /// The FFT operators of the reduced form on the contact elements: the rolling step
  /// K1 = Pi' A0 Pi/dt, the compliance part of K0, Pi' A Pi/dt, and the matrix-free
  /// preconditioner Pi' (C/dt + cbar I)^{-1} Pi (docs/contact_model.md Sec. 5).
  enum class ReducedOperator { rolling_step, compliance, preconditioner };
  std::unique_ptr<contact::ElementOperator> reduced_operator(ReducedOperator which, double cbar = 0.0) const;
  /// The diagonal shift cbar of the matrix-free preconditioner's symbol.
  double preconditioner_shift() const;
  /// Pi' S Pi X: the tractions rolled on by one element (the start of the PCG solves).
  Eigen::MatrixXd rolled(const Eigen::MatrixXd& X) const;
  /// K0^{-1} B where B is the right-hand side of the step after `previous` (a traction history):
  /// an iterative solver starts from `previous` rolled on by one element, a direct one ignores it.
  Eigen::MatrixXd solve_step(const StepSolver& step, const Eigen::MatrixXd& B, const Eigen::MatrixXd& previous) const;

  // ---- the Markov sweep (markov_sweep.cpp) ----
  /// The starting block K0^{-1} [-Pi' W, s y] of the Markov sequence (r x block_), with Z = K0 X,
  /// gm_0 = dN + L' x0 of (G3), and the scale s of y (to the creepage columns).
  struct StartBlock {
    Eigen::MatrixXd X, Z;
    Eigen::Vector3d g0 = Eigen::Vector3d::Zero();
    double load_scale = 1.0;
  };
  StartBlock start_block() const;
  /// The block Krylov reduced model (markov_sweep.cpp, steps 2-3); nothing if it fails its checks.
  std::optional<MarkovSeries> krylov_markov(int max_contact_lengths, SweepInfo& info) const;
  /// The exact recursion; nothing if the h_j do not decay within max_contact_lengths.
  std::optional<MarkovSeries> exact_markov(int max_contact_lengths, SweepInfo& info) const;
  /// Split the Markov parameters of the block (3 creepage columns, 1 scaled load column) into f's
  /// and g's.
  MarkovSeries markov_model(const std::vector<Eigen::MatrixXd>& h, const StartBlock& start) const;

  // ---- the transfer function (transfer.cpp) ----
  /// The Markov series of the fast sweep (built on first use): Krylov, else the exact recursion;
  /// empty with info.method = hessenberg when both fail or on the paper form.
  const MarkovSeries& series(int max_contact_lengths = 60) const;
  /// f of the creepage at t_k (CONTACT's sampling) -> f of sampling_, in place (one factor per
  /// frequency; the identity for contact).
  void apply_sampling(std::vector<CreepMatrix>& f, const std::vector<double>& frequencies) const;
  /// f = -sum_j h_j z^j at the frequencies (Horner), with the sampling's phase.
  std::vector<CreepMatrix> creep_from_markov(const std::vector<Eigen::Matrix3d>& h,
                                             const std::vector<double>& frequencies) const;

  double dt_ = 0.0, speed_ = 0.0, mu_ = 0.0;
  LinearSolver solver_ = LinearSolver::automatic;
  Route route_ = Route::reduced_dense;
  contact::CreepageSampling sampling_ = contact::CreepageSampling::average;
  int steps_per_contact_length_ = 1;
  int threads_ = 1;  ///< LinearModelInput::threads resolved (>= 1)
  int n_adhesion_ = 0, n_slip_ = 0, r_ = 0;
  contact::InfluenceTable table_;
  std::shared_ptr<const contact::HalfSpaceOperator> A0_op_;  ///< A0 (shift 1) by FFT
  std::vector<int> el_;                  ///< contact elements in sweep order (grid indices)
  std::vector<int> offset_;              ///< first reduced unknown of each element
  std::vector<Eigen::Vector2d> t_;       ///< slip elements: traction direction t_e (unused for adhesion)
  std::vector<double> c_;                ///< slip elements: c_e = |s_bar|/(mu pn) (0 for adhesion)
  std::vector<char> slip_;               ///< 1 for slip elements
  std::vector<double> kappa_;            ///< slip elements: mu' |s_bar| / mu (falling friction), else 0
  bool falling_ = false;                 ///< some kappa_e != 0: the paper form only (see above)
  Eigen::MatrixXd W_;   ///< n x 3 inputs per unit creepage: V U1, V U2, V Usp
  Eigen::MatrixXd L_;   ///< n x 3 outputs: dx dy B' U1, B' U2, B' Usp0
  Eigen::MatrixXd Wr_;  ///< r x 3 reduced inputs  -Pi' W
  Eigen::MatrixXd Lr_;  ///< r x 3 reduced outputs  dx dy Pi' U
  // Normal-load input (G1-G3), zero when there is no slip element.
  int block_ = 3;            ///< Krylov block: 3 creepage inputs (+ 1 normal load)
  Eigen::VectorXd wN0_, wN1_;  ///< n: A bN/dt, A0 bN/dt (paper form, per N)
  Eigen::VectorXd rN0_, rN1_;  ///< r: -Pi' A bN/dt, +Pi' A0 bN/dt
  Eigen::Vector3d dN_ = Eigen::Vector3d::Zero();  ///< dx dy U' bN
  Eigen::VectorXd bN_;  ///< n: bN of (G1) per element (model order), zero without slip elements
  std::unique_ptr<Built> built_;
};

}  // namespace rollnoise::nss
