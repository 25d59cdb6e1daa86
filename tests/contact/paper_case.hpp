// The paper's Hertzian case (a = 7.18 mm, b = 5.29 mm, N = 98.1 kN, E = 210 GPa, nu = 0.28,
// mu = 0.3, V = 50 km/h) on CONTACT's reference grids, shared by the contact and nss tests.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "contact/hertz.hpp"
#include "contact/patch.hpp"

namespace rollnoise::testing {

inline const contact::Material kSteel{210e9, 0.28};
inline constexpr double kSpeed = 13.8888888888889, kMu = 0.3, kN = 98100;

/// The paper's patch on CONTACT's "coarse" (34 x 25) or "fine" (68 x 50) grid, solved once.
inline const contact::ContactPatch& paper_patch(const std::string& grid = "coarse") {
  static std::map<std::string, std::unique_ptr<contact::ContactPatch>> cache;
  auto& p = cache[grid];
  if (!p) {
    const bool fine = grid == "fine";
    const contact::Grid g =
        contact::Grid::around_ellipse(fine ? 68 : 34, fine ? 50 : 25, 7.18e-3, 5.29e-3, 34.0 / 30.0);
    const contact::HertzContact h = contact::hertz_from_semi_axes(7.18e-3, 5.29e-3, kN, kSteel);
    p = std::make_unique<contact::ContactPatch>(
        contact::solve_patch(g, kSteel, contact::quadratic_distance(g, h.A, h.B), kN));
  }
  return *p;
}

inline const contact::ContactPatch& coarse_patch() { return paper_patch("coarse"); }

}  // namespace rollnoise::testing
