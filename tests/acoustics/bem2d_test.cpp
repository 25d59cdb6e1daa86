// The 2D boundary element model of a cross-section's radiation (acoustics/bem2d.hpp) against the
// exact solutions of the circular cylinder, its irregular frequencies with and without CHIEF, the
// low- and high-frequency limits, the rigid ground plane against the image construction, and the
// UIC60 rail section (radiation efficiencies printed).
//
// Exact cylinder solutions for e^{+i omega t} (fluid.hpp). Outgoing waves are H_n^(2)(kr).
//   Pulsating (v_n = V): p = A H_0^(2)(kr); dp/dr(a) = -A k H_1^(2)(ka) = -i k rho c V (Euler),
//     so p(a) = i rho c V H_0^(2)(ka) / H_1^(2)(ka) and Z_0 = p / V = i rho c H_0 / H_1.
//   Oscillating (rigid translation U along y, v_n = U cos(theta)): p = A H_1^(2)(kr) cos(theta);
//     A k H_1^(2)'(ka) = -i k rho c U, H_1' = H_0 - H_1 / (ka), so Z_1 = -i rho c H_1 / H_1'.
// W' = (1/2) Re(Z) |V|^2 x (2 pi a, resp. Int cos^2 = pi a), and sigma = Re Z / (rho c) for both
// (the normalisation Int <v_n^2> ds carries the same perimeter factor). By the Wronskian
// J_n Y_n' - J_n' Y_n = 2/(pi z): Re Z_0/(rho c) = 2/(pi ka |H_1|^2) > 0 and
// Re Z_1/(rho c) = 2/(pi ka |H_1'|^2) > 0; both -> 1 as ka -> inf (H_n^(2) ~ sqrt(2/(pi z))
// e^{-i(z - n pi/2 - pi/4)}), and as ka -> 0: sigma_0 ~ (pi/2) ka (2D monopole, slope 1),
// sigma_1 ~ (pi/2) (ka)^3 (2D dipole, slope 3).
#include "acoustics/bem2d.hpp"

#include <gsl/gsl_sf_bessel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ac = rollnoise::acoustics;
using cd = std::complex<double>;
using Eigen::Vector2d;

