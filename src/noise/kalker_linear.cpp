#include "noise/kalker_linear.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

// Kalker 1990, Table E.3 (C11, C22, C23) with C33 from the same table as reproduced by Johnson
// (1985, Ch. 8), Knothe & Stichel and Iwnicki's handbook. Rows: g = a/b = 0.1 ... 1.0, then
// b/a = 0.9 ... 0.1 (a/b = 1.111 ... 10); for each nu = 0, 0.25, 0.5.
constexpr int kRows = 19;
constexpr double kAspect[kRows] = {0.1,       0.2,       0.3,       0.4,       0.5,
                                   0.6,       0.7,       0.8,       0.9,       1.0,
                                   1.0 / 0.9, 1.0 / 0.8, 1.0 / 0.7, 1.0 / 0.6, 1.0 / 0.5,
                                   1.0 / 0.4, 1.0 / 0.3, 1.0 / 0.2, 1.0 / 0.1};
// g of the row: a/b for a <= b, b/a for a >= b.
constexpr double kG[kRows] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0,
                              0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1};
//                              nu = 0             nu = 0.25          nu = 0.5
constexpr double kC11[kRows][3] = {
    {2.51, 3.31, 4.85}, {2.59, 3.37, 4.81}, {2.68, 3.44, 4.80}, {2.78, 3.53, 4.82},
    {2.88, 3.62, 4.83}, {2.98, 3.72, 4.91}, {3.09, 3.81, 4.97}, {3.19, 3.91, 5.05},
    {3.29, 4.01, 5.12}, {3.40, 4.12, 5.20}, {3.51, 4.22, 5.30}, {3.65, 4.36, 5.42},
    {3.82, 4.54, 5.58}, {4.06, 4.78, 5.80}, {4.37, 5.10, 6.11}, {4.84, 5.57, 6.57},
    {5.57, 6.34, 7.34}, {6.96, 7.78, 8.82}, {10.7, 11.7, 12.9}};
constexpr double kC22[kRows][3] = {
    {2.51, 2.52, 2.53}, {2.59, 2.63, 2.66}, {2.68, 2.75, 2.81}, {2.78, 2.88, 2.98},
    {2.88, 3.01, 3.14}, {2.98, 3.14, 3.31}, {3.09, 3.28, 3.48}, {3.19, 3.41, 3.65},
    {3.29, 3.54, 3.82}, {3.40, 3.67, 3.98}, {3.51, 3.81, 4.16}, {3.65, 3.99, 4.39},
    {3.82, 4.21, 4.67}, {4.06, 4.50, 5.04}, {4.37, 4.90, 5.56}, {4.84, 5.48, 6.31},
    {5.57, 6.40, 7.51}, {6.96, 8.14, 9.79}, {10.7, 12.8, 16.0}};
constexpr double kC23[kRows][3] = {
    {0.334, 0.473, 0.731}, {0.483, 0.603, 0.809}, {0.607, 0.715, 0.889}, {0.720, 0.823, 0.977},
    {0.827, 0.929, 1.07},  {0.930, 1.03, 1.18},   {1.03, 1.14, 1.29},    {1.13, 1.25, 1.40},
    {1.23, 1.36, 1.51},    {1.33, 1.47, 1.63},    {1.44, 1.59, 1.77},    {1.58, 1.75, 1.94},
    {1.76, 1.95, 2.18},    {2.01, 2.23, 2.50},    {2.35, 2.62, 2.96},    {2.88, 3.24, 3.70},
    {3.79, 4.32, 5.01},    {5.72, 6.63, 7.89},    {12.2, 14.6, 18.0}};
constexpr double kC33[kRows][3] = {
    {6.42, 8.28, 11.7},    {3.46, 4.27, 5.66},    {2.49, 2.96, 3.72},    {2.02, 2.32, 2.77},
    {1.74, 1.93, 2.22},    {1.56, 1.68, 1.86},    {1.43, 1.50, 1.60},    {1.34, 1.37, 1.42},
    {1.27, 1.27, 1.27},    {1.21, 1.19, 1.16},    {1.16, 1.11, 1.06},    {1.10, 1.04, 0.954},
    {1.05, 0.965, 0.852},  {1.01, 0.892, 0.751},  {0.958, 0.819, 0.650}, {0.912, 0.747, 0.549},
    {0.868, 0.674, 0.446}, {0.828, 0.601, 0.341}, {0.795, 0.526, 0.228}};
constexpr double kNu[3] = {0.0, 0.25, 0.5};

