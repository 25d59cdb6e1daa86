#include "contact/rolling_history.hpp"

#include "contact/forces.hpp"

namespace rollnoise::contact {

std::vector<Eigen::Vector3d> rolling_forces(TransientRolling& rolling, const Grid& g,
                                            const CreepageHistory& h, double dt, long steps,
                                            const std::vector<double>& normal_force,
                                            const std::function<void(long)>& on_step) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(steps);
  for (long k = 1; k <= steps; ++k) {
    const TangentialSolution& s =
        normal_force.empty() ? rolling.step(h.at(k * dt)) : rolling.step(h.at(k * dt), normal_force[k]);
    const TangentialForces f = total_forces(g, s.px, s.py);
    out.emplace_back(f.Fx, f.Fy, f.Mz);
    if (on_step) on_step(k);
  }
  return out;
}

}  // namespace rollnoise::contact