namespace {

constexpr double kPiBem = 3.14159265358979323846;

cd hankel2_bem(int n, double z) {
  return {gsl_sf_bessel_Jn(n, z), -gsl_sf_bessel_Yn(n, z)};
}

/// Z_0 / (rho c) of the pulsating cylinder (file comment).
cd pulsating_impedance(double ka) {
  return cd(0.0, 1.0) * hankel2_bem(0, ka) / hankel2_bem(1, ka);
}

/// Z_1 / (rho c) of the oscillating cylinder (file comment).
cd oscillating_impedance(double ka) {
  const cd h1_prime = hankel2_bem(0, ka) - hankel2_bem(1, ka) / ka;
  return cd(0.0, -1.0) * hankel2_bem(1, ka) / h1_prime;
}

/// A regular N-gon inscribed in the circle of radius a about (0, zc); a vertex at the bottom.
ac::Section2d cylinder_polygon(double a, int N, double zc = 0.0) {
  ac::Section2d s;
  for (int i = 0; i < N; ++i) {
    const double t = -0.5 * kPiBem + 2.0 * kPiBem * i / N;
    s.outline.emplace_back(a * std::cos(t), zc + a * std::sin(t));
  }
  return s;
}

/// Pulsating (column 0) and lateral/vertical translation patterns on given elements.
Eigen::MatrixXd cylinder_patterns(const std::vector<ac::BoundaryElement2d>& el,
                                  const Vector2d& translation) {
  Eigen::MatrixXd p(el.size(), 2);
  for (size_t j = 0; j < el.size(); ++j) {
    p(j, 0) = 1.0;
    p(j, 1) = translation.dot(el[j].normal);
  }
  return p;
}

/// The BEM's pulsating and oscillating efficiencies of the N-gon at ka (power relative to the
/// exact circle's perimeter factors 2 pi a and pi a, so that geometric error counts as error).
std::pair<double, double> bem_cylinder_sigmas(double ka, int N, int chief_points) {
  const double a = 0.1;
  const ac::Fluid air;
  ac::Bem2dOptions o;
  o.target_elements = N;
  o.chief_points = chief_points;
  const ac::Section2d s = cylinder_polygon(a, N);
  const auto el = ac::boundary_elements_2d(s, o);
  const Eigen::MatrixXcd P =
      ac::radiated_power_matrix_2d(s, ka / a, cylinder_patterns(el, {1.0, 0.0}), air, o);
  const double norm0 = air.impedance() * 0.5 * 2.0 * kPiBem * a;  // rho c Int <v_n^2>, |V| = 1
  const double norm1 = air.impedance() * 0.5 * kPiBem * a;
  return {P(0, 0).real() / norm0, P(1, 1).real() / norm1};
}

/// The UIC60 (60E1) section. Origin: models/rail/uic60_outline.csv (= dynamics::uic60_outline()),
/// approximate, from the EN 13674-1 principal dimensions; the csv lists the full closed polygon,
/// whose y >= 0 half is copied here (mm, from the foot's centre up to the crown) and mirrored.
ac::Section2d uic60_section() {
  static const double half[14][2] = {{0.0, 0.0},    {75.0, 0.0},   {75.0, 10.5},  {30.0, 18.5},
                                     {14.0, 25.0},  {8.25, 36.0},  {8.25, 120.0}, {16.0, 128.0},
                                     {36.0, 133.0}, {36.0, 158.0}, {33.0, 166.5}, {25.0, 170.8},
                                     {12.0, 171.8}, {0.0, 172.0}};
  ac::Section2d s;
  for (const auto& p : half) s.outline.emplace_back(1e-3 * p[0], 1e-3 * p[1]);
  for (int i = 12; i >= 1; --i) s.outline.emplace_back(-1e-3 * half[i][0], 1e-3 * half[i][1]);
  return s;
}

double band_centre_bem(int n) {
  return 1000.0 * std::pow(10.0, n / 10.0);
}

}  // namespace

// The exact expressions themselves: Re Z > 0, the Wronskian forms, -> rho c at high ka, the
// low-ka asymptotes (pi/2) ka and (pi/2) (ka)^3.
TEST(Bem2dExact, CylinderImpedancesArePassiveAndTendToRhoC) {
  for (double ka = 0.01; ka < 200.0; ka *= 1.25) {
    const cd z0 = pulsating_impedance(ka), z1 = oscillating_impedance(ka);
    EXPECT_GT(z0.real(), 0.0) << ka;
    EXPECT_GT(z1.real(), 0.0) << ka;
    const cd h1p = hankel2_bem(0, ka) - hankel2_bem(1, ka) / ka;
    EXPECT_NEAR(z0.real(), 2.0 / (kPiBem * ka * std::norm(hankel2_bem(1, ka))),
                1e-12 * (1 + z0.real()));
    EXPECT_NEAR(z1.real(), 2.0 / (kPiBem * ka * std::norm(h1p)), 1e-12 * (1 + z1.real()));
  }
  EXPECT_NEAR(pulsating_impedance(150.0).real(), 1.0, 1e-3);
  EXPECT_NEAR(oscillating_impedance(150.0).real(), 1.0, 1e-3);
  EXPECT_NEAR(pulsating_impedance(150.0).imag(), 0.0, 1e-2);
  EXPECT_NEAR(pulsating_impedance(1e-3).real() / (0.5 * kPiBem * 1e-3), 1.0, 1e-3);
  EXPECT_NEAR(oscillating_impedance(1e-3).real() / (0.5 * kPiBem * 1e-9), 1.0, 1e-3);
}

