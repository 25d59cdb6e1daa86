#include "noise/stability.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::noise {

// ---------------------------------------------------------------------------------------------
// The loop at complex s
// ---------------------------------------------------------------------------------------------

namespace {

cdouble modal_denominator(const LoopMode& m, cdouble s) {  // m_k D_k(s)
  const double w = dynamics::angular(m.frequency);
  return m.modal_mass * (w * w + 2.0 * m.damping_ratio * w * s + s * s);
}

Receptance4 modal_term(const LoopMode& m, cdouble s) {
  return (m.shape * m.shape.transpose()).cast<cdouble>() / modal_denominator(m, s);
}

}  // namespace

Receptance4 LaplaceLoop::matrix(cdouble s) const {
  Receptance4 a = rest(s);
  for (const LoopMode& m : modes) a += modal_term(m, s);
  return a;
}

std::vector<LoopMode> contact_frame_modes(const dynamics::WheelModel& wheel, const ContactPosition& p) {
  std::vector<LoopMode> out;
  const std::vector<dynamics::WheelMode> table = wheel.modes_at(p.wheel_shift_y);  // the FE wheel follows the contact
  for (std::size_t n = 0; n < table.size(); ++n) {
    const dynamics::WheelMode& w = table[n];
    // psi psi^T = T^T L embed(phi phi^T) L^T T (the wheel's modal part in wheel_receptance6 and
    // to_contact_frame, for one mode); psi from the rank-one matrix.
    Receptance6 r = embed((w.shape * w.shape.transpose()).cast<cdouble>());
    if (p.wheel_shift_y != 0.0) r = move_point(r, Eigen::Vector3d(0.0, p.wheel_shift_y, 0.0));
    const Eigen::Matrix4d M = to_contact_frame(r, p.contact_angle).real();
    Eigen::Index i = 0;
    M.diagonal().maxCoeff(&i);
    LoopMode m;
    m.frequency = w.frequency;
    m.damping_ratio = w.damping_ratio;
    m.modal_mass = w.modal_mass;
    m.shape = M(i, i) > 0.0 ? Eigen::Vector4d(M.col(i) / std::sqrt(M(i, i))) : Eigen::Vector4d::Zero();
    m.label = w.label;
    m.index = n;
    out.push_back(m);
  }
  return out;
}

Eigen::Matrix4d rigid_flexibility(const dynamics::RigidWheelset& w, const ContactPosition& p) {
  // wheelset_centre_receptance at omega = 1 is -C; alpha(s) = -C/omega^2 = C/s^2.
  Receptance6 centre = Receptance6::Zero();
  const double inv[6] = {1.0 / w.mass, 1.0 / w.mass, 1.0 / w.mass, 1.0 / w.roll_inertia, 1.0 / w.spin_inertia,
                         1.0 / w.yaw_inertia};
  for (int i = 0; i < 6; ++i) centre(i, i) = inv[i];
  const Receptance6 moved = move_point(centre, Eigen::Vector3d(0.0, w.contact_offset_y + p.wheel_shift_y, -w.wheel_radius));
  return to_contact_frame(moved, p.contact_angle).real();
}

Receptance4 rail_receptance_laplace(const dynamics::RailModel& rail, cdouble s, const ContactPosition& p) {
  Receptance6 a = embed(rail.receptance_laplace(s));
  if (p.rail_offset_y != 0.0) a = move_point(a, Eigen::Vector3d(0.0, p.rail_offset_y, 0.0));
  return to_contact_frame(a, p.contact_angle);
}

// ---------------------------------------------------------------------------------------------
// Route 2
// ---------------------------------------------------------------------------------------------

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

}  // namespace

