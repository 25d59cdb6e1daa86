#include "nss/linear_response.hpp"

#include <algorithm>

#include "contact/harmonic_synthesis.hpp"

namespace rollnoise::nss {

LinearResponse linear_response(const LinearContactModel& m, const Eigen::Vector3d& mean_force,
                               double mean_normal_force, const contact::CreepageHistory& h,
                               long steps) {
  const double dt = m.time_step();
  LinearResponse r;
  std::vector<Eigen::Vector3d> xi;  // creepage variation, input of the recursion
  std::vector<double> dN;           // normal-load variation (N), input g of the model
  for (long k = 0; k <= steps; ++k) {
    r.time.push_back(k * dt);
    const auto c = h.step_creepage(m.sampling(), k, dt);  // the creepage of step k
    r.creepage.emplace_back(c.xi_x, c.xi_y, c.phi);
    const auto v = h.step_variation(m.sampling(), k, dt);
    xi.emplace_back(v[0], v[1], v[2]);
    dN.push_back(h.normal_variation(k * dt));
    r.normal_force.push_back(mean_normal_force + dN.back());
  }
  for (const auto& F : m.time_response(xi, dN)) r.recursion.push_back(mean_force + F);
  if (!h.frequencies().empty()) {
    const auto f = m.creep_coefficients(h.frequencies());
    const auto g = h.has_normal_variation() ? m.normal_load_coefficients(h.frequencies())
                                            : std::vector<LoadVector>{};
    // at t_k with f of the model's sampling (its factor contact::step_sampling_factor is the sampling)
    r.synthesis = contact::harmonic_synthesis(h, f, g, mean_force, dt, steps);
  }
  return r;
}

RecursionSynthesisGap recursion_synthesis_gap(const LinearResponse& r, double t_start) {
  RecursionSynthesisGap gap;
  if (!r.has_synthesis()) return gap;
  for (size_t k = 0; k < r.time.size(); ++k)
    if (r.time[k] >= t_start) {
      gap.difference = std::max(gap.difference, (r.recursion[k] - r.synthesis[k]).head<2>().cwiseAbs().maxCoeff());
      gap.variation = std::max(gap.variation, (r.synthesis[k] - r.synthesis[0]).head<2>().cwiseAbs().maxCoeff());
    }
  return gap;
}

}  // namespace rollnoise::nss