// Pulsating and oscillating cylinder, ka 0.1 ... 20, N = max(64, 10 ka) elements (>= 10 elements
// per wavelength): both within 1 % of the exact power (measured: below 0.4 %).
TEST(Bem2d, CylinderPowerMatchesExactSolutions) {
  std::printf("  ka      N  el/wavelength  sigma_0 exact  error      sigma_1 exact  error\n");
  for (double ka : {0.1, 0.3, 1.0, 2.0, 3.0, 5.0, 8.0, 12.0, 20.0}) {
    const int N = std::max(64, static_cast<int>(std::ceil(10.0 * ka)));
    const auto [s0, s1] = bem_cylinder_sigmas(ka, N, 10);
    const double e0 = pulsating_impedance(ka).real(), e1 = oscillating_impedance(ka).real();
    std::printf("  %5.2f %4d  %6.1f        %.6f      %+.2e  %.6e   %+.2e\n", ka, N, N / ka, e0,
                s0 / e0 - 1.0, e1, s1 / e1 - 1.0);
    EXPECT_NEAR(s0 / e0, 1.0, 0.01) << "pulsating, ka = " << ka;
    EXPECT_NEAR(s1 / e1, 1.0, 0.01) << "oscillating, ka = " << ka;
  }
  // high ka: sigma -> 1
  const auto [s0, s1] = bem_cylinder_sigmas(20.0, 200, 10);
  EXPECT_NEAR(s0, 1.0, 0.02);
  EXPECT_NEAR(s1, 1.0, 0.02);
}

// The first interior Dirichlet eigenvalues of the disc, j_01 = 2.4048 (pulsating, n = 0) and
// j_11 = 3.8317 (oscillating, n = 1), scanned finely (the 64-gon's discrete eigenvalue lies
// slightly above the disc's): the plain formulation breaks down (measured: errors up to 200 %,
// i.e. negative power), CHIEF stays within 1 % (measured: 2e-4).
TEST(Bem2d, ChiefRemovesTheIrregularFrequencies) {
  for (int mode = 0; mode < 2; ++mode) {
    const double centre = mode == 0 ? 2.4048 : 3.8317;
    double worst_plain = 0.0, worst_chief = 0.0;
    for (int i = -6; i <= 6; ++i) {
      const double ka = centre + 0.0025 * i;
      const double exact =
          mode == 0 ? pulsating_impedance(ka).real() : oscillating_impedance(ka).real();
      const auto plain = bem_cylinder_sigmas(ka, 64, 0);
      const auto chief = bem_cylinder_sigmas(ka, 64, 10);
      const double sp = mode == 0 ? plain.first : plain.second;
      const double sc = mode == 0 ? chief.first : chief.second;
      worst_plain = std::max(worst_plain, std::abs(sp / exact - 1.0));
      worst_chief = std::max(worst_chief, std::abs(sc / exact - 1.0));
    }
    std::printf("  %s cylinder near ka = %.4f: largest error plain %.3f, CHIEF %.2e\n",
                mode == 0 ? "pulsating" : "oscillating", centre, worst_plain, worst_chief);
    EXPECT_LT(worst_chief, 0.01);
    EXPECT_GT(worst_plain, 0.1);  // the irregular frequency is really there
  }
}

// Low ka: slope of log sigma over ka = 0.01 ... 0.1: 1 (pulsating, 2D monopole) and 3
// (oscillating, 2D dipole), within 0.2.
TEST(Bem2d, LowFrequencySlopes) {
  const auto lo = bem_cylinder_sigmas(0.01, 64, 10);
  const auto hi = bem_cylinder_sigmas(0.1, 64, 10);
  const double slope0 = std::log10(hi.first / lo.first);
  const double slope1 = std::log10(hi.second / lo.second);
  std::printf("  low-ka slopes (ka 0.01 -> 0.1): pulsating %.3f, oscillating %.3f\n", slope0,
              slope1);
  EXPECT_NEAR(slope0, 1.0, 0.2);
  EXPECT_NEAR(slope1, 3.0, 0.2);
}