struct Table {
  KalkerTableRow rows[kRows * 3];
  Table() {
    for (int i = 0; i < kRows; ++i)
      for (int j = 0; j < 3; ++j)
        rows[3 * i + j] = {kAspect[i], kNu[j], {kC11[i][j], kC22[i][j], kC23[i][j], kC33[i][j]}};
  }
};

// Quadratic Lagrange interpolation of 1/C through nu = 0, 0.25, 0.5.
double in_nu(const double (&c)[3], double nu) {
  const double l0 = (nu - kNu[1]) * (nu - kNu[2]) / ((kNu[0] - kNu[1]) * (kNu[0] - kNu[2]));
  const double l1 = (nu - kNu[0]) * (nu - kNu[2]) / ((kNu[1] - kNu[0]) * (kNu[1] - kNu[2]));
  const double l2 = (nu - kNu[0]) * (nu - kNu[1]) / ((kNu[2] - kNu[0]) * (kNu[2] - kNu[1]));
  return 1.0 / (l0 / c[0] + l1 / c[1] + l2 / c[2]);
}

}  // namespace

const KalkerTableRow* kalker_table(int* rows) {
  static const Table table;
  if (rows) *rows = kRows * 3;
  return table.rows;
}

KalkerCoefficients kalker_coefficients(double a_over_b, double nu) {
  if (!std::isfinite(a_over_b) || a_over_b < 0.1 * (1 - 1e-12) || a_over_b > 10.0 * (1 + 1e-12))
    throw InputError("a_over_b", "Kalker's table covers a/b from 0.1 to 10, got a/b = " +
                                     std::to_string(a_over_b));
  if (!std::isfinite(nu) || nu < 0.0 || nu > 0.5)
    throw std::invalid_argument("Kalker's table covers Poisson's ratio 0 to 0.5, got " +
                                std::to_string(nu));  // material.nu is checked where read
  // Bracketing rows i, i+1 in the table order and the weight t on row i+1, linear in g.
  int i = 0;
  double t = 0.0;
  if (a_over_b <= 1.0) {
    const double g = std::max(a_over_b, 0.1);
    i = std::min(static_cast<int>(std::floor(g * 10.0 + 1e-12)) - 1, 8);  // rows 0..9: g = 0.1..1
    t = (g - kG[i]) / (kG[i + 1] - kG[i]);
  } else {
    const double g = std::max(1.0 / a_over_b, 0.1);  // rows 9..18: g = 1 ... 0.1 (decreasing)
    i = 9;
    while (i < kRows - 2 && g < kG[i + 1]) ++i;
    t = (g - kG[i]) / (kG[i + 1] - kG[i]);
  }
  t = std::min(1.0, std::max(0.0, t));
  auto at = [&](const double(&table)[kRows][3]) {
    return (1.0 - t) * in_nu(table[i], nu) + t * in_nu(table[i + 1], nu);
  };
  return {at(kC11), at(kC22), at(kC23), at(kC33)};
}

Eigen::Matrix3d kalker_creep_matrix(double a, double b, double G, double nu) {
  // contracts: the semi-axes of a patch, G from material.E > 0 and material.nu in [0, 0.5)
  if (!(a > 0.0) || !std::isfinite(a)) throw std::invalid_argument("Kalker: semi-axis a must be positive");
  if (!(b > 0.0) || !std::isfinite(b)) throw std::invalid_argument("Kalker: semi-axis b must be positive");
  if (!(G > 0.0) || !std::isfinite(G)) throw std::invalid_argument("Kalker: shear modulus must be positive");
  const KalkerCoefficients k = kalker_coefficients(a / b, nu);
  const double c = std::sqrt(a * b), c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  Eigen::Matrix3d f = Eigen::Matrix3d::Zero();
  f(0, 0) = G * c2 * k.C11;  // Fx = -f11 xi_x
  f(1, 1) = G * c2 * k.C22;  // Fy = -f22 xi_y - f23 phi
  f(1, 2) = G * c3 * k.C23;
  f(2, 1) = -G * c3 * k.C23;  // Mz = -f32 xi_y - f33 phi = G c^3 C23 xi_y - G c^4 C33 phi
  f(2, 2) = G * c4 * k.C33;
  return f;
}

Eigen::Matrix3d kalker_creep_matrix(double a, double b, const contact::Material& material) {
  return kalker_creep_matrix(a, b, material.shear_modulus(), material.nu);
}

}  // namespace rollnoise::noise
