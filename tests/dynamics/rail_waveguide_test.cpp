// Checks of the rail cross-section properties (dynamics/rail_section.hpp) and of the waveguide
// finite-element rail (dynamics/rail_waveguide.hpp) against Saint-Venant torsion, beam theory
// (Timoshenko, Vlasov) and the Timoshenko track model, and its reciprocity and passivity.
#include "dynamics/rail_waveguide.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <vector>

#include "dynamics/rail_section.hpp"
#include "dynamics/track.hpp"
#include "fem/mesh.hpp"
#include "support/test_helpers.hpp"

namespace rd = rollnoise::dynamics;
namespace rf = rollnoise::fem;
using cd = std::complex<double>;

namespace {

using rollnoise::test_support::db;

rd::RailMaterial steel(double eta) {
  rd::RailMaterial m;
  m.loss_factor = eta;
  return m;
}

// The beam of one bending plane with the section's own A, I and the FE's material.
rd::BeamSection beam_of(const rd::SectionProperties& s, double I, double kappa,
                        const rd::RailMaterial& m) {
  rd::BeamSection b;
  b.youngs_modulus = m.youngs_modulus;
  b.shear_modulus = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
  b.area = s.area;
  b.second_moment = I;
  b.mass_per_length = m.density * s.area;
  b.shear_coefficient = kappa;
  b.loss_factor = m.loss_factor;
  return b;
}

// The free rail's propagating wavenumbers (real, positive) at omega.
std::vector<double> propagating(const rd::RailWaves& w) {
  std::vector<double> k;
  for (int j = 0; j < w.wavenumbers.size(); ++j)
    if (std::abs(w.wavenumbers(j).imag()) < 1e-6 * std::abs(w.wavenumbers(j)))
      k.push_back(w.wavenumbers(j).real());
  return k;
}

double nearest(const std::vector<double>& ks, double k) {
  double best = ks.at(0);
  for (double v : ks)
    if (std::abs(v - k) < std::abs(best - k)) best = v;
  return best;
}

}  // namespace

// Timoshenko & Goodier 1970, Sec. 109, Eq. (167): J of an a x b rectangle (a >= b),
//   J = (a b^3 / 3) [1 - (192 b / (pi^5 a)) sum_{n odd} tanh(n pi a / (2 b)) / n^5].
// Checks Eqs. (S1)-(S2) and that the shear centre of a doubly symmetric section is its centroid.
TEST(RailSection, TorsionConstantOfRectangleMatchesSaintVenantSeries) {
  const double a = 0.04, b = 0.02;
  const std::vector<Eigen::Vector2d> outline = {{0.0, 0.0}, {a, 0.0}, {a, b}, {0.0, b}};
  const rd::SectionProperties s = rd::section_properties(rf::mesh_polygon(outline, 0.005));
  double sum = 0.0;
  for (int n = 1; n < 40; n += 2) sum += std::tanh(n * M_PI * a / (2.0 * b)) / std::pow(n, 5);
  const double J = a * b * b * b / 3.0 * (1.0 - 192.0 * b / (std::pow(M_PI, 5) * a) * sum);
  EXPECT_NEAR(s.torsion_constant / J, 1.0, 2e-3);
  EXPECT_NEAR(s.area, a * b, 1e-12);
  EXPECT_NEAR(s.second_moment_yy, a * b * b * b / 12.0, 1e-12 * a * b * b * b);
  EXPECT_LT(s.shear_centre.norm(), 1e-4 * b);  // the mesh is not symmetric
}

// The approximate UIC60 outline against EN 13674-1's 60E1 values: A = 76.70 cm^2,
// I_yy = 3038.3 cm^4, I_zz = 512.3 cm^4, neutral axis 80.95 mm above the foot (tolerances: the
// fillets drawn as chamfers take ~2 % of the area); the shear centre lies on the symmetry axis
// below the centroid (towards the foot, whose warping dominates; Thompson 2009 Sec. 3.4 places it
// in the lower web).
TEST(RailSection, Uic60OutlineNearEn13674Values) {
  const rd::SectionProperties s =
      rd::section_properties(rf::mesh_polygon(rd::uic60_outline(), 0.01));
  EXPECT_NEAR(s.area / 76.70e-4, 1.0, 0.03);
  EXPECT_NEAR(s.second_moment_yy / 3038.3e-8, 1.0, 0.02);
  EXPECT_NEAR(s.second_moment_zz / 512.3e-8, 1.0, 0.03);
  EXPECT_NEAR(s.centroid.y(), 0.08095, 1e-3);
  EXPECT_NEAR(s.centroid.x(), 0.0, 1e-9);
  EXPECT_NEAR(s.shear_centre.x(), 0.0, 1e-6);
  EXPECT_LT(s.shear_centre.y(), 0.0);
  EXPECT_GT(s.torsion_constant, 1e-6);
  EXPECT_LT(s.torsion_constant, 4e-6);
}