// Rigid ground plane against the image construction: a cylinder touching the plane (a vertex on
// it) and one 0.2 a above it, pulsating, vertical and lateral translation: the half-space power
// (ground plane option) is half the free-field power of the cylinder plus its mirror image moving
// mirror-symmetrically (two bodies). Within 1 %.
TEST(Bem2d, GroundPlaneMatchesTheImageCylinder) {
  const ac::Fluid air;
  const double a = 0.1;
  const int N = 96;
  for (double gap : {0.0, 0.2 * a}) {
    const ac::Section2d body = cylinder_polygon(a, N, a + gap);
    const ac::Section2d image = cylinder_polygon(a, N, -(a + gap));
    ac::Bem2dOptions half;
    half.target_elements = N;
    half.ground_plane = true;
    half.ground_z = 0.0;
    ac::Bem2dOptions pair;
    pair.target_elements = 2 * N;
    const auto el_half = ac::boundary_elements_2d(body, half);
    const auto el_pair = ac::boundary_elements_2d({body, image}, pair);
    ASSERT_EQ(el_half.size(), static_cast<size_t>(N));
    ASSERT_EQ(el_pair.size(), static_cast<size_t>(2 * N));
    for (double ka : {0.5, 2.0, 5.0}) {
      const double k = ka / a;
      // columns: pulsating, vertical (image moves down), lateral (image moves the same way)
      Eigen::MatrixXd ph(N, 3), pp(2 * N, 3);
      for (int j = 0; j < N; ++j) ph.row(j) << 1.0, el_half[j].normal.y(), el_half[j].normal.x();
      for (int j = 0; j < 2 * N; ++j) {
        const double vertical = j < N ? 1.0 : -1.0;
        pp.row(j) << 1.0, vertical * el_pair[j].normal.y(), el_pair[j].normal.x();
      }
      const Eigen::MatrixXcd Ph = ac::radiated_power_matrix_2d(body, k, ph, air, half);
      const Eigen::MatrixXcd Pp = ac::radiated_power_matrix_2d({body, image}, k, pp, air, pair);
      for (int c = 0; c < 3; ++c) {
        const double ratio = 2.0 * Ph(c, c).real() / Pp(c, c).real();
        std::printf("  gap %.2f a, ka %.1f, %-9s: 2 W'(half space) / W'(image pair) = %.5f\n",
                    gap / a, ka,
                    c == 0   ? "pulsating"
                    : c == 1 ? "vertical"
                             : "lateral",
                    ratio);
        EXPECT_NEAR(ratio, 1.0, 0.01);
      }
    }
  }
}

// A half cylinder resting on the plane (its flat side on the ground is dropped): pulsating and
// lateral motion are exactly half the full cylinder's pulsating and oscillating problems, so the
// efficiencies equal the exact sigma_0 and sigma_1. Within 1 %.
TEST(Bem2d, HalfCylinderOnTheGroundIsHalfTheCylinder) {
  const ac::Fluid air;
  const double a = 0.1;
  const int N = 64;  // arc segments
  ac::Section2d half_disc;
  for (int i = 0; i <= N; ++i) {
    const double t = kPiBem * i / N;
    half_disc.outline.emplace_back(a * std::cos(t), a * std::sin(t));
  }
  ac::Bem2dOptions o;
  o.target_elements = N;  // h = (pi a + 2a) / N: one element per arc segment, some on the base
  o.ground_plane = true;  // ground_z = min z = 0: the base is dropped
  const auto el = ac::boundary_elements_2d(half_disc, o);
  for (const auto& e : el) EXPECT_GT(std::max(e.start.y(), e.end.y()), 1e-9);
  for (double ka : {0.3, 1.0, 3.0, 6.0}) {
    const double k = ka / a;
    Eigen::MatrixXd p(el.size(), 1);
    for (size_t j = 0; j < el.size(); ++j) p(j, 0) = 1.0;
    const double sigma0 = ac::radiated_power_matrix_2d(half_disc, k, p, air, o)(0, 0).real() /
                          (air.impedance() * 0.5 * kPiBem * a);
    const double sigma1 =
        ac::rigid_translation_radiation_2d(half_disc, k, {1.0, 0.0}, air, o).efficiency;
    std::printf(
        "  half cylinder on the ground, ka %.1f: sigma_0 %.5f (exact %.5f), sigma_1 %.5f "
        "(exact %.5f)\n",
        ka, sigma0, pulsating_impedance(ka).real(), sigma1, oscillating_impedance(ka).real());
    EXPECT_NEAR(sigma0 / pulsating_impedance(ka).real(), 1.0, 0.01);
    EXPECT_NEAR(sigma1 / oscillating_impedance(ka).real(), 1.0, 0.01);
  }
}

