// Influence coefficients and the half-space operator: closed forms against quadrature of the point
// kernels, reciprocity, FFT against dense products, and the one-column shift of A0.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include <random>

#include "contact/halfspace_operator.hpp"
#include "contact/influence.hpp"
#include "paper_case.hpp"

using namespace rollnoise::contact;

using rollnoise::testing::kSteel;  // E = 210 GPa, nu = 0.28

namespace {

// Point-load kernels of the displacement difference (Johnson 1985, Eqs. 3.19, 3.86a):
// Boussinesq zz, Cerruti xx, yy, xy, for quasi-identical bodies.
double point_kernel(Component c, double X, double Y, const Material& m) {
  const double G = m.shear_modulus(), nu = m.nu, r = std::hypot(X, Y);
  switch (c) {
    case Component::zz: return (1 - nu) / (M_PI * G * r);
    case Component::xx: return ((1 - nu) / r + nu * X * X / (r * r * r)) / (M_PI * G);
    case Component::yy: return ((1 - nu) / r + nu * Y * Y / (r * r * r)) / (M_PI * G);
    case Component::xy: return nu * X * Y / (M_PI * G * r * r * r);
  }
  return 0;
}

// Integral of the point kernel over an element (GSL adaptive Gauss-Kronrod, nested).
double integrate_element(Component c, double X, double Y, double hx, double hy) {
  struct Ctx { Component c; double X, Y, xi; } ctx{c, X, Y, 0};
  gsl_integration_workspace* w1 = gsl_integration_workspace_alloc(200);
  gsl_integration_workspace* w2 = gsl_integration_workspace_alloc(200);
  struct Outer { Ctx* ctx; gsl_integration_workspace* w2; double hy; } outer{&ctx, w2, hy};
  gsl_function inner_f{[](double eta, void* p) {
                         auto* k = static_cast<Ctx*>(p);
                         return point_kernel(k->c, k->X - k->xi, k->Y - eta, kSteel);
                       }, &ctx};
  struct Both { Outer* o; gsl_function* f; } both{&outer, &inner_f};
  gsl_function outer_f{[](double xi, void* p) {
                         auto* b = static_cast<Both*>(p);
                         b->o->ctx->xi = xi;
                         double r, e;
                         gsl_integration_qag(b->f, -b->o->hy / 2, b->o->hy / 2, 0, 1e-10, 200,
                                             GSL_INTEG_GAUSS61, b->o->w2, &r, &e);
                         return r;
                       }, &both};
  double result, err;
  gsl_integration_qag(&outer_f, -hx / 2, hx / 2, 0, 1e-10, 200, GSL_INTEG_GAUSS61, w1, &result, &err);
  gsl_integration_workspace_free(w1);
  gsl_integration_workspace_free(w2);
  return result;
}

}  // namespace

TEST(InfluenceCoefficients, ClosedFormsEqualQuadratureOfPointLoadKernels) {
  gsl_set_error_handler_off();
  const double hx = 0.5e-3, hy = 0.4e-3;
  for (Component c : {Component::zz, Component::xx, Component::yy, Component::xy})
    for (auto [i, j] : std::vector<std::pair<int, int>>{{2, 1}, {-3, 2}, {1, -4}, {5, 0}}) {
      const double X = i * hx, Y = j * hy;
      const double closed = influence_coefficient(c, X, Y, hx, hy, kSteel);
      const double quad = integrate_element(c, X, Y, hx, hy);
      EXPECT_NEAR(closed, quad, 1e-8 * std::abs(influence_coefficient(Component::zz, X, Y, hx, hy, kSteel)))
          << "component " << int(c) << " offset " << i << "," << j;
    }
}

