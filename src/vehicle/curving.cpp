#include "vehicle/curving.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "geometry/wheel_rail.hpp"
#include "linalg/nearest_root.hpp"

namespace rollnoise::noise {
namespace {

struct Geometry {
  double a, l0, r0, inv_R, yf, Fu, f11, f22;
  std::function<double(double)> delta_r;  // Delta_r(y) = r_outer - r_inner
  // Gravitational stiffness (K7): lateral force of the normal loads on axle i at lateral y,
  // -(Q_o tan gamma_o(y) - Q_i tan gamma_o(-y)) with the tread loads of the current iterate.
  std::function<double(int, double)> gravity;
};

struct State {
  double y[2] = {0.0, 0.0};  // lateral displacements y1, y2
  double Y[2] = {0.0, 0.0};  // flange forces Y1, Y2
};

// Residuals of (K3) for given secant sums S_i of axle i, with (K1) and xi_x,i = l0/R - Delta_r/(2
// r0):
//   lateral = C1 psi1 + C2 psi2 + Y1 + Y2 + Fu + G1 + G2,
//   yaw     = sum_i l0 f11 S_i xi_x,i + a (C1 psi1 - C2 psi2) + a (Y1 - Y2) + a (G1 - G2)  (K7).
struct Residual {
  double lateral, yaw;
};
Residual residual(const Geometry& g, const std::array<double, 2>& S, const State& x) {
  const double C1 = g.f22 * S[0], C2 = g.f22 * S[1];
  const double theta = (x.y[0] - x.y[1]) / (2.0 * g.a);
  const double psi1 = theta + g.a * g.inv_R, psi2 = theta - g.a * g.inv_R;
  const double G1 = g.gravity(0, x.y[0]), G2 = g.gravity(1, x.y[1]);
  double yaw = g.a * (C1 * psi1 - C2 * psi2) + g.a * (x.Y[0] - x.Y[1]) + g.a * (G1 - G2);
  for (int i = 0; i < 2; ++i)
    yaw += g.l0 * g.f11 * S[i] * (g.l0 * g.inv_R - g.delta_r(x.y[i]) / (2.0 * g.r0));
  return {C1 * psi1 + C2 * psi2 + x.Y[0] + x.Y[1] + g.Fu + G1 + G2, yaw};
}

// A root of a scalar function on [lo, hi] scanned in `n` pieces for sign changes (the yaw equation
// of a flanging bogie need not be monotone), the one nearest to `prefer` (continuation from the
// previous iterate): linalg::nearest_root. False without a sign change.
template <class F>
bool find_root(F f, double lo, double hi, double prefer, double* root, int n = 200) {
  const std::optional<double> r = linalg::nearest_root(f, lo, hi, prefer, n);
  if (r) *root = *r;
  return r.has_value();
}

// (K3) for one choice of flange contacts (flange_i = 0 free, +1 at y = +y_f, -1 at y = -y_f).
// The lateral equation is linear in the flange forces and in theta; what remains is one scalar
// equation in the free displacement(s), solved by bisection over the admissible range.
// Returns false when this choice has no admissible solution.
bool solve_active_set(const Geometry& g, const std::array<double, 2>& S,
                      const std::array<int, 2>& flange, const State& previous, State* out) {
  const double yf = g.yf;
  State x;
  if (flange[0] == 0 && flange[1] == 0) {
    // Lateral: (C1 + C2) theta + (C1 - C2) a/R + Fu + G1(y1) + G2(y2) = 0 with theta = (y1 -
    // y2)/(2a); for each y1 it is one equation in y2 (decreasing in y2 for a restoring gravity
    // term), solved first; the yaw equation is then one scalar equation in y1. Where no y2 in
    // [-y_f, y_f] balances, y2 is clamped (continuity for the scan) and the state is rejected below
    // unless the lateral residual vanishes.
    auto trailing = [&](double y1) {
      auto lat = [&](double y2) {
        State t;
        t.y[0] = y1;
        t.y[1] = y2;
        return residual(g, S, t).lateral;
      };
      double y2;
      if (find_root(lat, -yf, yf, previous.y[1], &y2, 8)) return y2;
      return std::abs(lat(-yf)) < std::abs(lat(yf)) ? -yf : yf;
    };
    auto yaw = [&](double y1) {
      State t;
      t.y[0] = y1;
      t.y[1] = trailing(y1);
      return residual(g, S, t).yaw;
    };
    double y1;
    if (!find_root(yaw, -yf, yf, previous.y[0], &y1, 100)) return false;
    x.y[0] = y1;
    x.y[1] = trailing(y1);
    const double scale = std::abs(g.Fu) + g.f22 * (S[0] + S[1]) * 1e-3 + 1.0;
    if (std::abs(residual(g, S, x).lateral) > 1e-8 * scale) return false;
  } else if (flange[0] != 0 && flange[1] != 0) {
    // Both fixed: Y1 + Y2 = -rest_lat, Y1 - Y2 = -rest_yaw / a.
    x.y[0] = flange[0] * yf;
    x.y[1] = flange[1] * yf;
    const Residual r = residual(g, S, x);
    x.Y[0] = 0.5 * (-r.lateral - r.yaw / g.a);
    x.Y[1] = 0.5 * (-r.lateral + r.yaw / g.a);
  } else {
    // One axle k at its flange, the other (j) free: Y_k from the lateral equation, then the yaw
    // equation in y_j.
    const int k = flange[0] != 0 ? 0 : 1, j = 1 - k;
    const double sign_k = k == 0 ? 1.0 : -1.0;  // Y_k enters the yaw moment with +a (k=0), -a
    x.y[k] = flange[k] * yf;
    auto yaw = [&](double yj) {
      State t = x;
      t.y[j] = yj;
      const Residual r0 = residual(g, S, t);  // with Y = 0
      t.Y[k] = -r0.lateral;
      return r0.yaw + sign_k * g.a * t.Y[k];
    };
    double yj;
    if (!find_root(yaw, -yf, yf, previous.y[j], &yj)) return false;
    x.y[j] = yj;
    x.Y[k] = -residual(g, S, x).lateral;
  }
  // An outer flange (y = +y_f) can only push inwards (Y <= 0), an inner one outwards (Y >= 0).
  for (int i = 0; i < 2; ++i) {
    const double tol = 1e-9 * (std::abs(g.Fu) + g.f22 * 1e-6 + 1.0);
    if (flange[i] == 1 && x.Y[i] > tol) return false;
    if (flange[i] == -1 && x.Y[i] < -tol) return false;
    if (!std::isfinite(x.y[i]) || !std::isfinite(x.Y[i])) return false;
  }
  *out = x;
  return true;
}

// Below a tread load of this fraction of Q the wheel counts as unloaded.
constexpr double kUnloaded = 1e-3;

// The wheels' vertical loads: tread loads Q_t (index 2 i + side, side 0 outer, 1 inner), Q +- dQ
// (K4) less the flange share Q_f of a flanging wheel (K6), and Q_f of axle i.
struct WheelLoads {
  std::array<double, 4> tread;
  std::array<double, 2> flange = {0.0, 0.0};
};

// The secant factor's load dependence (K5): (Q_w / Q)^(2/3), Hertz's creep coefficients scaling
// with the patch area.
double load_factor(const WheelLoads& loads, double Q, int w) {
  const std::array<double, 4>& Qt = loads.tread;
  return std::cbrt(Qt[w] * Qt[w] / (Q * Q));
}

// The flange contact of (K6) as the iteration uses it: angle delta_f, friction mu_f, and whether
// a flange takes a vertical share (delta_f > 0). std::domain_error beyond Nadal's limit.
struct FlangeContact {
  double angle, friction;
  bool share;
};
FlangeContact flange_contact(const BogieCurvingInput& in) {
  const FlangeFriction f = flange_friction(in);
  if (!f.below_nadal_limit()) {
    char values[200];
    std::snprintf(values, sizeof values,
                  "flange friction mu_f = %.4g reaches tan(delta_f) = %.4g (flange angle %.4g rad): "
                  "Nadal's limit, the flange cannot carry a lateral force",
                  f.friction, std::tan(f.angle), f.angle);
    throw std::domain_error(values);
  }
  return {f.angle, f.friction, f.angle > 0.0};
}

// The bogie of (K1)-(K3) and (K7): half wheelbase a, contact half distance l0, wheel radius r0,
// 1/R, the flange clearance y_f, the unbalanced lateral force Fu = 4 Q h_d / (2 l0), Delta_r(y)
// (the profiles' table, a given function or the cone 2 lambda y) and the gravitational stiffness
// with the tread loads of the current iterate (`loads`, which must outlive the result).
Geometry bogie_geometry(const BogieCurvingInput& in, const WheelLoads& loads) {
  Geometry g;
  g.a = 0.5 * in.wheelbase;
  g.l0 = in.half_distance();
  g.r0 = in.wheel_radius;
  g.inv_R = std::isinf(in.radius) ? 0.0 : 1.0 / in.radius;
  const ProfileCurvingTable* table = in.profiles.get();
  g.yf = table ? table->flange_clearance : in.flange_clearance;
  g.Fu = 4.0 * in.wheel_load * in.cant_deficiency / (2.0 * g.l0);
  g.f11 = in.f11;
  g.f22 = in.f22;
  g.delta_r = [&in, table](double y) {
    if (table) return table->at(table->rolling_radius_difference, y);
    return in.rolling_radius_difference ? in.rolling_radius_difference(y) : 2.0 * in.conicity * y;
  };
  auto tan_gamma_outer = [&in, table](double y) {
    if (table) return std::tan(table->at(table->contact_angle, y));
    return std::isnan(in.contact_angle) ? in.conicity : std::tan(in.contact_angle);
  };
  // (K7): the normal loads' lateral components, -Q_w tan gamma_w towards the track centre.
  g.gravity = [&in, &loads, tan_gamma_outer](int i, double y) {
    if (!in.gravitational_stiffness) return 0.0;
    const std::array<double, 4>& Qt = loads.tread;
    return -(Qt[2 * i] * tan_gamma_outer(y) - Qt[2 * i + 1] * tan_gamma_outer(-y));
  };
  return g;
}

// The flange-contact state of (K3) at the secant sums S: the previous iterate's state first (it
// usually persists while the saturation settles), then the others with the fewest contacts first.
// Sets *active to the state found; NumericalError when none is consistent.
State solve_flange_state(const Geometry& g, const std::array<double, 2>& S, int iteration,
                         const State& previous, std::array<int, 2>* active) {
  static const std::array<std::array<int, 2>, 9> sets = {
      {{0, 0}, {1, 0}, {0, -1}, {-1, 0}, {0, 1}, {1, -1}, {1, 1}, {-1, -1}, {-1, 1}}};
  State x = previous;
  bool found = iteration > 0 && solve_active_set(g, S, *active, previous, &x);
  for (std::size_t c = 0; c < sets.size() && !found; ++c)
    if (solve_active_set(g, S, sets[c], previous, &x)) {
      *active = sets[c];
      found = true;
    }
  if (!found)
    throw NumericalError("curving estimate: no consistent flange-contact state (iteration " +
                         std::to_string(iteration) + ")");
  return x;
}

// The flange shares (K6): a flanging axle's flange normal force N_f = |Y| / (sin delta_f - mu_f
// cos delta_f), its vertical load Q_f = N_f (cos delta_f + mu_f sin delta_f), relaxed like the
// saturation, taken from the flanging wheel's tread load. Returns the largest change of Q_f / Q.
double update_flange_loads(const FlangeContact& f, const std::array<int, 2>& active,
                           const State& x, double Q, double dQ, WheelLoads* loads) {
  double change = 0.0;
  for (int i = 0; i < 2; ++i) {
    const double N_f = f.share && active[i] != 0
                           ? std::abs(x.Y[i]) / (std::sin(f.angle) - f.friction * std::cos(f.angle))
                           : 0.0;
    const double target = N_f * (std::cos(f.angle) + f.friction * std::sin(f.angle));
    double& Qf = loads->flange[i];
    change = std::max(change, std::abs(target - Qf) / Q);
    Qf = 0.5 * (Qf + target);
    for (int side = 0; side < 2; ++side) {
      const double base = side == 0 ? Q + dQ : Q - dQ;
      const bool flanging = (active[i] == 1 && side == 0) || (active[i] == -1 && side == 1);
      // Floored while the saturation settles (the first iterates, unsaturated, overestimate
      // the flange force); a converged state at the floor is reported by the caller.
      loads->tread[2 * i + side] = std::max(base - (flanging ? Qf : 0.0), kUnloaded * Q);
    }
  }
  return change;
}

// Saturation of the combined creep force of each wheel (K5), a relaxed fixed point on the secant
// factors s: u = k |(f11 xi_x, f22 xi_y)| / (mu Q_w), s -> k s(u) with k the load factor, xi_x of
// (K2) and xi_y = -psi_i of (K1). Returns the largest change of s.
double update_secant_factors(const BogieCurvingInput& in, const Geometry& g, const State& x,
                             const WheelLoads& loads, std::array<double, 4>* s) {
  double change = 0.0;
  const double theta = (x.y[0] - x.y[1]) / (2.0 * g.a);
  const double psi[2] = {theta + g.a * g.inv_R, theta - g.a * g.inv_R};
  for (int i = 0; i < 2; ++i) {
    const double xi_x = g.l0 * g.inv_R - g.delta_r(x.y[i]) / (2.0 * g.r0), xi_y = -psi[i];
    for (int w = 0; w < 2; ++w) {  // outer (+xi_x) and inner (-xi_x) wheel: same |xi|
      const double k = load_factor(loads, in.wheel_load, 2 * i + w);
      const double u =
          k * std::hypot(in.f11 * xi_x, in.f22 * xi_y) / (in.friction * loads.tread[2 * i + w]);
      const double target = in.saturation ? k * saturation_secant_factor(u) : k;
      double& sw = (*s)[2 * i + w];
      change = std::max(change, std::abs(target - sw));
      sw = 0.5 * (sw + target);
    }
  }
  return change;
}

// Axle i of the converged state: lateral displacement, attack angle (K1), flange force and
// contact, xi_x of its outer wheel (K2), the flange's loads (K6) and the tread loads.
AxleCurving axle_curving(const Geometry& g, const FlangeContact& f, const State& x,
                         const std::array<int, 2>& active, const WheelLoads& loads,
                         double bogie_yaw, int i) {
  AxleCurving ax;
  ax.lateral = x.y[i];
  ax.attack_angle = bogie_yaw + (i == 0 ? 1.0 : -1.0) * g.a * g.inv_R;
  ax.flange_force = x.Y[i];
  ax.flange = active[i];
  ax.xi_x_outer = g.l0 * g.inv_R - g.delta_r(ax.lateral) / (2.0 * g.r0);
  const double Qf = loads.flange[i];
  ax.flange_vertical_load = Qf;
  ax.flange_normal_force =
      Qf > 0.0 ? Qf / (std::cos(f.angle) + f.friction * std::sin(f.angle)) : 0.0;
  ax.tread_load_outer = loads.tread[2 * i];
  ax.tread_load_inner = loads.tread[2 * i + 1];
  return ax;
}

// The leading outer wheel's tread contact (K2): contact angle, rolling radius, the contact's
// positions on wheel and rail (the profiles' table, or the cone: its angle, with a given
// Delta_r(y) its local slope Delta_r'/2), and the creepages xi_x, xi_y, phi.
void set_leading_contact(const BogieCurvingInput& in, const Geometry& g, CurvingEstimate* e) {
  const ProfileCurvingTable* table = in.profiles.get();
  const double y1 = e->leading.lateral;
  if (table) {
    e->contact_angle = table->at(table->contact_angle, y1);
    e->rolling_radius = table->at(table->rolling_radius, y1);
    e->contact_shift_on_wheel = table->at(table->wheel_position, y1);
    e->rail_contact_offset = table->at(table->rail_position, y1);
  } else {
    double lambda = in.conicity;
    if (in.rolling_radius_difference) {
      const double h = 1e-5;
      lambda = (g.delta_r(y1 + h) - g.delta_r(y1 - h)) / (4.0 * h);
    }
    e->contact_angle = std::isnan(in.contact_angle) ? std::atan(lambda) : in.contact_angle;
    e->rolling_radius = g.r0 + 0.5 * g.delta_r(y1);
    e->contact_shift_on_wheel = -y1;
    e->rail_contact_offset = 0.0;
  }
  e->xi_x = e->leading.xi_x_outer;
  e->xi_y = -e->leading.attack_angle / std::cos(e->contact_angle);
  e->phi = -std::sin(e->contact_angle) / e->rolling_radius - std::cos(e->contact_angle) * g.inv_R;
}

}  // namespace

bool FlangeFriction::below_nadal_limit() const {
  return !(angle > 0.0) || std::sin(angle) - friction * std::cos(angle) > 0.0;
}

FlangeFriction flange_friction(const BogieCurvingInput& in) {
  const ProfileCurvingTable* table = in.profiles.get();
  FlangeFriction f;
  f.angle = !std::isnan(in.flange_angle) ? in.flange_angle : (table ? table->flange_angle : 0.0);
  f.friction = std::isnan(in.flange_friction) ? in.friction : in.flange_friction;
  return f;
}

double saturation_secant_factor(double u) {
  return u < 3.0 ? 1.0 - u / 3.0 + u * u / 27.0 : 1.0 / u;
}

double ProfileCurvingTable::at(const std::vector<double>& column, double y) const {
  const std::size_t n = lateral.size();
  ROLLNOISE_ASSERT(n > 0 && column.size() == n, "a profile table column of the table's length");
  if (y <= lateral.front()) return column.front();
  if (y >= lateral.back()) return column.back();
  const std::size_t j = static_cast<std::size_t>(
      std::upper_bound(lateral.begin(), lateral.end(), y) - lateral.begin());
  const double t = (y - lateral[j - 1]) / (lateral[j] - lateral[j - 1]);
  return (1.0 - t) * column[j - 1] + t * column[j];
}

ProfileCurvingTable profile_curving_table(const geometry::WheelRailPair& pair, double max_lateral,
                                          double step, double flange_angle) {
  ROLLNOISE_ASSERT(max_lateral > 0.0 && step > 0.0 && step <= max_lateral, "profile table: 0 < step <= max_lateral");
  ProfileCurvingTable t;
  const int n = static_cast<int>(std::round(max_lateral / step));
  bool flanging = false;
  for (int k = -n; k <= n; ++k) {
    const double u = k * step;
    // both wheels' contact points (no curvatures: the table does not keep them) in one pose
    const geometry::WheelsetPose pose = pair.equilibrium({u, 0.0});
    geometry::ContactOptions point_only;
    point_only.curvatures = false;
    const geometry::ContactGeometry outer =
        geometry::find_contact_at_pose(pair, pose, geometry::Side::Right, point_only);
    const geometry::ContactGeometry inner =
        geometry::find_contact_at_pose(pair, pose, geometry::Side::Left, point_only);
    t.lateral.push_back(u);
    t.rolling_radius_difference.push_back(outer.rolling_radius - inner.rolling_radius);
    t.contact_angle.push_back(outer.contact_angle);
    t.rolling_radius.push_back(outer.rolling_radius);
    t.wheel_position.push_back(outer.wheel_s);
    t.rail_position.push_back(outer.rail_y);
    if (u >= 0.0 && !flanging) {
      if (outer.contact_angle < flange_angle) {
        t.flange_clearance = u;
      } else {
        flanging = true;
        t.flange_angle = outer.contact_angle;
      }
    }
  }
  if (!(t.flange_clearance > 0.0))
    throw std::domain_error("the contact is on the flange already for the centred wheelset");
  return t;
}

double BogieCurvingInput::half_distance() const {
  return contact_half_distance > 0.0 ? contact_half_distance : 0.5 * (track_gauge + 0.065);
}

bool BogieCurvingInput::valid() const {
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  return radius > 0.0 && speed >= 0.0 && std::isfinite(speed) && std::isfinite(cant_deficiency) &&
         positive(wheelbase) && positive(wheel_radius) && positive(track_gauge) && contact_half_distance >= 0.0 &&
         (rolling_radius_difference || profiles || positive(conicity)) &&
         (std::isnan(contact_angle) || std::abs(contact_angle) < 0.5 * M_PI) &&
         (profiles || positive(flange_clearance)) && positive(wheel_load) && positive(friction) &&
         std::isfinite(load_transfer) && std::abs(load_transfer) < wheel_load &&
         (std::isnan(flange_angle) || (flange_angle >= 0.0 && flange_angle < 0.5 * M_PI)) &&
         (std::isnan(flange_friction) || (flange_friction >= 0.0 && std::isfinite(flange_friction))) &&
         positive(f11) && positive(f22);
}

CurvingEstimate estimate_bogie_curving(const BogieCurvingInput& in) {
  ROLLNOISE_ASSERT(in.valid(), "bogie curving input outside the model (pipeline::check_bogie_curving_input)");
  const FlangeContact flange = flange_contact(in);
  const double Q = in.wheel_load, dQ = in.load_transfer;
  WheelLoads loads;
  loads.tread = {Q + dQ, Q - dQ, Q + dQ, Q - dQ};  // (K4), before the flange shares
  const Geometry g = bogie_geometry(in, loads);

  // The saturation iteration: per iterate, the flange-contact state of (K3) at the current secant
  // factors, then the flange shares (K6) and the secant factors (K5), each relaxed.
  std::array<double, 4> s;  // effective secant factors: 1 outer, 1 inner, 2 outer, 2 inner
  for (int w = 0; w < 4; ++w) s[w] = load_factor(loads, Q, w);
  State x;
  std::array<int, 2> active = {0, 0};
  int it = 0;
  double change = 1.0;
  const int max_iterations = 500;
  for (; it < max_iterations && change > 1e-12; ++it) {
    const std::array<double, 2> S = {s[0] + s[1], s[2] + s[3]};
    x = solve_flange_state(g, S, it, x, &active);
    change = 0.0;
    change = std::max(change, update_flange_loads(flange, active, x, Q, dQ, &loads));
    change = std::max(change, update_secant_factors(in, g, x, loads, &s));
  }
  for (int w = 0; w < 4; ++w)
    if (!(loads.tread[w] > kUnloaded * Q))
      throw NumericalError(
          "curving estimate: a wheel is unloaded (load transfer or flange load at the wheel load: "
          "overturning or flange climbing, Nadal's limit)");
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
  e.bogie_yaw = (x.y[0] - x.y[1]) / (2.0 * g.a);
  AxleCurving* axles[2] = {&e.leading, &e.trailing};
  for (int i = 0; i < 2; ++i) *axles[i] = axle_curving(g, flange, x, active, loads, e.bogie_yaw, i);
  e.load_transfer = dQ;
  e.flange_angle = flange.share ? flange.angle : 0.0;
  set_leading_contact(in, g, &e);
  return e;
}

}  // namespace rollnoise::noise