// The 2.5D relation: kappa = 0 gives the 2D value, |kappa| >= k gives 0, even in kappa; near the
// coincidence kappa -> k the pulsating cylinder tends to (pi/2) k a (finite), the dipole to 0;
// with the BEM in the loop it reproduces (k/k_r) sigma_1(k_r a).
TEST(Bem2d, AxialWaveEfficiencyLimits) {
  const double a = 0.1, k = 20.0;
  auto s0 = [a](double kr) { return pulsating_impedance(kr * a).real(); };
  auto s1 = [a](double kr) { return oscillating_impedance(kr * a).real(); };
  EXPECT_DOUBLE_EQ(ac::axial_wave_efficiency(k, 0.0, s1), s1(k));
  EXPECT_EQ(ac::axial_wave_efficiency(k, k, s1), 0.0);
  EXPECT_EQ(ac::axial_wave_efficiency(k, -1.5 * k, s0), 0.0);
  EXPECT_DOUBLE_EQ(ac::axial_wave_efficiency(k, 0.7 * k, s0),
                   ac::axial_wave_efficiency(k, -0.7 * k, s0));
  const double near = k * (1.0 - 1e-8);
  EXPECT_NEAR(ac::axial_wave_efficiency(k, near, s0) / (0.5 * kPiBem * k * a), 1.0, 0.01);
  EXPECT_LT(ac::axial_wave_efficiency(k, near, s1), 1e-6);
  // (k / k_r) > 1 raises the efficiency of a supersonic wave above the 2D value at k_r
  const double kappa = 0.6 * k, kr = 0.8 * k;
  ac::Bem2dOptions o;
  o.target_elements = 64;
  const ac::Section2d s = cylinder_polygon(a, 64);
  const ac::Fluid air;
  const double bem = ac::axial_wave_efficiency(k, kappa, [&](double q) {
    return ac::rigid_translation_radiation_2d(s, q, {1.0, 0.0}, air, o).efficiency;
  });
  EXPECT_NEAR(bem / ((k / kr) * s1(kr)), 1.0, 0.01);
  EXPECT_THROW(ac::axial_wave_efficiency(0.0, 0.0, s0), std::invalid_argument);
}

