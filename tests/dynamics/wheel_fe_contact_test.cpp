// The FE wheel at its contacts (dynamics/wheel_fe_contact.hpp): the static flexibility of the modal
// sum against a direct static FE solve, reciprocity and passivity of the point and cross
// receptances in tilted contact frames, the table at a contact and the +-n Omega split.
#include "dynamics/wheel_fe_contact.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "dynamics/wheel_fe.hpp"
#include "fem/triangle6.hpp"
#include "io/wheel_section_file.hpp"
#include "support/test_inputs.hpp"

using namespace rollnoise;
using namespace rollnoise::dynamics;

namespace {

using rollnoise::test_support::default_section;

// The static compliance of order n at tread position s by a direct solve K_n u = f (bore clamped):
// the 3x3 map from a unit load on (U_r, U_theta, U_z) at the tread point to (U_r, U_theta, U_z)
// there, f the load's consistent nodal vector (the shape functions at the point).
Eigen::Matrix3d direct_static_compliance(const WheelSection& section, const WheelFeModes& w,
                                         const fem::IsotropicMaterial& material, int n, double s) {
  const auto km = fem::assemble_axisymmetric(w.mesh, material, n);
  const int ndof = static_cast<int>(km.stiffness.rows());
  std::vector<int> index(ndof, 0);
  for (int node : fem::nodes_on_segments(w.mesh, section.bore_segments))
    for (int c = 0; c < 3; ++c) index[3 * node + c] = -1;
  int nfree = 0;
  for (int& i : index)
    if (i >= 0) i = nfree++;
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < km.stiffness.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(km.stiffness, c); it; ++it)
      if (index[it.row()] >= 0 && index[it.col()] >= 0)
        t.emplace_back(index[it.row()], index[it.col()], it.value());
  Eigen::SparseMatrix<double> k(nfree, nfree);
  k.setFromTriplets(t.begin(), t.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(k);
  const fem::MeshPoint p =
      fem::locate(w.mesh, {tread_radius_at(w, s), s}, 1e-4);  // s: a tread sample
  const auto N = fem::triangle6_shape(p.xi, p.eta);
  const auto& tri = w.mesh.triangles[p.triangle];
  Eigen::Matrix<double, Eigen::Dynamic, 3> f = Eigen::MatrixXd::Zero(nfree, 3);
  for (int a = 0; a < 6; ++a)
    for (int c = 0; c < 3; ++c)
      if (index[3 * tri[a] + c] >= 0) f(index[3 * tri[a] + c], c) = N(a);
  const Eigen::MatrixXd u = ldlt.solve(Eigen::MatrixXd(f));
  return f.transpose() * u;
}

Eigen::Matrix3d modal_static_compliance(const WheelFeModes& w, int n, double s, double f_max) {
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  for (const auto& m : w.modes) {
    if (m.n != n || m.frequency > f_max) continue;
    const Eigen::Vector3d u = tread_shape_at(w, m, s);
    c += u * u.transpose() / std::pow(2 * M_PI * m.frequency, 2);
  }
  return c;
}

// The default wheel's modes n <= n_max up to f_max on a mesh of size h (m).
WheelFeModes coarse_wheel(int n_max, double f_max, double h) {
  WheelFeOptions o;
  o.n_max = n_max;
  o.f_max = f_max;
  o.mesh_size = h;
  return wheel_fe_modes(default_section(), o);
}

bool passive(const Receptance4& h) {
  const Eigen::Matrix4cd d = (h - h.adjoint()) / cdouble(0, 2);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix4cd>(d).eigenvalues().maxCoeff() <=
         1e-12 * h.norm();
}

}  // namespace

// Static flexible part: with every mode of order n (a coarse 60 mm mesh, all modes by the dense
// solver) the modal sum sum U U^T / omega^2 at a tread sample equals the direct static solve
// K_n^{-1} of the same mesh to 1e-8 (the spectral identity K^{-1} = Phi Omega^-2 Phi^T, which
// checks the mass normalisation with c_n, the tread sampling and the bore clamp). Truncated at 6
// kHz, the modal sum misses the point load's local flexibility (printed): that residual is not
// added to the receptance (docs/models.md Sec. 3.4).
TEST(WheelFeContact, StaticModalSumEqualsDirectStaticSolve) {
  const auto section = default_section();
  WheelFeOptions o;
  o.n_max = 1;  // orders 0 and 1: the same K_n code as any n (the machine is shared: keep it cheap)
  o.f_max = std::numeric_limits<double>::infinity();  // all modes (the dense solver)
  o.mesh_size = 0.06;
  const auto w = wheel_fe_modes(section, o);
  std::cout << w.mesh.triangles.size() << " triangles, " << 3 * w.mesh.nodes.size()
            << " DOFs per n\n";
  for (int n : {0, 1})
    for (double s :
         {w.tread_s[w.tread_s.size() / 2], w.tread_s[10]}) {  // samples: no interpolation
      const Eigen::Matrix3d direct = direct_static_compliance(section, w, o.material, n, s);
      const Eigen::Matrix3d modal = modal_static_compliance(w, n, s, 1e300);
      EXPECT_LT((direct - modal).norm(), 1e-8 * direct.norm()) << "n = " << n << ", s = " << s;
      const Eigen::Matrix3d truncated = modal_static_compliance(w, n, s, 6000.0);
      std::cout << "n = " << n << ", s = " << s * 1e3 << " mm: static C_zz " << direct(2, 2)
                << " m/N, modes <= 6 kHz give " << truncated(2, 2) / direct(2, 2) * 100
                << " %, C_rr " << direct(0, 0) << " m/N, " << truncated(0, 0) / direct(0, 0) * 100
                << " %\n";
    }
}

