#include "dynamics/rail_contact.hpp"

#include <cmath>

namespace rollnoise::dynamics {
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& d) {
  Eigen::Matrix3d S;
  S << 0.0, -d.z(), d.y(),  //
      d.z(), 0.0, -d.x(),   //
      -d.y(), d.x(), 0.0;
  return S;
}

namespace {

// L(d) M of (G1) applied to the columns of a 6-row M: u' = u + th x d.
template <class M>
void apply_lever(M& m, const Eigen::Vector3d& d) {
  for (Eigen::Index j = 0; j < m.cols(); ++j) {  // written out: Eigen's complex cross() conjugates
    const cdouble tx = m(3, j), ty = m(4, j), tz = m(5, j);
    m(0, j) += ty * d.z() - tz * d.y();
    m(1, j) += tz * d.x() - tx * d.z();
    m(2, j) += tx * d.y() - ty * d.x();
  }
}

}  // namespace

Receptance6 embed(const Receptance4& a) {
  Receptance6 out = Receptance6::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out(kSixOfFour[i], kSixOfFour[j]) = a(i, j);
  return out;
}

Receptance6 move_point(const Receptance6& a, const Eigen::Vector3d& d) {
  // u' = u + th x d = u - d x th,  th' = th.
  Eigen::Matrix<double, 6, 6> L = Eigen::Matrix<double, 6, 6>::Identity();
  L.topRightCorner<3, 3>() = -cross_matrix(d);
  const Eigen::Matrix<cdouble, 6, 6> Lc = L.cast<cdouble>();
  return Lc * a * Lc.transpose();
}

Receptance6 move_points(const Receptance6& alpha, const Eigen::Vector3d& d_a,
                        const Eigen::Vector3d& d_b) {
  Receptance6 left = alpha;  // L(d_a) alpha
  apply_lever(left, d_a);
  Receptance6 both = left.transpose();  // L(d_b) (L(d_a) alpha)^T, transposed back
  apply_lever(both, d_b);
  return both.transpose();
}

Eigen::Matrix<double, 6, 4> contact_frame(double gamma) {
  const double s = std::sin(gamma), c = std::cos(gamma);
  Eigen::Matrix<double, 6, 4> T = Eigen::Matrix<double, 6, 4>::Zero();
  T(1, 0) = -s;  // n = (0, -sin g, cos g)
  T(2, 0) = c;
  T(0, 1) = 1.0;  // t_x = (1, 0, 0)
  T(1, 2) = c;    // t_y = (0, cos g, sin g)
  T(2, 2) = s;
  T(4, 3) = -s;  // spin about n
  T(5, 3) = c;
  return T;
}

Receptance6 from_contact_frames(const Receptance4& a, double angle_a, double angle_b) {
  return contact_frame(angle_a).cast<cdouble>() * a *
         contact_frame(angle_b).cast<cdouble>().transpose();
}

}  // namespace rollnoise::dynamics