namespace {

// Vlasov's coupled lateral bending and torsion of a mono-symmetric beam (Vlasov 1961; Gere &
// Lin, J. Franklin Inst. 266, 1958): v the lateral displacement of the shear centre, theta the
// rotation about it, z_p the shear centre's height from the centroid (the centroid moves by
// v + z_p theta), I_c the polar moment about the centroid:
//   (EI_zz k^4 - rho A w^2) v - rho A w^2 z_p theta = 0,
//   -rho A w^2 z_p v + (GJ k^2 + E I_w k^4 - rho w^2 (I_c + A z_p^2)) theta = 0,
// whose determinant is a cubic in q = k^2. Returns its positive real roots' square roots.
std::vector<double> vlasov_wavenumbers(const rd::SectionProperties& s, const rd::RailMaterial& m,
                                       double w) {
  const double E = m.youngs_modulus, G = E / (2.0 * (1.0 + m.poisson_ratio)), rho = m.density;
  const double zp = s.shear_centre.y(), mA = rho * s.area * w * w;
  const double c = mA * zp, r = rho * w * w * (s.polar_moment() + s.area * zp * zp);
  const double a = E * s.second_moment_zz, e = E * s.warping_constant, g = G * s.torsion_constant;
  // (a q^2 - mA)(e q^2 + g q - r) - c^2 = a e q^4 + a g q^3 - (a r + mA e) q^2 - mA g q + mA r -
  // c^2
  Eigen::Matrix4d C = Eigen::Matrix4d::Zero();  // companion of the quartic in q
  const double coef[5] = {mA * r - c * c, -mA * g, -(a * r + mA * e), a * g, a * e};
  for (int i = 0; i < 3; ++i) C(i + 1, i) = 1.0;
  for (int i = 0; i < 4; ++i) C(i, 3) = -coef[i] / coef[4];
  const Eigen::Vector4cd q = Eigen::EigenSolver<Eigen::Matrix4d>(C).eigenvalues();
  std::vector<double> k;
  for (int i = 0; i < 4; ++i)
    if (std::abs(q(i).imag()) < 1e-9 * std::abs(q(i)) && q(i).real() > 0.0)
      k.push_back(std::sqrt(q(i).real()));
  return k;
}

}  // namespace

// At 100 Hz the free rail's propagating waves are the beam's: vertical bending (Timoshenko,
// kappa = 0.4), lateral bending and torsion (Vlasov, with J, I_w, shear centre from the same
// mesh) and the rod; the FE wavenumbers equal them within 2 % (the acceptance).
TEST(RailWaveguide, FreeRailWavenumbersEqualBeamTheoryAt100Hz) {
  const rf::QuadraticTriangleMesh mesh = rf::mesh_polygon(rd::uic60_outline(), 0.04);
  const rd::SectionProperties s = rd::section_properties(mesh);
  const rd::RailMaterial m = steel(0.0);
  const rd::RailWaveguide rail(mesh, m, std::nullopt);
  const double w = 2.0 * M_PI * 100.0;
  const std::vector<double> fe = propagating(rail.waves(w));
  ASSERT_EQ(fe.size(), 4u) << "only the four beam waves propagate at 100 Hz";
  const rd::InfiniteBeam vertical(beam_of(s, s.second_moment_yy, 0.4, m), w, 0.0);
  const double kv = vertical.wavenumbers()[0].real() > vertical.wavenumbers()[1].real()
                        ? vertical.wavenumbers()[0].real()
                        : vertical.wavenumbers()[1].real();
  EXPECT_NEAR(nearest(fe, kv) / kv, 1.0, 0.02) << "vertical bending";
  const std::vector<double> lt = vlasov_wavenumbers(s, m, w);
  ASSERT_EQ(lt.size(), 2u);
  for (double k : lt) EXPECT_NEAR(nearest(fe, k) / k, 1.0, 0.02) << "lateral/torsion k = " << k;
  const double krod = w / std::sqrt(m.youngs_modulus / m.density);
  EXPECT_NEAR(nearest(fe, krod) / krod, 1.0, 0.02) << "rod";
}

