#include "pipeline/steady_sweep.hpp"

#include <memory>

#include "contact/steady_rolling.hpp"

namespace rollnoise::pipeline {

std::vector<double> linear_points(double lo, double hi, long n) {
  std::vector<double> v;
  for (long i = 0; i < n; ++i) v.push_back(n == 1 ? lo : lo + (hi - lo) * double(i) / double(n - 1));
  return v;
}

std::vector<contact::TangentialSolution> steady_sweep(const ContactCase& base, const contact::ContactPatch& patch,
                                                      const std::vector<ContactCase>& points,
                                                      const SweepObserver& observe) {
  std::vector<contact::TangentialSolution> out;
  contact::TangentialSolution previous;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ContactCase& pc = points[i];
    // The normal problem is reused unless the sweep changes it.
    const bool same_normal = pc.grid.nx == base.grid.nx && pc.grid.ny == base.grid.ny && pc.grid.dx == base.grid.dx &&
                             pc.grid.dy == base.grid.dy && pc.material.E == base.material.E &&
                             pc.material.nu == base.material.nu && pc.normal_force == base.normal_force &&
                             pc.a == base.a && pc.b == base.b;
    std::unique_ptr<contact::ContactPatch> own;
    if (!same_normal) own = std::make_unique<contact::ContactPatch>(solve_patch(pc));
    const contact::ContactPatch& local = same_normal ? patch : *own;
    out.push_back(contact::solve_steady_rolling(local.influence, local.normal.pn, pc.steady_input(), pc.tangential,
                                                same_normal && i ? &previous : nullptr));
    if (observe) observe(i, pc, out.back());
    previous = out.back();
  }
  return out;
}

}  // namespace rollnoise::pipeline
