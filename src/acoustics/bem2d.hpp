// Two-dimensional exterior sound radiation of a vibrating cross-section (the rail), by a
// collocation boundary element method (Thompson, Railway Noise and Vibration, 2009, Sec. 6.3-6.5;
// the 2D BEM of TWINS).
//
// A rail vibrating in a wave that is long compared with its cross-section radiates, per unit
// length, like a 2D body: the pressure p(y, z) outside the section outline Gamma solves the
// Helmholtz equation  Laplace(p) + k^2 p = 0,  k = omega / c,  with the Neumann condition of
// Euler's equation on Gamma (fluid.hpp: e^{+i omega t}),
//   dp/dn = -i omega rho v_n = -i k rho c v_n,                                          (1)
// n the outward normal of the body (into the fluid), and the outgoing radiation condition.
//
// Boundary integral equation (Kirchhoff-Helmholtz, Green's second identity on the fluid region):
// with G(x, y) = -(i/4) H_0^(2)(k |x - y|) (fluid.hpp), (Laplace + k^2) G = -delta,
//   c(x) p(x) = Int_Gamma [ p(y) dG/dn_y(x, y) - G(x, y) dp/dn(y) ] ds_y,                   (2)
// c = 1 in the fluid, 1/2 on a smooth part of Gamma and 0 inside the body. The kernels:
//   G = -(1/4) Y_0(kR) - (i/4) J_0(kR),
//   dG/dn_y = (i k / 4) H_1^(2)(kR) (y - x).n_y / R        (R = |x - y|; -> -(y - x).n / (2 pi R^2)
//                                                            as k -> 0, the Laplace double layer).
//
// Discretisation: the polygon's sides are cut into straight elements of (nearly) equal length;
// p and v_n are constant per element (collocation at the element midpoints). Integrals over
// other elements: Gauss-Legendre (gsl_integration_glfixed_table) on the element, graded towards
// the point nearest to x when x is closer than one element length (corner neighbours, CHIEF
// points, ground images). The element's own (self) integral: dG/dn = 0 on a straight element
// ((y - x).n = 0), and the logarithm of G is subtracted and integrated analytically,
//   Int_{-h}^{h} G(|t|) dt = 2 [ -(1/(2 pi)) (h ln h - h) + Int_0^h (G(t) + ln(t) / (2 pi)) dt ],
// the remainder (smooth up to t^2 ln t) by Gauss-Legendre ("singularity subtraction"; no
// log-weighted rule is needed).
//
// Irregular frequencies. Eq. (2) on Gamma fails to have a unique solution at the eigenvalues of
// the interior Dirichlet problem of the section (for a disc of radius a: the zeros of J_n(ka),
// the first at ka = 2.405); near them the computed power is wrong (tests: errors beyond 100 %,
// even a negative power, within 0.01 of the disc's ka). Treatment: CHIEF (Schenck, J. Acoust. Soc.
// Am. 44, 1968, 41-58): the equation (2) with c = 0 at points inside the body is appended to the
// collocation equations and the overdetermined system is solved in the least-squares sense
// (Householder QR). A CHIEF point fails only on a nodal line of the interior mode; several points
// spread over the section make that negligible. The points are placed deterministically: candidates
// on a 48 x 48 grid over the body's bounding box, those inside and at least 0.3 times the deepest
// candidate's depth from the outline kept, then chosen by farthest-point sampling from the deepest
// one (a body thinner than the grid gets none). CHIEF was chosen over Burton-Miller because it
// needs no hypersingular operator (which with constant elements needs special regularisation),
// costs a few extra rows, and a solid section always has interior room; its known weakness,
// interior modes so dense at high ka that every point sits near a nodal line, lies far above the
// rail's range. The UIC60 section's first interior eigenvalue (a symmetric mode, so vertical
// motion) lies near 4.37 kHz, inside the 4 kHz band: there the plain formulation is off by up to 45
// %, CHIEF is smooth (tested; an antisymmetric one near 6.25 kHz affects lateral motion); the
// disc's first two are tested as well.
//
// Rigid ground plane (option). A rigid, reflecting plane z = z_ground (e.g. a slab track's
// concrete surface under the rail foot) is represented by the image Green's function
//   G_h(x, y) = G(x, y) + G(x, y'),  y' = (y_y, 2 z_ground - y_z),
// whose normal derivative vanishes on the plane, so the plane needs no elements; polygon sides
// lying on the plane (a foot resting on it) are not part of the radiating boundary and are
// dropped. Off by default: the caller decides. Ballast is porous and absorbing, not a rigid plane;
// for a rail on ballast use free field (or a model of the absorbing ground, not provided here).
// Ground-plane powers are those radiated into the half space z > z_ground.
//
// Power. W' = (1/2) Re Int_Gamma p v_n^* ds (W/m, time-averaged per unit length) with the element
// values: W' = (1/2) Re sum_j L_j p_j conj(v_j). Radiation efficiency (fluid.hpp, Thompson Eq.
// 6.1, per unit length): sigma = W' / (rho c Int_Gamma <v_n^2> ds), <v_n^2> = |v_n|^2 / 2.
//
// Accuracy: the circular cylinder's power within 0.1 % at 10 elements per acoustic wavelength
// (0.5 % at 4; tests/acoustics/bem2d_test.cpp). Corners converge more slowly (constant elements):
// the UIC60 section's efficiencies with the default 110 elements lie within 2 % of those with
// 400 elements, 100 Hz - 2.5 kHz. The functions refuse meshes with fewer than 4 elements per
// wavelength. Cost (UIC60, 110 elements, 10 CHIEF points, one core): 12 ms a call at 1 kHz,
// 24 ms at 5 kHz (Bessel functions dominate); with the ground plane 18 and 32 ms.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <limits>
#include <vector>