// Where the section does not deform: the vertical receptance of the head's crown (a uniform
// vertical traction over the crown, |y| < 25 mm, its response averaged the same way) on the
// continuous support equals the Timoshenko beam (track.hpp, kappa = 0.4, the section's own A and I,
// the same support) within 1.5 dB from 100 to 500 Hz (the acceptance). A nodal point force
// adds the local deformation under it (a real, mesh-dependent compliance, ~1.8e-9 m/N on this
// mesh); the response of the foot's bottom to the same load is the beam's too.
TEST(RailWaveguide, CentredVerticalReceptanceEqualsTimoshenkoTrack100To500Hz) {
  const rf::QuadraticTriangleMesh mesh = rf::mesh_polygon(rd::uic60_outline(), 0.04);
  const rd::SectionProperties s = rd::section_properties(mesh);
  const rd::TrackParameters t = rd::uic60_ballasted();
  const rd::RailMaterial m = steel(t.vertical.loss_factor);
  const rd::RailWaveguide rail(mesh, m,
                               rd::FootSupport{t.vertical_support, t.lateral_support,
                                               t.longitudinal_support, t.sleeper_spacing});
  std::vector<int> crown, foot;
  for (int i = 0; i < static_cast<int>(mesh.boundary_edges.size()); ++i) {
    bool in_crown = true, in_foot = true;
    for (int v : mesh.boundary_edges[i]) {
      in_crown = in_crown && mesh.nodes[v].y() > 0.165 && std::abs(mesh.nodes[v].x()) < 0.025;
      in_foot = in_foot && mesh.nodes[v].y() < 1e-9;
    }
    if (in_crown) crown.push_back(i);
    if (in_foot) foot.push_back(i);
  }
  ASSERT_FALSE(crown.empty());
  const Eigen::MatrixXd L = rail.edge_traction(crown, 2), B = rail.edge_traction(foot, 2);
  Eigen::MatrixXd loads(L.rows(), 2);
  loads << L, B;
  const rd::RailWaveguide reduced = rail.reduced(rd::RailReduction{}, loads);  // (full: 1.34 dB)
  const rd::BeamSection beam = beam_of(s, s.second_moment_yy, 0.4, m);
  for (double f : {100.0, 250.0, 500.0}) {
    const rd::RailWaves w = reduced.waves(2.0 * M_PI * f);
    const cd tb =
        rd::continuous_transfer(beam, t.vertical_support, t.sleeper_spacing, f, 0.0)(0, 0);
    EXPECT_NEAR(db(reduced.transfer(w, L, L, 0.0)(0, 0)), db(tb), 1.5) << "f = " << f;
    EXPECT_NEAR(db(reduced.transfer(w, B, L, 0.0)(0, 0)), db(tb), 1.5) << "foot, f = " << f;
  }
}

// The 4x4 contact receptance at the 300 m curve's contact (gauge corner, contact angle 0.52 rad)
// is reciprocal (symmetric) and passive (-Im R has no negative eigenvalue), and between two
// contacts 1.2 m apart H_ab(x) = H_ba(-x)^T; on the reduced model (as the loop uses it).
TEST(RailWaveguide, EccentricContactReceptanceIsReciprocalAndPassive) {
  const rf::QuadraticTriangleMesh mesh = rf::mesh_polygon(rd::uic60_outline(), 0.04);
  const rd::TrackParameters t = rd::uic60_ballasted();
  const rd::RailWaveguide rail(mesh, steel(0.02),
                               rd::FootSupport{t.vertical_support, t.lateral_support,
                                               t.longitudinal_support, t.sleeper_spacing});
  const double gamma = 0.52;
  const Eigen::Vector2d normal(-std::sin(gamma), std::cos(gamma));
  const int gauge = rd::nearest_boundary_node(mesh, Eigen::Vector2d(-0.0335, 0.1665));
  const int top = rd::nearest_boundary_node(mesh, Eigen::Vector2d(0.0, 0.172));
  const Eigen::MatrixXd La = rail.contact_loads(gauge, normal, rd::kUic60HeadBottom);
  const Eigen::MatrixXd Lb =
      rail.contact_loads(top, Eigen::Vector2d(0.0, 1.0), rd::kUic60HeadBottom);
  Eigen::MatrixXd loads(La.rows(), 8);
  loads << La, Lb;
  const rd::RailWaveguide reduced = rail.reduced(rd::RailReduction{}, loads);
  for (const rd::RailWaveguide* model : {&reduced}) {  // (the full model: the same formulation)
    const rd::RailWaveguide& rail = *model;
    const double f = 2500.0;
    const rd::RailWaves w = rail.waves(2.0 * M_PI * f);
    const rd::Receptance4 R = rail.contact_receptance(w, La, La, 0.0);
    EXPECT_LT((R - R.transpose()).norm(), 1e-8 * R.norm()) << "f = " << f;
    const Eigen::Matrix4d dissipation = -0.5 * (R.imag() + R.imag().transpose());
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(dissipation).eigenvalues().minCoeff(),
              -1e-10 * R.norm())
        << "f = " << f;
    const rd::Receptance4 ab = rail.contact_receptance(w, La, Lb, 1.2);
    const rd::Receptance4 ba = rail.contact_receptance(w, Lb, La, -1.2);
    EXPECT_LT((ab - ba.transpose()).norm(), 1e-8 * ab.norm()) << "f = " << f;
  }
}
