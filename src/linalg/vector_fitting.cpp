#include "linalg/vector_fitting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace rollnoise::linalg {
namespace {

using cd = std::complex<double>;

// Poles are kept as representatives: a real pole (imaginary part 0) or one of a complex pair (the
// one with positive imaginary part). In units of the reference frequency w_ref (s' = s / w_ref),
// so that the basis is of order one over the band.
int pole_count(const std::vector<cd>& poles) {
  int n = 0;
  for (const cd& a : poles) n += a.imag() == 0.0 ? 1 : 2;
  return n;
}

// The real-coefficient basis (Gustavsen-Semlyen 1999, Appendix B): 1/(s - a) for a real pole, and
// 1/(s - a) + 1/(s - a*), i/(s - a) - i/(s - a*) for a pair, so that real coefficients (c', c'')
// give the residues c' + i c'' at a and c' - i c'' at a*.
Eigen::MatrixXcd basis(const Eigen::VectorXcd& s, const std::vector<cd>& poles) {
  Eigen::MatrixXcd phi(s.size(), pole_count(poles));
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    int col = 0;
    for (const cd& a : poles) {
      if (a.imag() == 0.0) {
        phi(k, col++) = 1.0 / (s(k) - a);
      } else {
        const cd q1 = 1.0 / (s(k) - a), q2 = 1.0 / (s(k) - std::conj(a));
        phi(k, col++) = q1 + q2;
        phi(k, col++) = cd(0.0, 1.0) * (q1 - q2);
      }
    }
  }
  return phi;
}

// [Re M; Im M]: the complex equations as real ones (real unknowns).
Eigen::MatrixXd stack(const Eigen::MatrixXcd& M) {
  Eigen::MatrixXd R(2 * M.rows(), M.cols());
  R << M.real(), M.imag();
  return R;
}

// Least squares with the columns scaled to unit norm first (the basis columns of distant poles
// differ by orders of magnitude), by column-pivoting QR.
Eigen::VectorXd least_squares(Eigen::MatrixXd A, const Eigen::VectorXd& b) {
  Eigen::VectorXd scale = A.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < scale.size(); ++j)
    if (!(scale(j) > 0)) scale(j) = 1.0;
  A = A * scale.cwiseInverse().asDiagonal();
  return A.colPivHouseholderQr().solve(b).cwiseQuotient(scale);
}

// The data: scaled entries H_s,e(s_k) (only entries that are not identically zero) and weights.
struct Data {
  Eigen::VectorXcd s;                      // s'_k = 2 pi i f_k / w_ref
  Eigen::VectorXd weight;                  // 1 / |H_s(f_k)|_F
  std::vector<Eigen::VectorXcd> entry;     // weighted: weight_k H_s,e(s_k)
  std::vector<std::pair<int, int>> index;  // (i, j) of each entry
};