// Reciprocity H_ab = H_ba^T between a tread contact (s = 0, gamma = 0.02) and a flange-root contact
// (s = -30 mm, gamma = 0.6) to round-off, with and without the +-n Omega split; passivity of the
// point receptances ((H - H^H)/2i <= 0) at 200 Hz .. 4 kHz.
TEST(WheelFeContact, CrossReceptanceIsReciprocalAndPointReceptancePassive) {
  const auto w = coarse_wheel(6, 4000.0, 0.02);
  const TreadContact a{0.0, 0.02}, b{-0.03, 0.6};
  for (double spin : {0.0, 42.0}) {
    WheelFeContactOptions co;
    co.spin_speed = spin;
    for (double f : {200.0, 950.0, 2000.0, 4000.0}) {
      const Receptance4 hab = fe_cross_receptance(w, co, a, b, f),
                        hba = fe_cross_receptance(w, co, b, a, f);
      EXPECT_LT((hab - hba.transpose()).norm(), 1e-12 * hab.norm()) << f << " Hz";
      EXPECT_TRUE(passive(fe_cross_receptance(w, co, a, a, f))) << f << " Hz";
      EXPECT_TRUE(passive(fe_cross_receptance(w, co, b, b, f))) << f << " Hz";
    }
  }
}

// The contact frame: the receptance at angle gamma is T^T H(0) T with the 6x4 frame of
// noise/loop.hpp restricted to (z, x, y, rot z) (rotations about y absent); and at gamma = 0 it
// equals the WheelModel built from contact_mode_table (the same modes, the same point).
TEST(WheelFeContact, TiltedFrameIsTheRotatedReceptanceAndTableAgrees) {
  const auto w = coarse_wheel(4, 3000.0, 0.02);
  const double s = -0.02, g = 0.5, f = 1300.0;
  const Receptance4 h0 = fe_cross_receptance(w, {}, {s, 0.0}, {s, 0.0}, f);
  Eigen::Matrix4d T = Eigen::Matrix4d::Zero();  // columns: n, x, t_y, spin in (z, x, y, rot z)
  T(2, 0) = -std::sin(g), T(0, 0) = std::cos(g);
  T(1, 1) = 1.0;
  T(2, 2) = std::cos(g), T(0, 2) = std::sin(g);
  T(3, 3) = std::cos(g);
  const Receptance4 expected = T.transpose().cast<cdouble>() * h0 * T.cast<cdouble>();
  const Receptance4 hg = fe_cross_receptance(w, {}, {s, g}, {s, g}, f);
  EXPECT_LT((hg - expected).norm(), 1e-12 * expected.norm());
  RigidWheelset ws;
  ws.mass = 1500, ws.roll_inertia = 700, ws.spin_inertia = 110, ws.yaw_inertia = 700;
  ws.contact_offset_y = 0.75, ws.wheel_radius = 0.46;
  const WheelModel model(ws, contact_mode_table(w, s));
  EXPECT_LT((model.modal_receptance(f) - h0).norm(), 1e-12 * h0.norm());
}

// The +-n Omega split: with Omega = 42 rad/s every n >= 1 partner appears twice at f -+ n Omega/2pi
// with half its participation (shape / sqrt 2): the table's participation summed over the two waves
// equals the unsplit one, and the peaks sit at the split frequencies.
TEST(WheelFeContact, RotationSplitsEachPairByNOmega) {
  const auto w = coarse_wheel(3, 1500.0, 0.03);
  WheelFeContactOptions split;
  split.spin_speed = 42.0;
  const auto still = contact_mode_table(w, 0.0), turning = contact_mode_table(w, 0.0, split);
  ASSERT_EQ(turning.size(), 2 * still.size());
  for (std::size_t i = 0; i < still.size(); ++i) {
    const int n = still[i].label[still[i].label.find("n=") + 2] - '0';
    const double df = n * 42.0 / (2 * M_PI);
    EXPECT_NEAR(turning[2 * i].frequency, still[i].frequency - df, 1e-9);
    EXPECT_NEAR(turning[2 * i + 1].frequency, still[i].frequency + df, 1e-9);
    const Eigen::Matrix4d sum = turning[2 * i].shape * turning[2 * i].shape.transpose() +
                                turning[2 * i + 1].shape * turning[2 * i + 1].shape.transpose();
    EXPECT_LT((sum - still[i].shape * still[i].shape.transpose()).norm(),
              1e-14 * sum.norm() + 1e-30);
  }
}
