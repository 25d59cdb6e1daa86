// The S1002 wheel profile defined analytically (EN 13715; UIC 510-2): eight sections, polynomials
// and circular arcs in the lateral coordinate s.
//
// s is measured from the taping line (s = 0), positive towards the field side (the outer face of
// the wheel), so the flange is at s < 0 and the flange back at s = -70 mm. F(s) is the increase of
// the wheel radius over the radius at the taping line. This is exactly the profile frame of
// geometry::Profile (y = s, z = F): the Manchester-benchmark point file MBench_S1002_v3.prw, read
// with its mirror.y flag, has its origin at the taping line and agrees with F to 2e-6 mm.
#pragma once

#include "geometry/profile.hpp"

namespace rollnoise::geometry {

/// Lateral range of the definition (m): s from -70 mm (flange back) to +60 mm.
constexpr double s1002_s_min = -70e-3;
constexpr double s1002_s_max = 60e-3;

/// F(s) of S1002 (m) for s in metres; std::domain_error outside [s1002_s_min, s1002_s_max].
double s1002_height(double s);

/// The S1002 profile sampled from the analytic definition every `spacing` metres (plus the
/// section boundaries), as a wheel Profile. The vertical end at s = -70 mm (flange back, where the
/// arc H has a vertical tangent) is left out: the profile starts at s = -69.9 mm.
Profile s1002_profile(double spacing = 0.1e-3);

}  // namespace rollnoise::geometry
