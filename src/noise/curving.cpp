#include "noise/curving.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "geometry/wheel_rail.hpp"

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
  double a, l0, r0, inv_R, yf, Fu, f11, f22;
  std::function<double(double)> delta_r;  // Delta_r(y) = r_outer - r_inner
};

struct State {
  double y[2] = {0.0, 0.0};  // lateral displacements y1, y2
  double Y[2] = {0.0, 0.0};  // flange forces Y1, Y2
};

// Residuals of (K3) for given secant sums S_i of axle i, with (K1) and xi_x,i = l0/R - Delta_r/(2
// r0):
//   lateral = C1 psi1 + C2 psi2 + Y1 + Y2 + Fu,
//   yaw     = sum_i l0 f11 S_i xi_x,i + a (C1 psi1 - C2 psi2) + a (Y1 - Y2).
struct Residual {
  double lateral, yaw;
};
Residual residual(const Geometry& g, const std::array<double, 2>& S, const State& x) {
  const double C1 = g.f22 * S[0], C2 = g.f22 * S[1];
  const double theta = (x.y[0] - x.y[1]) / (2.0 * g.a);
  const double psi1 = theta + g.a * g.inv_R, psi2 = theta - g.a * g.inv_R;
  double yaw = g.a * (C1 * psi1 - C2 * psi2) + g.a * (x.Y[0] - x.Y[1]);
  for (int i = 0; i < 2; ++i)
    yaw += g.l0 * g.f11 * S[i] * (g.l0 * g.inv_R - g.delta_r(x.y[i]) / (2.0 * g.r0));
  return {C1 * psi1 + C2 * psi2 + x.Y[0] + x.Y[1] + g.Fu, yaw};
}

// A root of a scalar function on [lo, hi]: the interval is scanned in `n` pieces for sign
// changes (the yaw equation of a flanging bogie need not be monotone), each bracket is refined
// by bisection (robust to the jumps of a tabulated Delta_r: on a jump the root is the jump
// itself), and the root nearest to `prefer` is returned (continuation from the previous
// iterate). False without a sign change.
template <class F>
bool find_root(F f, double lo, double hi, double prefer, double* root, int n = 200) {
  if (!(lo <= hi)) return false;
  bool found = false;
  double best = 0.0;
  double a = lo, fa = f(lo);
  for (int k = 1; k <= n; ++k) {
    double b = lo + (hi - lo) * k / n, fb = f(b);
    double r = 0.0;
    bool bracket = false;
    if (fa == 0.0) {
      r = a;
      bracket = true;
    } else if ((fa > 0.0) != (fb > 0.0) || fb == 0.0) {
      double x0 = a, x1 = b, f0 = fa;
      for (int it = 0; it < 200 && x1 - x0 > 1e-14; ++it) {
        const double mid = 0.5 * (x0 + x1), fm = f(mid);
        if (fm != 0.0 && (fm > 0.0) == (f0 > 0.0)) {
          x0 = mid;
          f0 = fm;
        } else {
          x1 = mid;
        }
      }
      r = 0.5 * (x0 + x1);
      bracket = true;
    }
    if (bracket && (!found || std::abs(r - prefer) < std::abs(best - prefer))) {
      best = r;
      found = true;
    }
    a = b;
    fa = fb;
  }
  if (found) *root = best;
  return found;
}

