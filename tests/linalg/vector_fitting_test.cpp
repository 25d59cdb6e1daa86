// linalg::fit_rational (vector fitting with relaxation and pole flipping), the state-space helpers
// and the Eigensystem Realization Algorithm on systems whose answers are known.
#include "linalg/vector_fitting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "linalg/state_space.hpp"

namespace {

using namespace rollnoise::linalg;
using cd = std::complex<double>;

std::vector<double> log_axis(double f0, double f1, int n) {
  std::vector<double> f;
  for (int i = 0; i < n; ++i) f.push_back(f0 * std::pow(f1 / f0, double(i) / (n - 1)));
  return f;
}

// D + sum_n R_n/(s - a_n) + conjugates for the complex poles.
struct PoleResidue {
  std::vector<cd> poles;  // complex ones once (the conjugate is implied)
  std::vector<Eigen::MatrixXcd> residues;
  Eigen::MatrixXd D;
  Eigen::MatrixXcd at(double f) const {
    const cd s(0.0, 2.0 * M_PI * f);
    Eigen::MatrixXcd H = D.cast<cd>();
    for (size_t n = 0; n < poles.size(); ++n) {
      H += residues[n] / (s - poles[n]);
      if (poles[n].imag() != 0.0) H += residues[n].conjugate() / (s - std::conj(poles[n]));
    }
    return H;
  }
};

PoleResidue random_system(std::mt19937_64& rng, const std::vector<cd>& poles, int p, int m) {
  std::normal_distribution<double> g(0.0, 1.0);
  PoleResidue sys;
  sys.poles = poles;
  sys.D = Eigen::MatrixXd::NullaryExpr(p, m, [&] { return g(rng); });
  for (const cd& a : poles) {
    Eigen::MatrixXcd R(p, m);
    for (int i = 0; i < p; ++i)
      for (int j = 0; j < m; ++j)
        R(i, j) = std::abs(a) * (a.imag() == 0.0 ? cd(g(rng), 0.0) : cd(g(rng), g(rng)));
    sys.residues.push_back(R);
  }
  return sys;
}

TEST(VectorFitting, AKnownStableRationalSystemIsRecoveredToRoundOff) {
  std::mt19937_64 rng(12);
  const double w = 2.0 * M_PI;
  const std::vector<cd> poles = {
      {-w * 40.0, 0.0}, {-w * 30.0, w * 300.0}, {-w * 400.0, w * 2000.0}, {-w * 900.0, 0.0}};
  const PoleResidue sys = random_system(rng, poles, 3, 4);
  const std::vector<double> f = log_axis(1.0, 1e4, 300);
  std::vector<Eigen::MatrixXcd> H;
  for (double fk : f) H.push_back(sys.at(fk));
  RationalFitOptions o;
  o.target = 1e-12;
  const RationalFit fit = fit_rational(f, H, o);
  EXPECT_LT(fit.error, 1e-11) << "order " << fit.model.order();
  // the six poles (two pairs and two real), found to near round-off
  ASSERT_EQ(fit.poles.size(), 6u);
  std::vector<cd> expected;
  for (const cd& a : poles) {
    expected.push_back(a);
    if (a.imag() != 0.0) expected.push_back(std::conj(a));
  }
  for (const cd& a : expected) {
    double nearest = 1e300;
    for (const cd& b : fit.poles) nearest = std::min(nearest, std::abs(a - b) / std::abs(a));
    EXPECT_LT(nearest, 1e-9) << a;
  }
  // full-rank random residues: the minimal real realisation has 3 + 6 + 6 + 3 states
  EXPECT_EQ(fit.model.order(), 18);
  EXPECT_EQ(fit.flipped, 0);
  // the response between and beyond the samples
  for (double fk : {0.0, 7.3, 333.3, 2222.0, 2e4}) {
    const Eigen::MatrixXcd d = fit.model.frequency_response(fk) - sys.at(fk);
    EXPECT_LT(d.norm() / sys.at(fk).norm(), 1e-9) << fk;
  }
  for (cd a : fit.poles) EXPECT_LT(a.real(), 0.0);
}

TEST(VectorFitting, AnUnstablePoleIsFlippedIntoTheLeftHalfPlane) {
  std::mt19937_64 rng(7);
  const double w = 2.0 * M_PI;
  // a growing oscillation at 500 Hz (Re a > 0) and a stable real pole
  const PoleResidue sys = random_system(rng, {{w * 20.0, w * 500.0}, {-w * 100.0, 0.0}}, 2, 2);
  const std::vector<double> f = log_axis(10.0, 5e3, 200);
  std::vector<Eigen::MatrixXcd> H;
  for (double fk : f) H.push_back(sys.at(fk));
  RationalFitOptions o;
  o.target = 1e-12;
  o.max_poles = 12;
  const RationalFit fit = fit_rational(f, H, o);
  EXPECT_GT(fit.flipped, 0);
  for (cd a : fit.poles) EXPECT_LT(a.real(), 0.0) << a;
  for (int i = 0; i < fit.model.order(); ++i) {
    const Eigen::VectorXcd ev = fit.model.A.eigenvalues();
    EXPECT_LT(ev(i).real(), 0.0);
  }
  // a stable model cannot have the unstable response's phase: the error says so, and it is the true
  // one
  std::vector<Eigen::MatrixXcd> Hm;
  for (double fk : f) Hm.push_back(fit.model.frequency_response(fk));
  EXPECT_NEAR(fit.error, relative_response_error(H, Hm, fit.scaling), 1e-14);
  EXPECT_FALSE(fit.reached_target);
  EXPECT_GT(fit.error, 1e-6);
}

TEST(VectorFitting, ANoisyDelayedResponseReportsItsTrueFitError) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  const double tau = 2e-4, w0 = 2.0 * M_PI * 800.0, noise = 1e-4;
  const std::vector<double> f = log_axis(5.0, 4e3, 250);
  std::vector<Eigen::MatrixXcd> H;
  for (double fk : f) {
    const cd s(0.0, 2.0 * M_PI * fk);
    Eigen::MatrixXcd h(1, 2);
    h(0, 0) = std::exp(-s * tau) / (1.0 + s / w0);                  // a delay: not rational
    h(0, 1) = 3e5 / (s + w0) * (1.0 + noise * cd(g(rng), g(rng)));  // noisy
    H.push_back(h);
  }
  RationalFitOptions o;
  o.target = 1e-9;
  o.max_poles = 30;
  const RationalFit fit = fit_rational(f, H, o);
  std::vector<Eigen::MatrixXcd> Hm;
  for (double fk : f) Hm.push_back(fit.model.frequency_response(fk));
  size_t at = 0;
  const double truth = relative_response_error(H, Hm, fit.scaling, &at);
  EXPECT_NEAR(fit.error, truth, 1e-14 + 1e-12 * truth);
  EXPECT_EQ(fit.worst_frequency, f[at]);
  EXPECT_FALSE(fit.reached_target);
  EXPECT_GT(fit.error, 1e-5);  // the noise cannot be fitted away
  EXPECT_LT(fit.error, 1e-2);  // the delay over 0.8 rad of phase is
  for (cd a : fit.poles) EXPECT_LT(a.real(), 0.0);
}

