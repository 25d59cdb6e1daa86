#include "contact/rolling_history.hpp"

#include "contact/forces.hpp"

namespace rollnoise::contact {

void roll(TransientRolling& rolling, const CreepageHistory& h, CreepageSampling sampling, double dt, long steps,
          const std::vector<double>& normal_force, const StepCallback& on_step) {
  for (long k = 1; k <= steps; ++k) {
    const Creepage xi = h.step_creepage(sampling, k, dt);
    on_step(k, xi, normal_force.empty() ? rolling.step(xi) : rolling.step(xi, normal_force[k]));
  }
}

std::vector<Eigen::Vector3d> rolling_forces(TransientRolling& rolling, const Grid& g,
                                            const CreepageHistory& h, CreepageSampling sampling, double dt,
                                            long steps, const std::vector<double>& normal_force,
                                            const std::function<void(long)>& on_step) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(steps);
  roll(rolling, h, sampling, dt, steps, normal_force, [&](long k, const Creepage&, const TangentialSolution& s) {
    const TangentialForces f = total_forces(g, s.px, s.py);
    out.emplace_back(f.Fx, f.Fy, f.Mz);
    if (on_step) on_step(k);
  });
  return out;
}

}  // namespace rollnoise::contact
