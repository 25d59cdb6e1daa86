#include "contact/roughness_rolling.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::contact {

namespace {

constexpr double kBeta = 1.0 / 12.0, kGamma = 0.5;  // Fox-Goodwin (header)

// s of (R3): the displacement per unit contact force in the Newmark step, dz_{k+1}/dN_{k+1}
double newmark_compliance(const WheelMass& w, double dt) {
  return kBeta * dt * dt / (w.mass + kGamma * dt * w.damping);
}

// r_k = r(x + k dx) under every element (header; R1)
GridField roughness_at_step(const Grid& g, const RailRoughness& r, long k) {
  GridField out(g.size());
  for (int e = 0; e < g.size(); ++e) out[e] = r(g.x(e % g.nx) + k * g.dx);
  return out;
}

struct LoadSolve {
  double normal_force = 0.0, slope = 0.0;
  int solves = 0;
};

// (R3) by the secant method: g(N) = delta(N, r) + s N - target = 0, from the guess N with the
// slope dg/dN of the last step (<= 0: none yet, found from a probe of 1e-6 N0).
LoadSolve solve_load(TransientRolling& rolling, const GridField& r, double target, double s,
                     double N, double slope, double N0, double tolerance) {
  LoadSolve out;
  auto gap = [&](double n) {
    ++out.solves;
    return rolling.normal_approach(n, r) + s * n - target;
  };
  double g = gap(N);
  if (!(slope > 0.0)) {
    const double probe = N + 1e-6 * N0, gp = gap(probe);
    slope = (gp - g) / (probe - N);
    N = probe, g = gp;
  }
  for (int it = 0; it < 30; ++it) {
    const double dN = -g / slope;
    if (std::abs(dN) <= tolerance * N0) return {N, slope, out.solves};  // the last solve was at N
    const double next = N + dN, g_next = gap(next);
    // the secant slope only from steps well above the normal solver's noise on delta
    if (std::abs(dN) > 1e-7 * N0 && g_next != g) slope = (g_next - g) / dN;
    N = next, g = g_next;
  }
  std::ostringstream m;
  m << "roll_over_roughness: the load of the wheel's displacement (R3) did not converge (last N = "
    << N << " N)";
  throw NumericalError(m.str());
}

}  // namespace

WheelState newmark_step(const WheelMass& w, const WheelState& s, double dt, double normal_force) {
  // predictor (a_{k+1} = 0), then m a_{k+1} + c v_{k+1} = N0 - N_{k+1} (header, R2)
  const double z = s.z + dt * s.v + (0.5 - kBeta) * dt * dt * s.a;
  const double v = s.v + (1.0 - kGamma) * dt * s.a;
  const double a =
      (w.static_load - normal_force - w.damping * v) / (w.mass + kGamma * dt * w.damping);
  return {z + kBeta * dt * dt * a, v + kGamma * dt * a, a};
}

void roll_over_roughness(TransientRolling& rolling, const Grid& g, const RoughnessRollingInput& in,
                         const RoughnessStepCallback& on_step) {
  const double dt = rolling.time_step(), s = newmark_compliance(in.wheel, dt);
  const double N0 = in.wheel.static_load;
  WheelState wheel;
  double N = N0, N_before = N0, slope = 0.0;
  for (long k = 0; k < in.steps; ++k) {
    const GridField r = roughness_at_step(g, in.roughness, k);
    // (R3): the wheel's displacement at N = 0 (the predictor and the static load) is the target
    const double target = in.approach + newmark_step(in.wheel, wheel, dt, 0.0).z;
    const LoadSolve load =
        solve_load(rolling, r, target, s, 2.0 * N - N_before, slope, N0, in.load_tolerance);
    N_before = N, N = load.normal_force, slope = load.slope;
    wheel = newmark_step(in.wheel, wheel, dt, N);
    const TangentialSolution& sol = rolling.step(in.creepage);
    on_step(k, {N, wheel, load.solves}, sol);
  }
}

}  // namespace rollnoise::contact