namespace {

cdouble uncoupled_root(const LoopMode& m) {
  const double w = dynamics::angular(m.frequency), z = m.damping_ratio;
  return {-z * w, w * std::sqrt(1.0 - z * z)};
}

// The modes with the same uncoupled root as mode k (k first): sin/cos partners.
std::vector<std::size_t> cluster_of(const LaplaceLoop& loop, std::size_t k) {
  std::vector<std::size_t> c{k};
  const cdouble s0 = uncoupled_root(loop.modes[k]);
  for (std::size_t j = 0; j < loop.modes.size(); ++j)
    if (j != k && std::abs(uncoupled_root(loop.modes[j]) - s0) <= 1e-9 * std::abs(s0)) c.push_back(j);
  return c;
}

// (S3) in the modal form over ALL modes of the loop, rows scaled by 1/(m_j omega_j^2):
//   H(s; lambda) = det R(s) det( diag(D_j(s)/omega_j^2) + lambda diag(1/(m_j omega_j^2)) Psi^T R(s)^{-1} Psi ),
// R = rest (rigid wheelset, rail, contact). det R cancels the poles of R^{-1} (a root passing close
// to one would repel Newton). The branches of the cluster K (modes with one uncoupled root) are
// tracked on it.
class ClusterFunction {
 public:
  ClusterFunction(const LaplaceLoop& loop, std::vector<std::size_t> cluster) : loop_(loop), k_(std::move(cluster)) {
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
  // |det M| / prod_i |M_i,:|_2, M = diag(D_j/omega_j^2) + Q at lambda = 1: the residual of (S1) in the
  // modal form, normalised by Hadamard's bound (|det M| <= prod of the row norms), so 0 <= residual
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
  const Eigen::MatrixXcd own_slope = (H.own(s0 * (1.0 + 1e-7)) - H.own(s0 * (1.0 - 1e-7))) / (2e-7 * s0);
  for (std::size_t i = 0; i < c; ++i) N.row(i) /= own_slope(i, i);  // diag(m D')^{-1} Q
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
        if (!taken[j] && std::abs(v(j)) / v.norm() > best) best = std::abs(v(j)) / v.norm(), bi = i, bj = j;
    }
    used[bi] = taken[bj] = true;
    start[bj] = s0 - lambda1 * es.eigenvalues()(bi);
  }
  return start;
}

}  // namespace