// (K3) for one choice of flange contacts (flange_i = 0 free, +1 at y = +y_f, -1 at y = -y_f).
// The lateral equation is linear in the flange forces and in theta; what remains is one scalar
// equation in the free displacement(s), solved by bisection over the admissible range.
// Returns false when this choice has no admissible solution.
bool solve_active_set(const Geometry& g, const std::array<double, 2>& S,
                      const std::array<int, 2>& flange, const State& previous, State* out) {
  const double C1 = g.f22 * S[0], C2 = g.f22 * S[1], yf = g.yf;
  State x;
  // Free choice: (C1 + C2) theta + (C1 - C2) a/R + Fu = 0 below.
  if (flange[0] == 0 && flange[1] == 0) {
    // Lateral: (C1 + C2) theta + (C1 - C2) a/R + Fu = 0 fixes theta; y2 = y1 - 2 a theta.
    const double theta = -(g.Fu + (C1 - C2) * g.a * g.inv_R) / (C1 + C2);
    const double d = 2.0 * g.a * theta;
    auto yaw = [&](double y1) {
      State t;
      t.y[0] = y1;
      t.y[1] = y1 - d;
      return residual(g, S, t).yaw;
    };
    double y1;
    if (!find_root(yaw, std::max(-yf, -yf + d), std::min(yf, yf + d), previous.y[0], &y1))
      return false;
    x.y[0] = y1;
    x.y[1] = y1 - d;
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

}  // namespace

double ProfileCurvingTable::at(const std::vector<double>& column, double y) const {
  const std::size_t n = lateral.size();
  if (n == 0 || column.size() != n) throw InputError("curving.profiles", "empty profile table");
  if (y <= lateral.front()) return column.front();
  if (y >= lateral.back()) return column.back();
  const std::size_t j = static_cast<std::size_t>(
      std::upper_bound(lateral.begin(), lateral.end(), y) - lateral.begin());
  const double t = (y - lateral[j - 1]) / (lateral[j] - lateral[j - 1]);
  return (1.0 - t) * column[j - 1] + t * column[j];
}

ProfileCurvingTable profile_curving_table(const geometry::WheelRailPair& pair, double max_lateral,
                                          double step, double flange_angle) {
  if (!(max_lateral > 0.0) || !(step > 0.0) || step > max_lateral)
    throw InputError("curving.profiles", "profile table: need 0 < step <= max_lateral");
  ProfileCurvingTable t;
  const int n = static_cast<int>(std::round(max_lateral / step));
  bool flanging = false;
  for (int k = -n; k <= n; ++k) {
    const double u = k * step;
    const geometry::ContactGeometry outer =
        geometry::find_contact(pair, {u, 0.0}, geometry::Side::Right);
    const geometry::ContactGeometry inner =
        geometry::find_contact(pair, {u, 0.0}, geometry::Side::Left);
    t.lateral.push_back(u);
    t.rolling_radius_difference.push_back(outer.rolling_radius - inner.rolling_radius);
    t.contact_angle.push_back(outer.contact_angle);
    t.rolling_radius.push_back(outer.rolling_radius);
    t.wheel_position.push_back(outer.wheel_s);
    t.rail_position.push_back(outer.rail_y);
    if (u >= 0.0 && !flanging) {
      if (outer.contact_angle < flange_angle)
        t.flange_clearance = u;
      else
        flanging = true;
    }
  }
  if (!(t.flange_clearance > 0.0))
    throw InputError(
        "curving.profiles",
        "profile table: the contact is on the flange already for the centred wheelset");
  return t;
}

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
  if (!rolling_radius_difference && !profiles) positive(conicity, "conicity");
  if (!std::isnan(contact_angle) && !(std::abs(contact_angle) < 0.5 * M_PI))
    throw InputError("curving.contact_angle", "curving.contact_angle must lie in (-pi/2, pi/2)");
  if (!profiles) positive(flange_clearance, "flange_clearance");
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
  const ProfileCurvingTable* table = in.profiles.get();
  g.yf = table ? table->flange_clearance : in.flange_clearance;
  g.Fu = 4.0 * in.wheel_load * in.cant_deficiency / (2.0 * g.l0);

  auto delta_r = [&](double y) {
    if (table) return table->at(table->rolling_radius_difference, y);
    return in.rolling_radius_difference ? in.rolling_radius_difference(y) : 2.0 * in.conicity * y;
  };
  g.f11 = in.f11;
  g.f22 = in.f22;
  g.delta_r = delta_r;

  // Flange-contact choices, fewest contacts first.
  const std::array<std::array<int, 2>, 9> sets = {
      {{0, 0}, {1, 0}, {0, -1}, {-1, 0}, {0, 1}, {1, -1}, {1, 1}, {-1, -1}, {-1, 1}}};
  std::array<double, 4> s = {1.0, 1.0, 1.0, 1.0};  // secant factors: 1 outer, 1 inner, 2 o, 2 i
  State x;
  std::array<int, 2> active = {0, 0};
  int it = 0;
  double change = 1.0;
  const int max_iterations = 500;
  for (; it < max_iterations && change > 1e-12; ++it) {
    const std::array<double, 2> S = {s[0] + s[1], s[2] + s[3]};
    // The previous flange-contact state first (it usually persists while the saturation
    // settles), then the others with the fewest contacts first.
    const State previous = x;
    bool found = it > 0 && solve_active_set(g, S, active, previous, &x);
    for (std::size_t c = 0; c < sets.size() && !found; ++c)
      if (solve_active_set(g, S, sets[c], previous, &x)) {
        active = sets[c];
        found = true;
      }
    if (!found)
      throw NumericalError("curving estimate: no consistent flange-contact state (iteration " +
                           std::to_string(it) + ")");
    if (!in.saturation) break;
    // Saturation of the combined creep force of each wheel (relaxed fixed point on s).
    change = 0.0;
    const double theta = (x.y[0] - x.y[1]) / (2.0 * g.a);
    const double psi[2] = {theta + g.a * g.inv_R, theta - g.a * g.inv_R};
    for (int i = 0; i < 2; ++i) {
      const double xi_x = g.l0 * g.inv_R - delta_r(x.y[i]) / (2.0 * g.r0), xi_y = -psi[i];
      const double u = std::hypot(in.f11 * xi_x, in.f22 * xi_y) / (in.friction * in.wheel_load);
      const double target = secant_factor(u);
      for (int w = 0; w < 2; ++w) {  // outer (+xi_x) and inner (-xi_x) wheel: same |xi|
        double& sw = s[2 * i + w];
        change = std::max(change, std::abs(target - sw));
        sw = 0.5 * (sw + target);
      }
    }
  }
  if (in.saturation && change > 1e-9) {
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
  for (int i = 0; i < 2; ++i) {
    AxleCurving& ax = *axles[i];
    ax.lateral = x.y[i];
    ax.attack_angle = e.bogie_yaw + (i == 0 ? 1.0 : -1.0) * g.a * g.inv_R;
    ax.flange_force = x.Y[i];
    ax.flange = active[i];
    ax.xi_x_outer = g.l0 * g.inv_R - delta_r(ax.lateral) / (2.0 * g.r0);
  }
  // The leading outer wheel's tread contact (K2).
  const double y1 = e.leading.lateral;
  if (table) {
    e.contact_angle = table->at(table->contact_angle, y1);
    e.rolling_radius = table->at(table->rolling_radius, y1);
    e.contact_shift_on_wheel = table->at(table->wheel_position, y1);
    e.rail_contact_offset = table->at(table->rail_position, y1);
  } else {
    // Conical tread: the cone angle; with a given Delta_r(y), its local slope Delta_r'/2.
    double lambda = in.conicity;
    if (in.rolling_radius_difference) {
      const double h = 1e-5;
      lambda = (delta_r(y1 + h) - delta_r(y1 - h)) / (4.0 * h);
    }
    e.contact_angle = std::isnan(in.contact_angle) ? std::atan(lambda) : in.contact_angle;
    e.rolling_radius = g.r0 + 0.5 * delta_r(y1);
    e.contact_shift_on_wheel = -y1;
    e.rail_contact_offset = 0.0;
  }
  e.xi_x = e.leading.xi_x_outer;
  e.xi_y = -e.leading.attack_angle / std::cos(e.contact_angle);
  e.phi = -std::sin(e.contact_angle) / e.rolling_radius - std::cos(e.contact_angle) * g.inv_R;
  return e;
}

}  // namespace rollnoise::noise
