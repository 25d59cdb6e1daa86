// Route 1 of the loop's stability (stability.hpp, docs/squeal.md Sec. 4): the rational models of
// the rail and of the contact coupled with the wheel's modal state space; the finite eigenvalues of
// the descriptor system E X' = M X (real QZ).
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "noise/stability.hpp"

namespace rollnoise::noise {

namespace {

bool has_dimensions(const StateSpace& ss, int in, int out) {
  const int n = ss.states();
  return ss.A.cols() == n && ss.B.rows() == n && ss.B.cols() == in && ss.C.rows() == out &&
         ss.C.cols() == n && ss.D.rows() == out && ss.D.cols() == in;
}

// The pencil (E, M) over the unknowns X = (rigid (u, v^), modes (q, v^) per mode, rail, contact,
// F^ = F / k_H).
struct Pencil {
  Eigen::MatrixXd E, M;
  int o_m = 0, o_r = 0, o_c = 0, o_f = 0, n = 0;  // offsets of modes, rail, contact, forces; size
};

// The wheel's rows (rigid wheelset and modes; exact) and U: its displacement u_w = U X (4 x n).
Eigen::MatrixXd wheel_rows(Pencil& p, const Eigen::MatrixXd& C_rig,
                           const std::vector<LoopMode>& modes, double kH) {
  Eigen::MatrixXd& E = p.E;
  Eigen::MatrixXd& M = p.M;
  const bool rigid = p.o_m > 0;
  const double w_ref = rigid ? std::sqrt(C_rig.cwiseAbs().maxCoeff() * kH) : 1.0;
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(4, p.n);
  if (rigid) {
    E.block(0, 0, 8, 8).setIdentity();
    M.block(0, 4, 4, 4) = w_ref * Eigen::Matrix4d::Identity();  // u' = w_ref v^
    M.block(4, p.o_f, 4, 4) = C_rig * kH / w_ref;               // v^' = C_rig F / w_ref
    U.block(0, 0, 4, 4).setIdentity();
  }
  for (int k = 0; k < static_cast<int>(modes.size()); ++k) {
    const LoopMode& m = modes[k];
    const double w = dynamics::angular(m.frequency);
    const int q = p.o_m + 2 * k, v = q + 1;
    E(q, q) = E(v, v) = 1.0;
    M(q, v) = w;  // q' = w v^
    M(v, q) = -w;
    M(v, v) = -2.0 * m.damping_ratio * w;
    M.block(v, p.o_f, 1, 4) = (kH / (m.modal_mass * w)) * m.shape.transpose();  // psi^T F / (m w)
    U.col(q) = m.shape;
  }
  return U;
}

// The rail's rows, the contact's rows and the closing rows of the forces (normal (C1),
// tangential), given the wheel's displacement U.
void rail_and_contact_rows(Pencil& p, const Eigen::MatrixXd& U, const StateSpace& rail,
                           const StateSpace& contact, double kH, double speed) {
  Eigen::MatrixXd& E = p.E;
  Eigen::MatrixXd& M = p.M;
  const int nr = rail.states(), nc = contact.states(), o_r = p.o_r, o_c = p.o_c, o_f = p.o_f;
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
}

// Balance the pencil (D1 M D2, D1 E D2: the same eigenvalues) by powers of two, alternating rows
// and columns to unit largest entry of |M| + |E| (the fitted models come in any units).
void balance(Eigen::MatrixXd& M, Eigen::MatrixXd& E) {
  const Eigen::Index n = M.rows();
  for (int sweep = 0; sweep < 8; ++sweep) {
    for (Eigen::Index i = 0; i < n; ++i) {
      const double m = std::max(M.row(i).cwiseAbs().maxCoeff(), E.row(i).cwiseAbs().maxCoeff());
      if (m > 0.0) {
        const double f = std::exp2(-std::round(std::log2(m)));
        M.row(i) *= f, E.row(i) *= f;
      }
    }
    for (Eigen::Index j = 0; j < n; ++j) {
      const double m = std::max(M.col(j).cwiseAbs().maxCoeff(), E.col(j).cwiseAbs().maxCoeff());
      if (m > 0.0) {
        const double f = std::exp2(-std::round(std::log2(m)));
        M.col(j) *= f, E.col(j) *= f;
      }
    }
  }
}

// The finite generalised eigenvalues of (M, E) (real QZ); infinite ones (|beta| <= 1e-12 |alpha|)
// dropped.
std::vector<cdouble> finite_eigenvalues(const Eigen::MatrixXd& M, const Eigen::MatrixXd& E) {
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> ges(M, E, false);
  if (ges.info() != Eigen::Success) throw NumericalError("squeal route 1: QZ did not converge");
  std::vector<cdouble> out;
  const Eigen::VectorXcd alpha = ges.alphas();
  const Eigen::VectorXd beta = ges.betas();
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    if (std::abs(beta(i)) > 1e-12 * std::abs(alpha(i))) out.push_back(alpha(i) / beta(i));
  return out;
}

}  // namespace

std::vector<cdouble> coupled_eigenvalues(const Eigen::MatrixXd& C_rig,
                                         const std::vector<LoopMode>& modes, const StateSpace& rail,
                                         const StateSpace& contact, double kH, double speed) {
  // The models come from the pipeline's fits (pipeline/squeal.cpp), k_H from Hertz and the speed
  // from the checked case: a mismatch is a programming error.
  ROLLNOISE_ASSERT(has_dimensions(rail, 4, 4),
                   "route 1: the rail model needs 4 inputs and 4 outputs");
  ROLLNOISE_ASSERT(has_dimensions(contact, 4, 3),
                   "route 1: the contact model needs 4 inputs and 3 outputs");
  ROLLNOISE_ASSERT(kH > 0.0 && speed > 0.0, "route 1 needs a positive normal stiffness and speed");
  ROLLNOISE_ASSERT(C_rig.rows() == 4 && C_rig.cols() == 4,
                   "route 1: one contact (a 4 x 4 rigid flexibility)");
  for (const LoopMode& m : modes)
    ROLLNOISE_ASSERT(m.shape.size() == 4, "route 1: one contact (4-vector mode shapes)");
  Pencil p;
  p.o_m = C_rig.cwiseAbs().maxCoeff() > 0.0 ? 8 : 0;
  p.o_r = p.o_m + 2 * static_cast<int>(modes.size());
  p.o_c = p.o_r + rail.states();
  p.o_f = p.o_c + contact.states();
  p.n = p.o_f + 4;
  p.E = Eigen::MatrixXd::Zero(p.n, p.n);
  p.M = Eigen::MatrixXd::Zero(p.n, p.n);
  const Eigen::MatrixXd U = wheel_rows(p, C_rig, modes, kH);
  rail_and_contact_rows(p, U, rail, contact, kH, speed);
  balance(p.M, p.E);
  return finite_eigenvalues(p.M, p.E);
}

}  // namespace rollnoise::noise
