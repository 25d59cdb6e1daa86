// Influence coefficients of the elastic half-space for piecewise-constant tractions on rectangular
// elements (Kalker 1990, Sec. 5.2; CONTACT's INFLCF = 2; docs/conventions.md Secs. 1-2).
//
// A unit uniform traction on element J produces at the centre of element I the displacement
// difference (body 1 relative to body 2) of the two quasi-identical half-spaces
//
//   A_zz = (1-nu)/(pi G) [[ X ln(Y+r) + Y ln(X+r) ]]                    (Boussinesq, integrated)
//   A_xx =     1/(pi G) [[ (1-nu) X ln(Y+r) + Y ln(X+r) ]]              (Cerruti, integrated)
//   A_yy =     1/(pi G) [[ X ln(Y+r) + (1-nu) Y ln(X+r) ]]
//   A_xy = A_yx = nu/(pi G) [[ -r ]]
//
// with X = x_I - xi, Y = y_I - eta, r = sqrt(X^2+Y^2) and [[F]] the double difference over the
// corners of element J. They depend on the index offsets (di, dj) = (i_I - i_J, j_I - j_J) only, so
// the matrices are block-Toeplitz. The table holds di in [-nx, nx] (one column more than A needs,
// for the shifted matrix A0 of the rolling step) and dj in [-(ny-1), ny-1].
#pragma once

#include <array>
#include <vector>

#include "contact/grid.hpp"
#include "contact/material.hpp"

namespace rollnoise::contact {

enum class Component { zz = 0, xx = 1, xy = 2, yy = 3 };

/// Unit-traction influence coefficients of one element, as a function of the element offset.
/// Exposed for tests: the closed forms above, for element size hx by hy at offset (X, Y).
double influence_coefficient(Component c, double X, double Y, double hx, double hy, const Material& m);

class InfluenceTable {
 public:
  InfluenceTable(const Grid& grid, const Material& material);

  const Grid& grid() const { return grid_; }
  const Material& material() const { return material_; }

  /// Coefficient for offsets di in [-nx, nx], dj in [-(ny-1), ny-1] (m/Pa: displacement per traction).
  double operator()(Component c, int di, int dj) const {
    return table_[static_cast<int>(c)][(dj + grid_.ny - 1) * row_ + (di + grid_.nx)];
  }

 private:
  Grid grid_;
  Material material_;
  int row_;  // 2 nx + 1
  std::array<std::vector<double>, 4> table_;
};

}  // namespace rollnoise::contact
