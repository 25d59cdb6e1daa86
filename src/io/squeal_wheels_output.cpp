#include "io/squeal_wheels_output.hpp"

#include <string>

namespace rollnoise::io {
namespace {

void write_roots(Hdf5Writer& w, const std::string& g, const std::vector<pipeline::WheelRoot>& roots,
                 bool with_wheel) {
  const std::size_t n = roots.size();
  std::vector<double> freq, zeta, share;
  std::vector<int> unstable, converged;
  std::vector<std::string> label, wheel;
  for (const pipeline::WheelRoot& r : roots) {
    freq.push_back(r.root.frequency);
    zeta.push_back(r.root.damping_ratio);
    share.push_back(r.share);
    unstable.push_back(r.root.unstable ? 1 : 0);
    converged.push_back(r.root.converged ? 1 : 0);
    label.push_back(r.root.label);
    wheel.push_back(noise::wheel_name(r.wheel));
  }
  w.write(g + "frequency", freq, {n}, "Hz (Im s / 2 pi)");
  w.write(g + "damping_ratio", zeta, {n}, "- (-Re s / |s|; negative: growing)");
  w.write(g + "unstable", unstable, {n}, "- (1: Re s > 0)");
  w.write(g + "mode", label, "- (label of the wheel mode the root continues, from the modes file)");
  w.write(g + "share", share, {n},
          "- (the wheel's share of the root's modal amplitudes, sum |q_j|^2 / |q|^2)");
  w.write(g + "converged", converged, {n}, "- (1: the continuation reached lambda = 1)");
  if (with_wheel) w.write(g + "wheel", wheel, "- (the wheel with the largest share)");
}

}  // namespace

void write_squeal_wheels(Hdf5Writer& w, const std::vector<pipeline::WheelsetSqueal>& s) {
  if (s.empty()) return;
  for (const pipeline::WheelsetSqueal& ws : s)
    for (noise::WheelId id : ws.wheels)
      write_roots(w, std::string("/squeal/wheels/") + noise::wheel_name(id) + "/",
                  pipeline::wheel_roots(s, id), false);
  write_roots(w, "/squeal/wheels/unstable/", pipeline::unstable_roots(s), true);
  std::string skipped;
  for (const pipeline::WheelsetSqueal& ws : s)
    if (!ws.skipped.empty()) skipped += (skipped.empty() ? "" : "; ") + ws.skipped;
  if (!skipped.empty())
    w.attribute("/squeal/wheels", "left_out", "wheelsets without roots: " + skipped);
  int patches = 0;
  for (const pipeline::WheelsetSqueal& ws : s) patches += ws.second_patches;
  if (patches > 0)
    w.attribute("/squeal/wheels", "second_patch",
                "the leading outer wheel's flange patch is a third contact of the leading "
                "wheelset (noise.second_patch = \"coupled\"; docs/squeal.md Sec. 8.2)");
  w.attribute("/squeal/wheels", "loop",
              "per wheelset, both wheels' contacts in one characteristic equation (rigid wheelset, "
              "the rails; "
              "docs/squeal.md Sec. 8); each root listed under the wheel with the largest modal "
              "share; the top-level "
              "/squeal is the leading outer wheel's single contact");
}

}  // namespace rollnoise::io
