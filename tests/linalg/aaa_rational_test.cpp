// The set-valued AAA rational (linalg/aaa_rational.hpp, Eqs. A1-A2): it interpolates at its
// support points, recovers a rational function of low degree from its samples to round-off with
// one denominator for several functions sharing their poles, and fits a sharp resonance of the kind
// the waveguide rail has near its cut-ons to the requested tolerance with few terms.
#include "linalg/aaa_rational.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/errors.hpp"

namespace la = rollnoise::linalg;
using cd = std::complex<double>;

namespace {

// Two functions with the same three poles (off the real axis) and different residues: type (2, 3)
// rationals of x.
Eigen::RowVector2cd two_rationals(double x) {
  const cd p1(1.0, 0.3), p2(2.0, 0.05), p3(-0.5, 1.0);
  const cd a = 1.0 / (x - p1) + 0.5 / (x - p2) + cd(0.0, 2.0) / (x - p3);
  const cd b = cd(0.3, -1.0) / (x - p1) - 2.0 / (x - p2) + 0.1 / (x - p3);
  return {a, b};
}

}  // namespace

// Sampled at 40 points of [0, 3] (one pole 0.05 from the axis at x = 2), fitted to 1e-12 of each
// function's largest magnitude: at most 5 support points (the exact rational has 4 in barycentric
// form: degree 3 needs m = 4), the support values exact to the bit, and between the samples the
// functions within 1e-9 relative.
TEST(AaaRational, RecoversARationalWithSharedPolesToRoundOff) {
  const int n = 40;
  Eigen::VectorXd x(n);
  Eigen::MatrixXcd F(n, 2);
  for (int i = 0; i < n; ++i) {
    x(i) = 3.0 * i / (n - 1);
    F.row(i) = two_rationals(x(i));
  }
  const Eigen::MatrixXd scale =
      Eigen::MatrixXd::Ones(n, 2) * F.cwiseAbs().maxCoeff();  // one scale: relative to the peak
  const la::BarycentricRational r = la::aaa_fit(x, F, scale, 1e-12, n - 1);
  EXPECT_LE(r.support.size(), 5);
  EXPECT_LE(la::aaa_residual(r, x, F, scale), 1e-12);
  for (Eigen::Index j = 0; j < r.support.size(); ++j) {
    Eigen::Index i = 0;
    (x.array() - r.support(j)).abs().minCoeff(&i);
    EXPECT_TRUE(r(r.support(j)) == F.row(i)) << r.support(j);
  }
  double worst = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double xm = 0.5 * (x(i) + x(i + 1));
    worst = std::max(worst, (r(xm) - two_rationals(xm)).cwiseAbs().maxCoeff() /
                                two_rationals(xm).cwiseAbs().maxCoeff());
  }
  std::printf("  %ld support points, largest relative error between samples %.2e\n",
              static_cast<long>(r.support.size()), worst);
  EXPECT_LT(worst, 1e-9);
}

// A damped resonance plus a cut-on onset 1/sqrt(1 - (f/fc)^2 (1 - i eta)) (loss 0.02), as a
// function of ln f on 30 samples from 0.9 fc to 1.1 fc, each entry measured against its own
// magnitude (Eq. F1's kind of scale): the fit meets tolerances of 1e-3 and 1e-5 at its samples,
// the tighter one with more terms, and with 1e-5 is within 1e-3 between the samples.
TEST(AaaRational, FitsACutOnAndAResonanceToTheTolerance) {
  const double fc = 1500.0, f0 = 1480.0, eta = 0.02;
  auto value = [&](double lnf) {
    const double f = std::exp(lnf), q = (f / fc) * (f / fc);
    const cd onset = 1.0 / std::sqrt(cd(1.0 - q, q * eta));
    const cd resonance = 0.3 / (1.0 - (f / f0) * (f / f0) + cd(0.0, eta));
    return Eigen::RowVector2cd(onset + resonance, onset - 0.5 * resonance);
  };
  const int n = 30;
  Eigen::VectorXd x(n);
  Eigen::MatrixXcd F(n, 2);
  for (int i = 0; i < n; ++i) {
    x(i) = std::log(0.9 * fc) + std::log(1.1 / 0.9) * i / (n - 1);
    F.row(i) = value(x(i));
  }
  const Eigen::MatrixXd scale = F.cwiseAbs();
  const la::BarycentricRational loose = la::aaa_fit(x, F, scale, 1e-3, n - 1),
                                tight = la::aaa_fit(x, F, scale, 1e-5, n - 1);
  EXPECT_LE(la::aaa_residual(loose, x, F, scale), 1e-3);
  EXPECT_LE(la::aaa_residual(tight, x, F, scale), 1e-5);
  EXPECT_LT(loose.support.size(), tight.support.size());
  EXPECT_LT(tight.support.size(), n / 2);
  double worst = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double xm = 0.5 * (x(i) + x(i + 1));
    worst = std::max(
        worst,
        ((tight(xm) - value(xm)).cwiseAbs().array() / value(xm).cwiseAbs().array()).maxCoeff());
  }
  std::printf("  %ld / %ld support points for 1e-3 / 1e-5; between the samples %.2e\n",
              static_cast<long>(loose.support.size()), static_cast<long>(tight.support.size()),
              worst);
  EXPECT_LT(worst, 1e-3);
}

// Bad input: too few samples, mismatched sizes, a non-positive scale, max_terms out of range.
TEST(AaaRational, RejectsInconsistentInput) {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);
  const Eigen::MatrixXcd F = Eigen::MatrixXcd::Ones(5, 1);
  const Eigen::MatrixXd scale = Eigen::MatrixXd::Ones(5, 1);
  EXPECT_THROW(la::aaa_fit(x.head(1), F.topRows(1), scale.topRows(1), 1e-3, 1),
               rollnoise::NumericalError);
  EXPECT_THROW(la::aaa_fit(x, F.topRows(4), scale, 1e-3, 2), rollnoise::NumericalError);
  EXPECT_THROW(la::aaa_fit(x, F, Eigen::MatrixXd::Zero(5, 1), 1e-3, 2), rollnoise::NumericalError);
  EXPECT_THROW(la::aaa_fit(x, F, scale, 1e-3, 5), rollnoise::NumericalError);
  // a constant: one support point, exact
  const la::BarycentricRational r = la::aaa_fit(x, F, scale, 1e-3, 4);
  EXPECT_EQ(r.support.size(), 1);
  EXPECT_EQ(r(0.37)(0), cd(1.0));
}
