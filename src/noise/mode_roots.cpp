// Route 2 of the loop's stability (stability.hpp, (S2), (S3)): each wheel mode's root of
// det A(s) = 0 continued from the uncoupled root by the homotopy in lambda.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/errors.hpp"
#include "noise/stability.hpp"

namespace rollnoise::noise {

namespace {

// The diagonal equilibration of solve_contact_forces: D_i = |A_ii|^{-1/2}.
Eigen::Vector4d equilibration(const Receptance4& A) {
  Eigen::Vector4d d;
  for (int i = 0; i < 4; ++i) {
    const double m = std::abs(A(i, i));
    d(i) = m > 0.0 && std::isfinite(m) ? 1.0 / std::sqrt(m) : 1.0;
  }
  return d;
}

double singular_ratio(const Receptance4& A) {
  const Eigen::Vector4d d = equilibration(A);
  const Receptance4 As = d.cast<cdouble>().asDiagonal() * A * d.cast<cdouble>().asDiagonal();
  const Eigen::JacobiSVD<Receptance4> svd(As);
  const auto& sv = svd.singularValues();
  return sv(3) / sv(0);
}

// The modes with the same uncoupled root as mode k (k first): sin/cos partners.
std::vector<std::size_t> cluster_of(const LaplaceLoop& loop, std::size_t k) {
  std::vector<std::size_t> c{k};
  const cdouble s0 = uncoupled_root(loop.modes[k]);
  for (std::size_t j = 0; j < loop.modes.size(); ++j)
    if (j != k && std::abs(uncoupled_root(loop.modes[j]) - s0) <= 1e-9 * std::abs(s0))
      c.push_back(j);
  return c;
}

// (S3) in the modal form over ALL modes of the loop, rows scaled by 1/(m_j omega_j^2):
//   H(s; lambda) = det R(s) det( diag(D_j(s)/omega_j^2) + lambda diag(1/(m_j omega_j^2)) Psi^T
//   R(s)^{-1} Psi ),
// R = rest (rigid wheelset, rail, contact). det R cancels the poles of R^{-1} (a root passing close
// to one would repel Newton). The branches of the cluster K (modes with one uncoupled root) are
// tracked on it.
class ClusterFunction {
 public:
  ClusterFunction(const LaplaceLoop& loop, std::vector<std::size_t> cluster)
      : loop_(loop), k_(std::move(cluster)) {
    const std::size_t n = loop_.modes.size();
    scale_.resize(n);
    Psi_.resize(4, n);
    for (std::size_t j = 0; j < n; ++j) {
      const LoopMode& m = loop_.modes[j];
      const double w = dynamics::angular(m.frequency);
      scale_(j) = m.modal_mass * w * w;
      Psi_.col(j) = m.shape;
    }
  }
  std::size_t size() const { return k_.size(); }
  // diag(1/(m_j omega_j^2)) Psi^T R^{-1} Psi (N x N), R equilibrated as in solve_contact_forces;
  // and det R.
  Eigen::MatrixXcd coupling_full(cdouble s, cdouble* det_R = nullptr) const {
    const Receptance4 R = loop_.rest(s);
    const Eigen::Vector4d d = equilibration(R);
    const Receptance4 Rs = d.cast<cdouble>().asDiagonal() * R * d.cast<cdouble>().asDiagonal();
    const Eigen::FullPivLU<Receptance4> lu(Rs);
    if (!lu.isInvertible() || !Rs.allFinite())
      throw NumericalError("squeal: the loop without the wheel modes is singular");
    if (det_R) *det_R = lu.determinant() / (d.prod() * d.prod());
    const Eigen::MatrixXcd P = (d.asDiagonal() * Psi_).cast<cdouble>();
    Eigen::MatrixXcd Q = P.transpose() * lu.solve(P);
    for (Eigen::Index j = 0; j < Q.rows(); ++j) Q.row(j) /= scale_(j);
    return Q;
  }
  Eigen::MatrixXcd own_full(cdouble s) const {  // diag(m_j D_j(s) / (m_j omega_j^2))
    const std::size_t n = loop_.modes.size();
    Eigen::MatrixXcd D = Eigen::MatrixXcd::Zero(n, n);
    for (std::size_t j = 0; j < n; ++j) D(j, j) = modal_denominator(loop_.modes[j], s) / scale_(j);
    return D;
  }
  // the cluster's blocks (for the splitting)
  Eigen::MatrixXcd coupling(cdouble s) const { return block(coupling_full(s)); }
  Eigen::MatrixXcd own(cdouble s) const { return block(own_full(s)); }
  cdouble operator()(cdouble s, double lambda) const {
    cdouble det_R;
    const Eigen::MatrixXcd Q = coupling_full(s, &det_R);
    return det_R * Eigen::MatrixXcd(own_full(s) + lambda * Q).partialPivLu().determinant();
  }
  // ds/dlambda along the root path: -H_lambda / H_s (central differences; H is analytic in both).
  cdouble tangent(cdouble s, double lambda) const {
    const double h = 1e-6 * std::abs(s), d = 1e-5;
    cdouble det_R;
    const Eigen::MatrixXcd O = own_full(s), Q = coupling_full(s, &det_R);
    const cdouble H_l = det_R *
                        (Eigen::MatrixXcd(O + (lambda + d) * Q).partialPivLu().determinant() -
                         Eigen::MatrixXcd(O + (lambda - d) * Q).partialPivLu().determinant()) /
                        (2.0 * d);
    const cdouble H_s = ((*this)(s + h, lambda) - (*this)(s - h, lambda)) / (2.0 * h);
    return -H_l / H_s;
  }
  // |det M| / prod_i |M_i,:|_2, M = diag(D_j/omega_j^2) + Q at lambda = 1: the residual of (S1) in
  // the modal form, normalised by Hadamard's bound (|det M| <= prod of the row norms), so 0 <=
  // residual
  // <= 1 whatever the frequency. Unnormalised, the rows of the modes far below the root
  // (|D_j/omega_j^2| ~ (omega/omega_j)^2) multiplied it up: 5e-2 at 4.66 kHz on curve_300m at a
  // root with sigma_min/sigma_max ~ 1e-17.
  double residual(cdouble s) const {
    const Eigen::MatrixXcd M = own_full(s) + coupling_full(s);
    double bound = 1.0;
    for (Eigen::Index i = 0; i < M.rows(); ++i) bound *= M.row(i).norm();
    return std::abs(M.partialPivLu().determinant()) / bound;
  }

