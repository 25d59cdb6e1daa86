#include "pipeline/squeal_wheels.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "core/errors.hpp"
#include "dynamics/rail_model.hpp"
#include "noise/flange_patch.hpp"
#include "pipeline/bogie_noise.hpp"
#include "pipeline/squeal_hertz_wheels.hpp"

namespace rollnoise::pipeline {
namespace {

// Every wheel's contact for the characteristic equation (SquealWheelContact: its position and mean
// contact with its transfer, as run_squeal builds the leading outer wheel's): the profile cases'
// curve states (curve_wheels), or the Hertz states of the Hertzian curve cases from the bogie
// estimate (squeal_hertz_wheels.hpp); none otherwise. Falling friction: a contact alone may be
// unstable (run_squeal's check); then its wheelset's roots are meaningless and the wheelset is left
// out (WheelsetSqueal::skipped; the mean contact has no transfer).
std::vector<SquealWheelContact> squeal_wheel_contacts(const SquealResult& r, const NoiseCase& nc,
                                                      const MeanContactOptions& o) {
  std::vector<SquealWheelContact> out;
  const CurveSetup& curve = r.mean.curve();
  if (curve.state) {
    bool leading_outer = false;
    for (const noise::WheelContact& w : curve_wheels(curve, nc)) {
      out.push_back({w.wheel, w.position(), wheel_mean_contact(r.mean.contact(), w, o)});
      leading_outer = leading_outer || w.wheel == noise::WheelId::leading_outer;
    }
    // noise.second_patch = "coupled": the flange patch of a two-point contact is one more contact
    // of the leading outer wheel in (S1), as in the loop (bogie_noise.hpp, second_patches)
    if (nc.second_patch && leading_outer && curve.state_input)
      if (const auto flange = noise::flange_patch_contact(*curve.state_input, *curve.state))
        out.push_back({flange->wheel, flange->position(),
                       wheel_mean_contact(r.mean.contact(), *flange, o), true});
  } else if (curve.estimated && !r.mean.contact().profiles) {
    out = hertz_squeal_wheels(r.curve_case, nc, o, r.mean_is_leading_outer_wheel ? &r.mean : nullptr);
  }
  return out;
}

}  // namespace

std::vector<WheelsetSqueal> squeal_wheelsets(const SquealResult& r, const NoiseCase& nc,
                                             const noise::StabilityOptions& options) {
  if (!nc.squeal_wheelsets) return {};
  const bool per_wheel =
      r.mean.curve().state || (r.mean.curve().estimated && !r.mean.contact().profiles);
  if (!per_wheel) return {};
  std::vector<double> in_band;
  for (const auto& m : nc.wheel->modes())
    if (m.frequency >= nc.band_min && m.frequency <= nc.band_max) in_band.push_back(m.frequency);
  const dynamics::RailModel& rail = *nc.rail;
  noise::StabilityOptions o = options;
  o.band_min = nc.band_min;
  o.band_max = nc.band_max;
  // every wheel's contact first (its time counted with its wheelset below)
  const auto t_contacts = std::chrono::steady_clock::now();
  const std::vector<SquealWheelContact> all =
      squeal_wheel_contacts(r, nc, squeal_contact_options(nc, in_band));
  const double contacts_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_contacts).count();
  std::vector<WheelsetSqueal> out;
  for (bool leading : {true, false}) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<const SquealWheelContact*> wheels;
    for (const SquealWheelContact& w : all)
      if (noise::is_leading(w.wheel) == leading) wheels.push_back(&w);
    if (wheels.empty()) continue;
    WheelsetSqueal ws;
    for (const SquealWheelContact* w : wheels) {
      if (w->second_patch)
        ++ws.second_patches;
      else
        ws.wheels.push_back(w->wheel);
      if (!w->mean.transfer())
        ws.skipped += std::string(ws.skipped.empty() ? "" : "; ") + noise::wheel_name(w->wheel) +
                      (w->second_patch ? " (flange patch)" : "") +
                      ": the linearised contact alone is unstable (spectral radius of M0^-1 M1 = " +
                      std::to_string(w->mean.spectral_radius()) + ")";
    }
    if (!ws.skipped.empty()) {
      out.push_back(std::move(ws));
      continue;
    }
    std::vector<noise::SquealContact> contacts;
    bool coupled = false;
    for (const SquealWheelContact* w : wheels) {
      noise::ContactPoint p;
      p.wheelset = leading ? 0 : 1;
      p.side = noise::is_outer(w->wheel) ? 1 : -1;
      p.position = w->position;
      p.rail_x = rail.position() + (leading ? 0.0 : nc.wheelbase);
      contacts.push_back({p, w->mean.transfer().get(), w->mean.normal_stiffness()});
      coupled = coupled || w->mean.coupled();
    }
    noise::LaplaceLoop loop =
        noise::laplace_loop(*nc.wheel, rail, contacts, r.mean.contact().speed, coupled);
    auto inner = loop.rest;
    long* count = &ws.evaluations;
    loop.rest = [inner, count](noise::cdouble s) {
      ++*count;
      return inner(s);
    };
    for (const noise::ModeRoot& root : noise::mode_roots(loop, o)) {
      // loop.wheels[i] = (wheelset, side): the wheel of this wheelset on that side
      const int side = loop.wheels[root.dominant_wheel].second;
      WheelRoot wr;
      wr.root = root;
      wr.share = root.wheel_share[root.dominant_wheel];
      for (noise::WheelId w : ws.wheels)
        if ((noise::is_outer(w) ? 1 : -1) == side) wr.wheel = w;
      ws.roots.push_back(std::move(wr));
    }
    ws.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() +
                 contacts_seconds * static_cast<double>(wheels.size()) / all.size();
    out.push_back(std::move(ws));
  }
  return out;
}

std::vector<WheelRoot> wheel_roots(const std::vector<WheelsetSqueal>& s, noise::WheelId w) {
  std::vector<WheelRoot> out;
  for (const WheelsetSqueal& ws : s)
    for (const WheelRoot& r : ws.roots)
      if (r.wheel == w) out.push_back(r);
  std::sort(out.begin(), out.end(), [](const WheelRoot& a, const WheelRoot& b) {
    return a.root.frequency < b.root.frequency;
  });
  return out;
}

std::vector<WheelRoot> unstable_roots(const std::vector<WheelsetSqueal>& s) {
  std::vector<WheelRoot> out;
  for (const WheelsetSqueal& ws : s)
    for (const WheelRoot& r : ws.roots)
      if (r.root.unstable) out.push_back(r);
  return out;
}

}  // namespace rollnoise::pipeline
