#include "linalg/state_space.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace rollnoise::linalg {

using cd = std::complex<double>;

Eigen::MatrixXcd StateSpace::response(cd s) const {
  const int n = order();
  Eigen::MatrixXcd H = D.cast<cd>();
  if (n == 0) return H;
  const Eigen::MatrixXcd M = s * Eigen::MatrixXcd::Identity(n, n) - A.cast<cd>();
  H += C.cast<cd>() * M.partialPivLu().solve(B.cast<cd>());
  return H;
}

Eigen::MatrixXcd StateSpace::frequency_response(double frequency) const {
  return response(cd(0.0, 2.0 * M_PI * frequency));
}

Eigen::MatrixXcd StateSpace::discrete_frequency_response(double frequency, double dt) const {
  return response(std::polar(1.0, 2.0 * M_PI * frequency * dt));
}

StateSpace bilinear_discretisation(const StateSpace& c, double dt) {
  // Franklin-Powell-Workman Eq. 6.48: s' = a (z - 1)/(z + 1), a = 2/dt; (s'I - A)^{-1} in z gives
  // the four matrices below (the sqrt(2a) split between B and C keeps them balanced).
  const double a = 2.0 / dt;
  const Eigen::Index n = c.A.rows();
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd M = (a * I - c.A).partialPivLu().inverse();  // n small: the fit's order
  StateSpace d;
  d.A = M * (a * I + c.A);
  const Eigen::MatrixXd MB = M * c.B;
  d.B = std::sqrt(2.0 * a) * MB;
  d.C = std::sqrt(2.0 * a) * (c.C * M);
  d.D = c.D + c.C * MB;
  return d;
}

std::vector<Eigen::MatrixXd> StateSpace::markov_parameters(int count) const {
  std::vector<Eigen::MatrixXd> h;
  if (count <= 0) return h;
  h.push_back(D);
  Eigen::MatrixXd AkB = B;
  for (int j = 1; j < count; ++j) {
    h.push_back(C * AkB);
    AkB = A * AkB;
  }
  return h;
}

std::vector<Eigen::VectorXd> simulate_first_order_hold(const StateSpace& m, double h,
                                                       const std::vector<Eigen::VectorXd>& u) {
  // exp(M h), M = [[A, B, 0], [0, 0, I/h], [0, 0, 0]] acting on (x, u_k, u_{k+1} - u_k): the input
  // u_k + (u_{k+1} - u_k) t/h over the step gives x_{k+1} = Phi x_k + G1 u_k + G2 (u_{k+1} - u_k)
  // with [Phi, G1, G2] the first block row of exp(M h).
  const int n = m.order(), q = m.inputs();
  std::vector<Eigen::VectorXd> y;
  y.reserve(u.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 2 * q, n + 2 * q);
  M.topLeftCorner(n, n) = m.A * h;
  M.block(0, n, n, q) = m.B * h;
  M.block(n, n + q, q, q) = Eigen::MatrixXd::Identity(q, q);
  const Eigen::MatrixXd E = M.exp();
  const Eigen::MatrixXd Phi = E.topLeftCorner(n, n), G1 = E.block(0, n, n, q),
                        G2 = E.block(0, n + q, n, q);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < u.size(); ++k) {
    y.push_back(m.C * x + m.D * u[k]);
    if (k + 1 < u.size()) x = Phi * x + G1 * u[k] + G2 * (u[k + 1] - u[k]);
  }
  return y;
}