 private:
  Eigen::MatrixXcd block(const Eigen::MatrixXcd& full) const {
    Eigen::MatrixXcd b(size(), size());
    for (std::size_t i = 0; i < size(); ++i)
      for (std::size_t j = 0; j < size(); ++j) b(i, j) = full(k_[i], k_[j]);
    return b;
  }
  const LaplaceLoop& loop_;
  std::vector<std::size_t> k_;
  Eigen::VectorXd scale_;
  Eigen::MatrixXd Psi_;
};

// Start of the branches of a cluster at lambda = lambda1: first-order splitting of the c-fold
// root s0: m_j D_j(s) ~ m_j D'(s0) (s - s0), so (s - s0) D'(s0) are the eigenvalues of
// -lambda diag(m)^{-1} Psi^T B_K(s0)^{-1} Psi. Branch i continues the mode with the largest
// component of its eigenvector (assigned greedily). Returns the starts in the order of k.
std::vector<cdouble> split_cluster(const ClusterFunction& H, cdouble s0, double lambda1) {
  const std::size_t c = H.size();
  Eigen::MatrixXcd N = H.coupling(s0);
  const Eigen::MatrixXcd own_slope =
      (H.own(s0 * (1.0 + 1e-7)) - H.own(s0 * (1.0 - 1e-7))) / (2e-7 * s0);
  for (std::size_t i = 0; i < c; ++i) N.row(i) /= own_slope(i, i);  // diag(m D')^{-1} Q
  return cluster_starts(N, s0, lambda1);
}

// Newton at fixed lambda: the derivative by a central difference at the start (H is analytic),
// then secant updates (one evaluation per iteration). `count` adds the iterations.
std::optional<cdouble> newton(const ClusterFunction& H, cdouble s, double lambda,
                              const StabilityOptions& o, int& count) {
  const double h = 1e-6 * std::abs(s);
  cdouble g = H(s, lambda);
  cdouble dg = (H(s + h, lambda) - H(s - h, lambda)) / (2.0 * h);
  for (int it = 0; it < o.max_iterations; ++it) {
    const cdouble ds = -g / dg;
    ++count;
    if (!std::isfinite(ds.real()) || !std::isfinite(ds.imag())) return std::nullopt;
    s += ds;
    if (std::abs(ds) <= o.tolerance * std::abs(s)) return s;
    const cdouble g_new = H(s, lambda);
    dg = (g_new - g) / ds;
    g = g_new;
  }
  return std::nullopt;
}

// The trust radius of a path from s0: half the distance to the nearest other uncoupled root,
// within [1e-3, 5e-2] |s0|.
double base_trust_radius(const LaplaceLoop& loop, cdouble s0) {
  double nearest = 1e300;
  for (const LoopMode& m : loop.modes) {
    const double d = std::abs(uncoupled_root(m) - s0);
    if (d > 1e-9 * std::abs(s0)) nearest = std::min(nearest, d);
  }
  return std::clamp(0.5 * nearest, 1e-3 * std::abs(s0), 5e-2 * std::abs(s0));
}

// The branches of one cluster followed from lambda = lambda1 to 1.
struct Branches {
  std::vector<cdouble> s;       // the current roots, one per mode of the cluster
  std::vector<ModeRoot> roots;  // their counters (iterations)
  double lambda = 0.0;
  int steps = 0;
  bool ok = true;
};

// The start of the paths. A single mode starts at lambda = 0 from s0. A cluster's c-fold root has
// no tangent there: its branches start at lambda1 = 1e-3 from the first-order splitting, refined
// by Newton.
Branches start_branches(const ClusterFunction& H, cdouble s0, const StabilityOptions& o) {
  const std::size_t c = H.size();
  Branches b;
  b.roots.resize(c);
  b.lambda = c > 1 ? 1e-3 : 0.0;
  b.s.assign(c, s0);
  try {
    if (c > 1) b.s = split_cluster(H, s0, b.lambda);
    for (std::size_t i = 0; i < c && b.ok && c > 1; ++i) {
      const auto r = newton(H, b.s[i], b.lambda, o, b.roots[i].iterations);
      b.ok = r.has_value();
      if (b.ok) b.s[i] = *r;
    }
  } catch (const NumericalError&) {
    b.ok = false;
  }
  return b;
}

// One Euler-Newton step of all branches from b.lambda to `target` along the tangents `slope`:
// the corrected roots, or nothing when a corrector fails, leaves its trust radius (base_trust and
// half the distance to the other branches' predictions) or moves more than half the predictor's
// step.
std::optional<std::vector<cdouble>> continuation_step(const ClusterFunction& H, Branches& b,
                                                      const std::vector<cdouble>& slope,
                                                      double target, cdouble s0, double base_trust,
                                                      const StabilityOptions& o) {
  const std::size_t c = H.size();
  std::vector<cdouble> next(c), pred(c);
  for (std::size_t i = 0; i < c; ++i) pred[i] = b.s[i] + (target - b.lambda) * slope[i];
  for (std::size_t i = 0; i < c; ++i) {
    double trust = base_trust;
    for (std::size_t j = 0; j < c; ++j)
      if (j != i)
        trust = std::min(trust, std::max(0.5 * std::abs(pred[i] - pred[j]), 1e-7 * std::abs(s0)));
    std::optional<cdouble> r;
    try {
      r = newton(H, pred[i], target, o, b.roots[i].iterations);
    } catch (const NumericalError&) {  // e.g. beyond the contact series' convergence
      r.reset();
    }
    const bool accepted =
        r && std::abs(*r - pred[i]) <= trust &&
        std::abs(*r - pred[i]) <= 0.5 * std::abs(pred[i] - b.s[i]) + 1e-9 * std::abs(s0);
    if (!accepted) return std::nullopt;
    next[i] = *r;
  }
  return next;
}

// Euler-Newton continuation to lambda = 1: predictor along the tangent ds/dlambda = -H_lambda /
// H_s, corrector Newton at the new lambda (continuation_step); an accepted step doubles the next
// one (up to max_step), a rejected one is halved, down to min_step.
void continue_branches(const ClusterFunction& H, Branches& b, cdouble s0, double base_trust,
                       const StabilityOptions& o) {
  const std::size_t c = H.size();
  double step = o.max_step;
  std::vector<cdouble> slope(c);
  bool have_slope = false;
  while (b.ok && b.lambda < 1.0) {
    const double target = std::min(1.0, b.lambda + step);
    try {
      if (!have_slope)
        for (std::size_t i = 0; i < c; ++i) slope[i] = H.tangent(b.s[i], b.lambda);
      have_slope = true;
    } catch (const NumericalError&) {
      b.ok = false;
      break;
    }
    if (const auto next = continuation_step(H, b, slope, target, s0, base_trust, o)) {
      b.lambda = target, b.s = *next;
      have_slope = false;
      ++b.steps;
      step = std::min(2.0 * step, o.max_step);
      continue;
    }
    step *= 0.5;
    if (step < o.min_step) break;
  }
}

// The reported roots of a cluster: s, frequency, damping, and the residual and singular-value
// ratio at the root.
std::vector<ModeRoot> report(const LaplaceLoop& loop, const ClusterFunction& H,
                             const std::vector<std::size_t>& cluster, cdouble s0, Branches b) {
  for (std::size_t i = 0; i < cluster.size(); ++i) {
    ModeRoot& r = b.roots[i];
    const LoopMode& m = loop.modes[cluster[i]];
    r.mode = cluster[i];
    r.label = m.label;
    r.natural_frequency = m.frequency;
    r.s0 = s0;
    r.s = b.s[i];
    r.steps = b.steps;
    r.converged = b.ok && b.lambda >= 1.0;
    r.frequency = r.s.imag() / (2.0 * M_PI);
    r.damping_ratio = -r.s.real() / std::abs(r.s);
    r.unstable = r.s.real() > 0.0;
    try {
      r.residual = H.residual(r.s);
      r.singular_ratio = singular_ratio(loop.matrix(r.s));
    } catch (const NumericalError&) {
      r.residual = r.singular_ratio = std::nan("");
      r.converged = false;
    }
  }
  return std::move(b.roots);
}

}  // namespace

std::vector<ModeRoot> mode_roots(const LaplaceLoop& loop, const StabilityOptions& o) {
  std::vector<ModeRoot> out;
  std::vector<bool> done(loop.modes.size(), false);
  for (std::size_t k = 0; k < loop.modes.size(); ++k) {
    const LoopMode& mk = loop.modes[k];
    if (done[k] || !(mk.frequency >= o.band_min && mk.frequency <= o.band_max)) continue;
    const std::vector<std::size_t> cluster = cluster_of(loop, k);
    for (std::size_t j : cluster) done[j] = true;
    const ClusterFunction H(loop, cluster);
    const cdouble s0 = uncoupled_root(mk);
    Branches b = start_branches(H, s0, o);
    continue_branches(H, b, s0, base_trust_radius(loop, s0), o);
    const std::vector<ModeRoot> roots = report(loop, H, cluster, s0, std::move(b));
    out.insert(out.end(), roots.begin(), roots.end());
  }
  std::sort(out.begin(), out.end(),
            [](const ModeRoot& a, const ModeRoot& b) { return a.mode < b.mode; });
  return out;
}

ModeRoot mode_root(const LaplaceLoop& loop, std::size_t k, const StabilityOptions& o) {
  StabilityOptions one = o;
  one.band_min = one.band_max = loop.modes.at(k).frequency;
  for (const ModeRoot& r : mode_roots(loop, one))
    if (r.mode == k) return r;
  throw NumericalError("squeal: mode not found");
}

std::vector<cdouble> cluster_starts(const Eigen::MatrixXcd& N, cdouble s0, double lambda1) {
  const std::size_t c = static_cast<std::size_t>(N.rows());
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(N);
  std::vector<cdouble> start(c, s0);
  std::vector<bool> taken(c, false), used(c, false);
  for (std::size_t round = 0; round < c; ++round) {  // the most dominant (branch, mode) pair first
    double best = -1.0;
    std::size_t bi = 0, bj = 0;
    for (std::size_t i = 0; i < c; ++i) {
      if (used[i]) continue;
      const Eigen::VectorXcd v = es.eigenvectors().col(i);
      for (std::size_t j = 0; j < c; ++j)
        if (!taken[j] && std::abs(v(j)) / v.norm() > best)
          best = std::abs(v(j)) / v.norm(), bi = i, bj = j;
    }
    used[bi] = taken[bj] = true;
    start[bj] = s0 - lambda1 * es.eigenvalues()(bi);
  }
  return start;
}

}  // namespace rollnoise::noise
