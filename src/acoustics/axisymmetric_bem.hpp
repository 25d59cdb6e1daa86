// Sound radiation of an axisymmetric body, one circumferential order at a time: the axisymmetric
// boundary element method for the exterior Helmholtz problem (Seybert, Soenarko, Rizzo & Shippy,
// JASA 77 (1985) 362-368; Thompson & Jones, JSV 253 (2002) 401-419 for the railway wheel).
//
// Geometry. A generator is a polyline of points (r, z) in the meridian half-plane r >= 0; the
// surface S is the polyline swept around the z axis. Either
//   closed: a ring whose outline does not touch the axis (all r > 0; the last point joins the
//           first), e.g. a wheel section;
//   open:   a body of revolution, first and last point on the axis (r = 0), the others at r > 0,
//           e.g. a sphere from pole to pole.
// Orientation: the outward normal is the right-hand normal (dz, -dr) / |ds| of a polygon traversed
// counter-clockwise in the (r, z) plane (r to the right, z up); for an open generator the polygon
// is closed along the axis, so counter-clockwise runs from the z-min pole through r > 0 to the
// z-max pole. The other sense is detected (sign of the enclosed area) and the normals flipped, so
// both orders give the same result. Elements are the straight segments between consecutive points
// (a cone frustum each), with constant values (one unknown per segment, collocation at the segment
// midpoint, where the discretised surface is smooth: free term 1/2).
//
// Fields of order n (time convention e^{+i omega t}, acoustics/fluid.hpp):
//   v_n(s, phi) = v(s) cos(n phi),  p(s, phi) = p(s) cos(n phi)  (sin(n phi): the same power).
// The Kirchhoff-Helmholtz integral equation on S, n the outward normal, G = e^{-ikR} / (4 pi R),
// dp/dn = -i omega rho v_n = -i k rho c v_n (momentum equation; exterior, Sommerfeld condition):
//   c(x) p(x) = int_S [ p(y) dG/dn_y(x, y) - G(x, y) dp/dn(y) ] dS_y,
// c = 1/2 on the smooth surface, 0 inside the body. With y = (r_y cos phi, r_y sin phi, z_y) and x
// at phi = 0 the phi-integral separates (dS = r ds dphi):
//   (1/2) p(x) - int p(y) H_n(x, y) r_y ds = i k rho c int v(y) G_n(x, y) r_y ds,
//   G_n = int_0^{2 pi} G cos(n phi) dphi,  H_n = int_0^{2 pi} dG/dn_y cos(n phi) dphi,
// as in Seybert et al. For constant elements: (1/2 I - H) p = i k rho c G v.
//
// Irregular frequencies: at the interior Dirichlet eigenvalues of the body the exterior equation
// above is singular. CHIEF (Schenck, JASA 44 (1968) 41-58) appends the interior equations
//   0 = int_S [ p dG/dn - G dp/dn ] dS  at interior points x_c,
// and solves the overdetermined system by least squares (Householder QR).
//
// Power. W = (1/2) Re int_S p v^* dS, with int_0^{2 pi} cos^2(n phi) dphi = 2 pi (n = 0) or
// pi (n >= 1), and int r ds over a segment = length (r_a + r_b) / 2.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "acoustics/fluid.hpp"