IoScaling equilibrate(const Eigen::MatrixXd& peak) {
  const int p = static_cast<int>(peak.rows()), m = static_cast<int>(peak.cols());
  IoScaling s{Eigen::VectorXd::Ones(p), Eigen::VectorXd::Ones(m)};
  Eigen::MatrixXd P = peak.cwiseAbs();
  for (int it = 0; it < 40; ++it) {
    Eigen::VectorXd r = P.rowwise().maxCoeff(), c = P.colwise().maxCoeff().transpose();
    for (int i = 0; i < p; ++i) r(i) = r(i) > 0 ? std::sqrt(r(i)) : 1.0;
    for (int j = 0; j < m; ++j) c(j) = c(j) > 0 ? std::sqrt(c(j)) : 1.0;
    P = r.cwiseInverse().asDiagonal() * P * c.cwiseInverse().asDiagonal();
    s.output = s.output.cwiseProduct(r);
    s.input = s.input.cwiseProduct(c);
    if ((r.array() - 1.0).abs().maxCoeff() < 1e-6 && (c.array() - 1.0).abs().maxCoeff() < 1e-6)
      break;
  }
  return s;
}

Realisation eigensystem_realisation(const std::vector<Eigen::MatrixXd>& markov, double tolerance) {
  if (markov.empty()) throw std::invalid_argument("eigensystem_realisation: no Markov parameters");
  const int p = static_cast<int>(markov[0].rows()), m = static_cast<int>(markov[0].cols());
  Realisation r;
  Eigen::MatrixXd peak = Eigen::MatrixXd::Zero(p, m);
  for (const auto& h : markov) peak = peak.cwiseMax(h.cwiseAbs());
  r.scaling = equilibrate(peak);
  const Eigen::VectorXd so = r.scaling.output, si = r.scaling.input;
  std::vector<Eigen::MatrixXd> hs;
  for (const auto& h : markov)
    hs.push_back(so.cwiseInverse().asDiagonal() * h * si.cwiseInverse().asDiagonal());
  r.model.D = markov[0];
  // H_1 ... H_L: Hankel matrices of `rows` x `cols` blocks use H_1 ... H_{rows+cols} (the shifted
  // one; a short sequence is continued by zeros)
  const int L = static_cast<int>(markov.size()) - 1;
  const int rows = std::max(1, L / 2), cols = std::max(1, L - rows);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(p, m);  // beyond the given sequence (decayed)
  auto block = [&](int j) -> const Eigen::MatrixXd& { return j <= L ? hs[j] : zero; };
  Eigen::MatrixXd H0(rows * p, cols * m), H1(rows * p, cols * m);
  for (int a = 0; a < rows; ++a)
    for (int b = 0; b < cols; ++b) {
      H0.block(a * p, b * m, p, m) = block(a + b + 1);
      H1.block(a * p, b * m, p, m) = block(a + b + 2);
    }
  Eigen::BDCSVD<Eigen::MatrixXd> svd(H0, Eigen::ComputeThinU | Eigen::ComputeThinV);
  r.singular_values = svd.singularValues();
  const Eigen::VectorXd& sv = r.singular_values;
  int n = 0;
  while (n < sv.size() && sv(n) > tolerance * sv(0)) ++n;
  const Eigen::VectorXd sq = sv.head(n).cwiseSqrt(), isq = sq.cwiseInverse();
  const Eigen::MatrixXd Un = svd.matrixU().leftCols(n), Vn = svd.matrixV().leftCols(n);
  r.model.A =
      isq.asDiagonal() * (Un.transpose() * H1 * Vn) * isq.asDiagonal();  // Juang-Pappa Eq. 21
  r.model.B = (sq.asDiagonal() * Vn.transpose()).leftCols(m) * si.asDiagonal();
  r.model.C = so.asDiagonal() * (Un * sq.asDiagonal()).topRows(p);
  // the check: the realisation's Markov parameters against the given ones (scaled)
  double err = 0.0, ref = 0.0;
  Eigen::MatrixXd AkB = r.model.B;
  for (int j = 1; j <= L; ++j) {
    const Eigen::MatrixXd hj =
        so.cwiseInverse().asDiagonal() * (r.model.C * AkB) * si.cwiseInverse().asDiagonal();
    err = std::max(err, (hj - hs[j]).norm());
    ref = std::max(ref, hs[j].norm());
    AkB = r.model.A * AkB;
  }
  r.markov_error = ref > 0 ? err / ref : err;
  return r;
}

}  // namespace rollnoise::linalg
