#include "dynamics/wheel_mode_family.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "dynamics/wheel_fe.hpp"

namespace rollnoise::dynamics {

ModeFamily section_family(const Eigen::Vector3d& kinetic_shares) {
  // out-of-plane (axial) against in-plane (radial + circumferential) motion of the whole section
  // (Thompson 2009 Sec. 5.2: axial modes are the web's out-of-plane bending, whatever the rim's
  // rocking does at the tread). On the 920 mm wheel at 8 mm the U_z share is 0.61-0.84 for the
  // one-nodal-circle axial modes n = 2..7 and 0.04-0.12 for the radial ones (docs/models.md
  // Sec. 3.4): the split is not near the boundary.
  const Eigen::Vector3d& e = kinetic_shares;
  if (e(2) > e(0) + e(1)) return ModeFamily::kAxial;
  return e(0) >= e(1) ? ModeFamily::kRadial : ModeFamily::kCircumferential;
}

int nodal_circle_component(ModeFamily family) {
  switch (family) {
    case ModeFamily::kAxial:
      return 2;
    case ModeFamily::kRadial:
      return 0;
    default:
      return 1;
  }
}

std::string mode_label(const WheelFeMode& m) {
  return std::string(family_name(m.family)) + " n=" + std::to_string(m.n) + " " +
         std::to_string(m.nodal_circles) + " circles";
}

std::vector<std::string> mode_labels(const std::vector<WheelFeMode>& modes) {
  std::vector<std::string> labels;
  std::map<std::string, std::vector<std::size_t>> alike;  // label -> the modes carrying it
  for (std::size_t k = 0; k < modes.size(); ++k) {
    labels.push_back(mode_label(modes[k]));
    alike[labels.back()].push_back(k);
  }
  for (auto& [label, ks] : alike) {
    if (ks.size() < 2) continue;
    std::stable_sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) {
      return modes[a].frequency < modes[b].frequency;
    });
    for (std::size_t i = 0; i < ks.size(); ++i) labels[ks[i]] += " #" + std::to_string(i + 1);
  }
  return labels;
}

}  // namespace rollnoise::dynamics