TEST(InfluenceCoefficients, SelfInfluenceIsFiniteAndLargest) {
  const double hx = 0.5e-3, hy = 0.4e-3;
  const double self = influence_coefficient(Component::zz, 0, 0, hx, hy, kSteel);
  EXPECT_TRUE(std::isfinite(self));
  EXPECT_GT(self, influence_coefficient(Component::zz, hx, 0, hx, hy, kSteel));
  EXPECT_GT(self, influence_coefficient(Component::zz, 0, hy, hx, hy, kSteel));
  // Homogeneity: the integral of 1/r over an element scales with its size (unit neutrality).
  for (Component c : {Component::zz, Component::xx, Component::yy})
    EXPECT_NEAR(influence_coefficient(c, 2 * hx, 2 * hy, 2 * hx, 2 * hy, kSteel),
                2 * influence_coefficient(c, hx, hy, hx, hy, kSteel), 1e-12 * self);
}

TEST(HalfSpaceOperator, ForceDisplacementReciprocity) {
  // Betti: q'(A p) = p'(A q) for the unshifted operator, normal and tangential.
  const Grid g = Grid::around_ellipse(9, 7, 5e-3, 4e-3, 1.2);
  const InfluenceTable t(g, kSteel);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(-1, 1);
  for (Problem pr : {Problem::Normal, Problem::Tangential}) {
    const HalfSpaceOperator A(t, pr, 0, Backend::Dense);
    std::vector<double> p(A.size()), q(A.size()), Ap(A.size()), Aq(A.size());
    for (auto& v : p) v = U(rng);
    for (auto& v : q) v = U(rng);
    A.apply(p.data(), Ap.data());
    A.apply(q.data(), Aq.data());
    double qAp = 0, pAq = 0;
    for (int k = 0; k < A.size(); ++k) qAp += q[k] * Ap[k], pAq += p[k] * Aq[k];
    EXPECT_NEAR(qAp, pAq, 1e-12 * std::abs(qAp));
  }
}

TEST(HalfSpaceOperator, FftAndDenseProductsAgree) {
  const Grid g = Grid::around_ellipse(13, 10, 6e-3, 4e-3, 1.15);
  const InfluenceTable t(g, kSteel);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0, 1e9);
  for (Problem pr : {Problem::Normal, Problem::Tangential})
    for (int shift : {0, 1}) {
      const HalfSpaceOperator dense(t, pr, shift, Backend::Dense), fft(t, pr, shift, Backend::Fft);
      std::vector<double> p(dense.size()), u1(dense.size()), u2(dense.size());
      for (auto& v : p) v = U(rng);
      dense.apply(p.data(), u1.data());
      fft.apply(p.data(), u2.data());
      double err = 0, ref = 0;
      for (int k = 0; k < dense.size(); ++k) err = std::max(err, std::abs(u1[k] - u2[k])), ref = std::max(ref, std::abs(u1[k]));
      EXPECT_LT(err, 1e-12 * ref) << "problem " << int(pr) << " shift " << shift;
    }
}

TEST(HalfSpaceOperator, ShiftedOperatorIsTheDisplacementOneElementUpstream) {
  // A0 p at element (i, j) equals A p at (i + 1, j) on a grid one column longer.
  const Grid g = Grid::around_ellipse(8, 6, 5e-3, 4e-3, 1.2);
  Grid wide = g;
  wide.nx += 1;
  const InfluenceTable t(g, kSteel), tw(wide, kSteel);
  const HalfSpaceOperator A0(t, Problem::Tangential, 1, Backend::Dense);
  const HalfSpaceOperator Aw(tw, Problem::Tangential, 0, Backend::Dense);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<double> p(A0.size()), u(A0.size()), pw(Aw.size(), 0.0), uw(Aw.size());
  for (auto& v : p) v = U(rng);
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) pw[c * wide.size() + wide.index(i, j)] = p[c * g.size() + g.index(i, j)];
  A0.apply(p.data(), u.data());
  Aw.apply(pw.data(), uw.data());
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        EXPECT_NEAR(u[c * g.size() + g.index(i, j)], uw[c * wide.size() + wide.index(i + 1, j)], 1e-25);
}