namespace rollnoise::acoustics {

/// The meridian outline of a body of revolution (see the file comment for the orientation rule).
struct AxisymmetricGenerator {
  std::vector<Eigen::Vector2d> points;  ///< (r, z) (m), r >= 0
  bool closed = true;  ///< true: a ring (last point joins the first); false: pole to pole on r = 0
};

/// One boundary element (a straight segment of the generator, swept: a cone frustum).
struct AxisymmetricElement {
  Eigen::Vector2d start, end;  ///< (r, z) ends (m), in the generator's order
  Eigen::Vector2d midpoint;    ///< collocation point (r, z) (m)
  Eigen::Vector2d normal;      ///< outward unit normal (n_r, n_z) (into the fluid)
  double length = 0.0;         ///< segment length (m)
  double r_ds = 0.0;           ///< int r ds over the segment = length (r_start + r_end) / 2 (m^2)
};

/// The elements of a generator, in its order, with outward normals; checks the generator (see
/// radiated_power_matrices for what is rejected).
std::vector<AxisymmetricElement> axisymmetric_elements(const AxisymmetricGenerator& generator);

/// The numerical parameters. The defaults integrate the kernels to ~1e-5 relative; the power's
/// accuracy is then set by the mesh (constant elements: error ~ (k h)^2; 12 elements per
/// wavelength gave <= 0.1 % on the sphere up to k a = 30, see the tests).
struct AxisymmetricBemOptions {
  /// Gauss-Legendre points per element (segment). Elements nearer to the observation point than
  /// their length are subdivided (graded towards it) on top of this.
  int gauss_points = 4;
  /// CHIEF interior points (deterministic, spread over the region the generator encloses, away
  /// from its outline and from the axis); 0 = the plain formulation, wrong near the irregular
  /// frequencies. On by default: the interior eigenvalues of a wheel section fall inside the
  /// railway frequency range (k a ~ 20-40 for a rim of 0.07 m by 0.14 m) and are dense in k at
  /// high k a, so without CHIEF some frequencies of a sweep would be silently wrong; the extra
  /// rows cost ~10 % of the assembly at 200 elements.
  int chief_points = 16;
  /// Intervals of the trapezoidal phi-rule on [0, pi] (the integrands are even and
  /// 2 pi-periodic); 0 = chosen from k r_max and the highest order (see the source).
  int phi_intervals = 0;
};

/// The radiated power matrices of the requested circumferential orders at one wavenumber.
///
/// For every order n with patterns[n] non-empty (an elements x m_n real matrix, each column a
/// normal-velocity amplitude per element, the pattern v_e cos(n phi), m/s per unit coefficient),
/// result[n] is the m_n x m_n Hermitian matrix P_n with the time-averaged radiated power
///   W = a^H P_n a  (W)
/// of the normal velocity V = patterns[n] a (complex a). P_n is real symmetric (reciprocity makes
/// the impedance of real patterns complex symmetric; its real part is the radiation resistance,
/// see the source). Orders with an empty pattern get an empty
/// matrix; result.size() == patterns.size(). All orders at one wavenumber k = omega / c (1/m) in
/// one call: the phi-integrals of the kernels of all orders come from one phi-quadrature.
///
/// Throws std::invalid_argument for k <= 0, a generator that is not one of the two kinds above
/// (fewer than 3 points, a zero-length segment, r < 0, an open generator's ends off the axis or
/// at one point, a closed generator touching the axis, a self-intersecting outline), a pattern
/// whose row count is not the number of elements or with non-finite values, a fluid of
/// non-positive density or sound speed, or options out of range.
std::vector<Eigen::MatrixXcd> radiated_power_matrices(const AxisymmetricGenerator& generator,
                                                      double k,
                                                      const std::vector<Eigen::MatrixXd>& patterns,
                                                      const Fluid& fluid,
                                                      const AxisymmetricBemOptions& options = {});

/// The radiation efficiency of one pattern of order n (acoustics/fluid.hpp):
///   sigma = W / (rho c S <v_n^2>),  S <v_n^2> = (1/2) sum_e |v_e|^2 r_ds_e c_n,
/// c_n = int_0^{2 pi} cos^2(n phi) dphi, S the whole surface. The pattern must not vanish.
double radiation_efficiency(const AxisymmetricGenerator& generator, int n, double k,
                            const Eigen::VectorXd& pattern, const Fluid& fluid,
                            const AxisymmetricBemOptions& options = {});

/// The CHIEF points the solver uses for this generator and count, (r, z) (m): deterministic, inside
/// the region enclosed by the generator (with the axis, for an open one), at r > 0.
std::vector<Eigen::Vector2d> axisymmetric_chief_points(const AxisymmetricGenerator& generator,
                                                       int count);

}  // namespace rollnoise::acoustics
