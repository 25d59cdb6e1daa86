// Total forces on body 1 (the wheel) from the tractions (docs/conventions.md Secs. 1-2):
//   Fx = dx dy sum px,  Fy = dx dy sum py,  Mz = dx dy sum (x py - y px)  (about the grid origin).
#pragma once

#include "contact/grid.hpp"

namespace rollnoise::contact {

struct TangentialForces {
  double Fx = 0.0;  ///< N
  double Fy = 0.0;  ///< N
  double Mz = 0.0;  ///< N m
};

inline TangentialForces total_forces(const Grid& g, const GridField& px, const GridField& py) {
  TangentialForces f;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const int k = g.index(ix, iy);
      f.Fx += px[k];
      f.Fy += py[k];
      f.Mz += g.x(ix) * py[k] - g.y(iy) * px[k];
    }
  const double A = g.element_area();
  f.Fx *= A, f.Fy *= A, f.Mz *= A;
  return f;
}

}  // namespace rollnoise::contact
