#include "contact/influence.hpp"

#include <cmath>

namespace rollnoise::contact {
namespace {

// X ln(Y + r), with Y + r evaluated without cancellation when Y < 0 (Y + r = X^2 / (r - Y)); the
// limit X -> 0 of X ln|X| is 0.
double x_log_y_plus_r(double X, double Y) {
  if (X == 0.0) return 0.0;
  const double r = std::hypot(X, Y);
  const double y_plus_r = Y >= 0.0 ? Y + r : X * X / (r - Y);
  return X * std::log(y_plus_r);
}

// Double difference over the element corners: [[F]] = F(X+,Y+) - F(X+,Y-) - F(X-,Y+) + F(X-,Y-).
template <class F>
double corners(F f, double X, double Y, double hx, double hy) {
  return f(X + hx, Y + hy) - f(X + hx, Y - hy) - f(X - hx, Y + hy) + f(X - hx, Y - hy);
}

}  // namespace

double influence_coefficient(Component c, double X, double Y, double hx, double hy,
                             const Material& m) {
  const double G = m.shear_modulus();
  const double nu = m.nu;
  const double hx2 = 0.5 * hx, hy2 = 0.5 * hy;
  auto f1 = [](double x, double y) { return x_log_y_plus_r(x, y); };  // X ln(Y+r)
  auto f2 = [](double x, double y) { return x_log_y_plus_r(y, x); };  // Y ln(X+r)
  switch (c) {
    case Component::zz:
      return (1.0 - nu) / (M_PI * G) *
             (corners(f1, X, Y, hx2, hy2) + corners(f2, X, Y, hx2, hy2));
    case Component::xx:
      return 1.0 / (M_PI * G) *
             ((1.0 - nu) * corners(f1, X, Y, hx2, hy2) + corners(f2, X, Y, hx2, hy2));
    case Component::yy:
      return 1.0 / (M_PI * G) *
             (corners(f1, X, Y, hx2, hy2) + (1.0 - nu) * corners(f2, X, Y, hx2, hy2));
    case Component::xy:
      return nu / (M_PI * G) *
             corners([](double x, double y) { return -std::hypot(x, y); }, X, Y, hx2, hy2);
  }
  return 0.0;
}

InfluenceTable::InfluenceTable(const Grid& grid, const Material& material)
    : grid_(grid), material_(material), row_(2 * grid.nx + 1) {
  const int rows = 2 * grid.ny - 1;
  for (auto& t : table_) t.assign(static_cast<size_t>(row_) * rows, 0.0);
  for (int dj = -(grid.ny - 1); dj <= grid.ny - 1; ++dj) {
    for (int di = -grid.nx; di <= grid.nx; ++di) {
      const double X = di * grid.dx, Y = dj * grid.dy;
      const size_t k = static_cast<size_t>(dj + grid.ny - 1) * row_ + (di + grid.nx);
      for (Component c : {Component::zz, Component::xx, Component::xy, Component::yy})
        table_[static_cast<int>(c)][k] =
            influence_coefficient(c, X, Y, grid.dx, grid.dy, material);
    }
  }
}

}  // namespace rollnoise::contact
