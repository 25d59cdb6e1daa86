// Cant and cant deficiency of a curve (EN 13803:2017, Sec. 3: the equilibrium cant of a speed V on
// a radius R is D_eq = s V^2 / (g R), with s the distance of the rail heads' centre lines, 1.5 m for
// standard gauge; the cant deficiency is I = D_eq - D; in EN 13803's units I = 11.8 V^2/R - D with V
// in km/h, R in m and D, I in mm).
#pragma once

namespace rollnoise::noise {

/// s (m): the distance of the rail heads' centre lines of standard gauge (EN 13803).
inline constexpr double kRailHeadDistance = 1.5;
/// g (m/s^2).
inline constexpr double kGravity = 9.81;

/// The cant deficiency I = s V^2 / (g R) - D (m) of speed V (m/s) on a curve of radius R > 0 (m)
/// with cant D (m); positive when the unbalanced force points outwards.
inline double cant_deficiency_from_cant(double speed, double radius, double cant) {
  return kRailHeadDistance * speed * speed / (kGravity * radius) - cant;
}

}  // namespace rollnoise::noise
