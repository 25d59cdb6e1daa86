#include "noise/curving.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

void positive(double v, const char* key) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(std::string("curving.") + key,
                     std::string("curving.") + key + " must be positive and finite");
}

// Cubic saturation, secant form: |F| = mu Q u s(u), s = 1 - u/3 + u^2/27 (u < 3), 1/u (u >= 3).
double secant_factor(double u) {
  return u < 3.0 ? 1.0 - u / 3.0 + u * u / 27.0 : 1.0 / u;
}

struct Geometry {
  double a, l0, r0, inv_R, yf, Fu;
};

// The equilibrium (K3) for given secant stiffnesses S_i (sum over the two wheels of axle i) and
// secant conicities lam_i (Delta_r(y_i) = 2 lam_i y_i), for one choice of flange contacts
// (flange_i = 0 free, +1 at y = +y_f, -1 at y = -y_f). Unknowns (y1, y2, Y1, Y2).
Eigen::Vector4d solve_active_set(const Geometry& g, double f11, double f22,
                                 const std::array<double, 2>& S, const std::array<double, 2>& lam,
                                 const std::array<int, 2>& flange) {
  // psi_1 = (y1 - y2)/(2a) + a/R, psi_2 = (y1 - y2)/(2a) - a/R
  // xi_x,i = l0/R - lam_i y_i / r0
  const double C1 = f22 * S[0], C2 = f22 * S[1];
  const double th = 1.0 / (2.0 * g.a);  // d theta / d y1 = -d theta / d y2
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  // Lateral: C1 psi1 + C2 psi2 + Y1 + Y2 + Fu = 0
  M(0, 0) = (C1 + C2) * th;
  M(0, 1) = -(C1 + C2) * th;
  M(0, 2) = 1.0;
  M(0, 3) = 1.0;
  rhs(0) = -g.Fu - (C1 - C2) * g.a * g.inv_R;
  // Yaw: sum_i l0 f11 S_i (l0/R - lam_i y_i/r0) + a (C1 psi1 - C2 psi2) + a (Y1 - Y2) = 0
  M(1, 0) = -g.l0 * f11 * S[0] * lam[0] / g.r0 + g.a * (C1 - C2) * th;
  M(1, 1) = -g.l0 * f11 * S[1] * lam[1] / g.r0 - g.a * (C1 - C2) * th;
  M(1, 2) = g.a;
  M(1, 3) = -g.a;
  rhs(1) = -g.l0 * f11 * (S[0] + S[1]) * g.l0 * g.inv_R - g.a * (C1 + C2) * g.a * g.inv_R;
  // Constraints: free axle Y_i = 0, flanging axle y_i = +-y_f.
  for (int i = 0; i < 2; ++i) {
    if (flange[i] == 0) {
      M(2 + i, 2 + i) = 1.0;
    } else {
      M(2 + i, i) = 1.0;
      rhs(2 + i) = flange[i] * g.yf;
    }
  }
  return M.fullPivLu().solve(rhs);
}

bool feasible(const Eigen::Vector4d& x, const std::array<int, 2>& flange, double yf) {
  const double tol = 1e-12;
  for (int i = 0; i < 2; ++i) {
    const double y = x(i), Y = x(2 + i);
    if (!std::isfinite(y) || !std::isfinite(Y)) return false;
    if (flange[i] == 0 && std::abs(y) > yf * (1 + 1e-9)) return false;
    // An outer flange (y = +y_f) pushes inwards (Y <= 0), an inner one outwards (Y >= 0).
    if (flange[i] == 1 && Y > tol * (1 + std::abs(Y))) return false;
    if (flange[i] == -1 && Y < -tol * (1 + std::abs(Y))) return false;
  }
  return true;
}

}  // namespace

double BogieCurvingInput::half_distance() const {
  return contact_half_distance > 0.0 ? contact_half_distance : 0.5 * (track_gauge + 0.065);
}

void BogieCurvingInput::validate() const {
  if (!(radius > 0.0) || std::isnan(radius))
    throw InputError("curving.radius", "curving.radius must be positive (inf for tangent track)");
  if (!(speed >= 0.0) || !std::isfinite(speed))
    throw InputError("curving.speed", "curving.speed must be >= 0");
  if (!std::isfinite(cant_deficiency))
    throw InputError("curving.cant_deficiency", "curving.cant_deficiency must be finite");
  positive(wheelbase, "wheelbase");
  positive(wheel_radius, "wheel_radius");
  positive(track_gauge, "track_gauge");
  if (!(contact_half_distance >= 0.0))
    throw InputError("curving.contact_half_distance", "curving.contact_half_distance must be >= 0");
  if (!rolling_radius_difference) positive(conicity, "conicity");
  if (!std::isnan(contact_angle) && !(std::abs(contact_angle) < 0.5 * M_PI))
    throw InputError("curving.contact_angle", "curving.contact_angle must lie in (-pi/2, pi/2)");
  positive(flange_clearance, "flange_clearance");
  positive(wheel_load, "wheel_load");
  positive(friction, "friction");
  positive(f11, "f11");
  positive(f22, "f22");
}

