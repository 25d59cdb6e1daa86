// The slip operator S of the tangential problem, s = rhs + S p, as a block-Toeplitz table.
//
// Paper Eq. 2 (unsteady CONTACT):  s = w + (A p - A0 p0)/dt. With the grid moving one element per
// step (V dt = dx), A0(I,J) = A(di + 1, dj), so
//   steady rolling (paper Eq. 3, p = p0):  S = V (A - A0) / dx,  rhs = w;
//   one transient step:                   S = A / dt,           rhs = w - A0 p0 / dt.
// S maps the tangential tractions (px, py) to slip velocities; its 2x2 blocks depend on the offset
// (di, dj) in [-(nx-1), nx-1] x [-(ny-1), ny-1] only. The xy block vanishes at dj = 0 by symmetry.
#pragma once

#include <vector>

#include "contact/influence.hpp"

namespace rollnoise::contact {

class SlipOperator {
 public:
  /// S = V (A - A0)/dx for steady rolling at speed V (m/s).
  static SlipOperator steady(const InfluenceTable& t, double speed);
  /// S = A/dt for one step of transient rolling.
  static SlipOperator transient(const InfluenceTable& t, double dt);

  const Grid& grid() const { return grid_; }
  int offset_index(int di, int dj) const { return (dj + grid_.ny - 1) * row_ + (di + grid_.nx - 1); }
  double xx(int k) const { return xx_[k]; }
  double xy(int k) const { return xy_[k]; }
  double yy(int k) const { return yy_[k]; }
  /// Coefficient of component c (xx, xy or yy) at the offset (di, dj).
  double operator()(Component c, int di, int dj) const {
    const int k = offset_index(di, dj);
    return c == Component::xx ? xx_[k] : c == Component::xy ? xy_[k] : yy_[k];
  }

 private:
  template <class Coefficient>
  static SlipOperator build(const Grid& g, Coefficient coeff);

  Grid grid_;
  int row_ = 0;  // 2 nx - 1
  std::vector<double> xx_, xy_, yy_;
};

}  // namespace rollnoise::contact
