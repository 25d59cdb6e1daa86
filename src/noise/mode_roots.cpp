// Route 2 of the loop's stability (stability.hpp, (S2), (S3)): each wheel mode's root of
// det A(s) = 0 continued from the uncoupled root by the homotopy in lambda, for a loop of any
// number of contacts.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "noise/stability.hpp"

namespace rollnoise::noise {
namespace {

Eigen::VectorXd equilibration(const Eigen::MatrixXcd& A) {  // D_i = |A_ii|^{-1/2}
  Eigen::VectorXd d(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    const double m = std::abs(A(i, i));
    d(i) = m > 0.0 && std::isfinite(m) ? 1.0 / std::sqrt(m) : 1.0;
  }
  return d;
}

}  // namespace

namespace {

class ModalForm {
 public:
  explicit ModalForm(const LaplaceLoop& loop) : loop_(loop) {
    const std::size_t m = loop.modes.size();
    scale_.resize(m);
    Psi_.resize(m ? loop.modes[0].shape.size() : 0, m);
    for (std::size_t j = 0; j < m; ++j) {
      const double w = dynamics::angular(loop.modes[j].frequency);
      scale_(j) = loop.modes[j].modal_mass * w * w;
      Psi_.col(j) = loop.modes[j].shape;
    }
  }
  // diag(1/(m_j omega_j^2)) Psi^T R^{-1} Psi and det R (R equilibrated).
  Eigen::MatrixXcd coupling(cdouble s, cdouble* det_R = nullptr) const {
    const Eigen::MatrixXcd R = loop_.rest(s);
    const Eigen::VectorXd d = equilibration(R);
    const Eigen::MatrixXcd Rs = d.cast<cdouble>().asDiagonal() * R * d.cast<cdouble>().asDiagonal();
    const Eigen::FullPivLU<Eigen::MatrixXcd> lu(Rs);
    if (!lu.isInvertible() || !Rs.allFinite())
      throw NumericalError("squeal: the loop without the wheel modes is singular");
    if (det_R) *det_R = lu.determinant() / (d.prod() * d.prod());
    const Eigen::MatrixXcd P = (d.asDiagonal() * Psi_).cast<cdouble>();
    Eigen::MatrixXcd Q = P.transpose() * lu.solve(P);
    for (Eigen::Index j = 0; j < Q.rows(); ++j) Q.row(j) /= scale_(j);
    return Q;
  }
  Eigen::MatrixXcd own(cdouble s) const {  // diag(D_j(s) / omega_j^2)
    const std::size_t m = loop_.modes.size();
    Eigen::MatrixXcd D = Eigen::MatrixXcd::Zero(m, m);
    for (std::size_t j = 0; j < m; ++j) D(j, j) = modal_denominator(loop_.modes[j], s) / scale_(j);
    return D;
  }
  cdouble operator()(cdouble s, double lambda) const {
    cdouble det_R;
    const Eigen::MatrixXcd Q = coupling(s, &det_R);
    return det_R * Eigen::MatrixXcd(own(s) + lambda * Q).partialPivLu().determinant();
  }
  // ds/dlambda = -H_lambda / H_s, both of H deflated by the cluster's other branches `others`
  // (G = H / prod_j (s - s_j), the same ratio at a root of H): at a near-double root (the same mode
  // of two wheels that hardly touch the contacts, branches ~1e-4 1/s apart) H_s = (s_1 - s_2) P(s)
  // is small and the central difference of H with h = 1e-6 |s| (~2e-3 1/s at 300 Hz) errs by
  // h^2 H_sss / 6 ~ h^2 P / d (d the distance to the next branch), of its own size; the deflated
  // G_s = P(s) is not small (docs/squeal.md Sec. 8.1).
  cdouble tangent(cdouble s, double lambda, const std::vector<cdouble>& others = {}) const {
    const double h = 1e-6 * std::abs(s), dl = 1e-5;
    auto deflation = [&](cdouble z) {
      cdouble p = 1.0;
      for (cdouble sj : others) p *= (z - sj);
      return p;
    };
    cdouble det_R;
    const Eigen::MatrixXcd O = own(s), Q = coupling(s, &det_R);
    const cdouble H_l = det_R *
                        (Eigen::MatrixXcd(O + (lambda + dl) * Q).partialPivLu().determinant() -
                         Eigen::MatrixXcd(O + (lambda - dl) * Q).partialPivLu().determinant()) /
                        (2.0 * dl);
    const cdouble G_s =
        ((*this)(s + h, lambda) / deflation(s + h) - (*this)(s - h, lambda) / deflation(s - h)) /
        (2.0 * h);
    return -(H_l / deflation(s)) / G_s;
  }
  Eigen::MatrixXcd modal_matrix(cdouble s) const { return own(s) + coupling(s); }

