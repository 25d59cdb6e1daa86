// The regular grid of rectangular elements over the potential contact area (Kalker 1990, Ch. 5).
//
// Elements are dx by dy; tractions are constant per element and the equations are collocated at the
// element centres x_i = x_min + (i + 1/2) dx, y_j = y_min + (j + 1/2) dy. Grid arrays are stored
// row-major as [iy][ix], i.e. flat index k = iy * nx + ix, the layout of the HDF5 output.
#pragma once

#include <vector>

namespace rollnoise::contact {

struct Grid {
  int nx = 0;          ///< elements in x (rolling direction)
  int ny = 0;          ///< elements in y (lateral)
  double dx = 0.0;     ///< element length in x (m)
  double dy = 0.0;     ///< element width in y (m)
  double x_min = 0.0;  ///< left edge of the potential contact area (m)
  double y_min = 0.0;  ///< lower edge (m)

  int size() const { return nx * ny; }
  int index(int ix, int iy) const { return iy * nx + ix; }
  double x(int ix) const { return x_min + (ix + 0.5) * dx; }
  double y(int iy) const { return y_min + (iy + 0.5) * dy; }
  double element_area() const { return dx * dy; }

  /// The grid spanning [-scale*a, scale*a] x [-scale*b, scale*b] with nx by ny elements
  /// (CONTACT's IPOTCN = -3 convention for Hertzian cases).
  static Grid around_ellipse(int nx, int ny, double a, double b, double scale) {
    Grid g;
    g.nx = nx;
    g.ny = ny;
    g.dx = 2.0 * scale * a / nx;
    g.dy = 2.0 * scale * b / ny;
    g.x_min = -scale * a;
    g.y_min = -scale * b;
    return g;
  }
};

/// A field on the grid, one value per element, layout [iy][ix].
using GridField = std::vector<double>;

}  // namespace rollnoise::contact