std::vector<ModeRoot> mode_roots(const LaplaceLoop& loop, const StabilityOptions& o) {
  std::vector<ModeRoot> out;
  std::vector<bool> done(loop.modes.size(), false);
  for (std::size_t k = 0; k < loop.modes.size(); ++k) {
    const LoopMode& mk = loop.modes[k];
    if (done[k] || !(mk.frequency >= o.band_min && mk.frequency <= o.band_max)) continue;
    const std::vector<std::size_t> cluster = cluster_of(loop, k);
    const std::size_t c = cluster.size();
    for (std::size_t j : cluster) done[j] = true;
    const ClusterFunction H(loop, cluster);
    const cdouble s0 = uncoupled_root(mk);
    // trust radius: half the distance to the nearest other uncoupled root, within [1e-3, 5e-2] |s0|
    double nearest = 1e300;
    for (const LoopMode& m : loop.modes) {
      const double d = std::abs(uncoupled_root(m) - s0);
      if (d > 1e-9 * std::abs(s0)) nearest = std::min(nearest, d);
    }
    const double base_trust = std::clamp(0.5 * nearest, 1e-3 * std::abs(s0), 5e-2 * std::abs(s0));

    std::vector<ModeRoot> roots(c);
    // Newton at fixed lambda: the derivative by a central difference at the start (H is analytic),
    // then secant updates (one evaluation per iteration).
    auto newton = [&](cdouble s, double lambda, int& count) -> std::optional<cdouble> {
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
    };

    // A single mode starts at lambda = 0 from s0. A cluster's c-fold root has no tangent there:
    // its branches start at lambda1 from the first-order splitting, refined by Newton.
    const double lambda1 = c > 1 ? 1e-3 : 0.0;
    std::vector<cdouble> s(c, s0);
    bool ok = true;
    try {
      if (c > 1) s = split_cluster(H, s0, lambda1);
      for (std::size_t i = 0; i < c && ok && c > 1; ++i) {
        const auto r = newton(s[i], lambda1, roots[i].iterations);
        ok = r.has_value();
        if (ok) s[i] = *r;
      }
    } catch (const NumericalError&) {
      ok = false;
    }
    // Euler-Newton continuation: predictor along the tangent ds/dlambda = -H_lambda / H_s,
    // corrector Newton at the new lambda; accepted when the corrector stays within the trust
    // radius and within half the predictor's step (else the step is halved).
    double lambda = lambda1, step = o.max_step;
    int steps = 0;
    std::vector<cdouble> slope(c);
    bool have_slope = false;
    while (ok && lambda < 1.0) {
      const double target = std::min(1.0, lambda + step);
      try {
        if (!have_slope)
          for (std::size_t i = 0; i < c; ++i) slope[i] = H.tangent(s[i], lambda);
        have_slope = true;
      } catch (const NumericalError&) {
        ok = false;
        break;
      }
      bool accepted = true;
      std::vector<cdouble> next(c), pred(c);
      for (std::size_t i = 0; i < c; ++i) pred[i] = s[i] + (target - lambda) * slope[i];
      for (std::size_t i = 0; i < c && accepted; ++i) {
        double trust = base_trust;  // and half the distance to the other branches' predictions
        for (std::size_t j = 0; j < c; ++j)
          if (j != i) trust = std::min(trust, std::max(0.5 * std::abs(pred[i] - pred[j]), 1e-7 * std::abs(s0)));
        std::optional<cdouble> r;
        try {
          r = newton(pred[i], target, roots[i].iterations);
        } catch (const NumericalError&) {  // e.g. beyond the contact series' convergence
          r.reset();
        }
        accepted = r && std::abs(*r - pred[i]) <= trust &&
                   std::abs(*r - pred[i]) <= 0.5 * std::abs(pred[i] - s[i]) + 1e-9 * std::abs(s0);
        if (accepted) next[i] = *r;
      }
      if (accepted) {
        lambda = target, s = next;
        have_slope = false;
        ++steps;
        step = std::min(2.0 * step, o.max_step);
        continue;
      }
      step *= 0.5;
      if (step < o.min_step) break;
    }
    for (std::size_t i = 0; i < c; ++i) {
      ModeRoot& r = roots[i];
      const LoopMode& m = loop.modes[cluster[i]];
      r.mode = cluster[i];
      r.label = m.label;
      r.natural_frequency = m.frequency;
      r.s0 = s0;
      r.s = s[i];
      r.steps = steps;
      r.converged = ok && lambda >= 1.0;
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
    out.insert(out.end(), roots.begin(), roots.end());
  }
  std::sort(out.begin(), out.end(), [](const ModeRoot& a, const ModeRoot& b) { return a.mode < b.mode; });
  return out;
}

ModeRoot mode_root(const LaplaceLoop& loop, std::size_t k, const StabilityOptions& o) {
  StabilityOptions one = o;
  one.band_min = one.band_max = loop.modes.at(k).frequency;
  for (const ModeRoot& r : mode_roots(loop, one))
    if (r.mode == k) return r;
  throw NumericalError("squeal: mode not found");
}

// ---------------------------------------------------------------------------------------------
// Route 1
// ---------------------------------------------------------------------------------------------

std::vector<cdouble> coupled_eigenvalues(const Eigen::Matrix4d& C_rig, const std::vector<LoopMode>& modes,
                                         const StateSpace& rail, const StateSpace& contact, double kH,
                                         double speed) {
  const int nr = rail.states(), nc = contact.states();
  auto check_dims = [](const StateSpace& ss, int in, int out, const char* key) {
    const int n = ss.states();
    if (ss.A.cols() != n || ss.B.rows() != n || ss.B.cols() != in || ss.C.rows() != out || ss.C.cols() != n ||
        ss.D.rows() != out || ss.D.cols() != in)
      throw InputError(key, std::string(key) + ": state-space dimensions do not match (" + std::to_string(in) +
                                " inputs, " + std::to_string(out) + " outputs expected)");
  };
  check_dims(rail, 4, 4, "rail");
  check_dims(contact, 4, 3, "contact");
  if (!(kH > 0.0) || !(speed > 0.0))
    throw InputError("normal_stiffness", "route 1 needs a positive normal stiffness and speed");
  const bool rigid = C_rig.cwiseAbs().maxCoeff() > 0.0;
  const int nrig = rigid ? 8 : 0, nm = static_cast<int>(modes.size());
  // offsets: rigid (u, v^), modes (q, v^) per mode, rail, contact, F^ = F / k_H
  const int o_m = nrig, o_r = o_m + 2 * nm, o_c = o_r + nr, o_f = o_c + nc, n = o_f + 4;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
  const double w_ref = rigid ? std::sqrt(C_rig.cwiseAbs().maxCoeff() * kH) : 1.0;

  // U: the wheel's displacement u_w = U X (4 x n) over the displacement states.
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(4, n);
  if (rigid) {
    E.block(0, 0, 8, 8).setIdentity();
    M.block(0, 4, 4, 4) = w_ref * Eigen::Matrix4d::Identity();  // u' = w_ref v^
    M.block(4, o_f, 4, 4) = C_rig * kH / w_ref;                 // v^' = C_rig F / w_ref
    U.block(0, 0, 4, 4).setIdentity();
  }
  for (int k = 0; k < nm; ++k) {
    const LoopMode& m = modes[k];
    const double w = dynamics::angular(m.frequency);
    const int q = o_m + 2 * k, v = q + 1;
    E(q, q) = E(v, v) = 1.0;
    M(q, v) = w;  // q' = w v^
    M(v, q) = -w;
    M(v, v) = -2.0 * m.damping_ratio * w;
    M.block(v, o_f, 1, 4) = (kH / (m.modal_mass * w)) * m.shape.transpose();  // psi^T F / (m w)
    U.col(q) = m.shape;
  }
  // rail: x_r' = A_r x_r - B_r F
  E.block(o_r, o_r, nr, nr).setIdentity();
  M.block(o_r, o_r, nr, nr) = rail.A;
  M.block(o_r, o_f, nr, 4) = -kH * rail.B;
  // e = u_w - u_r = U X - C_r x_r + D_r F: its rate as a row block over X'
  Eigen::MatrixXd Erate = U;
  Erate.block(0, o_r, 4, nr) -= rail.C;
  Erate.block(0, o_f, 4, 4) += kH * rail.D;
  const Eigen::MatrixXd xi = Erate.bottomRows(3) / speed;  // xi = e_t' / V
  const Eigen::MatrixXd Bxi = contact.B.leftCols(3), Dxi = contact.D.leftCols(3);
  // contact: x_c' - B_xi xi = A_c x_c + B_N F_n
  E.block(o_c, o_c, nc, nc).setIdentity();
  E.middleRows(o_c, nc) -= Bxi * xi;
  M.block(o_c, o_c, nc, nc) = contact.A;
  M.block(o_c, o_f, nc, 1) = kH * contact.B.col(3);
  // normal: 0 = e_n + F_n / k_H  (C1)
  M.row(o_f) = Erate.row(0);
  M(o_f, o_f) += 1.0;
  // tangential: D_xi xi / k_H = F^_t - C_c x_c / k_H - D_N F^_n
  E.middleRows(o_f + 1, 3) = Dxi * xi / kH;
  M.block(o_f + 1, o_c, 3, nc) = -contact.C / kH;
  M.block(o_f + 1, o_f + 1, 3, 3).setIdentity();
  M.block(o_f + 1, o_f, 3, 1) -= contact.D.col(3);

  // Balance the pencil (D1 M D2, D1 E D2: the same eigenvalues) by powers of two, alternating
  // rows and columns to unit largest entry of |M| + |E| (the fitted models come in any units).
  for (int sweep = 0; sweep < 8; ++sweep) {
    for (int i = 0; i < n; ++i) {
      const double m = std::max(M.row(i).cwiseAbs().maxCoeff(), E.row(i).cwiseAbs().maxCoeff());
      if (m > 0.0) {
        const double f = std::exp2(-std::round(std::log2(m)));
        M.row(i) *= f, E.row(i) *= f;
      }
    }
    for (int j = 0; j < n; ++j) {
      const double m = std::max(M.col(j).cwiseAbs().maxCoeff(), E.col(j).cwiseAbs().maxCoeff());
      if (m > 0.0) {
        const double f = std::exp2(-std::round(std::log2(m)));
        M.col(j) *= f, E.col(j) *= f;
      }
    }
  }
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> ges(M, E, false);
  if (ges.info() != Eigen::Success) throw NumericalError("squeal route 1: QZ did not converge");
  std::vector<cdouble> out;
  const Eigen::VectorXcd alpha = ges.alphas();
  const Eigen::VectorXd beta = ges.betas();
  for (int i = 0; i < n; ++i)
    if (std::abs(beta(i)) > 1e-12 * std::abs(alpha(i))) out.push_back(alpha(i) / beta(i));
  return out;
}

}  // namespace rollnoise::noise