TEST(StateSpace, TheRealisationOfAKnownDiscreteImpulseResponseIsMinimalAndExact) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  // a stable discrete system of order 7 (3 outputs, 4 inputs) and its Markov parameters
  StateSpace sys;
  Eigen::MatrixXd Q = Eigen::MatrixXd::NullaryExpr(7, 7, [&] { return g(rng); });
  const Eigen::VectorXd eig =
      (Eigen::VectorXd(7) << 0.9, -0.7, 0.5, 0.3, -0.2, 0.8, 0.1).finished();
  sys.A = Q * eig.asDiagonal() * Q.inverse();
  sys.B = Eigen::MatrixXd::NullaryExpr(7, 4, [&] { return g(rng); });
  sys.C = Eigen::MatrixXd::NullaryExpr(3, 7, [&] { return g(rng); });
  sys.D = Eigen::MatrixXd::NullaryExpr(3, 4, [&] { return g(rng); });
  // outputs and inputs of very different sizes (units): the scaling must keep the small ones
  const Eigen::VectorXd so = (Eigen::VectorXd(3) << 1e7, 1e-3, 1.0).finished();
  const Eigen::VectorXd si = (Eigen::VectorXd(4) << 1.0, 1e4, 1e-2, 1.0).finished();
  sys.B = sys.B * si.asDiagonal();
  sys.C = so.asDiagonal() * sys.C;
  sys.D = so.asDiagonal() * sys.D * si.asDiagonal();
  const std::vector<Eigen::MatrixXd> h = sys.markov_parameters(400);
  const Realisation r = eigensystem_realisation(h, 1e-10);
  EXPECT_EQ(r.model.order(), 7);
  EXPECT_LT(r.markov_error, 1e-10);
  for (double fdt : {0.0, 0.01, 0.2, 0.5}) {
    const Eigen::MatrixXcd a = r.model.discrete_frequency_response(fdt, 1.0),
                           b = sys.discrete_frequency_response(fdt, 1.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        EXPECT_LT(std::abs(a(i, j) - b(i, j)), 1e-9 * so(i) * si(j)) << fdt << " " << i << j;
  }
}

TEST(StateSpace, TheFirstOrderHoldSimulationIsExactForARamp) {
  // x' = -a x + u, y = x, u = t: x(t) = t/a - (1 - e^{-a t})/a^2
  StateSpace m;
  const double a = 300.0, h = 1e-3;
  m.A = Eigen::MatrixXd::Constant(1, 1, -a);
  m.B = Eigen::MatrixXd::Ones(1, 1);
  m.C = Eigen::MatrixXd::Ones(1, 1);
  m.D = Eigen::MatrixXd::Zero(1, 1);
  std::vector<Eigen::VectorXd> u;
  for (int k = 0; k < 50; ++k) u.push_back(Eigen::VectorXd::Constant(1, k * h));
  const std::vector<Eigen::VectorXd> y = simulate_first_order_hold(m, h, u);
  for (int k = 0; k < 50; ++k) {
    const double t = k * h, exact = t / a - (1.0 - std::exp(-a * t)) / (a * a);
    EXPECT_NEAR(y[k](0), exact, 1e-15 + 1e-12 * std::abs(exact)) << k;
  }
}

}  // namespace