 private:
  const LaplaceLoop& loop_;
  Eigen::VectorXd scale_;
  Eigen::MatrixXd Psi_;
};

// First-order splitting of a c-fold uncoupled root (route 2's splitting, stability.hpp).
std::vector<cdouble> split_cluster(const ModalForm& H, const std::vector<std::size_t>& k,
                                   cdouble s0, double lambda1) {
  const std::size_t c = k.size();
  const Eigen::MatrixXcd Qf = H.coupling(s0);
  const Eigen::MatrixXcd slope =
      (H.own(s0 * (1.0 + 1e-7)) - H.own(s0 * (1.0 - 1e-7))) / (2e-7 * s0);
  Eigen::MatrixXcd N(c, c);
  for (std::size_t i = 0; i < c; ++i)
    for (std::size_t j = 0; j < c; ++j) N(i, j) = Qf(k[i], k[j]) / slope(k[i], k[i]);
  return cluster_starts(N, s0, lambda1);
}

// Newton at fixed lambda: central-difference derivative, then secant updates, on H deflated by the
// other branches of the cluster, H(s) / prod_j (s - s_j) (Aberth 1973; the Weierstrass-Aberth
// deflation): the same root, but a near-double root of H (the same mode of two weakly coupled
// wheels, e.g. sin partners that hardly touch the contact) becomes simple, where plain Newton
// converged too slowly to reach the tolerance.
std::optional<cdouble> newton(const ModalForm& H, cdouble s, double lambda,
                              const StabilityOptions& o, int& count,
                              const std::vector<cdouble>& others = {}) {
  auto G = [&](cdouble z) {
    cdouble v = H(z, lambda);
    for (cdouble sj : others) v /= (z - sj);
    return v;
  };
  const double h = 1e-6 * std::abs(s);
  cdouble g = G(s);
  cdouble dg = (G(s + h) - G(s - h)) / (2.0 * h);
  for (int it = 0; it < o.max_iterations; ++it) {
    const cdouble ds = -g / dg;
    ++count;
    if (!std::isfinite(ds.real()) || !std::isfinite(ds.imag())) return std::nullopt;
    s += ds;
    if (std::abs(ds) <= o.tolerance * std::abs(s)) return s;
    const cdouble g_new = G(s);
    dg = (g_new - g) / ds;
    g = g_new;
  }
  return std::nullopt;
}

// The other branches of a cluster, for the deflation of branch i.
std::vector<cdouble> others_of(const std::vector<cdouble>& s, std::size_t i) {
  std::vector<cdouble> o;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (j != i) o.push_back(s[j]);
  return o;
}

// Euler-Newton continuation of the branches s (at lambda) to lambda = 1; returns lambda reached.
double continue_branches(const ModalForm& H, std::vector<cdouble>& s, double lambda,
                         double base_trust, cdouble s0, const StabilityOptions& o,
                         std::vector<int>& iterations, int& steps) {
  const std::size_t c = s.size();
  double step = o.max_step;
  std::vector<cdouble> slope(c);
  bool have_slope = false;
  while (lambda < 1.0) {
    const double target = std::min(1.0, lambda + step);
    try {
      if (!have_slope)
        for (std::size_t i = 0; i < c; ++i) slope[i] = H.tangent(s[i], lambda, others_of(s, i));
      have_slope = true;
    } catch (const NumericalError&) {
      return lambda;
    }
    bool accepted = true;
    std::vector<cdouble> next(c), pred(c);
    for (std::size_t i = 0; i < c; ++i) pred[i] = s[i] + (target - lambda) * slope[i];
    for (std::size_t i = 0; i < c && accepted; ++i) {
      double trust = base_trust;
      for (std::size_t j = 0; j < c; ++j)
        if (j != i)
          trust = std::min(trust, std::max(0.5 * std::abs(pred[i] - pred[j]), 1e-7 * std::abs(s0)));
      std::optional<cdouble> r;
      try {
        r = newton(H, pred[i], target, o, iterations[i], others_of(pred, i));
      } catch (const NumericalError&) {
        r.reset();
      }
      accepted = r && std::abs(*r - pred[i]) <= trust &&
                 std::abs(*r - pred[i]) <= 0.5 * std::abs(pred[i] - s[i]) + 1e-9 * std::abs(s0);
      if (accepted) next[i] = *r;
      // A branch that does not move (a mode that hardly touches any contact, e.g. a sin partner
      // with a small spin creep coefficient, next to the same mode of the other wheel: a
      // near-double root that Newton cannot resolve to the tolerance) keeps its prediction.
      if (!accepted && std::abs(pred[i] - s[i]) <= 1e-9 * std::abs(s0))
        accepted = true, next[i] = pred[i];
    }
    if (accepted) {
      lambda = target, s = next, have_slope = false, ++steps;
      step = std::min(2.0 * step, o.max_step);
      continue;
    }
    step *= 0.5;
    if (step < o.min_step) break;
  }
  return lambda;
}

// The root's report (ModeRoot, stability.hpp), with each wheel's share of the null vector.
ModeRoot report(const LaplaceLoop& loop, const ModalForm& H, std::size_t mode, cdouble s0,
                cdouble s, bool converged) {
  ModeRoot r;
  const LoopMode& m = loop.modes[mode];
  r.mode = mode, r.label = m.label, r.natural_frequency = m.frequency, r.s0 = s0, r.s = s;
  r.converged = converged;
  r.frequency = s.imag() / (2.0 * M_PI);
  r.damping_ratio = -s.real() / std::abs(s);
  r.unstable = s.real() > 0.0;
  r.wheel = m.wheel;
  r.wheel_share.assign(loop.wheels.size(), 0.0);
  try {
    const Eigen::MatrixXcd M = H.modal_matrix(s);
    double bound = 1.0;
    for (Eigen::Index i = 0; i < M.rows(); ++i) bound *= M.row(i).norm();
    r.residual = std::abs(M.partialPivLu().determinant()) / bound;
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(M, Eigen::ComputeFullV);
    const Eigen::VectorXcd q = svd.matrixV().col(M.cols() - 1);
    for (std::size_t j = 0; j < loop.modes.size(); ++j)
      r.wheel_share[loop.modes[j].wheel] += std::norm(q(j));
    r.own_share = std::norm(q(static_cast<Eigen::Index>(mode))) / q.squaredNorm();
    const Eigen::MatrixXcd A = loop.matrix(s);
    const Eigen::VectorXd d = equilibration(A);
    const Eigen::JacobiSVD<Eigen::MatrixXcd> sa(d.cast<cdouble>().asDiagonal() * A *
                                                d.cast<cdouble>().asDiagonal());
    r.singular_ratio = sa.singularValues()(A.rows() - 1) / sa.singularValues()(0);
  } catch (const NumericalError&) {
    r.residual = r.singular_ratio = std::nan("");
    r.converged = false;
  }
  r.dominant_wheel = static_cast<int>(std::max_element(r.wheel_share.begin(), r.wheel_share.end()) -
                                      r.wheel_share.begin());
  return r;
}

}  // namespace

namespace {

std::vector<ModeRoot> connected_mode_roots(const LaplaceLoop& loop, const StabilityOptions& o) {
  const ModalForm H(loop);
  std::vector<ModeRoot> out;
  std::vector<bool> done(loop.modes.size(), false);
  for (std::size_t k = 0; k < loop.modes.size(); ++k) {
    const LoopMode& mk = loop.modes[k];
    if (done[k] || !(mk.frequency >= o.band_min && mk.frequency <= o.band_max)) continue;
    const cdouble s0 = uncoupled_root(mk);
    std::vector<std::size_t> cluster{k};  // modes with the same uncoupled root (all wheels)
    double nearest = 1e300;
    for (std::size_t j = 0; j < loop.modes.size(); ++j) {
      const double d = std::abs(uncoupled_root(loop.modes[j]) - s0);
      if (j != k && d <= 1e-9 * std::abs(s0)) cluster.push_back(j);
      if (d > 1e-9 * std::abs(s0)) nearest = std::min(nearest, d);
    }
    for (std::size_t j : cluster) done[j] = true;
    const double base_trust = std::clamp(0.5 * nearest, 1e-3 * std::abs(s0), 5e-2 * std::abs(s0));
    const std::size_t c = cluster.size();
    const double lambda1 = c > 1 ? 1e-3 : 0.0;
    std::vector<cdouble> s(c, s0);
    std::vector<int> iterations(c, 0);
    int steps = 0;
    bool ok = true;
    try {
      if (c > 1) s = split_cluster(H, cluster, s0, lambda1);
      const std::vector<cdouble> start = s;  // first order in lambda1: kept where Newton fails
      for (std::size_t i = 0; i < c && c > 1; ++i) {
        const auto r = newton(H, start[i], lambda1, o, iterations[i], others_of(start, i));
        if (r && std::abs(*r - start[i]) <= 0.5 * std::abs(start[i] - s0) + 1e-9 * std::abs(s0))
          s[i] = *r;
      }
    } catch (const NumericalError&) {
      ok = false;
    }
    const double reached =
        ok ? continue_branches(H, s, lambda1, base_trust, s0, o, iterations, steps) : 0.0;
    for (std::size_t i = 0; i < c; ++i) {
      ModeRoot r = report(loop, H, cluster[i], s0, s[i], ok && reached >= 1.0);
      r.iterations = iterations[i];
      r.steps = steps;
      out.push_back(r);
    }
  }
  return out;
}

// The groups of contacts that the structures couple (union of the nonzero off-diagonal blocks of
// rest at a test point on the axis): e.g. the two wheelsets of a bogie when the rails' transfer is
// off. Their characteristic equations are independent factors of (S1), whose root paths may cross
// (no longer one analytic family), so each group is continued alone.
std::vector<int> contact_groups(const LaplaceLoop& loop, Eigen::Index n) {
  if (n == 1) return {0};
  const Eigen::MatrixXcd R = loop.rest(cdouble(0.0, 2.0 * M_PI * 997.0));
  std::vector<int> g(n);
  for (Eigen::Index a = 0; a < n; ++a) g[a] = static_cast<int>(a);
  auto root = [&](int a) {
    while (g[a] != a) a = g[a] = g[g[a]];
    return a;
  };
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b)
      if (a != b && (R.block(4 * a, 4 * b, 4, 4).cwiseAbs().maxCoeff() > 0.0)) g[root(a)] = root(b);
  for (Eigen::Index a = 0; a < n; ++a) g[a] = root(static_cast<int>(a));
  return g;
}

// A mode whose continuation reached another mode's root (distinct_roots): its own root searched
// at lambda = 1 by Newton from its uncoupled root s0 on H deflated by the roots already found near
// it (within 5 % of |s0|), H(s) / prod_j (s - s_j) (Aberth 1973, as newton() does for a cluster):
// a root already found repels the iteration, so that it converges to another. Taken when it
// converges (|delta s| <= tolerance |s| within 60 iterations) to a root that is not one of them
// (within 1e-7 |s|); else the mode stays lost (same_root_as). The report's singular ratio shows
// that it is a true zero of (S1).
std::vector<ModeRoot> own_roots_again(const LaplaceLoop& loop, const StabilityOptions& o,
                                      std::vector<ModeRoot> roots) {
  const ModalForm H(loop);
  StabilityOptions search = o;
  search.max_iterations = 60;
  for (ModeRoot& r : roots) {
    if (r.same_root_as < 0) continue;
    std::vector<cdouble> found;
    for (const ModeRoot& x : roots)
      if (x.converged && std::abs(x.s - r.s0) <= 0.05 * std::abs(r.s0)) found.push_back(x.s);
    int count = 0;
    std::optional<cdouble> found_s;
    try {
      found_s = newton(H, r.s0, 1.0, search, count, found);
    } catch (const NumericalError&) {
    }
    if (!found_s) continue;
    const cdouble s = *found_s;
    if (std::any_of(roots.begin(), roots.end(), [&](const ModeRoot& x) {
          return x.converged && std::abs(x.s - s) <= 1e-7 * std::abs(s);
        }))
      continue;  // a root already reported
    ModeRoot again = report(loop, H, r.mode, r.s0, s, true);
    again.iterations = r.iterations + count, again.steps = r.steps, again.refined = true;
    r = again;
  }
  return roots;
}

}  // namespace