#include "acoustics/fluid.hpp"

namespace rollnoise::acoustics {

/// A cross-section outline: a closed polygon in (y, z) (m), y lateral, z up, the last point not
/// repeated (a repeated first point is ignored). Either orientation; it is made counter-clockwise.
struct Section2d {
  std::vector<Eigen::Vector2d> outline;
};

/// Options of the 2D boundary element model.
struct Bem2dOptions {
  /// About this many elements over the whole perimeter: each polygon side of length l gets
  /// ceil(l / h) equal elements, h = perimeter / target_elements (so at least this many).
  int target_elements = 100;
  /// An upper bound on h (m); 0: none.
  double max_element_length = 0.0;
  /// Gauss-Legendre points per element (and per graded sub-interval near a point).
  int gauss_points = 8;
  /// CHIEF interior points per body; 0: the plain formulation (irregular frequencies untreated).
  int chief_points = 10;
  /// A rigid, reflecting ground plane z = ground_z (image source); false: free field.
  bool ground_plane = false;
  /// The plane's height (m); NaN: the lowest z of the section(s) (the rail foot's bottom).
  double ground_z = std::numeric_limits<double>::quiet_NaN();
};

/// A straight constant boundary element: from start to end, outward unit normal, length.
struct BoundaryElement2d {
  Eigen::Vector2d start;
  Eigen::Vector2d end;
  Eigen::Vector2d normal;  ///< outward (into the fluid)
  double length = 0.0;     ///< m
  Eigen::Vector2d midpoint() const { return 0.5 * (start + end); }
};

/// The radiating boundary elements of one or more bodies (free field: every side; with the
/// ground plane, the sides on the plane dropped), in polygon order, body after body. The rows of
/// every velocity pattern of this file follow this order.
std::vector<BoundaryElement2d> boundary_elements_2d(const std::vector<Section2d>& bodies,
                                                    const Bem2dOptions& options = {});
std::vector<BoundaryElement2d> boundary_elements_2d(const Section2d& section,
                                                    const Bem2dOptions& options = {});

/// The CHIEF points used (chief_points per body, inside each body; empty if chief_points = 0).
std::vector<Eigen::Vector2d> chief_points_2d(const std::vector<Section2d>& bodies,
                                             const Bem2dOptions& options = {});

/// The surface pressure amplitudes p (Pa, elements x m, complex) produced by the normal-velocity
/// amplitudes (m/s, elements x m, complex) at wavenumber k = omega / c (1/m): the solution of
/// Eq. (2) with Eq. (1). Several bodies radiate together (they scatter each other's sound).
Eigen::MatrixXcd surface_pressure_2d(const std::vector<Section2d>& bodies, double k,
                                     const Eigen::MatrixXcd& normal_velocities, const Fluid& fluid,
                                     const Bem2dOptions& options = {});

/// The m x m Hermitian matrix P with W' = a^H P a: the time-averaged power per unit length (W/m)
/// radiated by the normal-velocity amplitudes V = patterns a (patterns: elements x m, real, m/s
/// per unit of a) at wavenumber k (1/m). P = (C + C^H) / 4, C = patterns^T diag(L) p(patterns).
Eigen::MatrixXcd radiated_power_matrix_2d(const std::vector<Section2d>& bodies, double k,
                                          const Eigen::MatrixXd& patterns, const Fluid& fluid,
                                          const Bem2dOptions& options = {});
Eigen::MatrixXcd radiated_power_matrix_2d(const Section2d& section, double k,
                                          const Eigen::MatrixXd& patterns, const Fluid& fluid,
                                          const Bem2dOptions& options = {});

/// The normal velocity per element (m/s) of a rigid-body translation of the section with unit
/// velocity amplitude in the direction (dy, dz) (normalised here): v_n = d . n.
Eigen::VectorXd rigid_translation_pattern(const Section2d& section,
                                          const Eigen::Vector2d& direction,
                                          const Bem2dOptions& options = {});

/// The radiation of a rigid translation of the section (velocity amplitude U in one direction).
struct RigidRadiation2d {
  /// sigma = W' / (rho c Int_Gamma <v_n^2> ds), -> 1 at high k a.
  double efficiency = 0.0;
  /// W' / <v^2> (W/m per (m/s)^2): the power per unit length per unit mean-square velocity of
  /// the translation, <v^2> = |U|^2 / 2; = rho c efficiency radiating_width. The number the rail's
  /// sound power needs: W' = power_per_mean_square_velocity <v^2>.
  double power_per_mean_square_velocity = 0.0;
  /// Int_Gamma (d . n)^2 ds (m): the radiating width of the translation (the projected perimeter
  /// weighted by cos^2; pi a for a disc of radius a; the foot's bottom excluded on the ground).
  double radiating_width = 0.0;
};

/// The radiation of rigid translations in several directions, one solve (e.g. vertical (0, 1)
/// and lateral (1, 0) of a rail at one frequency).
std::vector<RigidRadiation2d> rigid_translation_radiation_2d(
    const Section2d& section, double k, const std::vector<Eigen::Vector2d>& directions,
    const Fluid& fluid, const Bem2dOptions& options = {});
RigidRadiation2d rigid_translation_radiation_2d(const Section2d& section, double k,
                                                const Eigen::Vector2d& direction,
                                                const Fluid& fluid,
                                                const Bem2dOptions& options = {});

/// The radiation efficiency of a wave v_n(y, z) e^{-i kappa x} travelling along a prismatic body
/// (axial wavenumber kappa, 1/m) at acoustic wavenumber k, from the body's 2D efficiency
/// (the "2.5D" relation; Nilsson, Jones, Thompson and Ryue, J. Sound Vib. 321 (2009) 813-836;
/// Thompson 2009, Sec. 6.5). The pressure e^{-i kappa x} p(y, z) solves the 2D Helmholtz equation
/// with k_r^2 = k^2 - kappa^2, and Eq. (1) still reads dp/dn = -i omega rho v_n: the 2D operator
/// of wavenumber k_r driven by omega rho = (k / k_r) (k_r rho c). Hence
///   sigma_3D(kappa) = (k / k_r) sigma_2D(k_r),  k_r = sqrt(k^2 - kappa^2),   |kappa| < k,
/// and 0 for |kappa| >= k (the wave is subsonic along the body: a near field only, no power,
/// outside the corner regions of a finite body). efficiency_2d(k_r) is, e.g., a
/// rigid_translation_radiation_2d efficiency or a pattern's a^H P a / (rho c Int <v_n^2>).
/// At kappa -> k the factor k / k_r diverges; sigma_2D(k_r) -> 0 as k_r (pulsating, 2D monopole:
/// the limit is finite) or k_r^3 (dipole: the limit is 0).
double axial_wave_efficiency(double k, double kappa,
                             const std::function<double(double)>& efficiency_2d);

}  // namespace rollnoise::acoustics
