// The axisymmetric Fourier FE model (src/fem/axisymmetric) against thin-plate theory: an annular
// plate clamped at the bore (r = b) and free at the rim (r = a). The Kirchhoff frequencies come
// from the Bessel-function solution W = A J_n(kr) + B Y_n(kr) + C I_n(kr) + D K_n(kr), its 4x4
// determinant (clamped: W = W' = 0 at b; free: M_r = V_r = 0 at a; Leissa, Vibration of Plates,
// NASA SP-160 (1969), Sec. 2.2, Eqs. 2.3-2.4 and 2.12), solved here with GSL's Bessel functions.
#include <gsl/gsl_sf_bessel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "core/constants.hpp"
#include "fem/axisymmetric.hpp"
#include "fem/eigen_solve.hpp"
#include "fem/mesh.hpp"

using namespace rollnoise::fem;

namespace {

using rollnoise::kPi;

// Value, first and second derivative (by x) of one of J_n, Y_n (kind 0, 1) or I_n, K_n (2, 3).
Eigen::Vector3d bessel(int kind, int n, double x) {
  double z, zp;
  switch (kind) {
    case 0:
      z = gsl_sf_bessel_Jn(n, x), zp = n / x * z - gsl_sf_bessel_Jn(n + 1, x);
      break;
    case 1:
      z = gsl_sf_bessel_Yn(n, x), zp = n / x * z - gsl_sf_bessel_Yn(n + 1, x);
      break;
    case 2:
      z = gsl_sf_bessel_In(n, x), zp = n / x * z + gsl_sf_bessel_In(n + 1, x);
      break;
    default:
      z = gsl_sf_bessel_Kn(n, x), zp = n / x * z - gsl_sf_bessel_Kn(n + 1, x);
      break;
  }
  // Bessel's equation: Z'' = -Z'/x - (1 - n^2/x^2) Z; modified: Z'' = -Z'/x + (1 + n^2/x^2) Z.
  const double s = kind < 2 ? -1.0 : 1.0;
  const double zpp = -zp / x + (s + double(n) * n / (x * x)) * z;
  return {z, zp, zpp};
}

// The clamped-free determinant at wavenumber k (columns scaled to unit maximum: same roots).
double determinant(int n, double k, double b, double a, double nu) {
  Eigen::Matrix4d m;
  for (int kind = 0; kind < 4; ++kind) {
    const Eigen::Vector3d zb = bessel(kind, n, k * b), za = bessel(kind, n, k * a);
    const double w = za(0), w1 = k * za(1), w2 = k * k * za(2);
    const double lap = kind < 2 ? -k * k : k * k;  // laplacian of the basis function / itself
    m(0, kind) = zb(0);
    m(1, kind) = k * zb(1);
    m(2, kind) = w2 + nu * (w1 / a - n * n * w / (a * a));                        // M_r = 0
    m(3, kind) = lap * w1 - (1 - nu) * n * n * (w1 / (a * a) - w / (a * a * a));  // V_r = 0
    m.col(kind) /= m.col(kind).cwiseAbs().maxCoeff();
  }
  return m.determinant();
}

// The lowest `count` roots k of the determinant (scan in ka, then bisection to 1e-13 relative).
std::vector<double> plate_wavenumbers(int n, double b, double a, double nu, int count) {
  std::vector<double> roots;
  const double step = 0.005 / a;
  double k0 = 0.2 / a, d0 = determinant(n, k0, b, a, nu);
  while (static_cast<int>(roots.size()) < count) {
    const double k1 = k0 + step, d1 = determinant(n, k1, b, a, nu);
    if (d0 * d1 < 0) {
      double lo = k0, hi = k1, dlo = d0;
      while (hi - lo > 1e-13 * hi) {
        const double mid = 0.5 * (lo + hi), dm = determinant(n, mid, b, a, nu);
        (dm * dlo < 0 ? hi : lo) = mid;
        if (dm * dlo >= 0) dlo = dm;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    k0 = k1, d0 = d1;
  }
  return roots;
}

struct Plate {
  double b = 0.1, a = 0.5, h = 0.01;  // bore radius, outer radius, thickness (m)
  IsotropicMaterial steel{2.1e11, 0.3, 7850.0};
};

// Kirchhoff frequency (Hz) of wavenumber k: omega = k^2 sqrt(D / (rho h)), D = E h^3 / 12 (1 -
// nu^2).
double kirchhoff_hz(const Plate& p, double k) {
  const double d = p.steel.youngs_modulus * std::pow(p.h, 3) /
                   (12 * (1 - p.steel.poisson_ratio * p.steel.poisson_ratio));
  return k * k * std::sqrt(d / (p.steel.density * p.h)) / (2 * kPi);
}

// Nodal circles of a bending mode: sign changes of U_z along the mid-plane, ignoring |U_z| below 2
// % of its maximum (the clamped bore).
int nodal_circles(const QuadraticTriangleMesh& mesh, const Eigen::VectorXd& phi, const Plate& p) {
  std::vector<double> w;
  for (int i = 1; i <= 200; ++i)
    w.push_back(displacement_at(mesh, phi, Eigen::Vector2d(p.b + (p.a - p.b) * i / 200.0, 0.0))(2));
  return sign_changes(w, 0.02);
}

// The FE bending (U_z-dominated) modes of order n: frequency (Hz) and nodal circles, ascending.
std::vector<std::pair<double, int>> fe_bending_modes(const Plate& p, double mesh_size, int n,
                                                     double f_max, bool clamped = true) {
  const std::vector<Eigen::Vector2d> section = {
      {p.b, -p.h / 2}, {p.a, -p.h / 2}, {p.a, p.h / 2}, {p.b, p.h / 2}};
  const auto mesh = mesh_polygon(section, mesh_size);
  const auto km = assemble_axisymmetric(mesh, p.steel, n);
  std::vector<int> fixed;
  for (int node : nodes_on_segments(
           mesh, clamped ? std::vector<int>{3}
                         : std::vector<int>{}))  // segment 3: (b, h/2) -> (b, -h/2), the bore
    for (int c = 0; c < 3; ++c) fixed.push_back(3 * node + c);
  const auto modes = lowest_modes(km.stiffness, km.mass, fixed, 2 * kPi * f_max);
  std::vector<std::pair<double, int>> out;
  for (int j = 0; j < modes.omega.size(); ++j)
    if (kinetic_energy_shares(km.mass, modes.shapes.col(j))(2) > 0.5)
      out.emplace_back(modes.omega(j) / (2 * kPi), nodal_circles(mesh, modes.shapes.col(j), p));
  return out;
}

}  // namespace

// h/a = 0.02: for n = 0..4 the FE bending modes with 0 and 1 nodal circles equal Kirchhoff's within
// 1 % and 2 % (the acceptance), with the nodal circles counted on the FE shape.
TEST(AnnularPlate, ThinPlateBendingFrequenciesMatchKirchhoffBessel) {
  const Plate p;
  for (int n = 0; n <= 4; ++n) {
    const auto k = plate_wavenumbers(n, p.b, p.a, p.steel.poisson_ratio, 2);
    const double f0 = kirchhoff_hz(p, k[0]), f1 = kirchhoff_hz(p, k[1]);
    const auto fe = fe_bending_modes(p, p.h, n, 1.2 * f1);
    ASSERT_GE(fe.size(), 2u) << "n = " << n;
    std::cout << "n = " << n << ": Kirchhoff " << f0 << ", " << f1 << " Hz; FE " << fe[0].first
              << ", " << fe[1].first << " Hz (circles " << fe[0].second << ", " << fe[1].second
              << ")\n";
    EXPECT_EQ(fe[0].second, 0) << "n = " << n;
    EXPECT_EQ(fe[1].second, 1) << "n = " << n;
    EXPECT_NEAR(fe[0].first / f0, 1.0, 0.01) << "n = " << n;
    EXPECT_NEAR(fe[1].first / f1, 1.0, 0.02) << "n = " << n;
  }
}

// Mesh convergence at h/a = 0.1 (n = 2, 1 nodal circle) under halving of the element size (h/2,
// h/4, h/8): the observed order p = log2(|f_h - f_h/2| / |f_h/2 - f_h/4|) of the frequency. Free at
// both edges the displacement is smooth and quadratic elements give eigenvalue errors O(h^4)
// (Strang & Fix, An Analysis of the FEM (1973) Sec. 6.3): p > 3 asserted. Clamped at the bore, the
// corners where the clamped face meets the free faces carry a stress singularity r^(lambda - 1)
// (Williams, J. Appl. Mech. 19 (1952) 526-528), which bounds the asymptotic order by 2 lambda; on
// these unstructured meshes the measured order is 2.4 (1.4 one level coarser): asserted only > 1
// (converging), the clamped wheel's convergence is measured on the wheel itself.
TEST(AnnularPlate, FrequencyConvergesUnderMeshRefinementAtObservedOrder) {
  Plate p;
  p.h = 0.05;
  for (bool clamped : {false, true}) {
    std::vector<double> f;
    for (double size : {p.h / 2, p.h / 4, p.h / 8}) {
      const auto fe = fe_bending_modes(p, size, 2, 3000.0, clamped);
      ASSERT_GE(fe.size(), 2u);
      f.push_back(fe[1].first);
    }
    const double order = std::log2(std::abs(f[0] - f[1]) / std::abs(f[1] - f[2]));
    std::cout << (clamped ? "clamped" : "free")
              << ", n = 2, second bending mode, h/a = 0.1: " << f[0] << ", " << f[1] << ", " << f[2]
              << " Hz; observed order " << order << "\n";
    if (clamped) {
      EXPECT_GT(order, 1.0);
    } else {
      EXPECT_GT(order, 3.0);
    }
  }
}

// Thicker plates: the FE frequencies fall below Kirchhoff's, by shear deformation and rotary
// inertia, which Mindlin's theory adds at leading order (k h)^2 (Mindlin, J. Appl. Mech. 18 (1951)
// 31-38): for a bending wave f_M / f_K - 1 ~ -(k h)^2 (1 + 2 / (kappa^2 (1 - nu))) / 24, kappa^2 =
// pi^2/12. Asserted: below Kirchhoff at h/a = 0.05 and 0.1, and the shortfall grows as (h/a)^2
// (ratio between h/a = 0.1 and 0.05 within [2.5, 5], 4 for a pure square law) for the 1-circle
// modes; the Mindlin first-order value is printed beside it (Mindlin's exact annular-plate solution
// is not computed here: it agrees to its sign and size, not better, as the clamp adds shear near
// the bore).
TEST(AnnularPlate, ThickPlatesFallBelowKirchhoffGrowingAsThicknessSquared) {
  const double nu = 0.3, kappa2 = kPi * kPi / 12;
  for (int n : {0, 2, 4}) {
    std::vector<double> shortfall;
    for (double ratio : {0.05, 0.1}) {
      Plate p;
      p.h = ratio * p.a;
      const auto k = plate_wavenumbers(n, p.b, p.a, nu, 2);
      const auto fe = fe_bending_modes(p, std::min(p.h, 0.02), n, 1.5 * kirchhoff_hz(p, k[1]));
      ASSERT_GE(fe.size(), 2u);
      for (int s = 0; s < 2; ++s) {
        const double measured = fe[s].first / kirchhoff_hz(p, k[s]) - 1;
        const double mindlin = -std::pow(k[s] * p.h, 2) * (1 + 2 / (kappa2 * (1 - nu))) / 24;
        std::cout << "h/a " << ratio << " n " << n << " circles " << s
                  << ": FE/Kirchhoff - 1 = " << measured << ", Mindlin leading order " << mindlin
                  << "\n";
        EXPECT_LT(measured, 0.0);
      }
      shortfall.push_back(fe[1].first / kirchhoff_hz(p, k[1]) - 1);
    }
    EXPECT_GT(shortfall[1] / shortfall[0], 2.5) << "n = " << n;
    EXPECT_LT(shortfall[1] / shortfall[0], 5.0) << "n = " << n;
  }
}