std::vector<ModeRoot> mode_roots(const LaplaceLoop& loop, const StabilityOptions& o) {
  if (loop.modes.empty()) return {};
  const Eigen::Index n = loop.modes.front().shape.size() / 4;
  if (loop.contact_wheel.size() != static_cast<std::size_t>(n))
    throw InputError("contacts", "squeal: the loop needs the wheel of each contact");
  const std::vector<int> group = contact_groups(loop, n);
  std::vector<ModeRoot> out;
  for (Eigen::Index leader = 0; leader < n; ++leader) {
    if (group[leader] != leader) continue;
    std::vector<Eigen::Index> rows;  // the group's rows of (S1)
    for (Eigen::Index a = 0; a < n; ++a)
      if (group[a] == leader)
        for (int i = 0; i < 4; ++i) rows.push_back(4 * a + i);
    LaplaceLoop sub;
    sub.wheels = loop.wheels;
    std::vector<std::size_t> index;  // sub mode -> loop mode
    std::vector<bool> in_group(loop.wheels.size(), false);
    for (Eigen::Index a = 0; a < n; ++a)
      if (group[a] == leader) in_group[loop.contact_wheel[a]] = true;
    for (std::size_t k = 0; k < loop.modes.size(); ++k) {
      if (!in_group[loop.modes[k].wheel]) continue;  // a wheel of another group
      LoopMode m = loop.modes[k];
      m.shape = Eigen::VectorXd(rows.size());
      for (std::size_t i = 0; i < rows.size(); ++i) m.shape(i) = loop.modes[k].shape(rows[i]);
      sub.modes.push_back(m);
      index.push_back(k);
    }
    const auto rest = loop.rest;
    sub.rest = [rest, rows](cdouble s) -> Eigen::MatrixXcd { return rest(s)(rows, rows); };
    for (ModeRoot r : connected_mode_roots(sub, o)) {
      r.mode = index[r.mode];
      out.push_back(r);
    }
  }
  std::sort(out.begin(), out.end(),
            [](const ModeRoot& a, const ModeRoot& b) { return a.mode < b.mode; });
  return own_roots_again(loop, o, distinct_roots(std::move(out)));
}

std::vector<ModeRoot> distinct_roots(std::vector<ModeRoot> roots) {
  for (std::size_t i = 0; i < roots.size(); ++i)
    for (std::size_t j = i + 1; j < roots.size(); ++j) {
      ModeRoot &a = roots[i], &b = roots[j];
      if (!a.converged || !b.converged || std::abs(a.s - b.s) > 1e-7 * std::abs(a.s)) continue;
      // the root is the mode's with the larger share of its vector (else the nearer uncoupled
      // root's); the other's continuation failed
      const bool a_keeps = a.own_share != b.own_share
                               ? a.own_share > b.own_share
                               : std::abs(a.s0 - a.s) <= std::abs(b.s0 - b.s);
      ModeRoot& lost = a_keeps ? b : a;
      lost.same_root_as = static_cast<long>((a_keeps ? a : b).mode);
      lost.converged = false;
      lost.unstable = false;
    }
  return roots;
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