// One pole relocation with relaxation (Gustavsen 2006, Eq. 8) in the fast QR form (Deschrijver et
// al. 2008): per entry e, the equations w (phi c_e + d_e) - w H_e (phi c~ + d~) = 0; a QR of each
// entry's block leaves R22 [c~; d~] = 0 for sigma's unknowns; the stacked R22 with the
// normalisation Re sum_k (phi_k c~ + d~) = K give c~, d~, and the new poles are the zeros of sigma,
// eig(Lambda - b c~' / d~) (Gustavsen-Semlyen 1999, Eq. A.8). Unstable poles are flipped.
std::vector<cd> relocate(const Data& d, const std::vector<cd>& poles, int& flipped) {
  const Eigen::MatrixXcd phi = basis(d.s, poles);
  const Eigen::Index K = d.s.size(), N = phi.cols();
  const Eigen::Index E = static_cast<Eigen::Index>(d.entry.size());
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(E * (N + 1) + 1, N + 1);
  double norm2 = 0.0;
  for (Eigen::Index e = 0; e < E; ++e) {
    const Eigen::VectorXcd& h = d.entry[e];
    Eigen::MatrixXcd M(K, 2 * N + 2);
    M.leftCols(N) = d.weight.asDiagonal() * phi;
    M.col(N) = d.weight.cast<cd>();
    M.middleCols(N + 1, N) = -(h.asDiagonal() * phi);
    M.col(2 * N + 1) = -h;
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(stack(M));
    big.block(e * (N + 1), 0, N + 1, N + 1) =
        qr.matrixQR().block(N + 1, N + 1, N + 1, N + 1).triangularView<Eigen::Upper>();
    norm2 += h.squaredNorm();
  }
  const double scale = std::sqrt(norm2) / double(K);
  big.block(E * (N + 1), 0, 1, N) = scale * phi.colwise().sum().real();
  big(E * (N + 1), N) = scale * double(K);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(big.rows());
  rhs(E * (N + 1)) = scale * double(K);
  Eigen::VectorXd x = least_squares(big, rhs);
  Eigen::VectorXd ct = x.head(N);
  double dt = x(N);
  if (!(std::abs(dt) >
        1e-8)) {  // d~ ~ 0: the relaxed solution is degenerate, fix d~ = 1 (1999 form)
    const Eigen::MatrixXd A = big.topRows(E * (N + 1));
    ct = least_squares(A.leftCols(N), -A.col(N));
    dt = 1.0;
  }
  // zeros of sigma = d~ + sum c~_n phi_n: Lambda real block-diagonal, b = 1 (real) or (2, 0) (pair)
  Eigen::MatrixXd Lambda = Eigen::MatrixXd::Zero(N, N);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(N);
  int col = 0;
  for (const cd& a : poles) {
    if (a.imag() == 0.0) {
      Lambda(col, col) = a.real(), b(col) = 1.0;
      ++col;
    } else {
      Lambda(col, col) = Lambda(col + 1, col + 1) = a.real();
      Lambda(col, col + 1) = a.imag(), Lambda(col + 1, col) = -a.imag();
      b(col) = 2.0;
      col += 2;
    }
  }
  const Eigen::VectorXcd z =
      Eigen::EigenSolver<Eigen::MatrixXd>(Lambda - b * ct.transpose() / dt, false).eigenvalues();
  std::vector<cd> out;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    cd a = z(i);
    if (a.imag() < 0.0) continue;                                 // the pair's other half
    if (a.real() > 0.0) a = cd(-a.real(), a.imag()), ++flipped;   // flip into the left half-plane
    if (a.real() == 0.0) a = cd(-1e-12 * std::abs(a), a.imag());  // strictly stable
    out.push_back(a);
  }
  // EigenSolver returns exact conjugate pairs (real Schur form); guard against a lost partner
  if (pole_count(out) != N) {
    out.clear();
    for (Eigen::Index i = 0; i < z.size(); ++i)
      out.push_back(cd(-std::abs(z(i).real()) - 1e-12 * std::abs(z(i)), 0.0));
  }
  std::sort(out.begin(), out.end(), [](cd a, cd b) { return std::abs(a) < std::abs(b); });
  return out;
}

// The residues and constant term of each entry for fixed poles (linear least squares, weighted).
Eigen::MatrixXd fit_residues(const Data& d, const Eigen::MatrixXcd& phi) {
  const Eigen::Index N = phi.cols();
  Eigen::MatrixXcd M(d.s.size(), N + 1);
  M.leftCols(N) = d.weight.asDiagonal() * phi;
  M.col(N) = d.weight.cast<cd>();
  const Eigen::MatrixXd A = stack(M);
  Eigen::VectorXd scale = A.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < scale.size(); ++j)
    if (!(scale(j) > 0)) scale(j) = 1.0;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A * scale.cwiseInverse().asDiagonal());
  Eigen::MatrixXd coef(N + 1, d.entry.size());
  for (size_t e = 0; e < d.entry.size(); ++e)
    coef.col(e) = qr.solve(stack(d.entry[e])).cwiseQuotient(scale);
  return coef;
}

// Max over k of the relative (weighted, Frobenius) error of the pole-residue model.
double weighted_error(const Data& d, const Eigen::MatrixXcd& phi, const Eigen::MatrixXd& coef) {
  Eigen::VectorXd err2 = Eigen::VectorXd::Zero(d.s.size());
  const Eigen::Index N = phi.cols();
  for (size_t e = 0; e < d.entry.size(); ++e) {
    const Eigen::VectorXcd fit =
        d.weight.asDiagonal() *
        (phi * coef.col(e).head(N).cast<cd>() + Eigen::VectorXcd::Constant(d.s.size(), coef(N, e)));
    err2 += (fit - d.entry[e]).cwiseAbs2();
  }
  return std::sqrt(err2.maxCoeff());  // the weights make |H_s(f_k)|_F = 1
}