CurvingEstimate estimate_bogie_curving(const BogieCurvingInput& in) {
  in.validate();
  Geometry g;
  g.a = 0.5 * in.wheelbase;
  g.l0 = in.half_distance();
  g.r0 = in.wheel_radius;
  g.inv_R = std::isinf(in.radius) ? 0.0 : 1.0 / in.radius;
  g.yf = in.flange_clearance;
  g.Fu = 4.0 * in.wheel_load * in.cant_deficiency / (2.0 * g.l0);

  auto delta_r = [&](double y) {
    return in.rolling_radius_difference ? in.rolling_radius_difference(y) : 2.0 * in.conicity * y;
  };
  // Secant conicity Delta_r(y)/(2y); the slope at y = 0.
  auto secant_conicity = [&](double y) {
    if (!in.rolling_radius_difference) return in.conicity;
    const double h = 1e-6;
    const double lam = std::abs(y) > h ? delta_r(y) / (2.0 * y) : (delta_r(h) - delta_r(-h)) / (4.0 * h);
    if (!(lam > 0.0) || !std::isfinite(lam))
      throw InputError("curving.rolling_radius_difference",
                       "the rolling-radius difference must increase with y (Delta_r(y)/y > 0)");
    return lam;
  };

  // Active sets, fewest flange contacts first.
  const std::array<std::array<int, 2>, 9> sets = {{{0, 0},
                                                   {1, 0},
                                                   {0, -1},
                                                   {-1, 0},
                                                   {0, 1},
                                                   {1, -1},
                                                   {1, 1},
                                                   {-1, -1},
                                                   {-1, 1}}};
  std::array<double, 4> s = {1.0, 1.0, 1.0, 1.0};  // secant factors: 1o, 1i, 2o, 2i
  std::array<double, 2> lam = {secant_conicity(0.0), secant_conicity(0.0)};
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  std::array<int, 2> active = {0, 0};
  int it = 0;
  double change = 1.0;
  const int max_iterations = 1000;
  for (; it < max_iterations && change > 1e-12; ++it) {
    const std::array<double, 2> S = {s[0] + s[1], s[2] + s[3]};
    bool found = false;
    for (const auto& set : sets) {
      const Eigen::Vector4d trial = solve_active_set(g, in.f11, in.f22, S, lam, set);
      if (feasible(trial, set, g.yf)) {
        x = trial;
        active = set;
        found = true;
        break;
      }
    }
    if (!found)
      throw NumericalError("curving estimate: no consistent flange-contact state (iteration " +
                           std::to_string(it) + ")");
    // Update the saturation and the secant conicities (relaxed fixed point).
    change = 0.0;
    const double theta = (x(0) - x(1)) / (2.0 * g.a);
    const double psi[2] = {theta + g.a * g.inv_R, theta - g.a * g.inv_R};
    for (int i = 0; i < 2; ++i) {
      const double lam_new = secant_conicity(x(i));
      change = std::max(change, std::abs(lam_new - lam[i]) / lam[i]);
      lam[i] = 0.5 * (lam[i] + lam_new);
      const double xi_x = g.l0 * g.inv_R - lam[i] * x(i) / g.r0, xi_y = -psi[i];
      for (int w = 0; w < 2; ++w) {  // outer (+xi_x), inner (-xi_x): same magnitude
        double target = 1.0;
        if (in.saturation) {
          const double u = std::hypot(in.f11 * xi_x, in.f22 * xi_y) / (in.friction * in.wheel_load);
          target = secant_factor(u);
        }
        double& sw = s[2 * i + w];
        change = std::max(change, std::abs(target - sw));
        sw = 0.5 * (sw + target);
      }
    }
  }
  if (change > 1e-9) {
    std::ostringstream m;
    m << "curving estimate: saturation iteration did not converge (change " << change << " after "
      << it << " iterations)";
    throw NumericalError(m.str());
  }

  CurvingEstimate e;
  e.iterations = it;
  e.unbalanced_force = g.Fu;
  e.yaw_rate = -in.speed * g.inv_R;
  e.bogie_yaw = (x(0) - x(1)) / (2.0 * g.a);
  AxleCurving* axles[2] = {&e.leading, &e.trailing};
  for (int i = 0; i < 2; ++i) {
    AxleCurving& ax = *axles[i];
    ax.lateral = active[i] == 0 ? x(i) : active[i] * g.yf;
    ax.attack_angle = e.bogie_yaw + (i == 0 ? 1.0 : -1.0) * g.a * g.inv_R;
    ax.flange_force = x(2 + i);
    ax.flange = active[i];
    ax.xi_x_outer = g.l0 * g.inv_R - delta_r(ax.lateral) / (2.0 * g.r0);
  }
  // The leading outer wheel's tread contact (K2).
  const double y1 = e.leading.lateral;
  e.contact_angle = std::isnan(in.contact_angle)
                        ? std::atan(in.rolling_radius_difference ? secant_conicity(y1) : in.conicity)
                        : in.contact_angle;
  e.rolling_radius = g.r0 + 0.5 * delta_r(y1);
  e.xi_x = e.leading.xi_x_outer;
  e.xi_y = -e.leading.attack_angle / std::cos(e.contact_angle);
  e.phi = -std::sin(e.contact_angle) / e.rolling_radius - std::cos(e.contact_angle) * g.inv_R;
  e.contact_shift_on_wheel = -y1;
  return e;
}

}  // namespace rollnoise::noise