// The UIC60 section (free field and on a rigid ground at the foot): vertical and lateral
// efficiencies of rigid motion at the 1/3-octave centres 100 Hz ... 5 kHz, printed. Checks:
// free field, both rise like a dipole ((ka)^3: 25-35 dB/decade over 100-200 Hz) and vertical rises
// monotonically to 1 kHz; with the ground, vertical motion against the plane is a monopole pair
// (slope near 10 dB/decade) and lateral lies below vertical at 100 and 125 Hz (equal at 160 Hz);
// above 1.6 kHz all are of order 1 (0.4 ... 2.5: the rigid rail's head-foot pockets resonate, sigma
// reaching about 2 for vertical motion near 2 kHz and 4.8 kHz; mesh-converged and checked against
// the far-field flux during development). Free field, lateral lies above vertical at low frequency:
// the fluid between head and foot moves with the rail laterally, so the lateral dipole strength
// (section area plus added mass / rho, from W' = rho c k^3 D^2 |U|^2 / 16) is set by the outline's
// hull, D = 0.051 m^2, against 0.029 m^2 vertically where that fluid is not trapped (checked on an
// I-section and against the strip, square and ellipse added masses during development). The lateral
// < vertical order at low frequency holds with the ground, where vertical motion against the plane
// is monopole-like.
TEST(Bem2d, Uic60RailRadiationEfficiencies) {
  const ac::Fluid air;
  const ac::Section2d rail = uic60_section();
  ac::Bem2dOptions free_field;  // 100 target elements: 110 elements (sides split unevenly)
  ac::Bem2dOptions ground = free_field;
  ground.ground_plane = true;  // at the foot's bottom
  std::printf(
      "  UIC60: %zu elements free field, %zu on the ground; widths Int (d.n)^2 ds: "
      "vertical %.4f m, lateral %.4f m\n",
      ac::boundary_elements_2d(rail, free_field).size(),
      ac::boundary_elements_2d(rail, ground).size(),
      ac::rigid_translation_radiation_2d(rail, 1.0, {0.0, 1.0}, air).radiating_width,
      ac::rigid_translation_radiation_2d(rail, 1.0, {1.0, 0.0}, air).radiating_width);
  std::printf("  f (Hz)   free: vertical  lateral   ground: vertical  lateral\n");
  std::vector<double> fv, fl, gv, gl;
  const std::vector<Vector2d> directions = {{0.0, 1.0}, {1.0, 0.0}};
  for (int n = -10; n <= 7; ++n) {
    const double f = band_centre_bem(n), k = 2.0 * kPiBem * f / air.sound_speed;
    const auto r = ac::rigid_translation_radiation_2d(rail, k, directions, air, free_field);
    const auto g = ac::rigid_translation_radiation_2d(rail, k, directions, air, ground);
    fv.push_back(r[0].efficiency);
    fl.push_back(r[1].efficiency);
    gv.push_back(g[0].efficiency);
    gl.push_back(g[1].efficiency);
    std::printf("  %6.0f        %8.4f  %8.4f          %8.4f  %8.4f\n", f, fv.back(), fl.back(),
                gv.back(), gl.back());
  }
  // dipole slopes in free field over 100 -> 200 Hz (bands 0 and 3), dB/decade
  const double decade = std::log10(band_centre_bem(-7) / band_centre_bem(-10));
  EXPECT_NEAR(10.0 * std::log10(fv[3] / fv[0]) / decade, 30.0, 5.0);
  EXPECT_NEAR(10.0 * std::log10(fl[3] / fl[0]) / decade, 30.0, 5.0);
  EXPECT_LT(10.0 * std::log10(gv[3] / gv[0]) / decade, 15.0);  // monopole-like
  for (int i = 1; i <= 10; ++i) EXPECT_GT(fv[i], fv[i - 1]) << band_centre_bem(i - 10);
  for (int i = 0; i <= 1; ++i) EXPECT_LT(gl[i], gv[i]) << band_centre_bem(i - 10);  // 100, 125 Hz
  for (int i = 0; i <= 6; ++i) EXPECT_GT(fl[i], fv[i]) << band_centre_bem(i - 10);  // to 400 Hz
  for (size_t i = 12; i < fv.size(); ++i) {
    for (double s : {fv[i], fl[i], gv[i], gl[i]}) {
      EXPECT_GT(s, 0.4) << band_centre_bem(static_cast<int>(i) - 10);
      EXPECT_LT(s, 2.5) << band_centre_bem(static_cast<int>(i) - 10);
    }
  }
  // time per call (vertical and lateral together, one solve), free field and ground
  for (double f : {1000.0, 5000.0}) {
    const double k = 2.0 * kPiBem * f / air.sound_speed;
    for (int g = 0; g < 2; ++g) {
      const auto t0 = std::chrono::steady_clock::now();
      const int calls = 5;
      for (int c = 0; c < calls; ++c)
        ac::rigid_translation_radiation_2d(rail, k, directions, air, g ? ground : free_field);
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      std::printf("  time per call at %4.0f Hz, %s: %.1f ms\n", f, g ? "ground" : "free field",
                  ms / calls);
    }
  }
}