std::vector<cd> starting_poles(int n, double lo, double hi) {
  // complex pairs with imaginary parts log-spaced over [lo, hi] and real parts 1/100 of them
  // (Gustavsen-Semlyen 1999, Sec. IV), one real pole at -lo for odd n
  std::vector<cd> p;
  const int pairs = n / 2;
  for (int i = 0; i < pairs; ++i) {
    const double u = pairs == 1 ? 0.5 : double(i) / double(pairs - 1);
    const double beta = lo * std::pow(hi / lo, u);
    p.emplace_back(-beta / 100.0, beta);
  }
  if (n % 2) p.emplace_back(-lo, 0.0);
  return p;
}

// The real realisation of D + sum_n R_n/(s - a_n): per pole, the residue's SVD R = U S V^H keeps
// its rank r (singular values above 1e-13 of the largest) as r states (real pole: a I_r, B = S^1/2
// V', C = U S^1/2) or r complex states x' = a x + b u, y = 2 Re(c x), c = U_l S_l^1/2, b = S_l^1/2
// V_l^H, in real form [xr; xi]' = [[Re a, -Im a], [Im a, Re a]] [xr; xi] + [Re b; Im b] u, y = 2
// (Re c xr - Im c xi).
StateSpace realise(const std::vector<cd>& poles, const std::vector<Eigen::MatrixXcd>& residues,
                   const Eigen::MatrixXd& D) {
  const Eigen::Index p = D.rows(), m = D.cols();
  std::vector<Eigen::MatrixXd> Ab, Bb, Cb;
  for (size_t n = 0; n < poles.size(); ++n) {
    const cd a = poles[n];
    if (a.imag() == 0.0) {  // a real residue: the real SVD
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(residues[n].real(),
                                            Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Eigen::VectorXd sv = svd.singularValues();
      int r = 0;
      while (r < sv.size() && sv(r) > 1e-13 * sv(0)) ++r;
      Ab.push_back(a.real() * Eigen::MatrixXd::Identity(r, r));
      Bb.push_back(sv.head(r).cwiseSqrt().asDiagonal() * svd.matrixV().leftCols(r).transpose());
      Cb.push_back(svd.matrixU().leftCols(r) * sv.head(r).cwiseSqrt().asDiagonal());
    } else {
      Eigen::JacobiSVD<Eigen::MatrixXcd> svd(residues[n],
                                             Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Eigen::VectorXd sv = svd.singularValues();
      int r = 0;
      while (r < sv.size() && sv(r) > 1e-13 * sv(0)) ++r;
      const Eigen::MatrixXcd c = svd.matrixU().leftCols(r) * sv.head(r).cwiseSqrt().asDiagonal();
      const Eigen::MatrixXcd b =
          sv.head(r).cwiseSqrt().asDiagonal() * svd.matrixV().leftCols(r).adjoint();
      for (int l = 0; l < r; ++l) {
        Eigen::Matrix2d A2;
        A2 << a.real(), -a.imag(), a.imag(), a.real();
        Eigen::MatrixXd B2(2, m), C2(p, 2);
        B2 << b.row(l).real(), b.row(l).imag();
        C2 << 2.0 * c.col(l).real(), -2.0 * c.col(l).imag();
        Ab.push_back(A2);
        Bb.push_back(B2);
        Cb.push_back(C2);
      }
    }
  }
  Eigen::Index n = 0;
  for (const auto& a : Ab) n += a.rows();
  StateSpace ss;
  ss.A = Eigen::MatrixXd::Zero(n, n), ss.B.resize(n, m), ss.C.resize(p, n), ss.D = D;
  Eigen::Index at = 0;
  for (size_t i = 0; i < Ab.size(); ++i) {
    const Eigen::Index r = Ab[i].rows();
    ss.A.block(at, at, r, r) = Ab[i];
    ss.B.middleRows(at, r) = Bb[i];
    ss.C.middleCols(at, r) = Cb[i];
    at += r;
  }
  return ss;
}

}  // namespace

double relative_response_error(const std::vector<Eigen::MatrixXcd>& H,
                               const std::vector<Eigen::MatrixXcd>& Hm, const IoScaling& s,
                               size_t* at) {
  double worst = -1.0;
  for (size_t k = 0; k < H.size(); ++k) {
    const Eigen::MatrixXcd Hs =
        s.output.cwiseInverse().asDiagonal() * H[k] * s.input.cwiseInverse().asDiagonal();
    const Eigen::MatrixXcd dH =
        s.output.cwiseInverse().asDiagonal() * (Hm[k] - H[k]) * s.input.cwiseInverse().asDiagonal();
    const double ref = Hs.norm();
    const double e = ref > 0 ? dH.norm() / ref : dH.norm();
    if (e > worst) {
      worst = e;
      if (at) *at = k;
    }
  }
  return std::max(worst, 0.0);
}

namespace {

// The frequency range of the samples (checked): the highest f and the lowest positive one.
std::pair<double, double> sample_range(const std::vector<double>& frequency, const std::vector<Eigen::MatrixXcd>& H) {
  const size_t K = frequency.size();
  if (K < 2 || H.size() != K)
    throw std::invalid_argument("fit_rational: need two or more samples, one per frequency");
  for (const auto& h : H)
    if (h.rows() != H[0].rows() || h.cols() != H[0].cols())
      throw std::invalid_argument("fit_rational: samples differ in size");
  double f_max = 0.0, f_lo = std::numeric_limits<double>::infinity();
  for (double f : frequency) {
    if (!(f >= 0.0) || !std::isfinite(f))
      throw std::invalid_argument("fit_rational: frequencies must be >= 0");
    f_max = std::max(f_max, f);
    if (f > 0) f_lo = std::min(f_lo, f);
  }
  if (!(f_max > 0)) throw std::invalid_argument("fit_rational: no positive frequency");
  return {f_max, f_lo};
}

// The fit's data: s'_k = i f_k / f_max, the samples scaled by `sc` and weighted by 1/|H_s(f_k)|_F,
// one weighted vector per entry that is not zero everywhere (|H_ij| peak > 0).
Data scaled_data(const std::vector<double>& frequency, const std::vector<Eigen::MatrixXcd>& H, double f_max,
                 const IoScaling& sc, const Eigen::MatrixXd& peak) {
  const size_t K = frequency.size();
  Data d;
  d.s.resize(K);
  d.weight.resize(K);
  std::vector<Eigen::MatrixXcd> Hs(K);
  for (size_t k = 0; k < K; ++k) {
    d.s(k) = cd(0.0, frequency[k] / f_max);
    Hs[k] = sc.output.cwiseInverse().asDiagonal() * H[k] * sc.input.cwiseInverse().asDiagonal();
    const double nk = Hs[k].norm();
    d.weight(k) = nk > 0 ? 1.0 / nk : 1.0;
  }
  for (Eigen::Index i = 0; i < peak.rows(); ++i)
    for (Eigen::Index j = 0; j < peak.cols(); ++j) {
      if (peak(i, j) == 0.0) continue;  // fitted as 0
      Eigen::VectorXcd e(K);
      for (size_t k = 0; k < K; ++k) e(k) = d.weight(k) * Hs[k](i, j);
      d.entry.push_back(e);
      d.index.emplace_back(int(i), int(j));
    }
  return d;
}

// The best fit over the orders (poles in units of w_ref): pole_step, 2 pole_step, ... poles, at
// most K - 1 (the QR blocks need K >= N + 1), until the weighted error reaches the target.
struct OrderFit {
  std::vector<cd> poles;
  Eigen::MatrixXd coef;
  int flipped = 0;
};
OrderFit best_order(const Data& d, double lo, const RationalFitOptions& o) {
  OrderFit best;
  if (d.entry.empty()) {  // H = 0: the zero model
    best.coef = Eigen::MatrixXd::Zero(1, 0);
    return best;
  }
  const int max_poles = std::max(1, std::min(o.max_poles, int(d.s.size()) - 1));
  const int step = std::max(1, o.pole_step);
  double best_err = std::numeric_limits<double>::infinity();
  for (int n = std::min(step, max_poles); n <= max_poles; n += step) {
    std::vector<cd> poles = starting_poles(n, lo, 1.0);
    int flipped = 0;
    for (int it = 0; it < o.iterations; ++it) {
      const std::vector<cd> next = relocate(d, poles, flipped);
      double moved = 0.0;
      for (size_t i = 0; i < next.size() && i < poles.size(); ++i)
        moved = std::max(moved, std::abs(next[i] - poles[i]) / std::abs(next[i]));
      poles = next;
      if (it >= 2 && moved < 1e-10) break;  // converged
    }
    const Eigen::MatrixXcd phi = basis(d.s, poles);
    const Eigen::MatrixXd coef = fit_residues(d, phi);
    const double err = weighted_error(d, phi, coef);
    if (err < best_err) best_err = err, best.poles = poles, best.coef = coef, best.flipped = flipped;
    if (best_err <= o.target) break;
  }
  return best;
}

// The state space of a fit in physical units: poles w_ref a', residues R = w_ref so_i si_j R',
// D = so_i si_j d'; the realisation, and the poles with their conjugates.
void physical_model(const OrderFit& f, const Data& d, double w_ref, Eigen::Index p, Eigen::Index m, RationalFit& out) {
  const IoScaling& sc = out.scaling;
  const int N = pole_count(f.poles);
  std::vector<Eigen::MatrixXcd> residues(f.poles.size(), Eigen::MatrixXcd::Zero(p, m));
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(p, m);
  for (size_t e = 0; e < d.index.size(); ++e) {
    const auto [i, j] = d.index[e];
    const double u = sc.output(i) * sc.input(j);
    int col = 0;
    for (size_t n = 0; n < f.poles.size(); ++n) {
      if (f.poles[n].imag() == 0.0) {
        residues[n](i, j) = w_ref * u * f.coef(col++, e);
      } else {
        residues[n](i, j) = w_ref * u * cd(f.coef(col, e), f.coef(col + 1, e));
        col += 2;
      }
    }
    D(i, j) = u * f.coef(N, e);
  }
  std::vector<cd> poles_phys;
  for (cd a : f.poles) poles_phys.push_back(w_ref * a);
  out.model = realise(poles_phys, residues, D);
  for (cd a : poles_phys) {
    out.poles.push_back(a);
    if (a.imag() != 0.0) out.poles.push_back(std::conj(a));
  }
  out.flipped = f.flipped;
}

}  // namespace

RationalFit fit_rational(const std::vector<double>& frequency,
                         const std::vector<Eigen::MatrixXcd>& H, const RationalFitOptions& o) {
  const auto [f_max, f_lo] = sample_range(frequency, H);
  const size_t K = frequency.size();
  const Eigen::Index p = H[0].rows(), m = H[0].cols();
  const double w_ref = 2.0 * M_PI * f_max;
  const double lo = std::max(f_lo / f_max, 1e-4);  // starting poles from the lowest sample (relative)

  RationalFit best;
  Eigen::MatrixXd peak = Eigen::MatrixXd::Zero(p, m);
  for (const auto& h : H) peak = peak.cwiseMax(h.cwiseAbs());
  best.scaling =
      o.scaling.output.size() == p && o.scaling.input.size() == m ? o.scaling : equilibrate(peak);
  const IoScaling& sc = best.scaling;
  const Data d = scaled_data(frequency, H, f_max, sc, peak);
  physical_model(best_order(d, lo, o), d, w_ref, p, m, best);

  // the reported errors, from the realised model
  std::vector<Eigen::MatrixXcd> Hm(K);
  for (size_t k = 0; k < K; ++k) Hm[k] = best.model.frequency_response(frequency[k]);
  size_t at = 0;
  best.error = relative_response_error(H, Hm, sc, &at);
  best.worst_frequency = frequency[at];
  for (size_t k = 0; k < K; ++k)
    for (Eigen::Index i = 0; i < p; ++i)
      for (Eigen::Index j = 0; j < m; ++j)
        if (peak(i, j) > 0)
          best.element_error =
              std::max(best.element_error, std::abs(Hm[k](i, j) - H[k](i, j)) / peak(i, j));
  best.reached_target = best.error <= o.target;
  return best;
}

}  // namespace rollnoise::linalg
