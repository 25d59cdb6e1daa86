#include "nss/falling_friction.hpp"

#include <cmath>

namespace rollnoise::nss {

Eigen::Matrix2d full_slip_creep_coefficients(double normal_force, double speed, double xi_x, double xi_y,
                                             const contact::FrictionLaw& law) {
  const double xi = std::hypot(xi_x, xi_y), v = speed * xi;
  const Eigen::Vector2d s(xi_x / xi, xi_y / xi), t(-s(1), s(0));
  // (S1): f = -dF/dxi with F = -mu(V|xi|) N xi/|xi|
  return normal_force * (speed * law.slope(v) * s * s.transpose() + law.mu(v) / xi * t * t.transpose());
}

double critical_damping_ratio(double along_slip_coefficient, double speed, double psi, double modal_mass,
                              double omega_n) {
  // (S2): 2 zeta w_n m + f_par psi^2 / V = 0
  return -along_slip_coefficient * psi * psi / (speed * 2.0 * modal_mass * omega_n);
}

}  // namespace rollnoise::nss