// The UIC60's first irregular frequency (a symmetric interior Dirichlet mode of the section, near
// 4.37 kHz with 110 elements): the plain formulation's vertical efficiency jumps there, CHIEF's
// is smooth (second differences over a 10 Hz grid below 1 % of the value).
TEST(Bem2d, Uic60IrregularFrequencyIsTreated) {
  const ac::Fluid air;
  const ac::Section2d rail = uic60_section();
  ac::Bem2dOptions chief, plain;
  plain.chief_points = 0;
  std::vector<double> sc, sp;
  for (double f = 4300.0; f <= 4450.0; f += 10.0) {
    const double k = 2.0 * kPiBem * f / air.sound_speed;
    sc.push_back(ac::rigid_translation_radiation_2d(rail, k, {0.0, 1.0}, air, chief).efficiency);
    sp.push_back(ac::rigid_translation_radiation_2d(rail, k, {0.0, 1.0}, air, plain).efficiency);
  }
  double worst_plain = 0.0, worst_curvature = 0.0;
  for (size_t i = 0; i < sc.size(); ++i) {
    worst_plain = std::max(worst_plain, std::abs(sp[i] / sc[i] - 1.0));
    if (i > 0 && i + 1 < sc.size())
      worst_curvature =
          std::max(worst_curvature, std::abs(sc[i + 1] - 2.0 * sc[i] + sc[i - 1]) / sc[i]);
  }
  std::printf(
      "  UIC60 vertical, 4.30-4.45 kHz: plain differs from CHIEF by up to %.1f %%; CHIEF's "
      "largest second difference %.2e\n",
      100.0 * worst_plain, worst_curvature);
  EXPECT_GT(worst_plain, 0.05);
  EXPECT_LT(worst_curvature, 0.01);
}

TEST(Bem2d, RejectsBadInput) {
  const ac::Fluid air;
  const ac::Section2d circle = cylinder_polygon(0.1, 32);
  ac::Section2d two_points;
  two_points.outline = {{0.0, 0.0}, {1.0, 0.0}};
  EXPECT_THROW(ac::boundary_elements_2d(two_points), std::invalid_argument);
  ac::Section2d bow_tie;
  bow_tie.outline = {{0.0, 0.0}, {1.0, 1.0}, {1.0, 0.0}, {0.0, 1.0}};
  EXPECT_THROW(ac::boundary_elements_2d(bow_tie), std::invalid_argument);
  ac::Section2d line;
  line.outline = {{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}};
  EXPECT_THROW(ac::boundary_elements_2d(line), std::invalid_argument);
  EXPECT_THROW(ac::rigid_translation_radiation_2d(circle, 0.0, {0.0, 1.0}, air),
               std::invalid_argument);
  EXPECT_THROW(ac::rigid_translation_radiation_2d(circle, 1.0, {0.0, 0.0}, air),
               std::invalid_argument);
  // 32 elements on a 0.1 m circle: 20 mm elements; at 5 kHz (lambda 69 mm) < 4 per wavelength
  ac::Bem2dOptions coarse;
  coarse.target_elements = 32;
  EXPECT_THROW(ac::rigid_translation_radiation_2d(circle, 2.0 * kPiBem * 5000.0 / 343.2, {0.0, 1.0},
                                                  air, coarse),
               std::invalid_argument);
  EXPECT_THROW(ac::radiated_power_matrix_2d(circle, 1.0, Eigen::MatrixXd::Ones(5, 1), air),
               std::invalid_argument);
  ac::Bem2dOptions below;
  below.ground_plane = true;
  below.ground_z = 0.0;  // the circle reaches z = -0.1
  EXPECT_THROW(ac::boundary_elements_2d(circle, below), std::invalid_argument);
  // orientation: a clockwise outline gives the same (outward) normals
  ac::Section2d clockwise = circle;
  std::reverse(clockwise.outline.begin(), clockwise.outline.end());
  const auto e1 = ac::boundary_elements_2d(circle), e2 = ac::boundary_elements_2d(clockwise);
  for (const auto& e : e2) EXPECT_GT(e.normal.dot(e.midpoint()), 0.0);
  EXPECT_EQ(e1.size(), e2.size());
}
